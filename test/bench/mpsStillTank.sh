#!/usr/bin/env bash
# mpsStillTank.sh [STEPS [SNAPSHOTS]] — long-run drift of still water, not a
# test: tutorials/mpsFluid/hydrostaticTank2D (400 fluid particles, dp = 5 mm,
# deltaT 5e-4 s) run for STEPS steps (default 100000, 50 s of flow) with
# SNAPSHOTS fluid.vtu written at equal intervals (default 50). Prints, per
# snapshot: time, steps, largest fluid speed / sqrt(g h) (E1-08 asks < 0.01
# for ever), relative L2 of the snapshot's pressure against rho g (h - y),
# the bottom probe (y = 2.5 mm) averaged since the previous snapshot against
# rho g (h - 0.0025), the fluid particle count; then the first snapshot where
# the speed passes 0.01 sqrt(g h). Draws stillTank.png (gnuplot) in the
# current directory. One thread (OMP_NUM_THREADS=1); about 1 s of wall time
# per 1000 steps on a quiet machine. KEEP=DIR keeps the case in DIR.
# SET='system/mpsSchemes:shifting=none system/mpsSchemes:sourceMix=0.01'
# changes or adds entries of the copied case first (bin/dictTool -new -set),
# to compare variants of the scheme. The start is the tutorial's: a
# relaxed state (mpsFluid -relax RELAX, default 10 s as in its Allrun);
# RELAX=0 starts from genParticles' lattice instead.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
STEPS=${1:-100000}
SNAP=${2:-50}
export OMP_NUM_THREADS=1
c=${KEEP:-$(mktemp -d)/case}
[ -n "$KEEP" ] || trap 'rm -rf "${c%/case}"' EXIT
rm -rf "$c"; cp -r "$ROOT/tutorials/mpsFluid/hydrostaticTank2D" "$c"
(cd "$c" && ./Allclean > /dev/null 2>&1)
for kv in ${SET:-}; do
    "$ROOT/bin/dictTool" "$c/${kv%%:*}" -new -set "${kv#*:}" > /dev/null || exit 1
done
dt=$(sed 's|//.*||' "$c/system/controlDict" | awk '/^deltaT/ { gsub(";", "", $2); print $2 }')
end=$(awk -v n=$STEPS -v dt=$dt 'BEGIN { printf "%.10g", n * dt }')
wi=$(awk -v e=$end -v k=$SNAP 'BEGIN { printf "%.10g", e / k }')
s=$(date +%s)
(cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) || { echo "genParticles failed"; exit 1; }
# the depth of the lattice (a relaxed start keeps the volume, not the top row)
h=$("$ROOT/bin/vtuInfo" -dump "$c/0/fluid.vtu" 2>/dev/null | awk '!/^#/ && NF > 10 && $4 == 0 { if ($2 > m) m = $2 } END { print m + 0.0025 }')
RELAX=${RELAX:-10}
if [ "$RELAX" != 0 ]; then
    (cd "$c" && "$ROOT/bin/mpsFluid" -relax "$RELAX" > log.relax 2>&1) || { echo "relaxation failed: $c/log.relax"; exit 1; }
fi
"$ROOT/bin/dictTool" "$c/system/controlDict" -set "endTime=$end" > /dev/null || exit 1
"$ROOT/bin/dictTool" "$c/system/controlDict" -set "writeInterval=$wi" > /dev/null || exit 1
(cd "$c" && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1)
rc=$?
wall=$(( $(date +%s) - s ))
echo "# hydrostaticTank2D${SET:+ ($SET)}$([ "$RELAX" = 0 ] && echo ", lattice start" || echo ", relaxed start of $RELAX s"), $STEPS steps of $dt s (endTime $end s), exit $rc, $wall s wall, load $(cut -d' ' -f1-3 /proc/loadavg)"
[ $rc -eq 0 ] || { grep -A2 FATAL "$c/log.mpsFluid"; }
rho=1000; g=9.81
probe="$c/postProcessing/bottom/0/probes.dat"
printf '%-10s %8s %14s %10s %16s %10s\n' t steps 'umax/sqrt(gh)' 'L2(p)' 'p_bottom/ref-1' particles > "$c/table"
for t in $(cd "$c" && ls -d [0-9]* | sort -g); do
    [ "$t" = 0 ] && { prev=0; continue; }
    "$ROOT/bin/vtuInfo" -dump "$c/$t/fluid.vtu" 2>/dev/null | awk -v t=$t -v dt=$dt -v h=$h -v rho=$rho -v g=$g \
        -v prev=$prev -v probe="$probe" '
        !/^#/ && NF > 10 && $4 == 0 { n++; u = sqrt($6^2 + $7^2 + $8^2); if (u > um) um = u
            pe = rho * g * (h - $2); e2 += ($9 - pe)^2; r2 += pe^2 }
        END { while ((getline l < probe) > 0) { split(l, a, " ")
                  if (l !~ /^#/ && a[1] > prev + 1e-12 && a[1] <= t + 1e-12) { ps += a[2]; np++ } }
              printf "%-10s %8d %14.5f %10.5f %+16.5f %10d\n", t, t / dt + 0.5, um / sqrt(g * h),
                     sqrt(e2 / r2), np ? (ps / np) / (rho * g * (h - 0.0025)) - 1 : 0, n }' >> "$c/table"
    prev=$t
done
cat "$c/table"
awk 'NR > 1 && $3 > 0.01 { print "first snapshot with umax > 0.01 sqrt(gh): t = " $1 " s (step " $2 ")"; f = 1; exit }
     END { if (!f) print "umax <= 0.01 sqrt(gh) at every snapshot" }' "$c/table"
gnuplot -e "set terminal pngcairo size 900,420 noenhanced; set output 'stillTank.png';
    set multiplot layout 1,2; set xlabel 't [s]'; set grid; set key top left;
    set ylabel 'max |u| / sqrt(g h)';
    plot '$c/table' every ::1 u 1:3 w lp pt 7 ps 0.5 t 'hydrostaticTank2D', 0.01 w l dt 2 t 'E1-08 target';
    set ylabel 'relative error'; set key bottom right;
    plot '$c/table' every ::1 u 1:4 w lp pt 7 ps 0.5 t 'L2 of p vs rho g (h - y)',
         '' every ::1 u 1:5 w lp pt 6 ps 0.5 t 'bottom probe / rho g (h - 0.0025) - 1';
    unset multiplot" && echo "wrote stillTank.png"
