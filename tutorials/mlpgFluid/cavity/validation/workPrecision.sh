#!/bin/bash
# Usage: validation/workPrecision.sh [SPACINGS [SCHEMES]]
# The cavity at Re = 400 to its steady state at each spacing (default
# 0.05 0.025 0.02 0.0125 0.01) with the improved and the original wall
# scheme: RMS deviation from Ghia et al. (1982) against the wall time of
# the run, one thread. Runs in wp/<scheme>-<dl>/; writes
# validation/workPrecision.dat and validation/workPrecision.png (a run
# that fails is a row of NaN saying where); the header records the
# machine's load (timings depend on it).
. "${MPSDEM_DIR:-${0%/*}/../../../..}/bin/tools/RunFunctions" 2>/dev/null || {
    echo "${0##*/}: bin/tools/RunFunctions not found: set MPSDEM_DIR to the mpsdem directory" >&2; exit 1; }
cd "${0%/*}/.." || exit 1
spacings=${1:-0.05 0.025 0.02 0.0125 0.01}
out=validation/workPrecision.dat
[ -n "${2:-}" ] || rm -f $out  # SCHEMES given: add to the table
{
    echo "# cavity Re 400 to steady state: scheme dl nodes steps seconds rms_u rms_v   (one thread)"
    echo "# $(date -u +%F), $(nproc --all) cores, load at the start $(cut -d' ' -f1-3 /proc/loadavg)"
} >> $out
mkdir -p wp
for scheme in ${2:-improved original}; do
    for dl in $spacings; do
        d=wp/$scheme-$dl
        rm -rf $d; mkdir -p $d; cp -r constant system $d/
        dt=$(awk -v h=$dl 'BEGIN { a = 0.1 * h; b = 0.1 * h * h * 400; print (a < b ? a : b) }')
        dictTool $d/system/particleDict -set "dp=$dl" > /dev/null
        dictTool $d/constant/transportProperties -set "nu=[0 2 -1 0 0 0 0] 0.0025" > /dev/null
        dictTool $d/system/mlpgSchemes -set "wallScheme=$scheme" > /dev/null
        dictTool $d/system/controlDict -set "deltaT=$dt" > /dev/null
        (cd $d && genParticles > log.genParticles 2>&1) || exit 1
        t0=$(date +%s.%N)
        if (cd $d && OMP_NUM_THREADS=1 mlpgFluid > log.mlpgFluid 2>&1); then
            r=$(validation/compare.sh 400 $d | awk '/^E3-10/ { print $4, $5 }')
        else  # the run failed: say where, keep going
            r="NaN NaN # failed at t = $(grep '^Time' $d/log.mlpgFluid | tail -1 | awk '{ print $3 }') s: $(grep -A1 FATAL $d/log.mlpgFluid | tail -1 | sed 's/^ *//')"
        fi
        t1=$(date +%s.%N)
        n=$(grep -m1 'MLPG cloud' $d/log.mlpgFluid | awk '{ print $3 }')
        st=$(grep -c '^Time' $d/log.mlpgFluid)
        echo "$scheme $dl $n $st $(awk -v a=$t0 -v b=$t1 'BEGIN { printf "%.1f", b - a }') $r" | tee -a $out
    done
done
command -v gnuplot > /dev/null || exit 0
gnuplot <<GP
set terminal pngcairo size 800,550
set output 'validation/workPrecision.png'
set logscale xy; set grid; set key top right
set xlabel 'wall time of the run to steady state [s] (one thread)'; set ylabel 'RMS deviation from Ghia'
set title 'Cavity, Re = 400: error against run time (dl = $spacings)'
plot for [s in "improved original"] '$out' u (strcol(1) eq s ? \$5 : 1/0):6 w lp t s.' u(y)', \
     for [s in "improved original"] '$out' u (strcol(1) eq s ? \$5 : 1/0):7 w lp dt 2 t s.' v(x)'
GP
echo "wrote $out validation/workPrecision.png"
