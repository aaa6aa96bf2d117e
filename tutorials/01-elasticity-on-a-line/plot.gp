# Lab 1's plots: kinetic energy after, and relative velocity after, against elasticity.
load common."/style.gp"
data = outdir."/elasticity.csv"
if (!exists("sweep")) sweep = 0
cli = outdir."/sweep.csv"

set xrange [0:3]
set xtics 0.5
set xlabel "elasticity e (dimensionless; = 1 + coefficient of restitution)"
# The regions of section 1.3: below 1 the bodies still approach after the collision, above 2
# the collision adds energy.
set object 1 rect from 0,graph 0 to 1,graph 1 behind fc rgb "#fdf1dc" fs solid noborder
set object 2 rect from 2,graph 0 to 3,graph 1 behind fc rgb "#fde3e3" fs solid noborder
set label 1 "tunnelling" at 0.5,graph 0.06 center
set label 2 "ordinary collisions" at 1.5,graph 0.06 center
set label 3 "energy gained" at 2.5,graph 0.06 center

set output file("energy")
set title "Lab 1: kinetic energy after a head-on collision"
set ylabel "kinetic energy (J)"
set key top left Left reverse
if (sweep) {
  plot data using "elasticity":"energy_before" with lines lt 8 dt 2 title "before the collision", \
       data using "elasticity":"energy_after" with linespoints lt 1 pi 2 title "after (library, one\\_d::collide)", \
       cli using "elasticity":"energy_after" with points lt 2 pt 6 ps 1.4 title "after (impulselab sweep)"
} else {
  plot data using "elasticity":"energy_before" with lines lt 8 dt 2 title "before the collision", \
       data using "elasticity":"energy_after" with linespoints lt 1 pi 2 title "after (library, one\\_d::collide)"
}

set output file("relative-velocity")
set title "Lab 1: relative velocity after the collision"
set ylabel "relative velocity v_2 - v_1 (m/s)"
set key bottom right Left reverse
set offsets 0, 0, 1, 4
set label 1 at 0.5,graph 0.93
set label 2 at 1.5,graph 0.93
set label 3 at 2.5,graph 0.93
set xzeroaxis lt 7 lw 1
plot data using "elasticity":"relative_velocity_before" with lines lt 8 dt 2 \
       title "before: v_2 - v_1 (negative: closing)", \
     data using "elasticity":"relative_velocity_after" with linespoints lt 3 pi 2 \
       title "after: v_2' - v_1' (positive: separating)"
