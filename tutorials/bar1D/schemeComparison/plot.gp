# Plots for the scheme comparison (run by Allrun), from the runs of the study:
# postProcessing/study/runs/<scheme>_n<particles>_t<endTime>/ (see system/studyDict).
set terminal pngcairo size 1200,1000 font "Sans,10"
set datafile commentschars "#"
tip(v, n, t) = sprintf("postProcessing/study/runs/%s_n%d_t%s/postProcessing/tipError/tipError.dat", v, n, t)

# 1. The free end over 5 ms against the exact solution, one panel per variant.
set output "tipHistory.png"
set multiplot layout 3,2 title "Dyka bar, 40 particles: free-end displacement [mm] vs time [ms]"
set grid
set key bottom left
set yrange [-1.6:1.6]
do for [v in "TLnone ULnone TLgradF ULgradF ULvidal ULhourglass"] {
    set title v
    plot tip(v, 40, "5ms") using ($1*1e3):($3*1e3) every 20 with lines lw 2 lc rgb "black" title "exact", \
         ""                 using ($1*1e3):($2*1e3) every 20 with lines lw 1.5 lc rgb "#d62728" title "SPH"
}
unset multiplot

# 2. Creep over 50 ms: the mean tip displacement over each numerical period (exact: 0), and the
#    tip history of the schemes that fail.
set output "creep.png"
set multiplot layout 2,1 title "Dyka bar over 50 ms"
set title "mean free-end displacement over each period / amplitude (exact: 0)"
set xlabel "time [ms]"
set yrange [*:*]
set key top left
amplitude = 9.3734e-4
plot for [v in "TLnone TLgradF ULgradF ULgradFN10 ULhourglassN10 ULnone ULnoneN10 ULvidal ULvidalDefault"] tip(v, 40, "50ms") \
        using ($1*1e3):($7/amplitude) every 50 with lines lw 2 title v." (40)", \
     tip("ULnone", 160, "50ms") using ($1*1e3):($7/amplitude) every 200 with lines lw 2 dt 2 title "ULnone (160)", \
     tip("ULgradF", 160, "50ms") using ($1*1e3):($7/amplitude) every 200 with lines lw 2 dt 2 title "ULgradF (160)"
set title "free-end displacement [mm]: updated-Lagrangian without and with the gradient of F"
plot tip("ULnone", 160, "50ms") using ($1*1e3):($2*1e3) every 200 with lines lw 1.5 title "ULnone (160)", \
     tip("ULnone", 40, "50ms") using ($1*1e3):($2*1e3) every 50 with lines lw 1.5 title "ULnone (40)", \
     tip("ULgradF", 40, "50ms") using ($1*1e3):($2*1e3) every 50 with lines lw 1 lc rgb "black" title "ULgradF (40)"
unset multiplot
