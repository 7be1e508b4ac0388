# gnuplot plot.gp (after ./Allrun): the load-penetration curve against Prandtl's (2 + pi) c_u
# (loadPenetration.png) and the equivalent plastic strain at the end, mirrored about the centre
# line (plasticStrain.png; docs/img/prandtlFooting-plasticStrain.png comes from the B/40 run).
# The tutorial's values: footing velocity v, start gap, width B, c_u (constant/walls, bodies).
v = 0.025; gap = 1e-4; B = 0.1; cu = 1e4; prandtl = 2 + pi
# postProcessing/walls/walls.dat: time, then x, y force and work of centre, side, floor,
# footing; footing_Fy is column 12, the half footing's (x = 0 is the symmetry plane).
pen(t) = (v*t - gap)/B
q(Fy) = -2*Fy/B/cu
set terminal pngcairo size 800,500 font "Sans,11"
set output "loadPenetration.png"
set xlabel "penetration / B"; set ylabel "q / c_u"
set xrange [0:0.1]; set yrange [0:6.5]
set grid; set key bottom right
set object 1 rect from 0.05, graph 0 to 0.1, graph 1 fc rgb "#eeeeee" behind
plot prandtl*1.05 with lines dt 2 lc rgb "gray" title "±5 %", prandtl*0.95 with lines dt 2 lc rgb "gray" notitle, \
     prandtl with lines lw 2 lc rgb "black" title "Prandtl (2 + π) c_u", \
     "postProcessing/walls/walls.dat" using (pen($1)):(q($12)) with lines lw 2 lc rgb "#c03020" title "sphSolid (plateau: mean over the shaded window)"

last = system("ls postProcessing/particles/particles_*.dat | sort -t_ -k2 -g | tail -1")
set output "plasticStrain.png"
set terminal pngcairo size 800,330 font "Sans,10"
unset object 1
set size ratio -1
set xrange [-0.25:0.25]; set yrange [-0.15:0.03]
set xlabel "x [m]"; set ylabel "y [m]"
set cblabel "equivalent plastic strain"
set cbrange [0:0.1]
set palette rgbformulae 22,13,-31
set key off
# Prandtl's mechanism in the initial configuration (black): the rigid wedge under the footing
# (45 deg, apex B/2 deep), the fans (radius B/sqrt 2 about the footing's edges) and the passive
# wedges reaching B beyond each edge.
do for [side in "-1 1"] {
    sx = side + 0
    set arrow from sx*B/2, 0 to 0, -B/2 nohead lc rgb "black" lw 1.5 front
    set arrow from sx*B/2, 0 to sx*B, -B/2 nohead lc rgb "black" lw 1.5 front
    set arrow from sx*B, -B/2 to sx*3*B/2, 0 nohead lc rgb "black" lw 1.5 front
}
set object 3 circle at B/2, 0 size B/sqrt(2) arc [225:315] fs empty border lc rgb "black" lw 1.5 front
set object 4 circle at -B/2, 0 size B/sqrt(2) arc [225:315] fs empty border lc rgb "black" lw 1.5 front
set object 2 rect from -B/2, (-v*system("echo ".last." | sed 's/.*particles_//; s/.dat//'")+gap) to B/2, 0.02 fc rgb "gray" front
plot last using 1:2:3 with points pt 7 ps 0.3 palette, \
     last using (-$1):2:3 with points pt 7 ps 0.3 palette
