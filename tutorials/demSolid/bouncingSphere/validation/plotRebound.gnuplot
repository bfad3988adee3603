# gnuplot validation/plotRebound.gnuplot  (run in the case directory after
# ./Allrun): height of the dropped bead above the floor minus its radius,
# and the surface gap of the head-on pair, against time.
set terminal png size 900,500
set output 'validation/rebound.png'
set xlabel 'time [s]'
set ylabel 'gap [m]'
set grid
R = 0.00135
plot 'postProcessing/beads/0/grainState.dat' u 1:($4-R) w l t 'drop: z - R', \
     '' u 1:($20-$11-2*R) w l t 'pair: surface gap'
