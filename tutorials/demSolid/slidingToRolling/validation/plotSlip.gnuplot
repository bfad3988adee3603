# gnuplot validation/plotSlip.gnuplot (in the case directory after ./Allrun)
set terminal png size 900,500
set output 'validation/slip.png'
set xlabel 'time [s]'; set ylabel 'speed [m/s]'; set grid
v0 = 0.5; mu = 0.2; g = 9.81; R = 0.00135; ts = 2*v0/(7*mu*g)
va(t) = t < ts ? v0 - mu*g*t : 5*v0/7
wa(t) = t < ts ? 2.5*mu*g*t : 5*v0/7
plot 'postProcessing/bead/0/grainState.dat' u 1:5 w l t 'v_x', \
     '' u 1:(R*$9) w l t 'R omega_y', va(x) dt 2 t 'v_x exact', \
     wa(x) dt 3 t 'R omega_y exact'
