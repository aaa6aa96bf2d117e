# Lab 9's plots: a rod striking a rough floor, with three laws of restitution.
load common."/style.gp"
data = outdir."/rough-floor.csv"

set xlabel "coefficient of friction {/Symbol m} (dimensionless)"
set xrange [0:*]

set output file("rough-floor-energy")
set title "Lab 9: the rod's kinetic energy after, against the friction"
set ylabel "kinetic energy (J)"
set yrange [0.5:0.85]
set key bottom right Left reverse
plot data using "mu":"energy_before" with lines lt 7 dt 2 title "before the collision", \
     data using "mu":"energy_newton" with lines lt 1 title "after: Newton's law", \
     data using "mu":"energy_poisson" with lines lt 2 title "after: Poisson's law", \
     data using "mu":"energy_energetic" with lines lt 3 title "after: the energetic law"

set output file("rough-floor-impulse")
set title "Lab 9: the impulses, against the friction"
set ylabel "impulse on the rod (N s)"
set yrange [-0.1:1.3]
set key top left Left reverse maxrows 3
plot data using "mu":"normal_newton" with lines lt 1 title "normal P_n: Newton", \
     data using "mu":"normal_poisson" with lines lt 2 title "normal P_n: Poisson", \
     data using "mu":"normal_energetic" with lines lt 3 title "normal P_n: energetic", \
     data using "mu":"tangential_newton" with lines lt 1 dt 2 title "tangential P_t: Newton", \
     data using "mu":"tangential_poisson" with lines lt 2 dt 2 title "tangential P_t: Poisson", \
     data using "mu":"tangential_energetic" with lines lt 3 dt 2 title "tangential P_t: energetic"

# Routh's diagrams: straight lines between the corners the library reports (the end of each
# phase), and where each law ends (circle: Newton, square: Poisson, diamond: energetic).
set xlabel "normal impulse P_n (N s)"
set yrange [*:*]
set xrange [0:*]
set xzeroaxis lt 7 lw 1
route(k) = sprintf("%s/routh-%d.csv", outdir, k)
ends(k) = sprintf("%s/routh-%d-ends.csv", outdir, k)

set output file("routh-slip")
set title "Lab 9: Routh's diagram, the slip of the rod's end\n{/*0.8 ends: circle Newton, square Poisson, diamond energetic}"
set ylabel "slip u_t (m/s; velocity of the end along the floor)"
set yrange [-0.6:2.6]
set key top right Left reverse
plot for [k=1:3] route(k) using 1:4 with linespoints lt k pt 7 ps 0.6 title columnhead(5), \
     for [k=1:3] ends(k) using "normal":"slip" every ::0::0 with points lt k pt 6 ps 2 notitle, \
     for [k=1:3] ends(k) using "normal":"slip" every ::1::1 with points lt k pt 4 ps 2 notitle, \
     for [k=1:3] ends(k) using "normal":"slip" every ::2::2 with points lt k pt 12 ps 2 notitle

set output file("routh-separation")
set title "Lab 9: Routh's diagram, the separation of the rod's end\n{/*0.8 ends: circle Newton, square Poisson, diamond energetic}"
set yrange [*:*]
set ylabel "separation u_n (m/s; negative: approaching)"
set key bottom right Left reverse
plot for [k=1:3] route(k) using 1:3 with linespoints lt k pt 7 ps 0.6 title columnhead(5), \
     for [k=1:3] ends(k) using "normal":"separation" every ::0::0 with points lt k pt 6 ps 2 notitle, \
     for [k=1:3] ends(k) using "normal":"separation" every ::1::1 with points lt k pt 4 ps 2 notitle, \
     for [k=1:3] ends(k) using "normal":"separation" every ::2::2 with points lt k pt 12 ps 2 notitle
