# gnuplot validation/plotSlip.gnuplot (in the case directory after ./Allrun):
# validation/slip.png: translational speed v_x and rim speed R omega_y of the
# bead against time, with the rigid-body solution (E2-06): slip stops at
# t* = 2 v0/(7 mu g) = 0.07281 s, then v = R omega = 5 v0/7 = 0.35714 m/s.
# The key gives the measured t* (first probe with v_x - R omega_y < 1e-3 v0)
# and the final speed.
f = 'postProcessing/bead/0/grainState.dat'
v0 = 0.5; mu = 0.2; g = 9.81; R = 0.00135; ts = 2*v0/(7*mu*g)
va(t) = t < ts ? v0 - mu*g*t : 5*v0/7
wa(t) = t < ts ? 2.5*mu*g*t : 5*v0/7
tm = -1
stats f u (tm < 0 && $5 - R*$9 < 1e-3*v0 ? tm = $1 : 0, vend = $5) nooutput
set terminal pngcairo size 900,550 font ',11'
set output 'validation/slip.png'
set title sprintf('slidingToRolling: v_0 = 0.5 m/s, {/Symbol m} = 0.2 -- measured t* = %.4f s (exact %.5f s), final v_x = %.5f m/s (exact %.5f)', tm, ts, vend, 5*v0/7) font ',10'
set xlabel 'time t [s]'; set ylabel 'speed [m/s]'; set grid
set yrange [0:0.55]
set key center right
set arrow from ts, graph 0 to ts, graph 1 nohead dt 4 lc 'gray40'
set label 't* exact' at ts, graph 0.05 offset 0.5,0
plot f u 1:5 w l lw 3 t 'v_x (demSolid)', \
     '' u 1:(R*$9) w l lw 3 t 'R {/Symbol w}_y (demSolid)', \
     va(x) dt 2 lw 2 lc 'black' t 'v_x exact', \
     wa(x) dt 3 lw 2 lc 'red' t 'R {/Symbol w}_y exact'
