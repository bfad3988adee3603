#!/usr/bin/env bash
# mpsDemWorkPrecision.sh — work-precision of the MPS-DEM coupling scheme on
# the root case (coarse 3-D two-phase dam break, doc/theory.md A.12.2, Model
# B, 0.2 s; --quick 0.05 s): the two coupling schemes of
# system/couplingDict (sequential = MSS, DEM first; concurrent = one-step
# lag, both programs at once) times the DEM sub-stepping of
# system/demSolution (ARKode ERK at rtol 1e-3 ... 1e-6, the absolute
# tolerances scaled with rtol as the root case's 1e-6 set; and the
# fixed-step Verlet, rayleighFraction 0.2, the root case's setting).
#
#   test/bench/mpsDemWorkPrecision.sh [--quick] [--keep] [OUTDIR]
#
# Reference: sequential with ARKode at rtol 1e-8 (the tightest setting,
# the paper's sequential scheme). Errors against it, from the function
# objects written every 5 fluid steps (2 ms):
#   e_w  = max over the rows of |X_water(t) - X_water,ref(t)|  [m]
#   e_s  = max over the rows of |X_sed(t) - X_sed,ref(t)|      [m]
# (fluidFront and sedimentFront of the root case's controlDict), and the
# final values. Cost: wall clock of the tandem and the CPU time of each
# program (ExecutionTime of its log; the blocking waits use futexes and
# cost no CPU). Both programs run with one OpenMP thread each (2 cores).
#
# Prints a table; writes OUTDIR/mpsDemWorkPrecision.{dat,png} (OUTDIR
# default: the current directory) with gnuplot (pngcairo, else png).
# The grain dynamics are chaotic: past the first contacts, an error of
# one setting against another is bounded below by the divergence of
# trajectories, not by the step (see the floor of e_s).
# MPSFLUID / DEMSOLID override the programs (default bin/).
NAME=mpsDemWorkPrecision
. "$(cd "$(dirname "$0")/.." && pwd)/cases/lib/tandem.sh"
quick=0
out="$PWD"
for a in "$@"; do
    case "$a" in
        --quick) quick=1 ;;
        --keep) KEEP=1; echo "work directory: $TMP" ;;
        -*) echo "usage: $0 [--quick] [--keep] [OUTDIR]" >&2; exit 2 ;;
        *) out="$a" ;;
    esac
done
mkdir -p "$out" || exit 1
out="$(cd "$out" && pwd)"
# the programs copied once: the build is shared (a rebuild during the
# benchmark must neither break a run nor mix two builds)
mkdir -p "$TMP/bin"
cp "$MPSFLUID" "$DEMSOLID" "$ROOT/bin/genParticles" "$TMP/bin/" || exit 1
MPSFLUID="$TMP/bin/$(basename "$MPSFLUID")"
DEMSOLID="$TMP/bin/$(basename "$DEMSOLID")"
end=0.2
settings=(ref verlet 1e-3 1e-4 1e-5 1e-6)
if [ $quick = 1 ]; then
    end=0.05
    settings=(ref verlet 1e-3 1e-6)
fi

# one generated case, copied for every run (same particles)
base="$TMP/base"
mkdir -p "$base"
cp -r "$ROOT/system" "$ROOT/constant" "$base/"
sed -i "s/^endTime .*/endTime $end;/" "$base/system/controlDict"
sed -i "s/^timeout .*/timeout 120;/" "$base/system/couplingDict"
(cd "$base" && "$TMP/bin/genParticles" > log.genParticles 2>&1) \
    || { echo "genParticles failed: $(tail -3 "$base/log.genParticles")"; exit 1; }

