#!/usr/bin/env bash
# mpsDemSuspension3D.sh — a dilute 3-D suspension with the coupled defaults
# (issue 23): 486 Table-1 beads (d = 2.7 mm, cubic lattice of 4.8 mm, 9 %
# solids, jitter 0.1) in the upper part of a 0.048 x 0.048 m tank of still
# water 0.16 m deep, dp = 4 mm, Model B, every key of mpsSchemes,
# demSolution and couplingDict at its default, 200 steps of 2e-4 s:
#   suspension_run       both programs reach End, no fluid particle escapes
#                        (with the former defaults a 9 % suspension threw
#                        605 of 9360 particles out within seven steps)
#   suspension_settles   the grain cloud's top and bottom both sink by
#                        2-10 mm in 0.04 s (submerged free fall: 4.7 mm)
#   suspension_surface   the water surface stays within 1 cm of where it
#                        started (no splash, no expansion)
#   suspension_quiet     the pre-run check (couple_fluid.c) says nothing
#   suspension_warnings  with the paper's literal forms (grainVolume fill,
#                        ppeDivergence intrinsic) it warns before the first
#                        step, naming grainVolume and couplingDict's
#                        ppeDivergence with its line
NAME=mpsDemSuspension3D
. "$(dirname "$0")/lib/tandem.sh"

# suspension DIR: the case, with the water region's extra keys in $2
suspension()
{
    local c="$1" H='FoamFile { version 2.0; format ascii; class dictionary; object X; }' f
    mkdir -p "$c/system" "$c/constant" "$c/0"
    for f in mpsSchemes mpsSolution demSolution couplingDict controlDict particleDict; do
        echo "${H/X/$f}" > "$c/system/$f"
    done
    cp "$ROOT"/constant/{demProperties,transportProperties,g} "$c/constant/"
    echo 'PPE { solver bicgstab; preconditioner amg; tolerance 1e-8; }' >> "$c/system/mpsSolution"
    printf 'model B;\ntimeout 30;\nchannel mpsdem-susp3d-%s-%s;\n' "${c##*/}" "$$" >> "$c/system/couplingDict"
    cat >> "$c/system/controlDict" <<'EOD'
startFrom startTime; startTime 0; endTime 0.04; deltaT 2e-4; adjustTimeStep no;
writeControl runTime; writeInterval 0.04; writeFormat binary;
functions
{
    grains { type cloudInfo; cloud dem; writeControl timeStep; writeInterval 25; }
    fluid  { type cloudInfo; cloud fluid; writeControl timeStep; writeInterval 25; }
}
EOD
    cat >> "$c/system/particleDict" <<EOD
dimension 3; dp 0.004; kernelRadius 3.1; wallLayers auto;
regions
(
    tank  { type tankWall; shape box; min (0 0 0); max (0.048 0.048 0.2); open (zmax); }
    water { type fluid; shape box; min (0 0 0); max (0.048 0.048 0.16);
            hydrostaticPressure yes; $2 }
    beads { type grains; shape box; min (0.0024 0.0024 0.1); max (0.0456 0.0456 0.13);
            diameter 0.0027; lattice cubic; spacing 0.0048; jitter 0.1; }
);
EOD
    (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1)
}

c="$TMP/defaults"
if ! suspension "$c" ""; then
    fail suspension_run "genParticles failed: $(tail -n 3 "$c/log.genParticles" | tr '\n' ' ')"; exit 1
fi
run_tandem "$c" 300; ok=$?
esc=$(grep -o 'escaped [0-9]*' "$c/log.mpsFluid" | awk '{ print $2 }' | sort -n | tail -1)
if [ $ok -eq 0 ] && [ "$esc" = 0 ]; then
    pass suspension_run
else
    fail suspension_run "exit $rf/$rd, escaped up to $esc: $(fatal_of "$c")"; exit 1
fi
# cloudInfo rows: time n xmin ymin zmin xmax ymax zmax (first and last)
read -r b0 t0 b1 t1 <<< "$(awk '!/^#/ { if (!n++) { b0 = $5; t0 = $8 } b1 = $5; t1 = $8 }
    END { print b0, t0, b1, t1 }' "$c/postProcessing/grains/0/cloudInfo.dat")"
awk -v b0="$b0" -v t0="$t0" -v b1="$b1" -v t1="$t1" 'BEGIN {
        db = b0 - b1; dt = t0 - t1; exit !(db >= 0.002 && db <= 0.01 && dt >= 0.002 && dt <= 0.01) }' \
    && pass "suspension_settles bottom $b0 -> $b1 m, top $t0 -> $t1 m" \
    || fail suspension_settles "bottom $b0 -> $b1 m, top $t0 -> $t1 m (each must sink 2-10 mm)"
read -r s0 s1 <<< "$(awk '!/^#/ { if (!n++) s0 = $NF; s1 = $NF } END { print s0, s1 }' \
    "$c/postProcessing/fluid/0/cloudInfo.dat")"
awk -v a="$s0" -v b="$s1" 'BEGIN { d = b - a; exit !(d < 0.01 && d > -0.01) }' \
    && pass "suspension_surface top fluid particle $s0 -> $s1 m" \
    || fail suspension_surface "top fluid particle $s0 -> $s1 m (within 1 cm)"
grep -q 'WARNING' "$c/log.mpsFluid" \
    && fail suspension_quiet "$(grep -m1 -A1 WARNING "$c/log.mpsFluid" | tr '\n' ' ' | cut -c1-200)" \
    || pass suspension_quiet

c="$TMP/paper"
if suspension "$c" "grainVolume fill;"; then
    echo 'ppeDivergence intrinsic;' >> "$c/system/couplingDict"
    sed -i 's/endTime 0.04;/endTime 0.001;/' "$c/system/controlDict"
    run_tandem "$c" 120
    w=$(grep -A1 'WARNING' "$c/log.mpsFluid" | tr '\n' ' ')
    if [[ "$w" == *"grainVolume scale"*"system/particleDict"* ]] \
       && [[ "$w" == *"system/couplingDict:"[0-9]*"ppeDivergence intrinsic"* ]]; then
        pass suspension_warnings
    else
        fail suspension_warnings "no warning naming grainVolume and ppeDivergence: ${w:0:300}"
    fi
else
    fail suspension_warnings "genParticles failed"
fi
exit $((fails > 0))
