#!/usr/bin/env bash
# mpsDemStress.sh — stress tests of the coupled MPS-DEM solver (issue 6;
# doc/theory.md A.7, A.8, A.12.1-A.12.2). A benchmark command, not part of
# Alltest: it prints tables and exits 1 when a stated band is violated.
#
#   test/bench/mpsDemStress.sh [--quick] [--keep] [a] [b] [c]
#
# (a) long settling: the 2-D sedimentation case of
#     test/cases/mpsDemSedimentation2D.sh (15 beads of 5 mm, dp = 5 mm, the
#     fluid leaving out the grain volume: grainVolume scale),
#     Model B, to 5 s (--quick 2 s); Model A beside it, reported only.
#     Bands (B):
#       settled      t_s = first time after the kinetic-energy peak with
#                    E <= 1e-6 of the peak (at rest: measured E ~ 1e-10 of
#                    the peak from 0.7 s on; 1e-2 is not rest, the beads
#                    still roll and knock at 4 % of the peak around 0.4 s);
#                    t_s <= 1.5 s;
#       no regrowth  for every row t >= t_s: max E over [t, end] <= E(t) +
#                    1e-6 of the peak (the slack: the resting beads feel
#                    the MPS pressure noise, E jitters between 1e-11 and
#                    1e-9 of the peak; a regrowth to the slack is a bead
#                    moving by ~1e-3 of its settling speed);
#       no escape    no fluid particle removed, no grain removed, every
#                    grain centre inside the tank at every row;
#       hydrostatic  bottom pressure (Shepard probe at x = 0.025, one dp/2
#                    above the floor) averaged over the last second within
#                    5 % of rho g (eta - dp/2), eta the measured free
#                    surface at x = 0.025 (the surface stands above 0.1 m:
#                    doc/theory.md A0-16).
# (b) perturbed runs, Model B, 3 seeds x deltaT x 0.8 and x 1.2 (6 runs per
#     case) against the unperturbed run: fluid lattice jittered by +-0.1 dp,
#     grain lattice by +-0.1 spacing (genParticles jitter/seed), on
#       sed2D   the sedimentation case to 0.96 s: kinetic-energy peak
#               (band 30 %), largest total drag |sum F^d| (10 %; it is the
#               settling drag ~ submerged weight), final bed top (+-0.5 d);
#       dam2D   the 2-D dam break of test/cases/mpsDemDamBreak2D.sh to
#               0.192 s: water front at 0.096 s and 0.192 s (+-2 dp),
#               final sediment front (+-2 d), kinetic-energy peak (30 %);
#     and in every run no NaN, no escape. (The end times are multiples of
#     all three steps.)
# (c) largest fixed deltaT that each model (A, B) survives on the root
#     case (coarse 3-D two-phase dam break, 0.2 s; --quick 0.05 s), by a
#     ladder of deltaT going up until the first failure. Survives = both
#     programs reach End, no NaN in the function-object output, no fluid
#     particle or grain lost, fluid volume (N dp^3) within 1 %.
#
# Full run ~20-25 min on 2 cores, --quick ~4 min. Each section can be
# chosen alone (a b c). MPSFLUID / DEMSOLID override the programs.
NAME=mpsDemStress
. "$(cd "$(dirname "$0")/.." && pwd)/cases/lib/tandem.sh"
quick=0
sections=""
for a in "$@"; do
    case "$a" in
        --quick) quick=1 ;;
        --keep) KEEP=1; echo "work directory: $TMP" ;;
        a|b|c) sections="$sections $a" ;;
        *) echo "usage: $0 [--quick] [--keep] [a] [b] [c]" >&2; exit 2 ;;
    esac
