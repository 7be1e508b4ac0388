# gnuplot plot.gp (after ./Allrun): the thrust coefficient against the wall's displacement with
# Rankine's K_a (thrust.png, from postProcessing/walls/curve.dat that thrust.py --curve writes)
# and the equivalent plastic strain at the end with Rankine's wedge boundary at 45 + phi/2
# through the heel (plasticStrain.png; docs/img/activeEarthPressure-plasticStrain.png comes from
# the H/40 run). The tutorial's values: phi = 30 degrees, H = 1 m (constant/bodies, particlesDict).
phi = 30.0; H = 1.0
ka = (1 - sin(phi*pi/180))/(1 + sin(phi*pi/180)); k0 = 1 - sin(phi*pi/180)
set terminal pngcairo size 800,500 font "Sans,11"
set output "thrust.png"
set xlabel "wall displacement [mm]"; set ylabel "K = 2 F_x / (ρ g H^2)"
set xrange [0:5]; set yrange [0:0.6]
set grid; set key top right
set object 1 rect from 2, graph 0 to 5, graph 1 fc rgb "#eeeeee" behind
plot k0 with lines dt 3 lc rgb "gray40" title "at rest K_0 = 1 - sin φ", \
     ka*1.05 with lines dt 2 lc rgb "gray" title "±5 %", ka*0.95 with lines dt 2 lc rgb "gray" notitle, \
     ka with lines lw 2 lc rgb "black" title "Rankine K_a = (1 - sin φ)/(1 + sin φ)", \
     "postProcessing/walls/curve.dat" using 1:2 with lines lw 2 lc rgb "#c03020" title "sphSolid (plateau: mean over the shaded window)"

last = system("ls postProcessing/particles/particles_*.dat | sort -t_ -k2 -g | tail -1")
set output "plasticStrain.png"
set terminal pngcairo size 900,560 font "Sans,10"
unset object 1
set size ratio -1
set xrange [0:1.5]; set yrange [0:1.05]
set xlabel "x [m]"; set ylabel "y [m]"
set cblabel "equivalent plastic strain"
set cbrange [0:0.02]
set palette rgbformulae 22,13,-31
set key top right
set datafile commentschars "#"
plot last using 1:2:3 with points pt 7 ps 0.6 palette notitle, \
     "+" using (($1 < 0 || $1 > H) ? 1/0 : $1/tan((45 + phi/2)*pi/180)):1 with lines lw 2 dt 2 lc rgb "black" \
         title "Rankine's wedge, 45° + φ/2 through the heel"
