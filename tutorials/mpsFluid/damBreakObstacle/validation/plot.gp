# plot.gp — damBreakObstacle against the MARIN measurements: H1-H4 and P1.
# Run from the case directory: gnuplot validation/plot.gp
# The data are the repository's data/kleefsman_spheric2: $MPSDEM_DIR/data/...
# (set by bin/tools/RunFunctions), else the case is taken to sit in
# tutorials/mpsFluid/ of the repository; -e "data='DIR'" overrides both.
if (!exists("data")) data = system("echo ${MPSDEM_DIR:-../../..}")."/data/kleefsman_spheric2"
exp = data.'/spheric_test2_marin_exp.csv'
# a restarted run writes postProcessing/<name>/<startTime>/: join them
fo(n, f) = sprintf("< for d in $(ls postProcessing/%s | sort -g); do cat postProcessing/%s/$d/%s; done", n, n, f)
set terminal pngcairo size 1200,800 noenhanced
set output 'validation/damBreakObstacle.png'
set datafile separator ' ,'
set multiplot layout 3,2
set xrange [0:6]; set xlabel 't [s]'
do for [k=1:4] {
    set ylabel sprintf('H%d [m]', k)
    plot exp u 1:(column(9+k)) every ::1 w l lc rgb 'gray' t 'MARIN', \
         fo('heights', 'waveGauges.dat') u 1:(column(k+1)) w l lw 2 t 'mpsFluid'
}
set ylabel 'P1 [Pa]'
plot exp u 1:2 every ::1 w l lc rgb 'gray' t 'MARIN', \
     fo('pressure', 'probes.dat') u 1:2 w l lw 2 t 'mpsFluid'
set ylabel 'F_x on the box [N]'
plot fo('load', 'forces.dat') u 1:2 w l lw 2 t 'mpsFluid'
unset multiplot
