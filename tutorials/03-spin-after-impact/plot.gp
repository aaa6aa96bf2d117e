# Lab 3's plots: a rod landing on one end, against its angle to the ground.
load common."/style.gp"
data = outdir."/rod.csv"

set xrange [0:90]
set xtics 15
set xlabel "angle of the rod to the ground (degrees; 0 flat, 90 upright)"
deg = pi / 180
# The closed form for a uniform rod falling at v without spin (m = l = v = 1 here).
closed(e, a) = e / (1 + 3 * cos(a * deg)**2)

set output file("impulse")
set title "Lab 3: the impulse at the landing end"
set ylabel "impulse F dt (N s)"
set yrange [0:2.1]
set key top left Left reverse
set samples 181
plot data using "angle":"impulse_e1" every 3 with points lt 1 pt 7 title "library, e = 1", \
     data using "angle":"impulse_e1.5" every 3 with points lt 2 pt 5 title "library, e = 1.5", \
     data using "angle":"impulse_e2" every 3 with points lt 3 pt 9 title "library, e = 2", \
     closed(1, x) with lines lt 1 title "lines: closed form e m v / (1 + 3 cos^2{/Symbol q})", \
     closed(1.5, x) with lines lt 2 notitle, \
     closed(2, x) with lines lt 3 notitle

set output file("spin")
set title "Lab 3: the rod's spin after landing"
set ylabel "angular velocity after (rad/s)"
set yrange [0:*]
set key bottom left Left reverse
plot data using "angle":"spin_e1" with linespoints lt 1 pi 5 title "e = 1 (restitution 0)", \
     data using "angle":"spin_e1.5" with linespoints lt 2 pi 5 title "e = 1.5 (restitution 0.5)", \
     data using "angle":"spin_e2" with linespoints lt 3 pi 5 title "e = 2 (restitution 1)"

set output file("energy-share")
set title "Lab 3: the share of the kinetic energy after that is rotation"
set ylabel "rotational energy / kinetic energy, after (dimensionless)"
set yrange [0:1.05]
set key bottom center Left reverse
plot data using "angle":"rotation_share_e1" with linespoints lt 1 pi 5 title "e = 1", \
     data using "angle":"rotation_share_e1.5" with linespoints lt 2 pi 5 title "e = 1.5", \
     data using "angle":"rotation_share_e2" with linespoints lt 3 pi 5 title "e = 2"
