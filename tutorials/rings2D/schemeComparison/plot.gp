# Comparison plots (run by Allrun), from the runs of the study:
# postProcessing/study/runs/<variant>/ (see system/studyDict), in the study's order.
set terminal pngcairo size 1100,650 font "Sans,11"
set datafile commentschars "#"
set grid
set key outside right top
set autoscale xfix
set xlabel "time [s]"
runs = "postProcessing/study/runs/"
variants = system("tail -n +2 postProcessing/study/results.csv | cut -d, -f1")

set output "extent.png"
set title "Colliding rings: largest y-displacement of ring A (seed Fig. 9)"
set ylabel "max y-displacement [mm]"
plot for [v in variants] runs.v."/postProcessing/extent/extent.dat" using 1:($2*1e3) with lines lw 2 title v

set output "stability.png"
set title "Zero-energy-mode indicator max_a {/Symbol S}_b W_{ab} |x_{ba} - F_a X_{ba}| / h"
set ylabel "indicator"
set logscale y
plot for [v in variants] runs.v."/postProcessing/stability/stability.dat" using 1:2 with lines lw 2 title v
