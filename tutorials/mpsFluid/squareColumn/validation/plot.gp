# plot.gp — squareColumn against Yeh & Petroff; run from the case directory
# after validation/compare.sh (which writes validation/series.dat and
# validation/velocity.dat, the only run output it reads):
#   gnuplot validation/plot.gp  ->  validation/squareColumn.png
# MPSDEM_DIR (the mpsdem directory) locates data/ for a copied case.
root = system("echo ${MPSDEM_DIR:-$(cd \"$(dirname validation)/../../..\" && pwd)}")
data = root . "/data/yeh_petroff_column/"
uarr = real(system("awk '!/^#/ && $2 != \"nan\" && $2 > 0.5 { print $1; exit }' validation/velocity.dat"))
set terminal pngcairo size 1200,900 font ",10"
set output "validation/squareColumn.png"
set datafile separator whitespace
set multiplot layout 2,2
set grid
set key top right
set xlabel "t [s]"
set ylabel "F_x on the column [N]"
set datafile separator ","
plot [0:3] data."yeh_petroff_force_anuga.csv" every ::1 using 1:2 with points pt 7 ps 0.3 lc rgb "#bbbbbb" title "measured (ANUGA digitisation)", \
     data."yeh_petroff_force_pysph.csv" every ::1 using 1:2 with points pt 7 ps 0.4 lc rgb "black" title "measured (PySPH digitisation)", \
     "< grep -v '^#' validation/series.dat | tr ' ' ','" using 1:2 with lines lc rgb "red" title "mpsFluid"
set ylabel "u_x at (0.814, 0.305, 0.026) [m/s]"
set xlabel "t - t_{arrival} [s]"
plot [0:1.5] data."yeh_petroff_velocity_pysph.csv" every ::1 using 1:2 with points pt 7 ps 0.5 lc rgb "black" title "measured", \
     "< grep -v '^#' validation/velocity.dat | tr ' ' ','" using ($1 - uarr):2 with lines lc rgb "red" title "mpsFluid"
set datafile separator whitespace
set xlabel "t [s]"
set ylabel "water front [m]"
set key bottom right
plot [0:1] "validation/series.dat" using 1:6 with lines lc rgb "red" title "mpsFluid (fluid > 0.03 m up)", \
     (x > 0 ? 0.4 + 1.889 * x : 1/0) with lines dt 2 lc rgb "black" title "Stoker bore 1.889 m/s", \
     0.9 with lines dt 3 lc rgb "gray" title "column face"
set ylabel "P1 [Pa] / H1 [mm]"
set key top right
plot [0:3] "validation/series.dat" using 1:3 with lines lc rgb "blue" title "P1 (face, z = 0.025 m)", \
     "validation/series.dat" using 1:($5 * 1000) with lines lc rgb "dark-green" title "H1 (0.65, 0.305) x 1000"
unset multiplot
