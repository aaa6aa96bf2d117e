# Lab 5's plots: the velocities after by each method, and the spring chain as its springs stiffen.
load common."/style.gp"

# Velocities after, one cluster of bars per ball, one bar per method.
set style data histograms
set style histogram clustered gap 1.5
set style fill solid 0.85 border rgb "#333333"
set boxwidth 1
set xlabel "ball (ball 1 arrives at 1 m/s, the others are at rest)"
set ylabel "velocity after the collision (m/s)"
set yrange [-1.15:1.1]
set ytics 0.25
set xzeroaxis lt 7 lw 1
set key bottom right Left reverse
do for [n in "3 5"] {
  set output file("cradle-".n)
  set xrange [-0.6:n - 0.4]
  set title sprintf("Lab 5: Newton's cradle with %s balls, velocities after by method", n)
  f = outdir."/cradle-".n.".csv"
  plot f using "simultaneous":xtic(1) lt 1 title "simultaneous (paper, A·Fdt = B)", \
       f using "serial" lt 2 title "serial (pair by pair)", \
       f using "linear_touching" lt 3 title "springs, linear, touching", \
       f using "hertz_touching" lt 4 title "springs, Hertz, touching", \
       f using "linear_gapped" lt 5 title "springs, linear, small gaps"
}
unset style data
unset style fill
set style data lines
set xrange [*:*]
set yrange [*:*]
set ytics autofreq

# The first ball's velocity as the springs stiffen, 3 balls.
set output file("stiffness")
set title "Lab 5: 3 balls joined by springs that only push, stiffer and stiffer"
set logscale x
set format x "10^{%L}"
set xlabel "spring stiffness k (N/m^{/Symbol a}; gaps of 0.001 m where there are gaps)"
set ylabel "velocity of ball 1 after (m/s)"
set yrange [-0.8:0.05]
set ytics 0.1
set key bottom right Left reverse
data = outdir."/stiffness.csv"
plot 0 lt 2 dt 2 lw 2 title "serial answer: 0", \
     -1.0/3 lt 1 dt 2 lw 2 title "simultaneous answer: -1/3", \
     data using "stiffness":"linear_touching_v1" with linespoints lt 3 title "linear, touching", \
     data using "stiffness":"hertz_touching_v1" with linespoints lt 4 title "Hertz, touching", \
     data using "stiffness":"linear_gapped_v1" with linespoints lt 5 title "linear, small gaps", \
     data using "stiffness":"hertz_gapped_v1" with linespoints lt 6 title "Hertz, small gaps"

# Two contacts of different stiffness: k_2 = ratio * k_1.
set output file("stiffness-ratio")
set title "Lab 5: 3 touching balls, linear springs of different stiffness"
set xlabel "stiffness ratio k_{23} / k_{12} (dimensionless; second contact over first)"
set ylabel "velocity after (m/s)"
set yrange [-0.5:1.1]
set ytics 0.25
set key at graph 0.98, graph 0.67 top right Left reverse
data = outdir."/stiffness-ratio.csv"
plot data using "ratio":"v1" with linespoints lt 1 title "ball 1", \
     data using "ratio":"v2" with linespoints lt 2 title "ball 2", \
     data using "ratio":"v3" with linespoints lt 3 title "ball 3", \
     -1.0/3 lt 7 dt 2 title "simultaneous", 2.0/3 lt 7 dt 2 notitle, \
     0 lt 8 dt 3 lw 2 title "serial", 1 lt 8 dt 3 lw 2 notitle
