# gnuplot plotStudy.gp (after sphStudy): the free surface at t = 1 s of the study's runs against
# the measured one, the tutorial's scheme (UL gradF conserving) and TL gradF at the three spacings,
# and the completing schemes at 5 mm
# (studyProfiles.png; docs/img/columnCollapse-profiles.png), and the failure lines.
set terminal pngcairo size 1100,1000 font "Sans,11"
set output "studyProfiles.png"
set multiplot layout 3,1
set datafile commentschars "#x"
set xlabel "x [m]"; set ylabel "height [m]"
set xrange [0:0.6]; set yrange [0:0.11]
set key top right
set grid
runs = "postProcessing/study/runs/"
measured = "< tr ',' ' ' < constant/measuredSurface.csv"
set title "The tutorial's scheme (UL gradF elasticState + impenetrability + conserving weights) at t = 1 s: three spacings"
plot for [s in "s10mm s5mm s2p5mm"] runs.s."_ULgradFconserving/postProcessing/surface/surface_1.dat" using 1:2 with steps lw 1.5 title s, \
     measured using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb "black" title "measured (Bui et al. 2008)"
set title "TL gradF at t = 1 s: three spacings"
plot for [s in "s10mm s5mm s2p5mm"] runs.s."_TLgradF/postProcessing/surface/surface_1.dat" using 1:2 with steps lw 1.5 title s, \
     measured using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb "black" title "measured (Bui et al. 2008)"
set title "5 mm (800 particles) at t = 1 s: the schemes that complete"
plot for [v in "ULgradFconserving TLgradF TLnone ULnone"] runs."s5mm_".v."/postProcessing/surface/surface_1.dat" using 1:2 with steps lw 1.5 title v, \
     measured using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb "black" title "measured (Bui et al. 2008)"
unset multiplot

# The failure line at t = 1 s in the initial column (studyFailureLines.png;
# docs/img/columnCollapse-failureLines.png): below each line the material moved less than 1 mm.
set terminal pngcairo size 1500,420 font "Sans,11"
set output "studyFailureLines.png"
set multiplot layout 1,3
set datafile commentschars "#"
set xlabel "initial x [m]"; set ylabel "initial height [m]"
set xrange [0:0.2]; set yrange [0:0.1]
set size ratio -1
set key bottom left
set title "TL gradF"
plot for [s in "s10mm s5mm s2p5mm"] runs.s."_TLgradF/postProcessing/failure/failure_1.dat" using 1:2 with steps lw 1.5 title s
set title "UL gradF conserving (the tutorial's)"
plot for [s in "s10mm s5mm s2p5mm"] runs.s."_ULgradFconserving/postProcessing/failure/failure_1.dat" using 1:2 with steps lw 1.5 title s
set title "UL gradF elasticState + impenetrability"
plot for [s in "s10mm s5mm s2p5mm"] runs.s."_ULgradFelasticStateImpenetrable/postProcessing/failure/failure_1.dat" using 1:2 with steps lw 1.5 title s
unset multiplot
