# Lab 6's plots: where mixed elasticities gain energy, and how the answer depends on the observer.
load common."/style.gp"

set output file("gain-map")
set title "Lab 6: energy change with elasticities 2 (body 1) and 1 (body 2)"
set xlabel "velocity of body 1 (on the left), v_1 (m/s)"
set ylabel "velocity of body 2 (on the right), v_2 (m/s)"
set xrange [-3.025:3.025]
set yrange [-3.025:3.025]
set xtics 1
set ytics 1
set cbrange [-1:1]
set cbtics 0.5
set cblabel "energy change / ({/Symbol m} u^2 / 2) (dimensionless)" offset 1,0
# Blues for a loss, reds for a gain, with a jump at zero so that the sign shows at a glance.
set palette defined (-1 "#2166ac", 0 "#d1e5f0", 0 "#fddbc7", 1 "#b2182b")
set key top left Left reverse opaque
unset grid
set grid front lc rgb "#888888" lw 0.5
set label 1 "no collision here:\nthe bodies do not approach" at -1.4,1.2 center front
# Values beyond the colour range are clipped to it (with image leaves them out otherwise). The
# NaN cells must stay in the grid, undefined (transparent), rather than be skipped as missing.
unset datafile missing
clip(c) = c > 1 ? 1 : (c < -1 ? -1 : c)
plot outdir."/gain-map.csv" using "v1":"v2":(clip(column("relative_energy_change"))) \
       with image notitle, \
     x with lines lt 7 lw 1.5 title "v_1 = v_2", \
     "+" using (2):(1) every ::0::0 with points lt 7 pt 7 ps 1.8 title "worked example (2, 1)"
unset label 1
set datafile missing "NaN"
set grid back lc rgb "#d0d0d0" lw 0.7

set output file("frames")
set title "Lab 6: the same collision seen by observers moving at w"
set xlabel "observer's velocity w (m/s)"
set ylabel "energy change in the collision (J)"
set xrange [-1:3]
set yrange [-0.6:2.1]
set xtics 0.5
set ytics 0.5
set xzeroaxis lt 7 lw 1
# The three observers the worksheet asks about.
set arrow 1 from 0, graph 0 to 0, graph 1 nohead lt 8 dt 3 back
set arrow 2 from 1, graph 0 to 1, graph 1 nohead lt 8 dt 3 back
set arrow 3 from 2, graph 0 to 2, graph 1 nohead lt 8 dt 3 back
set label 11 "ground" at 0.05, graph 0.05 left
set label 12 "with body 2" at 1.05, graph 0.05 left
set label 13 "with body 1" at 2.05, graph 0.05 left
set key top right Left reverse
data = outdir."/frames.csv"
plot data using "boost":"mixed_energy_change" with linespoints lt 2 pi 4 title "elasticities 2 and 1", \
     data using "boost":"equal_1.5_energy_change" with linespoints lt 1 pi 4 title "elasticities 1.5 and 1.5", \
     data using "boost":"equal_2_energy_change" with linespoints lt 3 pi 4 title "elasticities 2 and 2"

set output file("frames-velocities")
set title "Lab 6: the velocities after, brought back to the ground frame"
set ylabel "velocity after, in the ground frame (m/s)"
set yrange [-0.5:4.2]
set key top left Left reverse maxrows 2 opaque
plot data using "boost":"mixed_v1_after" with linespoints lt 2 pi 4 title "2 and 1: body 1", \
     data using "boost":"mixed_v2_after" with linespoints lt 2 dt 2 pt 4 pi 4 title "2 and 1: body 2", \
     data using "boost":"equal_1.5_v1_after" with linespoints lt 1 pi 4 title "1.5 and 1.5: body 1", \
     data using "boost":"equal_1.5_v2_after" with linespoints lt 1 dt 2 pt 4 pi 4 title "1.5 and 1.5: body 2"
