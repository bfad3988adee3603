# gnuplot validation/plotRebound.gnuplot  (run in the case directory after
# ./Allrun): validation/rebound.png.
#   left:  height of the dropped bead above the floor minus its radius, and
#          the surface gap of the head-on pair, against time (negative =
#          overlap during the contact);
#   right: normal velocity of the dropped bead and separation speed of the
#          pair, with the impact speed 0.5 m/s and the rebound e v = 0.45 m/s
#          of the set restitution e = 0.9 (Hertz law with the default
#          damping restitution, exact: A0-22, E2-04 allows 0.5 %); the key
#          gives the measured e.
f = 'postProcessing/beads/0/grainState.dat'
R = 0.00135; v0 = 0.5; e = 0.9
# measured e from the last row (both contacts are over by 2.2 ms)
stats f u (ew = $7/v0) nooutput               # wall: rebound / impact
stats f u (ep = ($23-$14)/v0) nooutput        # pair: separation / approach
set terminal pngcairo size 1200,500 font ',11'
set output 'validation/rebound.png'
set multiplot layout 1,2 title 'bouncingSphere: glass bead (R = 1.35 mm, Hertz, e = 0.9) at 0.5 m/s'
set xlabel 'time t [ms]'; set grid
set ylabel 'gap [mm]'
set key top right
plot f u ($1*1e3):(($4-R)*1e3) w l lw 2 t 'drop: z - R (floor)', \
     '' u ($1*1e3):(($20-$11-2*R)*1e3) w l lw 2 t 'pair: surface gap', \
     0 dt 2 lc 'black' notitle
set ylabel 'velocity [m/s]'
set yrange [-0.6:0.9]
set key top left
plot f u ($1*1e3):7 w l lw 2 t sprintf('drop: v_z (e = %.4f)', ew), \
     '' u ($1*1e3):($23-$14) w l lw 2 t sprintf('pair: v_2 - v_1 (e = %.4f)', ep), \
     -v0 dt 2 lc 'black' t 'impact -0.5 m/s', \
     e*v0 dt 3 lc 'red' lw 2 t 'rebound e v_0 = 0.45 m/s'
unset multiplot
