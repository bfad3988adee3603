# gnuplot validation/plotEnergy.gnuplot (in the case directory after
# ./Allrun): kinetic energy against time on a log scale with the E2-09
# threshold (1e-9 J), and the front of the pack.
set terminal png size 1000,450
set output 'validation/energy.png'
set multiplot layout 1,2
set xlabel 'time [s]'; set grid
set logscale y; set ylabel 'E_k [J]'
plot 'postProcessing/energy/0/kineticEnergy.dat' u 1:4 w l t 'E_k', \
     1e-9 dt 2 t 'E2-09 threshold'
unset logscale y; set ylabel 'front x [m]'
plot 'postProcessing/front/0/front.dat' u 1:2 w l t 'front'
unset multiplot
