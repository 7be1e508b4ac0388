# The Taylor bar's final shape: the particles of the mid-plane (initial |y| < half a spacing,
# columns of postProcessing/section) coloured by the equivalent plastic strain, beside the
# finite-element references (radius 7.11-7.22 mm, length 21.42-21.48 mm), at the last snapshot
# each run wrote (its time is in the title). Run it in this folder after ./Allrun:
#   gnuplot plot.gp                                    # this case -> section.png
#   gnuplot -e "runs='a b c'; titles='A B C'" plot.gp  # several run folders side by side
#   gnuplot -e "output='mine.png'" plot.gp             # another file name
if (!exists("runs")) runs = "."
if (!exists("titles")) titles = (runs eq "." ? "" : runs)
if (!exists("output")) output = "section.png"
if (!exists("halfwidth")) halfwidth = 0.3e-3   # [m] initial |y| of the mid-plane rows
n = words(runs)
# The last snapshot of each run (files section_<time>.dat; the time is sorted as a number) and
# its time in µs.
files = ""
times = ""
do for [i = 1:n] {
    dir = word(runs, i)
    f = system("ls " . dir . "/postProcessing/section/section_*.dat 2>/dev/null | " . \
               "sed 's|.*section_\\(.*\\)\\.dat$|\\1 &|' | sort -g | tail -1 | cut -d' ' -f2-")
    if (strlen(f) == 0) {
        print sprintf("plot.gp: %s has no postProcessing/section/section_*.dat: run ./Allrun there first", dir)
        exit status 1
    }
    # (awk converts the time: gnuplot reads "8e-05" as the number 8 and fails on the rest)
    t = system("echo '" . f . "' | sed 's|.*section_\\(.*\\)\\.dat$|\\1|' | awk '{ printf \"%.4g\", $1 * 1e6 }'")
    files = files . " " . f
    times = times . " " . t
}
# One time for every panel in the title; otherwise each panel says its own.
same = 1
do for [i = 2:n] { if (word(times, i) ne word(times, 1)) { same = 0 } }
heading = same ? sprintf("Copper Taylor bar at %s µs: mid-plane, equivalent plastic strain", word(times, 1)) \
               : "Copper Taylor bar, last snapshot of each run: mid-plane, equivalent plastic strain"
set terminal pngcairo size 380*n+160,620 font "Sans,10"
set output output
# The left margin leaves room for the z label of the first panel.
set multiplot layout 1,n title heading margins 0.1,0.88,0.08,0.88 spacing 0.02,0.0
set size ratio -1
set xrange [-8:8]
set yrange [0:24]
set xtics 4
set cbrange [0:3]
set palette defined (0 "#f7f7f7", 0.5 "#fee090", 1.5 "#f46d43", 3 "#a50026")
unset key
set style line 1 lc rgb "#2166ac" dt 2 lw 1
set xlabel "x [mm]"
set arrow 1 from -7.11,0 to -7.11,3 nohead ls 1
set arrow 2 from 7.22,0 to 7.22,3 nohead ls 1
set arrow 3 from -3.2,21.45 to 3.2,21.45 nohead ls 1
do for [i = 1:n] {
    set title (same ? word(titles, i) : sprintf("%s, %s µs", word(titles, i), word(times, i)))
    if (i == n) { set colorbox vertical user origin 0.9,0.15 size 0.015,0.65 } else { unset colorbox }
    # The z axis is labelled on the first (left) panel only; the others share its scale.
    if (i == 1) { set ylabel "z [mm]"; set format y "%g" } else { unset ylabel; set format y "" }
    plot word(files, i) using ($1*1e3):(abs($2-$5) < halfwidth ? $3*1e3 : NaN):7 with points pt 7 ps 0.5 palette
}
unset multiplot
