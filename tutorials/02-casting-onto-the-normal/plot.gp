# Lab 2's plots: velocity components after an oblique collision, against the normal's angle.
# Before: lines; after: open markers. Where a marker sits on a line of the other colour, the two
# pucks have exchanged that component; on a line of its own colour, the component is unchanged.
load common."/style.gp"
data = outdir."/oblique.csv"

set xrange [-90:90]
set xtics 30
set xlabel "angle of the contact normal from the x axis (degrees)"
set xzeroaxis lt 7 lw 1

set output file("normal")
set title "Lab 2: velocity components along the normal n"
set ylabel "velocity along the normal (m/s)"
set yrange [-1.15:1.1]
set key bottom center Left reverse maxrows 2
plot data using "angle":"a_normal_after" every 2 with points lt 1 pt 6 ps 1.6 title "A after", \
     data using "angle":"b_normal_after" every 2 with points lt 2 pt 4 ps 1.6 title "B after", \
     data using "angle":"a_normal_before" with lines lt 1 title "A before", \
     data using "angle":"b_normal_before" with lines lt 2 title "B before"

set output file("tangential")
set title "Lab 2: velocity components along the tangent t"
set ylabel "velocity along the tangent (m/s)"
set yrange [-1.1:1.1]
set key top right Left reverse
plot data using "angle":"a_tangent_after" every 2 with points lt 1 pt 6 ps 1.6 title "A after", \
     data using "angle":"b_tangent_after" every 2 with points lt 2 pt 4 ps 1.6 title "B after", \
     data using "angle":"a_tangent_before" with lines lt 1 title "A before", \
     data using "angle":"b_tangent_before" with lines lt 2 title "B before"

set output file("velocities")
set title "Lab 2: the pucks' velocities after, in the plane's axes"
set ylabel "velocity component after (m/s)"
set yrange [-1.3:1.1]
set key bottom center Left reverse maxrows 2
plot data using "angle":"a_vx" with linespoints lt 1 pi 3 title "A, x", \
     data using "angle":"a_vy" with linespoints lt 3 pi 3 title "A, y", \
     data using "angle":"b_vx" with linespoints lt 2 pi 3 title "B, x", \
     data using "angle":"b_vy" with linespoints lt 4 pi 3 title "B, y"
