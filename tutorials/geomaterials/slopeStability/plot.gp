# The failure surface of a failing run: each particle at its initial position, coloured by how
# far it moved by the end of the run, the base of the sliding mass
# (failureSurface.py) and Bishop's critical circle (bishop.py).
#   python3 bishop.py; python3 failureSurface.py RUN; gnuplot -e "run='RUN'" plot.gp
# RUN defaults to this case (the slope at F = 1.5). Writes failureSurface.png.
if (!exists("run")) run = "."
set terminal pngcairo size 1100,500 font ",11"
set output "failureSurface.png"
set size ratio -1
set xrange [0:36]
set yrange [-0.5:11]
set xlabel "x [m]"
set ylabel "y [m]"
set cblabel "displacement at the end [m]"
set palette defined (0 "#f7f7f7", 0.25 "#9ecae1", 0.5 "#3182bd", 0.75 "#e6550d", 1 "#a50f15")
set key below
set title "Slope of Griffiths and Lane (1999), example 1: how far the soil moved (F above the factor of safety)"
plot run."/failureSurface.dat" using 1:2:3 with points pt 7 ps 0.5 lc palette notitle, \
     run."/failureLine.dat" using 1:2 with points pt 6 ps 1.0 lc rgb "black" title "base of the sliding mass (half its displacement)", \
     "bishopCircle.dat" using 1:2 with lines lw 2 lc rgb "#31a354" title "Bishop's critical circle, F_s = 1.378", \
     "-" using 1:2 with lines lw 1 lc rgb "gray30" title "the slope"
0 10
12 10
32 0
36 0
e
