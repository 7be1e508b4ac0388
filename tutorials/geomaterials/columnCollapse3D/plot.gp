# gnuplot plot.gp (after ./Allrun): the slab's deposit at t = 1 s in 3D, the particles coloured
# by the equivalent plastic strain (deposit3D.png; docs/img/columnCollapse3D-deposit.png comes
# from the 5 mm run), and the mid-plane's surface against the 2D run's and the measured one
# (profiles.png).
set terminal pngcairo size 1000,520 font "Sans,10"
set output "deposit3D.png"
set datafile commentschars "#"
set view 62, 335, 1.2, 1.0
set xlabel "x [m]" offset 0,-1; set ylabel "z [m]" offset 2,0; set zlabel "height [m]" rotate
set xrange [0:0.6]; set zrange [0:0.1]
set xtics 0.1; set ytics 0.025; set ztics 0.025
set xyplane 0
set ticslevel 0
set cblabel "equivalent plastic strain"
set cbrange [0:3]
set palette rgbformulae 22,13,-31
set key off
splot "postProcessing/particles/particles_1.dat" using 1:3:2:4 with points pt 7 ps 0.35 palette
set output "profiles.png"
set terminal pngcairo size 1000,420 font "Sans,11"
unset view; set view map; unset view
set size noratio
set xlabel "x [m]"; set ylabel "height [m]"
set xrange [0:0.6]; set yrange [0:0.11]
set key top right
set datafile commentschars "#x"
plot "plane2D/postProcessing/surface/surface_1.dat" using 1:2 with steps lw 2 title "2D plane strain", \
     "postProcessing/surface/surface_1.dat" using 1:2 with steps lw 2 title "3D slab, mid-plane", \
     "< tr ',' ' ' < constant/measuredSurface.csv" using 1:2 with linespoints pt 7 ps 0.5 title "measured (Bui et al. 2008)"
