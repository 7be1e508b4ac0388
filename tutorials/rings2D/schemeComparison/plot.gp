# Comparison plots (run by Allrun).
set terminal pngcairo size 1100,650 font "Sans,11"
set datafile commentschars "#"
set grid
set xlabel "time [s]"
variants = system("awk '!/^#/ && NF { print $1 }' variants")

set output "extent.png"
set title "Colliding rings: largest y-displacement of ring A (seed Fig. 9)"
set ylabel "max y-displacement [mm]"
plot for [v in variants] "runs/".v."/postProcessing/extent/extent.dat" using 1:($2*1e3) with lines lw 2 title v

set output "stability.png"
set title "Zero-energy-mode indicator max_a sum_b W_ab |x_ba - F_a X_ba| / h"
set ylabel "indicator"
set logscale y
set key top left
plot for [v in variants] "runs/".v."/postProcessing/stability/stability.dat" using 1:2 with lines lw 2 title v
