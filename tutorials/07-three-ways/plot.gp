# Lab 7's plots: the three methods' velocities for two rows of balls, the spinning rod's rising
# end (its impulse and its approach speed after) as the spin grows, and how many serial
# collisions a cradle needs as the elasticity falls.
load common."/style.gp"

# --- Velocities after, one cluster of bars per ball, one bar per method; two scenes side by side.
set output file("three-ways-balls")
set multiplot layout 1,2 title "Lab 7: velocities after, elasticity 2, balls of mass 1" font ",15"
set style data histograms
set style histogram clustered gap 1.2
set style fill solid 0.85 border rgb "#333333"
set boxwidth 1
set xlabel "ball (a count)"
set yrange [-2.5:3.5]
set ytics 1
set xzeroaxis lt 7 lw 1
set key top left Left reverse font ",11"
set xrange [-0.6:2.6]
set ylabel "velocity after (m/s)"
set title "Newton's cradle: (3, 0, 0) before" font ",13"
f = outdir."/cradle.csv"
plot f using "simultaneous":xtic(1) lt 1 title "simultaneous", \
     f using "complementarity" lt 3 title "complementarity", \
     f using "serial" lt 2 title "serial"
set title "Two balls hit one: (3, 0, -1.5) before" font ",13"
set ylabel ""
unset key
f = outdir."/two-hit-one.csv"
plot f using "simultaneous":xtic(1) lt 1 notitle, \
     f using "complementarity" lt 3 notitle, \
     f using "serial" lt 2 notitle
unset multiplot
unset style data
unset style fill
set style data lines
set xrange [*:*]
set yrange [*:*]
set ytics autofreq
unset xzeroaxis
unset title

rod = outdir."/rod.csv"
set xlabel "spin {/Symbol w} before (rad/s)"

# --- The impulse at the rising end as the spin grows, at elasticity 2 and 1.
set output file("three-ways-rod-impulse")
set multiplot layout 1,2 title "Lab 7: a rod falling at 1 and spinning at {/Symbol w} lands on two points:\nthe impulse at the end that rises (for {/Symbol w} > 1)" font ",14"
set xzeroaxis lt 7 lw 1
set yrange [-1.8:1.4]
set ytics 0.5
set xtics 2
set key bottom left Left reverse font ",11"
set ylabel "impulse Fdt at the rising end (N s)"
set title "elasticity 2" font ",13"
plot rod using "omega":"serial_impulse_e2" lt 2 lw 5 title "serial", \
     rod using "omega":"simultaneous_impulse_e2" lt 1 title "simultaneous", \
     rod using "omega":"complementarity_impulse_e2" lt 3 dt 2 title "complementarity"
set title "elasticity 1" font ",13"
set ylabel ""
unset key
plot rod using "omega":"serial_impulse_e1" lt 2 lw 5 notitle, \
     rod using "omega":"simultaneous_impulse_e1" lt 1 notitle, \
     rod using "omega":"complementarity_impulse_e1" lt 3 dt 2 notitle
unset multiplot

# --- The rising end's approach speed after (> 0: it comes back down into the ground).
set output file("three-ways-rod-approach")
set multiplot layout 1,2 title "Lab 7: the same rod, the approach speed of its rising end after\n(> 0: it is still moving into the ground)" font ",14"
set yrange [-5:7.5]
set ytics 2
set key top left Left reverse font ",11"
set ylabel "approach speed after at the rising end (m/s)"
set title "elasticity 2" font ",13"
plot rod using "omega":"serial_approach_e2" lt 2 lw 5 title "serial", \
     rod using "omega":"simultaneous_approach_e2" lt 1 title "simultaneous", \
     rod using "omega":"complementarity_approach_e2" lt 3 dt 2 title "complementarity"
set title "elasticity 1" font ",13"
set ylabel ""
unset key
plot rod using "omega":"serial_approach_e1" lt 2 lw 5 notitle, \
     rod using "omega":"simultaneous_approach_e1" lt 1 notitle, \
     rod using "omega":"complementarity_approach_e1" lt 3 dt 2 notitle
unset multiplot
unset xzeroaxis
unset title

# --- Serial collisions as the elasticity falls: inelastic collapse, cut off by the tolerance.
set output file("three-ways-collisions")
set title "Lab 7: how many serial collisions until no contact approaches"
set xlabel "elasticity (dimensionless; 1: perfectly inelastic, 2: perfectly elastic)"
set ylabel "serial collisions (a count)"
set logscale y
set yrange [1:300]
set ytics (1, 2, 3, 5, 10, 20, 50, 100, 200)
set xrange [1:2]
set xtics 0.1
set key top right Left reverse
data = outdir."/collisions.csv"
plot data using "elasticity":"cradle_3" with steps lt 1 title "cradle of 3, (1, 0, 0)", \
     data using "elasticity":"cradle_5" with steps lt 2 title "cradle of 5, (1, 0, 0, 0, 0)", \
     data using "elasticity":"rod_omega_2" with steps lt 3 title "rod spinning at 2"
