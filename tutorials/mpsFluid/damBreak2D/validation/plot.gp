# plot.gp — surge front Z(T) and column height H(tau) of damBreak2D against
# Martin & Moyce (1952). Run from the case directory: gnuplot validation/plot.gp
# The data are the repository's data/martin_moyce_1952: $MPSDEM_DIR/data/...
# (set by bin/tools/RunFunctions), else the case is taken to sit in
# tutorials/mpsFluid/ of the repository; -e "data='DIR'" overrides both.
if (!exists("data")) data = system("echo ${MPSDEM_DIR:-../../..}")."/data/martin_moyce_1952"
if (!exists("shift")) shift = 0
a = 0.05715; g = 9.81
# the front is the centre of the leading particle: its edge is dp/2 further
if (!exists("dp")) dp = real(system("awk '/^dp/ { gsub(\";\", \"\", $2); print $2 }' constant/particlePatches"))
set terminal pngcairo size 1000,420 noenhanced
set output 'validation/damBreak2D.png'
set multiplot layout 1,2
set datafile separator ' ,'
set xlabel 'T = t sqrt(2g/a)'; set ylabel 'Z = x/a'; set key top left
set xrange [0:3.5]
plot 'postProcessing/surge/0/front.dat' u ($1*sqrt(2*g/a)+shift):(($2+dp/2)/a) w l lw 2 t 'mpsFluid', \
     data.'/martin_moyce_1952_surge_front_n2-2_a2.25in.csv' u 1:2 every ::1 w p pt 7 t 'Martin & Moyce 1952' 
set xlabel 'tau = t sqrt(g/a)'; set ylabel 'H = h/(2a)'; set key top right
set xrange [0:2.6]; set yrange [0:1.05]
plot 'postProcessing/column/0/waveGauges.dat' u ($1*sqrt(g/a)+shift):($2/(2*a)) w l lw 2 t 'mpsFluid', \
     data.'/martin_moyce_1952_column_height_n2-2_a2.25in.csv' u 1:2 every ::1 w p pt 7 t 'Martin & Moyce 1952'
unset multiplot
