# plot.gp — columnSediment: the paper's Figs. 24-27 from the series that
# validation/compare.sh writes (all H_s on one panel per quantity); run
# from the case directory: gnuplot validation/plot.gp
set terminal pngcairo size 1400,1000 font ",10"
set output "validation/columnSediment.png"
set multiplot layout 3,2
set grid
set xlabel "t [s]"
set key top right
hs = "0 0.041 0.084"
f(h) = "validation/series_Hs".h.".dat"
set ylabel "F_x fluid on the column [N]"
plot for [h in hs] f(h) using 1:2 with lines title "H_s = ".h." m"
set ylabel "P1 [Pa]"
plot for [h in hs] f(h) using 1:3 with lines title "H_s = ".h." m"
set ylabel "F_x solids on the column [N]"
plot for [h in hs] f(h) using 1:4 with lines title "H_s = ".h." m"
set ylabel "H1 [m]"
plot for [h in hs] f(h) using 1:5 with lines title "H_s = ".h." m"
set ylabel "water front [m]"
set key bottom right
plot [0:1.5] for [h in hs] f(h) using 1:6 with lines title "H_s = ".h." m", 0.9 with lines dt 2 lc rgb "gray" title "column face"
set ylabel "sediment front [m]"
plot [0:3] for [h in hs] f(h) using 1:7 with lines title "H_s = ".h." m", 0.9 with lines dt 2 lc rgb "gray" title "column face"
unset multiplot
