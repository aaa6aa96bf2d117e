# Lab 4's plots: impulses on two contacts for a box and a bead, and the split in a shallow V.
load common."/style.gp"

set output file("lever")
data = outdir."/lever.csv"
set title "Lab 4: two contacts, a box (rank 2) and a bead (rank 1)"
set xlabel "horizontal offset of the centre of mass (m; contacts at -1 m and +1 m)"
set ylabel "impulse at the contact (N s)"
set xrange [-1:1]
set yrange [-0.05:2.1]
set key top center Left reverse maxrows 3
plot data using "offset":"box_j1" with linespoints lt 1 pi 4 title "box, left contact", \
     data using "offset":"box_j2" with linespoints lt 2 pi 4 title "box, right contact", \
     data using "offset":"bead_min_norm_j1" with lines lt 3 lw 3 title "bead, minimum norm (both)", \
     data using "offset":"bead_basic_j1" with lines lt 4 dt 2 lw 2.5 title "bead, basic: left", \
     data using "offset":"bead_basic_j2" with lines lt 5 dt 2 lw 2.5 title "bead, basic: right"

set output file("split")
data = outdir."/tilt.csv"
set title "Lab 4: a bead in a shallow V, which support takes the impulse?"
set xlabel "share of the tilt given to the left support, {/Symbol b}_1 / ({/Symbol b}_1 + {/Symbol b}_2) (dimensionless)"
set ylabel "share of the impulse on the left support (dimensionless)"
set xrange [0:1]
set yrange [-0.05:1.15]
set key bottom left Left reverse maxrows auto
plot data using "left_fraction":"share_tilt_2" with linespoints lt 1 title "total tilt 2 degrees", \
     data using "left_fraction":"share_tilt_30" with points lt 2 pt 4 ps 1.4 title "total tilt 30 degrees", \
     0.5 lt 3 dt 2 lw 2 title "flat supports, minimum norm", \
     1.0 lt 4 dt 3 lw 2.5 title "flat supports, basic"
