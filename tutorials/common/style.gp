# The look shared by every lab's plots. A lab's plot script loads this first, with gnuplot run as
#   gnuplot -e "outdir='OUT'; fmt='png'; common='tutorials/common'" plot.gp   (or fmt='svg')
# and names each file with  set output file('name')  which gives OUT/name.png (or .svg).
if (!exists("outdir")) outdir = "."
if (!exists("fmt")) fmt = "png"
file(name) = sprintf("%s/%s.%s", outdir, name, fmt)

if (fmt eq "svg") {
  set terminal svg size 800,500 enhanced font "DejaVu Sans,13" linewidth 1.5 background rgb "white"
} else {
  set terminal pngcairo size 800,500 enhanced font "DejaVu Sans,13" linewidth 1.5 background rgb "white"
}

set datafile separator comma
set datafile columnheaders
set datafile missing "NaN"
set grid lc rgb "#d0d0d0" lw 0.7
set key box opaque samplen 2.5 spacing 1.2
set border lw 1.0
set tics nomirror
set title font ",15"

# Okabe-Ito colours, distinguishable with the common colour-vision deficiencies.
set linetype 1 lc rgb "#0072B2" lw 2 pt 7 ps 0.9
set linetype 2 lc rgb "#D55E00" lw 2 pt 5 ps 0.9
set linetype 3 lc rgb "#009E73" lw 2 pt 9 ps 1.0
set linetype 4 lc rgb "#CC79A7" lw 2 pt 11 ps 1.0
set linetype 5 lc rgb "#E69F00" lw 2 pt 13 ps 1.0
set linetype 6 lc rgb "#56B4E9" lw 2 pt 6 ps 1.0
set linetype 7 lc rgb "#000000" lw 1.5 pt 4 ps 1.0
set linetype 8 lc rgb "#777777" lw 1.5 pt 2 ps 1.0
