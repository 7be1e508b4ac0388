# Free-end displacement and velocity against the exact solution (seed Figs. 3 and 5).
# Run by Allrun: gnuplot plot.gp  ->  freeEnd.png
set terminal pngcairo size 1000,750 font "Sans,11"
set output "freeEnd.png"
set datafile commentschars "#"
set multiplot layout 2,1 title "Dyka bar, free end: ".system("awk '/^Scheme/{s=$2} /^Formulation/{f=$2} END{print f\" + \"s}' log.sphSolid")
set xlabel "time [ms]"
set ylabel "displacement [mm]"
set key bottom left
set grid
plot "postProcessing/tipError/tipError.dat" using ($1*1e3):($3*1e3) with lines lw 2 lc rgb "black" title "exact", \
     "" using ($1*1e3):($2*1e3) with lines lw 2 lc rgb "#d62728" title "SPH"
set ylabel "velocity [m/s]"
plot "postProcessing/tipError/tipError.dat" using ($1*1e3):6 with lines lw 2 lc rgb "black" title "exact", \
     "" using ($1*1e3):5 with lines lw 1.5 lc rgb "#1f77b4" title "SPH"
unset multiplot
