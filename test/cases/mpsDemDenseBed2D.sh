#!/usr/bin/env bash
# mpsDemDenseBed2D.sh — a packed bed of touching grains (the paper's
# simple-cubic packing, porosity 0.48; doc/theory.md A.12.1) in still water,
# 2-D, dp = 5 mm, 45 beads of d = 5 mm, Model B, 0.5 s in tandem.
#   genParticles with `grainVolume scale;` gives the fluid particles the
#   volume fractions phi = eps (field volumeFraction); the solid volume it
#   reports equals the beads' volume within 10 % (kernel tails reach into
#   the walls) and the fluid volume is (200 - that) dp^2;
#   the coupled run starts at rest: no particle escapes, the fluid volume
#   sum phi dp^2 is conserved exactly and written again at every output
#   time (a restart from 0.02 s gives the continuous run's 0.04 s fields
#   to round-off), the bed falls the one diameter it starts above the
#   floor and settles: the peak grain kinetic energy stays below the work
#   of the submerged weight over that fall (2.17e-4 J), the energy at
#   0.5 s is <= 1 % of the peak, and |total drag| at the end is <= 2 % of
#   the submerged weight. (With `fill`, the default, the same bed throws
#   24 of its 200 fluid particles out of the tank in the first 4 steps.)
# All of it again with the sedimentation tutorial's still-bed settings
# (ppeDivergence superficial, porousWalls no) and the water exchange on
# (volumeFractionRelaxation 0.005 s; checks named denseBed2D_stillBed_*):
# the fluid volume then constant to 1e-12 (the water the particles trade
# sums to round-off), and a restart repeats the exchange.
# MPSFLUID / DEMSOLID override the programs (default bin/).
NAME=mpsDemDenseBed2D
. "$(dirname "$0")/lib/tandem.sh"
# same_cloud A B: the largest column-wise |A - B| / max |A| of two .vtu files
same_cloud() {
    paste -d'|' <("$ROOT/bin/vtuInfo" -dump "$1" 2>/dev/null) <("$ROOT/bin/vtuInfo" -dump "$2" 2>/dev/null) |
    awk -F'|' '$1 ~ /^[-0-9]/ { n = split($1, a, " "); split($2, b, " ")
        for (i = 1; i <= n; i++) { d = a[i] - b[i]; d = d < 0 ? -d : d; v = a[i] < 0 ? -a[i] : a[i]
            if (d > dm[i]) dm[i] = d; if (v > vm[i]) vm[i] = v }; rows++ }
        END { w = 0; for (i in dm) { r = dm[i] / (vm[i] > 0 ? vm[i] : 1); if (r > w) w = r }
              print (rows > 0 ? w : "norows") }'
}
# dense_bed NAME COUPLING-LINES SUFFIX DVMAX: the run and its checks in
# $TMP/NAME, with COUPLING-LINES appended to couplingDict, check names
# denseBed2D<SUFFIX>_*, the fluid volume constant within DVMAX (relative)
dense_bed()
{
    c="$TMP/$1"
    case_2d "$c" <<'EOD'
regions
(
    tank   { type tankWall; shape box; min (0 0 0); max (0.05 0.15 0); open (ymax); }
    water  { type fluid; shape box; min (0 0 0); max (0.05 0.1 0);
             hydrostaticPressure yes; grainVolume scale; }
    beads  { type grains; shape box; min (0.0025 0.005 0); max (0.0475 0.0305 0);
             diameter 0.005; lattice cubic; spacing 0.005; }
);
EOD
    cat > "$c/system/controlDict" <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
startFrom startTime; startTime 0; endTime 0.5; deltaT 4e-4; adjustTimeStep no;
writeControl runTime; writeInterval 0.1; writeFormat ascii;
functions
{
    energy { type kineticEnergy; cloud dem; writeControl timeStep; writeInterval 5; }
    forces { type couplingForces; cloud dem; writeControl timeStep; writeInterval 5; }
    volume { type volume; cloud fluid; writeControl timeStep; writeInterval 5; }
}
EOD
    sed -i "s/^model .*/model B;/; s/^timeout .*/timeout 30;/" "$c/system/couplingDict"
    echo "channel mpsdem-densebed2d-$1-$$;" >> "$c/system/couplingDict"
    printf "$2" >> "$c/system/couplingDict"
    (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) \
        || { fail denseBed2D${3}_genParticles "$(fatal_of "$c")"; return 1; }
    # "Region water: grainVolume scale: ... take out S dp^2 where ..."
    solid=$(sed -n 's/.*take out \([0-9.]*\) dp.*/\1/p' "$c/log.genParticles")
    # 45 spheres of d = dp spread over the depth dp: 45 pi/6 dp^2
    awk -v s="${solid:-x}" 'BEGIN { V = 45 * 3.14159265358979 / 6
            exit !(s > 0.9 * V && s <= V) }' \
        && pass "denseBed2D${3}_scale solid volume $solid dp^2 (45 pi/6 = 23.56)" \
        || fail denseBed2D${3}_scale "solid volume '$solid' dp^2 (45 pi/6 = 23.56)"
    run_tandem "$c"; ok=$?
    esc=$(grep -o 'escaped [0-9]*' "$c/log.mpsFluid" | tail -1 | awk '{ print $2 }')
    if [ $ok -ne 0 ] || [ "$esc" != 0 ]; then
        fail denseBed2D${3}_run "exit $rf/$rd, escaped $esc: $(fatal_of "$c")"
        return 1
    fi
    pass denseBed2D${3}_run
    read -r ke kr <<< "$(awk '!/^#/ { if ($4 > pk) pk = $4; last = $4 } END { print pk, last / pk }' \
         "$c/postProcessing/energy/0/kineticEnergy.dat")"
    # 45 beads, rho_s - rho_f = 1500, fall of d = 5 mm
    awk -v e="$ke" -v r="$kr" 'BEGIN { W = 45 * 4 / 3 * 3.14159265358979 * 0.0025^3 * 1500 * 9.81
            exit !(e <= W * 0.005 && r <= 0.01) }' \
        && pass "denseBed2D${3}_settles peak E_k $ke J (<= W' d), E(0.5 s)/E_peak = $kr" \
        || fail denseBed2D${3}_settles "peak E_k $ke J (<= 2.17e-4), E(0.5 s)/E_peak = $kr (<= 1 %)"
    read -r v0 vmax <<< "$(awk '!/^#/ { if (!v0) v0 = $3; d = $3 / v0 - 1; if (d < 0) d = -d; if (d > m) m = d } END { print v0, m + 0 }' \
          "$c/postProcessing/volume/0/volume.dat")"
    awk -v v="$v0" -v s="$solid" -v d="$vmax" -v dmax="$4" 'BEGIN { e = v / 0.005^2 - (200 - s)
            exit !(d <= dmax && e < 0.05 && e > -0.05) }' \
        && pass "denseBed2D${3}_volume fluid volume $v0 m^2 = (200 - $solid) dp^2, largest relative change $vmax" \
        || fail denseBed2D${3}_volume "fluid volume $v0 m^2 (200 - $solid dp^2), largest change $vmax"
    "$ROOT/bin/vtuInfo" -case "$c" 0.5/fluid.vtu 2>/dev/null | grep -q "field volumeFraction" \
        && pass "denseBed2D${3}_written volumeFraction in 0.5/fluid.vtu" \
        || fail denseBed2D${3}_written "no volumeFraction in 0.5/fluid.vtu"
    dr=$(awk '!/^#/ { l = $0 } END { split(l, a)
            W = 45 * 4 / 3 * 3.14159265358979 * 0.0025^3 * 1500 * 9.81
            print sqrt(a[2]^2 + a[3]^2) / W }' "$c/postProcessing/forces/0/couplingForces.dat")
    awk -v d="$dr" 'BEGIN { exit !(d <= 0.02) }' \
        && pass "denseBed2D${3}_drag |F_d|/W' = $dr at 0.5 s" \
        || fail denseBed2D${3}_drag "|F_d|/W' = $dr (<= 2 %)"
    # restart: 0 -> 0.04 s continuous, then 0.02 -> 0.04 s from the written
    # state (volume fractions read back, porosity rebuilt): the same fields to
    # round-off (every column within 1e-9 of its largest magnitude; the files
    # are not always bit-identical here: a 1e-16 difference in a velocity
    # grows to 1e-11 Pa in the pressure over 50 steps)
    r="$TMP/$1-restart"
    cp -r "$c" "$r"
    rm -rf "$r"/0.[0-9]* "$r/postProcessing" "$r"/*.pvd
    sed -i 's/endTime 0.5;/endTime 0.04;/; s/writeInterval 0.1;/writeInterval 0.02;/' "$r/system/controlDict"
    sed -i "s/^channel .*/channel mpsdem-densebed2d-$1-r-$$;/" "$r/system/couplingDict"
    (cd "$r" && "$ROOT/bin/genParticles" > log.genParticles 2>&1)
    if run_tandem "$r" 120 1 && mv "$r/0.04" "$r/continuous" \
       && sed -i 's/startFrom startTime;/startFrom latestTime;/' "$r/system/controlDict" \
       && run_tandem "$r" 120 2; then
        df=$(same_cloud "$r/continuous/fluid.vtu" "$r/0.04/fluid.vtu")
        dd=$(same_cloud "$r/continuous/dem.vtu" "$r/0.04/dem.vtu")
        awk -v f="$df" -v d="$dd" 'BEGIN { exit !(f != "norows" && d != "norows" && f <= 1e-9 && d <= 1e-9) }' \
            && pass "denseBed2D${3}_restart fluid $df, grains $dd (relative to each column's largest value)" \
            || fail denseBed2D${3}_restart "restart from 0.02 s vs continuous at 0.04 s: fluid $df, grains $dd"
    else
        fail denseBed2D${3}_restart "a run failed: $(fatal_of "$r")"
    fi
}
dense_bed B "" "" 0
# The still-bed settings of tutorials/mpsDem/multipleParticleSedimentation
# with the water exchange (src/mps/volume_exchange.c), which keeps sum phi
# to round-off only; the restart must repeat it too.
dense_bed stillBed "ppeDivergence superficial;\nporousWalls no;\nvolumeFractionRelaxation 0.005;\n" _stillBed 1e-12
c="$TMP/B"
# the same particles in a run without coupling: refused, with the reason
sed -i 's/^coupled .*/coupled no;/' "$c/system/couplingDict"
if (cd "$c" && "$MPSFLUID" > log.uncoupled 2>&1); then
    fail denseBed2D_uncoupled "mpsFluid ran a volumeFraction cloud without coupling"
else
    grep -q "volumeFraction.*needs a coupled run" "$c/log.uncoupled" \
        && pass "denseBed2D_uncoupled refused: $(grep -o "field 'volumeFraction'.*" "$c/log.uncoupled" | head -1 | cut -c1-60)" \
        || fail denseBed2D_uncoupled "no clear message: $(fatal_of "$c")"
fi
exit $((fails > 0))
