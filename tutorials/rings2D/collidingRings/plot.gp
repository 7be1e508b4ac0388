# Plots of the colliding rings (run by Allrun; ../schemeComparison/Allrun runs it in the folder of
# each of its runs for snapshots-<variant>.png).
set terminal pngcairo size 1000,600 font "Sans,11"
set datafile commentschars "#"
set grid
set autoscale xfix
scheme = system("awk '/^Scheme/{s=$2} /^Formulation/{f=$2} END{print f\" + \"s}' log.sphSolid")

# Seed Fig. 9: the largest y-displacement of each ring.
set output "extent.png"
set title "Colliding rings (".scheme."): largest y-displacement of each ring"
set xlabel "time [s]"
set ylabel "max y-displacement [mm]"
set key top right
plot "postProcessing/extent/extent.dat" using 1:($2*1e3) with lines lw 2 title "ring A", \
     "" using 1:($8*1e3) with lines lw 2 dt 2 title "ring B"    # columns: see the header line

# Energy balance: kinetic + strain - contact work is conserved by an exact integrator.
set output "energy.png"
set title "Colliding rings (".scheme."): energy [J]"
set ylabel "energy [J]"
set key center right
plot "postProcessing/energy/energy.dat" using 1:2 with lines lw 2 title "kinetic", \
     "" using 1:3 with lines lw 2 title "strain", \
     "" using 1:(-$5) with lines lw 2 title "- contact work", \
     "" using 1:6 with lines lw 2 lc rgb "black" title "total"

# Seed Fig. 8: P_xx on the deformed rings every 0.01 s.
set terminal pngcairo size 1500,720 font "Sans,10"
set output "snapshots.png"
set multiplot layout 4,3 title "Colliding rings (".scheme."): P_{xx} [MPa]" margins 0.01,0.9,0.02,0.9 spacing 0.01,0.06
unset grid
unset key
unset colorbox
set size ratio -1
set xrange [-0.15:0.15]
set yrange [-0.05:0.05]
unset xlabel
unset ylabel
set format x ""
set format y ""
unset xtics
unset ytics
set cbrange [-0.06:0.06]
set palette defined (-1 "#2166ac", -0.5 "#92c5de", 0 "#f7f7f7", 0.5 "#f4a582", 1 "#b2182b")
files = system("ls postProcessing/rings/rings_*.dat | sort -t_ -k2 -g")
do for [i = 1:words(files)] {
    f = word(files, i)
    t = f[strstrt(f, "rings_") + 6 : strlen(f) - 4]
    set title sprintf("t = %.3f s", t + 0)
    if (i == words(files)) { set colorbox vertical user origin 0.92,0.1 size 0.015,0.75 }
    plot f using 1:2:($3*1e-6) with points pt 7 ps 0.3 palette
}
unset multiplot
