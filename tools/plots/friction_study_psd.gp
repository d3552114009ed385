# Body and wheel acceleration PSDs of a friction study (seed 000, Figures 9-11 style).
# Usage: gnuplot -e "psd='out/demo/sweep_2mm_psd.csv'; png='out/demo/sweep_2mm_psd.png'; title='2 mm sweep'" friction_study_psd.gp
set terminal pngcairo size 1200,500 noenhanced font ",10"
set output png
set datafile separator ","
set key top right font ",9"
# "body_acc_psd_Fc12N[...]" -> "Fc = 12 N"
label(h) = "Fc = " . h[strstrt(h, "_Fc") + 3 : strstrt(h, "N[") - 1] . " N"
set logscale xy
set grid xtics ytics mxtics
set format y "%.0e"
set multiplot layout 1,2 title title
stats psd skip 1 nooutput
n = (STATS_columns - 1) / 2
set xrange [0.5:30]
set title "body acceleration"
set xlabel "frequency [Hz]"
set ylabel "PSD [(m/s^2)^2/Hz]"
set yrange [1e-8:*]
plot for [i=2:n+1] psd using 1:i with lines lw 1.5 title label(columnhead(i))
set title "wheel acceleration"
set key top left
set yrange [1e-7:*]
plot for [i=n+2:2*n+1] psd using 1:i with lines lw 1.5 title label(columnhead(i))
unset multiplot
