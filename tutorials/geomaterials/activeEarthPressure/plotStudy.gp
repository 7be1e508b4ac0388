# gnuplot plotStudy.gp (after sphStudy): the thrust coefficient of the study's runs against the
# wall's displacement with Rankine's K_a: TL none at four spacings and with psi = 0 (left), and
# every scheme at H/40 (right) (studyCurves.png; docs/img/activeEarthPressure-curves.png).
# The tutorial's values: wall velocity 1 mm/s, rho g H^2 = 2000 x 9.81 x 1 (constant/walls,
# bodies, particlesDict); retainer_Fx is column 8 of the wallForce table (time, then x, y force
# and work of floor, back, retainer).
v = 1e-3; rgh2 = 2000*9.81*1.0; phi = 30.0
ka = (1 - sin(phi*pi/180))/(1 + sin(phi*pi/180))
mm(t) = 1e3*v*t
K(Fx) = 2*Fx/rgh2
runs = "postProcessing/study/runs/"
table = "/postProcessing/walls/walls.dat"
set terminal pngcairo size 1100,450 font "Sans,10"
set output "studyCurves.png"
set multiplot layout 1,2
set xlabel "wall displacement [mm]"; set ylabel "K = 2 F_x / (ρ g H^2)"
set xrange [0:5]
set grid; set key bottom right
set object 1 rect from 2, graph 0 to 5, graph 1 fc rgb "#eeeeee" behind
set title "TL none at four spacings; dashed: ψ = 0 (shaded: the plateau window)"
set yrange [0:0.6]
plot ka with lines lw 2 lc rgb "black" title "Rankine K_a", \
     for [i=1:4] runs.word("H10 H20 H40 H80", i)."_TLnone".table using (mm($1)):(K($8)) with lines lw 1.2 lc i title word("H10 H20 H40 H80", i), \
     for [i=1:4] runs.word("H10 H20 H40 H80", i)."_TLnonePsi0".table using (mm($1)):(K($8)) with lines lw 1 dt 2 lc i title word("H10 H20 H40 H80", i)." ψ = 0"
set title "H/40: every scheme"
set key top right
plot ka with lines lw 2 lc rgb "black" title "Rankine K_a", \
     for [s in "TLnone ULnoneImpenetrable ULnone TLgradF ULgradF ULgradFelasticStateImpenetrable ULgradFbarImpenetrable TLhourglass"] \
         runs."H40_".s.table using (mm($1)):(K($8)) with lines lw 1.2 title s
unset multiplot
