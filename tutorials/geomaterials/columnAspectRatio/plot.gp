# gnuplot plot.gp (after ./Allrun): the run-out and the final height against the aspect ratio
# a = H0/L0, from postProcessing/study/results.csv, beside the quasi-2D scaling laws
# (aspectRatio.png). L0 = 0.1 m for every variant (system/studyDict); a = particles/400 at the
# 5 mm spacing (20 columns of 20 a rows). TL gradF only: the runs that fail are left out, and
# UL none's finished runs have particles flying off (README).
set terminal pngcairo size 1100,450 font "Sans,11"
set datafile separator ","
set output "aspectRatio.png"
set multiplot layout 1,2
L0 = 0.1
tl = "< grep ',TLgradF,finished,' postProcessing/study/results.csv"
set logscale xy
set xrange [0.4:5]
set grid
set key top left
set xlabel "aspect ratio a = H_0/L_0"
set ylabel "run-out {/Symbol D}L/L_0"
set title "Run-out"
plot 1.2*x dashtype 2 lw 2 lc rgb "gray40" title "1.2 a (small a)", \
     1.9*x**(2./3) dashtype 3 lw 2 lc rgb "gray20" title "1.9 a^{2/3} (tall)", \
     tl using ($5/400):(($10-L0)/L0) with linespoints pt 7 lw 2 title "TL gradF, farthest particle", \
     tl using ($5/400):(($11-L0)/L0) with linespoints pt 5 lw 2 title "TL gradF, deposit end"
set ylabel "final height H_{/Symbol \245}/L_0"
set title "Final height"
plot x dashtype 2 lw 2 lc rgb "gray40" title "a (the top does not move)", \
     x**0.4 dashtype 3 lw 2 lc rgb "gray20" title "a^{2/5} (tall)", \
     tl using ($5/400):($12/L0) with linespoints pt 7 lw 2 title "TL gradF"
unset multiplot