done
[ -n "$sections" ] || sections=" a b c"
# the programs copied once: the build is shared, and a rebuild during the
# benchmark must neither break a run (text file busy) nor mix two builds
mkdir -p "$TMP/bin"
cp "$MPSFLUID" "$DEMSOLID" "$ROOT/bin/genParticles" "$ROOT/bin/vtuInfo" "$TMP/bin/" || exit 1
MPSFLUID="$TMP/bin/$(basename "$MPSFLUID")"
DEMSOLID="$TMP/bin/$(basename "$DEMSOLID")"
GEN="$TMP/bin/genParticles"
VTUINFO="$TMP/bin/vtuInfo"
bad=0
verdict() {   # verdict OK|VIOLATED: count the violations
    [ "$1" = OK ] || bad=$((bad + 1))
    echo "$1"
}

# ---- the 2-D cases --------------------------------------------------------
# common DIR MODEL DT END WRITE: system/ and constant/ of the root case,
# 2-D gravity, model, step and times
common()
{
    local c="$1"
    mkdir -p "$c/system" "$c/constant" "$c/0"
    cp "$ROOT"/system/{couplingDict,mpsSchemes,mpsSolution,demSolution} "$c/system/"
    cp "$ROOT"/constant/{demProperties,transportProperties} "$c/constant/"
    cp "$ROOT/tutorials/mpsFluid/damBreak2D/constant/g" "$c/constant/"
    sed -i "s/^model .*/model $2;/; s/^timeout .*/timeout 60;/" "$c/system/couplingDict"
    cat > "$c/system/controlDict" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
startFrom startTime; startTime 0; endTime $4; deltaT $3; adjustTimeStep no;
writeControl runTime; writeInterval $5; writeFormat binary;
functions
{
    energy { type kineticEnergy; cloud dem; writeControl timeStep; writeInterval 5; }
    forces { type couplingForces; cloud dem; writeControl timeStep; writeInterval 5; }
    grains { type cloudInfo; cloud dem; writeControl timeStep; writeInterval 5; }
    bed    { type bedHeight; cloud dem; up (0 1 0); minContacts 1; writeControl timeStep; writeInterval 5; }
    sedimentFront { type front; cloud dem; direction (1 0 0); tolerance 0.9; writeControl timeStep; writeInterval 5; }
    volume { type volume; cloud fluid; writeControl timeStep; writeInterval 5; }
    fluidFront { type front; cloud fluid; direction (1 0 0); maxHeight 0.02; minNumberDensity 0.5; writeControl timeStep; writeInterval 5; }
    bottom { type probes; cloud fluid; probeLocations ((0.025 0.0025)); writeControl timeStep; writeInterval 5; }
    surface { type waveGauges; cloud fluid; gaugeLocations ((0.025)); writeControl timeStep; writeInterval 5; }
}
EOD
}

# sed_case DIR MODEL DT END WRITE FLUIDJITTER GRAINJITTER SEED
# beads: 5 x 3 at 10 mm; the box grows by twice the jitter amplitude so
# that the jittered lattice keeps all 15
sed_case()
{
    local c="$1" amp
    common "$@"
    amp=$(awk -v j="$7" 'BEGIN { print 2 * j * 0.01 }')
    cat > "$c/system/particleDict" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object particleDict; }
dimension 2; dp 0.005; kernelRadius 3.1; wallLayers auto;
regions
(
    tank  { type tankWall; shape box; min (0 0 0); max (0.05 0.15 0); open (ymax); }
    water { type fluid; shape box; min (0 0 0); max (0.05 0.1 0); hydrostaticPressure yes;
            grainVolume scale; jitter $6; seed $8; }
    beads { type grains; shape box; min (0.0025 0.0105 0);
            max ($(awk -v a="$amp" 'BEGIN { print 0.0475 + a, 0.0405 + a }') 0);
            diameter 0.005; lattice cubic; spacing 0.01; jitter $7; seed $8; }
);
EOD
}

# dam_case DIR MODEL DT END WRITE FLUIDJITTER GRAINJITTER SEED
# beads: 21 at 6.5 mm at the bottom of the column (the box grows likewise)
dam_case()
{
    local c="$1" amp
    common "$@"
    amp=$(awk -v j="$7" 'BEGIN { print 2 * j * 0.0065 }')
    cat > "$c/system/particleDict" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object particleDict; }
