# gnuplot validation/plot.gnuplot (from the case directory, after
# ./Allrun -import): runout and height of the pile against the time since
# the gate went, continuous run and imported bed, with the runout of
# Lube et al. (2005), Delta L / L0 = 1.2 a (a = H0/L0 < 2.3).
L0 = 0.05; H0 = 0.0849; T0 = 0.4
set terminal pngcairo size 1000,420 noenhanced
set output 'validation/collapse.png'
set multiplot layout 1,2
set xlabel 't - t_release [s]'; set grid; set key top left; set xrange [-0.1:0.8]
set ylabel '(L - L0) / L0'
plot 'postProcessing/front/0/front.dat' u ($1 - T0):(($2 - L0) / L0) every 5 w l lw 2 t 'poured, settled, gate removed at 0.4 s', \
     'import/postProcessing/front/0/front.dat' u 1:(($2 - L0) / L0) every 5 w l lw 2 dt 2 t 'bed imported from CSV, gate removed at 0', \
     1.2 * H0 / L0 w l lc rgb 'black' dt 3 t 'Lube et al. 2005: 1.2 a'
set ylabel 'mean surface height [m]'; set key top right; set yrange [0:0.1]
plot 'postProcessing/bed/0/bedHeight.dat' u ($1 - T0):3 every 5 w l lw 2 t 'poured', \
     'import/postProcessing/bed/0/bedHeight.dat' u 1:3 every 5 w l lw 2 dt 2 t 'imported'
unset multiplot
