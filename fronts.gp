# fronts.gp — the root case's water and sediment fronts against time.
# Run from the repository root after ./Allrun: gnuplot fronts.gp
# writes fronts.png. Columns of postProcessing/*/0/front.dat: t [s], x [m].
set terminal pngcairo size 800,480 noenhanced
set output 'fronts.png'
set xlabel 't [s]'; set ylabel 'front x [mm]'
set key bottom right; set grid
set yrange [0:220]
set arrow from graph 0, first 200 to graph 1, first 200 nohead dt 2 lc rgb 'gray'
set label 'end wall' at graph 0.02, first 204 tc rgb 'gray'
plot 'postProcessing/fluidFront/0/front.dat' u 1:($2*1000) w l lw 2 t 'water front', \
     'postProcessing/sedimentFront/0/front.dat' u 1:($2*1000) w l lw 2 t 'sediment front (largest pack)'
