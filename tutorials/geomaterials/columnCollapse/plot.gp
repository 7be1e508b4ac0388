# gnuplot plot.gp (after ./Allrun): the final free surface against the measured one
# (finalProfile.png), the surface at a few times (collapse.png) and the particles at t = 1 s
# coloured by the equivalent plastic strain (plasticStrain.png, from the `particles` snapshot),
# and the failure line in the initial column (failureLine.png, from `failure`).
set terminal pngcairo size 1000,420 font ",11"
set datafile separator whitespace
set xlabel "x [m]"
set ylabel "height [m]"
set size ratio -1
set xrange [0:0.55]
set yrange [0:0.12]
set key top right
set output "finalProfile.png"
set datafile commentschars "#x"
plot "postProcessing/surface/surface_1.dat" using 1:2 with steps lw 2 title "sphSolid, t = 1 s", \
     "< tr ',' ' ' < constant/measuredSurface.csv" using 1:2 with linespoints pt 7 ps 0.6 title "measured (Bui et al. 2008)"
set output "collapse.png"
plot for [t in "0 0.1 0.2 0.3 0.5 1"] "postProcessing/surface/surface_".t.".dat" using 1:2 with steps title "t = ".t." s"
set output "plasticStrain.png"
set datafile commentschars "#"
set cblabel "equivalent plastic strain"
set cbrange [0:3]
set palette rgbformulae 22,13,-31
plot "postProcessing/particles/particles_1.dat" using 1:2:3 with points pt 7 ps 0.5 palette notitle, \
     "< tr ',' ' ' < constant/measuredSurface.csv" using 1:2 with lines lw 2 lc rgb "black" title "measured surface"
set output "failureLine.png"
unset cblabel
set xrange [0:0.2]
set yrange [0:0.1]
set xlabel "initial x [m]"
set ylabel "initial height [m]"
set datafile commentschars "#"
plot "postProcessing/failure/failure_1.dat" using 1:2 with steps lw 2 title "failure line at t = 1 s: below it the material moved < 1 mm"
