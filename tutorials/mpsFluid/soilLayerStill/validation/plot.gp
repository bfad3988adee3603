# plot.gp — soilLayerStill: time-averaged pressure of every particle
# against its mean height, with rho g (h_w - h_s) + rho_s g (h_s - y) in
# the soil and rho g (h_w - y) in the water; run from the case directory
# after validation/soilLayer.sh (which writes validation/pressure.dat):
#   gnuplot validation/plot.gp  ->  validation/soilLayerStill.png
set terminal pngcairo size 800,600 font ",10"
set output "validation/soilLayerStill.png"
set grid
set xlabel "pressure [Pa]"
set ylabel "y [m]"
set key top right
plot "validation/pressure.dat" using ($2 == 1 ? $4 : 1/0):3 with points pt 7 ps 0.4 lc rgb "brown" title "soil particles", \
     "" using ($2 == 0 ? $4 : 1/0):3 with points pt 7 ps 0.4 lc rgb "blue" title "water particles", \
     "" using 5:3 with points pt 1 ps 0.3 lc rgb "black" title "exact"