# run SCHEME SETTING: one tandem in $TMP/SCHEME.SETTING; prints
# "wall cpu_fluid cpu_dem substeps" or "FAILED ..."
run()
{
    local c="$TMP/$1.$2" rt
    rm -rf "$c"; cp -r "$base" "$c"
    sed -i "s/^scheme .*/scheme               $1;/" "$c/system/couplingDict"
    if [ "$2" = verlet ]; then
        sed -i "s/^integrator .*/integrator      verlet;/" "$c/system/demSolution"
    else
        rt=$2; [ "$2" = ref ] && rt=1e-8
        sed -i "s/^integrator .*/integrator      arkode;/" "$c/system/demSolution"
        sed -i "s/^\( *rtol *\).*;/\1$rt;/" "$c/system/demSolution"
        sed -i "s/^\( *atolPosition *\).*;/\1$(awk -v r=$rt 'BEGIN { print r * 1e-4 }');/" "$c/system/demSolution"
        sed -i "s/^\( *atolVelocity *\).*;/\1$(awk -v r=$rt 'BEGIN { print r * 0.1 }');/" "$c/system/demSolution"
        sed -i "s/^\( *atolOmega *\).*;/\1$(awk -v r=$rt 'BEGIN { print r * 100 }');/" "$c/system/demSolution"
    fi
    local t0 t1
    t0=$(date +%s.%N)
    if ! run_tandem "$c" 1800; then
        echo "FAILED exit $rf/$rd: $(fatal_of "$c" | cut -c1-120)"
        return
    fi
    t1=$(date +%s.%N)
    local cf cd st
    cf=$(awk '/^ExecutionTime/ { v = $3 } END { print v }' "$c/log.mpsFluid")
    cd=$(awk '/^ExecutionTime/ { v = $3 } END { print v }' "$c/log.demSolid")
    st=$(awk '/steps taken/ { print $3 }' "$c/log.demSolid")
    awk -v a="$t0" -v b="$t1" -v f="$cf" -v d="$cd" -v s="$st" \
        'BEGIN { printf "%.1f %.2f %.2f %s\n", b - a, f, d, s }'
}

# errs DIR: "e_w e_s X_w(end) X_s(end)" against the reference
errs()
{
    local c="$1" r="$TMP/sequential.ref" f
    for f in fluidFront sedimentFront; do
        awk 'FNR == 1 { k++ } /^#/ { next }
             k == 1 { ref[sprintf("%.6f", $1)] = $2; next }
             { t = sprintf("%.6f", $1); if (t in ref) { d = $2 - ref[t]; d = d < 0 ? -d : d
               if (d > m) m = d; n++ } last = $2 }
             END { printf "%.3g %.4f ", n ? m : "nan", last }' \
            "$r/postProcessing/$f/0/front.dat" "$c/postProcessing/$f/0/front.dat"
    done | awk '{ print $1, $3, $2, $4 }'
}

echo "mpsDemWorkPrecision ($([ $quick = 1 ] && echo quick || echo full)): root case, Model B, to $end s," \
     "$(date -u '+%Y-%m-%d %H:%M UTC'), git $(cd "$ROOT" && git rev-parse --short HEAD)"
echo "reference: scheme sequential, DEM ARKode rtol 1e-8 (atolPosition 1e-12 m, atolVelocity 1e-9 m/s)"
dat="$out/mpsDemWorkPrecision.dat"
{
    echo "# mpsDemWorkPrecision: root case, Model B, to $end s"
    echo "# scheme dem wall_s cpuFluid_s cpuDem_s demSubsteps e_water_m e_sed_m xWaterEnd_m xSedEnd_m"
} > "$dat"
printf "%-11s %-7s %8s %9s %8s %9s %9s %9s %8s %8s\n" scheme DEM wall_s cpuFluid cpuDem substeps \
       e_water e_sed x_w_end x_s_end
