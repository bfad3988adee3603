# gnuplot validation/plot.gnuplot (in the tutorial directory, after
# ./Allrun): Models A and B side by side (Figs. 3-5 of the paper):
# grain kinetic energy (log scale), bottom-centre pressure against
# rho g h_fs, total drag and pressure-gradient force (A) / buoyancy (B).
set terminal png size 1350,420 noenhanced
set output 'validation/sedimentation.png'
set multiplot layout 1,3
set grid; set xlabel 't [s]'; set key top right
set logscale y; set ylabel 'E_k [J]'
plot 'modelA/postProcessing/energy/0/kineticEnergy.dat' u 1:4 w l t 'A', \
     'modelB/postProcessing/energy/0/kineticEnergy.dat' u 1:4 w l t 'B'
unset logscale y; set ylabel 'bottom-centre pressure [Pa]'
plot 'modelA/postProcessing/bottom/0/probes.dat' u 1:2 w l t 'A', \
     'modelB/postProcessing/bottom/0/probes.dat' u 1:2 w l t 'B', \
     'modelB/postProcessing/level/0/waveGauges.dat' u 1:($2*9810) w l dt 2 t 'rho g h_fs (B)'
set ylabel 'force on the grains [N]'
plot 'modelA/postProcessing/forces/0/couplingForces.dat' u 1:(sqrt($2**2+$3**2+$4**2)) w l t '|drag| A', \
     'modelB/postProcessing/forces/0/couplingForces.dat' u 1:(sqrt($2**2+$3**2+$4**2)) w l t '|drag| B', \
     'modelA/postProcessing/forces/0/couplingForces.dat' u 1:7 w l t 'pressure-gradient force A', \
     'modelB/postProcessing/forces/0/couplingForces.dat' u 1:7 w l t 'buoyancy B'
unset multiplot
