#!/bin/bash
# Usage: validation/workPrecision.sh [SEEDS]
# Error against run time for the patch test at k = 0.3: every wall scheme
# and three PPE solvers (BiCGSTAB with ILU(0), with Jacobi, with the
# aggregation multigrid), over the tutorial's spacings, SEEDS seeds each
# (default 3). Runs in a copy (wp/), one thread; writes
# validation/workPrecision.dat (scheme solver dl Er seconds-per-solve) and
# validation/workPrecision.png. Timings depend on the machine and its
# load: the table's header records both.
. "${MPSDEM_DIR:-${0%/*}/../../../..}/bin/tools/RunFunctions" 2>/dev/null || {
    echo "${0##*/}: bin/tools/RunFunctions not found: set MPSDEM_DIR to the mpsdem directory" >&2; exit 1; }
cd "${0%/*}/.." || exit 1
seeds=${1:-3}
out=validation/workPrecision.dat
{
    echo "# patch test, k = 0.3, $seeds seeds: scheme solver dl Er seconds (assembly + solve, mean per solve)"
    echo "# $(date -u +%F), $(nproc --all) cores, load $(cut -d' ' -f1-3 /proc/loadavg), OMP_NUM_THREADS=1"
} > $out
for pc in ilu0 jacobi amg; do
    rm -rf wp; mkdir wp; cp -r system wp/
    dictTool wp/system/patchTestDict -set "randomness=(0.3)" -set "seeds=$seeds" \
        -set "PPE/preconditioner=$pc" > /dev/null || exit 1
    (cd wp && OMP_NUM_THREADS=1 mlpgPatchTest > log.mlpgPatchTest 2>&1) || { tail -5 wp/log.mlpgPatchTest; exit 1; }
    awk -v pc="bicgstab-$pc" '!/^#/ { print $1, pc, $3, $5, $11 }' wp/postProcessing/patchTest/errors.dat >> $out
done
rm -rf wp
command -v gnuplot > /dev/null || exit 0
gnuplot <<GP
set terminal pngcairo size 800,550
set output 'validation/workPrecision.png'
set logscale xy; set grid; set key top right
set xlabel 'seconds per solve (assembly + PPE, one thread)'; set ylabel 'Er'
set title 'Patch test, k = 0.3: error against run time'
plot for [s in "improved improvedConsistent original"] for [p in "bicgstab-ilu0 bicgstab-jacobi bicgstab-amg"] \
     '$out' u (strcol(1) eq s && strcol(2) eq p ? \$5 : 1/0):4 w lp t s.' '.p
GP
echo "wrote $out validation/workPrecision.png"
