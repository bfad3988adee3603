# plot.gnuplot — drawn by validation/plot.sh (which sets the variables below
# from validation/hydrostatic.sh CASE WINDOW DIR): still water, E1-08.
#   data  DIR with pressure.dat (id, mean height, mean p, rho g (h - height))
#         and speed.dat (t, max |u|, max |u| / sqrt(g h))
#   png   output; name, dim, dp  case; h  water depth [m];
#   L2, urel  hydrostatic.sh's L2 and max speed / sqrt(g h) over the window;
#   tend, win  last time and window [s]
P = data.'/pressure.dat'; U = data.'/speed.dat'
v = (dim == 2 ? 'y' : 'z')                                # vertical axis
stats P u ($4 / (h - $2)) nooutput; rhog = STATS_mean     # rho g [Pa/m]
set terminal pngcairo size 1500,520 font ',11'
set output png
set multiplot layout 1,3 title sprintf("%s (%d-D, dp = %g mm, h = %g m): pressure averaged over %g-%g s, L2 = %.4f (E1-08: < 0.03); max |u| / {/Symbol \326}(gh) = %.4f over the window (< 0.01)", \
    name, dim, dp * 1e3, h, tend - win, tend, L2, urel) font ',12'
set grid
set xlabel 'depth h - '.v.' [mm]'
set xrange [0:h * 1e3]
# (a) pressure against depth
set ylabel 'time-averaged pressure [Pa]'
set key top left Left reverse
plot P u ((h - $2) * 1e3):3 w p pt 7 ps 0.5 lc rgb '#1f77b4' t 'fluid particles', \
     rhog * x / 1e3 w l lw 2 lc 'black' dt 2 t '{/Symbol r} g (h - '.v.')'
# (b) its departure from rho g (h - y)  (y: the vertical axis, z in 3-D)
set ylabel 'pressure - {/Symbol r} g (h - '.v.') [Pa]'
stats P u ($3 - $4) nooutput
dmax = (abs(STATS_max) > abs(STATS_min) ? abs(STATS_max) : abs(STATS_min)) * 1.25
set yrange [-dmax:dmax]
set key bottom right
plot P u ((h - $2) * 1e3):($3 - $4) w p pt 7 ps 0.5 lc rgb '#1f77b4' t 'fluid particles', \
     0 w l lw 2 lc 'black' dt 2 notitle
# (c) largest fluid speed against time
stats U u 3 nooutput
set xrange [0:tend]; set yrange [0:(STATS_max * 1.5 > 0.015 ? STATS_max * 1.5 : 0.015)]
set xlabel 'time t [s]'
set ylabel 'max fluid speed / {/Symbol \326}(g h) [-]'
set key top left Left reverse
set object 1 rect from tend - win, graph 0 to tend, graph 1 fc rgb 'gray90' fs solid noborder behind
set label 1 'window' at tend - win / 2, graph 0.04 center
plot U u 1:3 w lp pt 7 ps 0.7 lw 2 lc rgb '#d62728' t 'max |u| / {/Symbol \326}(g h), fluid.vtu snapshots', \
     0.01 w l lw 2 lc 'black' dt 2 t 'E1-08 target 0.01'
unset multiplot
