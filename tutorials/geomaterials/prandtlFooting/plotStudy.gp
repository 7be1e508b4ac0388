# gnuplot plotStudy.gp (after sphStudy): the load-penetration curves of the study's runs against
# Prandtl's (2 + pi) c_u: TL none at three spacings, rough and smooth footing (left), and every
# scheme at B/20 (right) (studyCurves.png; docs/img/prandtlFooting-curves.png).
v = 0.025; gap = 1e-4; B = 0.1; cu = 1e4; prandtl = 2 + pi
pen(t) = (v*t - gap)/B
q(Fy) = -2*Fy/B/cu
runs = "postProcessing/study/runs/"
table = "/postProcessing/walls/walls.dat"
set terminal pngcairo size 1100,450 font "Sans,10"
set output "studyCurves.png"
set multiplot layout 1,2
set xlabel "penetration / B"; set ylabel "q / c_u"
set xrange [0:0.1]
set grid; set key bottom right
set object 1 rect from 0.05, graph 0 to 0.1, graph 1 fc rgb "#eeeeee" behind
set title "TL none at three spacings, rough and smooth footing (shaded: the plateau window)"
set yrange [0:6.5]
plot prandtl*1.05 with lines dt 2 lc rgb "gray" title "±5 %", prandtl*0.95 with lines dt 2 lc rgb "gray" notitle, \
     prandtl with lines lw 2 lc rgb "black" title "Prandtl (2 + π) c_u", \
     for [i=1:3] runs.word("B10 B20 B40", i)."_TLnone".table using (pen($1)):(q($12)) with lines lw 1.5 lc i title word("B10 B20 B40", i)." rough", \
     for [i=1:3] runs.word("B10 B20 B40", i)."_TLnoneSmooth".table using (pen($1)):(q($12)) with lines lw 1.5 dt 2 lc i title word("B10 B20 B40", i)." smooth"
set title "B/20: every scheme"
set yrange [0:10]
plot prandtl with lines lw 2 lc rgb "black" title "Prandtl (2 + π) c_u", \
     for [s in "TLnone TLnoneImpenetrable ULnone TLgradF ULgradFelasticState TLhourglass"] runs."B20_".s.table using (pen($1)):(q($12)) with lines lw 1.5 title s
unset multiplot
