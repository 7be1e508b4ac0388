# The Taylor bar's final shape: the particles of the mid-plane (initial |y| < half a spacing,
# columns of postProcessing/section) coloured by the equivalent plastic strain, beside the
# finite-element references (radius 7.11-7.22 mm, length 21.42-21.48 mm).
#   gnuplot plot.gp                                   # this case -> doc/section.png
#   gnuplot -e "runs='a b c'; titles='A B C'" plot.gp # several run folders side by side
if (!exists("runs")) runs = "."
if (!exists("titles")) titles = runs
if (!exists("output")) output = "doc/section.png"
if (!exists("halfwidth")) halfwidth = 0.3e-3   # [m] initial |y| of the mid-plane rows
n = words(runs)
set terminal pngcairo size 380*n+120,620 font "Sans,10"
set output output
set multiplot layout 1,n title "Copper Taylor bar at 80 µs: mid-plane, equivalent plastic strain" margins 0.05,0.88,0.08,0.88 spacing 0.02,0.0
set size ratio -1
set xrange [-8:8]
set yrange [0:24]
set xtics 4
set cbrange [0:3]
set palette defined (0 "#f7f7f7", 0.5 "#fee090", 1.5 "#f46d43", 3 "#a50026")
unset key
set style line 1 lc rgb "#2166ac" dt 2 lw 1
do for [i = 1:n] {
    dir = word(runs, i)
    file = system("ls " . dir . "/postProcessing/section/section_*.dat | sort -t_ -k2 -g | tail -1")
    set title word(titles, i)
    if (i == n) { set colorbox vertical user origin 0.9,0.15 size 0.015,0.65 } else { unset colorbox }
    if (i > 1) { set format y "" } else { set ylabel "z [mm]" }
    set xlabel "x [mm]"
    set arrow 1 from -7.11,0 to -7.11,3 nohead ls 1
    set arrow 2 from 7.22,0 to 7.22,3 nohead ls 1
    set arrow 3 from -3.2,21.45 to 3.2,21.45 nohead ls 1
    plot file using ($1*1e3):(abs($2-$5) < halfwidth ? $3*1e3 : NaN):7 with points pt 7 ps 0.5 palette
}
unset multiplot