dimension 2; dp 0.005; kernelRadius 3.1; wallLayers auto;
regions
(
    tank   { type tankWall; shape box; min (0 0 0); max (0.2 0.15 0); open (ymax); }
    column { type fluid; shape box; min (0 0 0); max (0.05 0.1 0); hydrostaticPressure yes;
             jitter $6; seed $8; }
    beads  { type grains; shape box; min (0.0025 0.0005 0);
             max ($(awk -v a="$amp" 'BEGIN { print 0.0475 + a, 0.0205 + a }') 0);
             diameter 0.005; lattice cubic; spacing 0.0065; jitter $7; seed $8; }
);
EOD
}

# run_case DIR LIMIT: genParticles and the tandem; prints "ok", or "FAILED
# reason"
run_case()
{
    local c="$1"
    if ! (cd "$c" && "$GEN" > log.genParticles 2>&1); then
        echo "FAILED genParticles: $(grep -A1 FATAL "$c/log.genParticles" | tail -1)"
        return
    fi
    if run_tandem "$c" "${2:-900}"; then echo ok
    else echo "FAILED exit $rf/$rd: $(fatal_of "$c" | cut -c1-160)"; fi
}

pp() { echo "$1/postProcessing/$2/0/$3.dat"; }

# health DIR XMAX: "nan escaped removed outside" over the whole run
health()
{
    local c="$1" nan esc rem out
    # bedHeight is nan (no grain resting) until the first contact
    nan=$(ls "$c"/postProcessing/*/0/*.dat | grep -v bedHeight | xargs cat | grep -v '^#' | grep -ci 'nan\|inf')
    esc=$(awk '!/^#/ { e = $5 } END { print e == "" ? "?" : e }' "$(pp "$c" volume volume)")
    rem=$(awk '/grains removed/ { print $3 }' "$c/log.demSolid")
    out=$(awk -v X="$2" '!/^#/ && ($3 < 0 || $3 > X || $4 < 0 || $6 > X || $7 > 0.15) { n++ }
                         END { print n + 0 }' "$(pp "$c" grains cloudInfo)")
    echo "${nan:-0} ${esc:-?} ${rem:-?} ${out:-?}"
}

# ---- (a) long settling ----------------------------------------------------
section_a()
{
    local end=5 model c r
    [ $quick = 1 ] && end=2
    echo
    echo "(a) 2-D sedimentation, 15 beads, dp = 5 mm, deltaT 4e-4 s, to $end s"
    printf "%-5s %8s %10s %8s %11s %8s %6s %5s %5s %9s %9s %8s  %s\n" model wall_s \
        "E_peak[J]" "t_s[s]" "regrow/Epk" "Eend/Epk" nan esc rem outside \
        "p_bot[Pa]" "p/hyd-1" verdict
    for model in B A; do
        c="$TMP/a$model"
        sed_case "$c" $model 4e-4 $end 1 0 0 1
        local t0=$SECONDS
        r=$(run_case "$c" 1800)
        local wall=$((SECONDS - t0))
        if [ "$r" != ok ]; then
            printf "%-5s %8s  %s  " $model $wall "$r"
            [ $model = B ] && verdict VIOLATED || echo "(reported only)"
            continue
        fi
        # settle time, worst regrowth beyond E(t) after it, last E / peak
        read -r epk ts grow eend <<< "$(awk '!/^#/ { t[n] = $1; e[n] = $4; n++ }
            END { pk = 0; for (i = 0; i < n; i++) if (e[i] > e[pk]) pk = i
                  s = -1; for (i = pk; i < n; i++) if (e[i] <= 1e-6 * e[pk]) { s = i; break }
                  g = 0; if (s >= 0) { m = e[n - 1]
                      for (i = n - 1; i >= s; i--) { if (e[i] > m) m = e[i]; if (m - e[i] > g) g = m - e[i] } }
                  printf "%.4g %s %.3g %.3g\n", e[pk], (s >= 0 ? t[s] : "none"), g / e[pk], e[n - 1] / e[pk] }' \
            "$(pp "$c" energy kineticEnergy)")"
        read -r nan esc rem out <<< "$(health "$c" 0.05)"
        # bottom probe against rho g (eta - dp/2), over the last second
        read -r pb rel <<< "$(awk -v t1=$((end - 1)) 'FNR == 1 { f++ } /^#/ { next }
            f == 1 && $1 >= t1 { p += $2; np++ } f == 2 && $1 >= t1 { h += $2; nh++ }
            END { p /= np; h /= nh; printf "%.1f %.4f\n", p, p / (1000 * 9.81 * (h - 0.0025)) - 1 }' \
            "$(pp "$c" bottom probes)" "$(pp "$c" surface waveGauges)")"
        v=OK
        if [ "$ts" = none ] || awk -v t="$ts" 'BEGIN { exit !(t > 1.5) }'; then v=VIOLATED; fi
        awk -v g="$grow" -v r="$rel" 'BEGIN { exit !(g <= 1e-6 && r <= 0.05 && r >= -0.05) }' || v=VIOLATED
        [ "$nan $esc $rem $out" = "0 0 0 0" ] || v=VIOLATED
        printf "%-5s %8s %10s %8s %11s %8s %6s %5s %5s %9s %9s %8s  " $model $wall "$epk" "$ts" \
            "$grow" "$eend" "$nan" "$esc" "$rem" "$out" "$pb" "$rel"
        if [ $model = B ]; then verdict $v; else echo "($v by B's bands; reported only)"; fi
    done
}

# ---- (b) perturbations ----------------------------------------------------
# outputs CASE DIR: the compared numbers of one run
outputs()
{
    local c="$2"
    if [ "$1" = sed ]; then
        awk 'FNR == 1 { f++ } /^#/ { next }
             f == 1 && $4 > ek { ek = $4 }
             f == 2 { d = sqrt($2^2 + $3^2 + $4^2); if (d > dm) dm = d }
             f == 3 { bed = $2 }
             END { printf "%.5g %.5g %.5g\n", ek, dm, bed }' \
            "$(pp "$c" energy kineticEnergy)" "$(pp "$c" forces couplingForces)" \
            "$(pp "$c" bed bedHeight)"
    else
        # grains: mean centre x and leading centre x at the end (the
        # front function object follows the largest pack, which jumps
        # between packs: not a continuous output to band)
        "$VTUINFO" -case "$c" -dump 0.192/dem.vtu > "$c/end.dump" 2>&1
        awk 'FNR == 1 { f++ } /^#/ { next }
             f == 1 && ($1 - 0.096)^2 < 1e-10 { x1 = $2 } f == 1 { x2 = $2 }
             f == 2 && $4 > ek { ek = $4 }
             f == 3 && NF > 10 { sx += $1; ng++; if ($1 > xl) xl = $1 }
             END { printf "%.5g %.5g %.5g %.5g %.5g\n", x1, x2, sx / ng, xl, ek }' \
            "$(pp "$c" fluidFront front)" "$(pp "$c" energy kineticEnergy)" "$c/end.dump"
    fi
}

section_b()
{
    local kase seed f dt c r ref end mk
    local -a seeds=(1 2 3) factors=(0.8 1.2)
    [ $quick = 1 ] && seeds=(1) 
    echo
    echo "(b) perturbed runs (Model B): fluid jitter 0.1 dp, grain jitter 0.1 spacing, deltaT x 0.8 / 1.2"
    for kase in sed dam; do
        if [ $kase = sed ]; then
            end=0.96; mk=sed_case
            echo "  sed2D to $end s: E_peak [J] (band 30 %), max |F_drag| [N] (10 %), bed top [m] (+-0.0025)"
            printf "  %-14s %11s %11s %11s %4s %4s %4s %4s  %s\n" run E_peak maxDrag bedTop nan esc rem out verdict
        else
            end=0.192; mk=dam_case
            echo "  dam2D to $end s: water front at 0.096 and $end s [m] (+-0.01), grains' mean x (+-0.005) and leading x (+-0.02) at $end s [m], E_peak [J] (30 %)"
            printf "  %-14s %9s %9s %9s %9s %11s %4s %4s %4s %4s  %s\n" run x_w0.096 x_w_end x_g_mean x_g_lead E_peak nan esc rem out verdict
        fi
        ref=""
        for run in ref "${seeds[@]}"; do
            for f in "${factors[@]}"; do
                if [ $run = ref ]; then
                    [ $f = 0.8 ] || continue
                    f=1; dt=4e-4; c="$TMP/b$kase.ref"; $mk "$c" B $dt $end 1 0 0 1
                else
                    dt=$(awk -v f=$f 'BEGIN { print 4e-4 * f }')
                    c="$TMP/b$kase.s$run.f$f"; $mk "$c" B $dt $end 1 0.1 0.1 $run
                fi
                local name="$run dt x$f"
                r=$(run_case "$c" 900)
                if [ "$r" != ok ]; then
                    printf "  %-14s %s  " "$name" "$r"; verdict VIOLATED; continue
                fi
                local o h
                o=$(outputs $kase "$c")
                h=$(health "$c" $([ $kase = sed ] && echo 0.05 || echo 0.2))
                [ $run = ref ] && ref="$o"
                local v
                v=$(echo "$o | $ref | $h" | awk -v k=$kase -F'|' '{
                    split($1, o, " "); split($2, r, " "); split($3, h, " "); ok = 1
                    if (h[1] != 0 || h[2] != 0 || h[3] != 0 || h[4] != 0) ok = 0
                    if (k == "sed") {
                        if ((o[1] / r[1] - 1)^2 > 0.09) ok = 0
                        if ((o[2] / r[2] - 1)^2 > 0.01) ok = 0
                        if ((o[3] - r[3])^2 > 0.0025^2) ok = 0
                    } else {
                        if ((o[1] - r[1])^2 > 0.01^2 || (o[2] - r[2])^2 > 0.01^2) ok = 0
                        if ((o[3] - r[3])^2 > 0.005^2 || (o[4] - r[4])^2 > 0.02^2) ok = 0
                        if ((o[5] / r[5] - 1)^2 > 0.09) ok = 0
                    }
                    print ok ? "OK" : "VIOLATED" }')
                if [ $kase = sed ]; then
                    printf "  %-14s %11s %11s %11s %4s %4s %4s %4s  " "$name" $o $h
                else
                    printf "  %-14s %9s %9s %9s %9s %11s %4s %4s %4s %4s  " "$name" $o $h
                fi
                verdict $v
            done
        done
    done
}

# ---- (c) largest fixed deltaT on the root case ------------------------------
# One run of the root case with model $1 and deltaT $2: prints its row and
# sets rung_ok (yes/no); the first run of a model sets the reference fronts.
rung()
{
    local model=$1 dt=$2 c r
    c="$TMP/c$model.$dt"
    mkdir -p "$c"
    cp -r "$ROOT"/system "$ROOT"/constant "$c/"
    sed -i "s/^model .*/model $model;/; s/^timeout .*/timeout 60;/" "$c/system/couplingDict"
    sed -i "s/^deltaT .*/deltaT $dt;/; s/^endTime .*/endTime $end;/" "$c/system/controlDict"
    sed -i '/^functions/,/^{/ s/^{/{\n    volume { type volume; cloud fluid; writeControl timeStep; writeInterval 5; }\n    grains { type cloudInfo; cloud dem; writeControl timeStep; writeInterval 5; }/' \
        "$c/system/controlDict"
    local t0=$SECONDS
    r=$(run_case "$c" 1200)
    [ $model = A ] && [ -z "$xw0" ] && echo "  $(grep '^MPS particles' "$c/log.genParticles")"
    local wall=$((SECONDS - t0)) h="? ? ? ?" dv="?" xw="?" xs="?" dxw="?" dxs="?"
    rung_ok=no
    if [ "$r" = ok ]; then
        h=$(health "$c" 0.2)
        dv=$(awk '!/^#/ { v = $4 } END { printf "%.2g", v }' "$(pp "$c" volume volume)")
        xw=$(awk '!/^#/ { v = $2 } END { printf "%.4f", v }' "$(pp "$c" fluidFront front)")
        xs=$(awk '!/^#/ { v = $2 } END { printf "%.4f", v }' "$(pp "$c" sedimentFront front)")
        [ -n "$xw0" ] || { xw0=$xw; xs0=$xs; }
        dxw=$(awk -v a=$xw -v b=$xw0 'BEGIN { printf "%+.4f", a - b }')
        dxs=$(awk -v a=$xs -v b=$xs0 'BEGIN { printf "%+.4f", a - b }')
        read -r nan esc rem out <<< "$h"
        [ "$nan $esc $rem" = "0 0 0" ] \
            && awk -v d="$dv" 'BEGIN { exit !(d <= 0.01 && d >= -0.01) }' && rung_ok=yes
    fi
    local co
    co=$(awk -v dt=$dt 'BEGIN { printf "%.2f", 2 * sqrt(9.81 * 0.1) * dt / 0.005 }')
    printf "  %-5s %9s %7s %6s %4s %4s %4s %7s %8s %8s %8s %8s  %s\n" $model $dt $wall $co \
        $(echo "$h" | cut -d' ' -f1-3) "$dv" "$xw" "$dxw" "$xs" "$dxs" $rung_ok
    [ "$r" = ok ] || echo "        $r" | cut -c1-150
}

section_c()
{
    local end=0.2 model dt
    # steps that divide the write interval 0.05 s (and the end time): the
    # ladder in steps per 0.05 s, then bisection on that count between the
    # last rung that survived and the first that failed
    local -a ladder=(125 80 50 40 32 25 20 16 10 8 5)
    [ $quick = 1 ] && end=0.05
    echo
    echo "(c) root case (3-D two-phase dam break, system/ and constant/ of the repository) to $end s: deltaT ladder, then bisection"
    echo "  Co_est = 2 sqrt(g 0.1 m) deltaT / dp; x_water, x_sed: fronts (function objects) at the end, and"
    echo "  their difference from the first rung's (the smallest step) [m]"
    printf "  %-5s %9s %7s %6s %4s %4s %4s %7s %8s %8s %8s %8s  %s\n" model deltaT wall_s Co_est nan esc rem dV x_water dx_water x_sed dx_sed survives
    for model in A B; do
        local ok_n="" fail_n="" xw0="" xs0="" n
        for n in "${ladder[@]}"; do
            rung $model "$(awk -v n=$n 'BEGIN { printf "%.6g", 0.05 / n }')"
            [ $rung_ok = yes ] || { fail_n=$n; break; }
            ok_n=$n
        done
        while [ -n "$ok_n" ] && [ -n "$fail_n" ] && [ $((ok_n - fail_n)) -gt 1 ]; do
            n=$(((ok_n + fail_n) / 2))
            rung $model "$(awk -v n=$n 'BEGIN { printf "%.6g", 0.05 / n }')"
            if [ $rung_ok = yes ]; then ok_n=$n; else fail_n=$n; fi
        done
        echo "  Model $model: largest deltaT that survives: $([ -n "$ok_n" ] && awk -v n=$ok_n 'BEGIN { printf "%.6g", 0.05 / n }' || echo none) s" \
             "(smallest that fails: $([ -n "$fail_n" ] && awk -v n=$fail_n 'BEGIN { printf "%.6g", 0.05 / n }' || echo none))"
    done
}

echo "mpsDemStress ($([ $quick = 1 ] && echo quick || echo full)), $(date -u '+%Y-%m-%d %H:%M UTC'), git $(cd "$ROOT" && git rev-parse --short HEAD)"
for s in $sections; do
    section_$s
done
echo
echo "violated bands: $bad"
exit $((bad > 0))
