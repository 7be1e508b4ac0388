# gnuplot plotStudy.gp (after sphStudy): the free surface at t = 1 s of the study's runs against
# the measured one, TL gradF at the three spacings and the completing schemes at 5 mm
# (studyProfiles.png; docs/img/columnCollapse-profiles.png).
set terminal pngcairo size 1100,700 font "Sans,11"
set output "studyProfiles.png"
set multiplot layout 2,1
set datafile commentschars "#x"
set xlabel "x [m]"; set ylabel "height [m]"
set xrange [0:0.6]; set yrange [0:0.11]
set key top right
set grid
runs = "postProcessing/study/runs/"
measured = "< tr ',' ' ' < constant/measuredSurface.csv"
set title "TL gradF at t = 1 s: three spacings"
plot for [s in "s10mm s5mm s2p5mm"] runs.s."_TLgradF/postProcessing/surface/surface_1.dat" using 1:2 with steps lw 1.5 title s, \
     measured using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb "black" title "measured (Bui et al. 2008)"
set title "5 mm (800 particles) at t = 1 s: the schemes that complete"
plot for [v in "TLgradF TLnone ULnone"] runs."s5mm_".v."/postProcessing/surface/surface_1.dat" using 1:2 with steps lw 1.5 title v, \
     measured using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb "black" title "measured (Bui et al. 2008)"
unset multiplot