declare -A wall cpus
for s in "${settings[@]}"; do
    for scheme in sequential concurrent; do
        r=$(run $scheme $s)
        case "$r" in
            FAILED*) printf "%-11s %-7s %s\n" $scheme $s "$r"; continue ;;
        esac
        e=$(errs "$TMP/$scheme.$s")
        wall[$scheme.$s]=${r%% *}
        cpus[$scheme.$s]=$(echo "$r" | awk '{ print $2, $3 }')
        name=$s; [ $s = ref ] && name=rtol1e-8
        printf "%-11s %-7s %8s %9s %8s %9s %9s %9s %8s %8s\n" $scheme $name $r $e
        echo "$scheme $name $r $e" >> "$dat"
    done
done
echo
echo "concurrent vs sequential: wall clock ratio (below 1: concurrent pays off), the saving"
echo "measured, and the most it can save on 2 cores, min(cpuFluid, cpuDem) of the sequential run:"
for s in "${settings[@]}"; do
    a=${wall[sequential.$s]}; b=${wall[concurrent.$s]}
    [ -n "$a" ] && [ -n "$b" ] && awk -v s=$s -v a="$a" -v b="$b" -v cpu="${cpus[sequential.$s]}" \
        'BEGIN { split(cpu, c, " "); m = c[1] < c[2] ? c[1] : c[2]
                 printf "  %-7s %.3f  (sequential %.1f s, concurrent %.1f s: saved %.1f s; at most %.1f s)\n",
                        s, b / a, a, b, a - b, m }'
done

if command -v gnuplot > /dev/null; then
    term="pngcairo size 1200,500"
    gnuplot -e "set terminal pngcairo" 2>/dev/null < /dev/null || term="png size 1200,500"
    gnuplot <<EOG 2> "$TMP/gnuplot.log"
set terminal $term
set output "$out/mpsDemWorkPrecision.png"
set multiplot layout 1,2 title "MPS-DEM work-precision, root case (3-D dam break, Model B, $end s); reference: sequential, ARKode rtol 1e-8"
set logscale y
set xlabel "wall clock [s] (2 cores)"
set grid
set key top right
set ylabel "max |X_{water} - X_{water,ref}| [m]"
plot "$dat" using (strcol(1) eq "sequential" && strcol(2) ne "rtol1e-8" ? \$3 : 1/0):(\$7 > 0 ? \$7 : 1e-9):2 with labels offset 0,1 notitle, \
     "" using (strcol(1) eq "sequential" && strcol(2) ne "rtol1e-8" ? \$3 : 1/0):(\$7 > 0 ? \$7 : 1e-9) with points pt 7 title "sequential", \
     "" using (strcol(1) eq "concurrent" ? \$3 : 1/0):(\$7 > 0 ? \$7 : 1e-9) with points pt 5 title "concurrent", \
     "" using (strcol(1) eq "concurrent" ? \$3 : 1/0):(\$7 > 0 ? \$7 : 1e-9):2 with labels offset 0,-1 notitle
set ylabel "max |X_{sed} - X_{sed,ref}| [m]"
plot "$dat" using (strcol(1) eq "sequential" && strcol(2) ne "rtol1e-8" ? \$3 : 1/0):(\$8 > 0 ? \$8 : 1e-9):2 with labels offset 0,1 notitle, \
     "" using (strcol(1) eq "sequential" && strcol(2) ne "rtol1e-8" ? \$3 : 1/0):(\$8 > 0 ? \$8 : 1e-9) with points pt 7 title "sequential", \
     "" using (strcol(1) eq "concurrent" ? \$3 : 1/0):(\$8 > 0 ? \$8 : 1e-9) with points pt 5 title "concurrent", \
     "" using (strcol(1) eq "concurrent" ? \$3 : 1/0):(\$8 > 0 ? \$8 : 1e-9):2 with labels offset 0,-1 notitle
unset multiplot
EOG
    if [ -s "$out/mpsDemWorkPrecision.png" ]; then echo "plot: $out/mpsDemWorkPrecision.png"
    else echo "gnuplot failed: $(head -3 "$TMP/gnuplot.log")"; fi
fi
echo "table: $dat"
