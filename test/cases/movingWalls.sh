#!/usr/bin/env bash
# movingWalls.sh — walls that move or are removed during a run (motion and
# removeAt of a wall region in system/particleDict, read by genParticles,
# demSolid and mpsFluid):
#   demLift_*      a bead resting on a floor that rises at 0.1 m/s from
#                  t = 0.05 s rides on it: v_z within 1 % of 0.1 m/s and
#                  a constant floor gap from 0.07 to 0.15 s (arkode and
#                  verlet; measured v_z = 0.1 to 1e-12)
#   demRemove_*    a column of 40 beads held by a gate removed at 0.05 s:
#                  no bead beyond the gate face before 0.05 s, none in
#                  contact with the gate in demContacts from 0.05 s, the
#                  leading bead past the gate's far face by 0.1 s
#   demRestart     the lifted bead restarted at 0.1 s (startFrom
#                  latestTime) ends where the continuous run does
#   mpsGateRemoved damBreak2D with a gate removed at t = 0: the surge front
#                  is the dam break's to the bit (front.dat identical)
#   mpsGateLift_*  damBreak2D with the gate lifted at 0.5 m/s: the gate's
#                  lowest particle at y0 + 0.5 t (1e-12 m) in every output,
#                  its velocity 0.5 m/s, no fluid inside the gate, water
#                  past the gate only once the gap opened
#   mpsGateTable   the same lift from a motion table: gate where the
#                  translation puts it
#   mpsRestart     the lifted gate restarted at 0.05 s: gate and front at
#                  0.1 s as in the continuous run
#   coupledGate    mpsFluid + demSolid in tandem, beads and water behind
#                  a gate lifted at 0.5 m/s: both reach End, the gate
#                  particles follow the lift, beads pass the gate
#   bad_*          bad motion input: file:line message, exit 1, nothing
#                  written (genParticles; demSolid and mpsFluid when the
#                  dictionary is spoilt after generation)
NAME=movingWalls
. "$(dirname "$0")/lib/tandem.sh"
BIN="$ROOT/bin"
for p in "$BIN/vtuInfo" "$BIN/dictTool"; do
    [ -x "$p" ] || { fail "$NAME" "$p not built"; exit 1; }
done
# points of a .vtu as a table (the columns of vtuInfo -dump)
dump() { "$BIN/vtuInfo" -dump "$1" | awk '$1 ~ /^-?[0-9]/'; }

# ---- DEM: bead on a rising floor ---------------------------------------------
dem_case() {   # DIR: a DEM case from bouncingSphere, gravity on, e = 0.3
    local c="$1"
    mkdir -p "$c"
    cp -r "$ROOT/tutorials/demSolid/bouncingSphere/constant" \
          "$ROOT/tutorials/demSolid/bouncingSphere/system" "$c/"
    sed -i 's/^e  .*/e       0.3;/' "$c/constant/demProperties"
    sed -i 's/value .*/value (0 0 -9.81);/' "$c/constant/g"
}
lift_dict() {
    cat > "$1/system/particleDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object particleDict; }
dimension 3; dp 0.0027; wallLayers 1; writeFormat ascii;
regions
(
    tank  { type tankWall; shape box; min (0 0 0); max (0.02 0.02 0.1);
            open (zmin zmax); }
    floor { type wall; shape plane; point (0 0 0.002); normal (0 0 1);
            motion { type translation; velocity (0 0 0.1); start 0.05; } }
    bead  { type grains; shape box; min (0.00865 0.00865 0.0025);
            max (0.01135 0.01135 0.0052); diameter 0.0027; }
);
EOF
    cat > "$1/system/controlDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application demSolid;
startFrom startTime; startTime 0; endTime 0.15; deltaT 1e-4;
writeControl adjustableRunTime; writeInterval 0.05; writeFormat ascii;
timePrecision 6;
functions
{
    bead { type grainState; ids (0); writeControl timeStep; writeInterval 1; }
}
EOF
}
# check_lift DIR NAME: v_z and the gap z - z_floor(t) over [0.07, 0.15]
check_lift() {
    local r
    r=$(awk '!/^#/ && $1 >= 0.07 - 1e-9 {
            zf = 0.002 + 0.1 * ($1 - 0.05); gap = $4 - zf
            dv = $7 / 0.1 - 1; if (dv < 0) dv = -dv; if (dv > e) e = dv
            if (!n++) { g0 = gap } d = gap - g0; if (d < 0) d = -d
            if (d > dg) dg = d }
            END { printf "%d %.3g %.3g", n, e, dg }' "$1/postProcessing/bead/0/grainState.dat")
    set -- $r
    if [ "${1:-0}" -gt 100 ] && awk -v e="$2" -v g="$3" 'BEGIN { exit !(e < 0.01 && g < 1e-7) }'; then
        pass "$NAME_ (rows $1, |v_z/0.1 - 1| <= $2, gap drift $3 m)"
    else
        fail "$NAME_" "rows ${1:-0}, |v_z/0.1 - 1| max ${2:-?}, gap drift ${3:-?} m"
    fi
}
for integ in arkode verlet; do
    c="$TMP/lift_$integ"
    dem_case "$c"; lift_dict "$c"
    sed -i "s/^integrator .*/integrator $integ;/" "$c/system/demSolution"
    NAME_=demLift_$integ
    if (cd "$c" && "$BIN/genParticles" > log.genParticles 2>&1 \
        && "$BIN/demSolid" > log.demSolid 2>&1); then
        check_lift "$c"
    else
        fail "$NAME_" "$(fatal_of "$c")"
    fi
done

# restart at 0.1 s: the floor must be where the continuous run has it
c="$TMP/lift_restart"
dem_case "$c"; lift_dict "$c"
"$BIN/dictTool" "$c/system/controlDict" -set endTime=0.1 > /dev/null
if (cd "$c" && "$BIN/genParticles" > log.genParticles 2>&1 \
    && "$BIN/demSolid" > log.demSolid.1 2>&1) \
    && "$BIN/dictTool" "$c/system/controlDict" -set endTime=0.15 -set startFrom=latestTime > /dev/null \
    && (cd "$c" && "$BIN/demSolid" > log.demSolid.2 2>&1); then
    a=$(dump "$TMP/lift_arkode/0.15/dem.vtu" | awk '{ print $3, $7 }')
    b=$(dump "$c/0.15/dem.vtu" | awk '{ print $3, $7 }')
    if awk -v a="$a" -v b="$b" 'BEGIN { split(a, x, " "); split(b, y, " ");
            d = x[1] - y[1]; if (d < 0) d = -d; exit !(d < 1e-9 && y[2] > 0.099) }'; then
        pass "demRestart (z, v_z at 0.15 s: continuous $a, restarted $b)"
    else
        fail demRestart "z, v_z at 0.15 s: continuous '$a', restarted '$b'"
    fi
else
    fail demRestart "$(fatal_of "$c")"
fi

# ---- DEM: a column held by a gate that is removed ------------------------------
c="$TMP/remove"
dem_case "$c"
cat > "$c/system/particleDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object particleDict; }
dimension 3; dp 0.0027; wallLayers 1; writeFormat ascii;
regions
(
    tank  { type tankWall; shape box; min (0 0 0); max (0.08 0.0031 0.04);
            open (zmax); }
    gate  { type wall; shape box; min (0.0136 0 0); max (0.0163 0.0031 0.04);
            removeAt 0.05; }
    beads { type grains; shape box; min (0 0 0); max (0.0135 0.0031 0.03);
            diameter 0.0027; spacing 0.003; jitter 0.05; }
);
EOF
cat > "$c/system/controlDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application demSolid;
startFrom startTime; startTime 0; endTime 0.1; deltaT 1e-3;
writeControl adjustableRunTime; writeInterval 0.01; writeFormat ascii;
timePrecision 6;
EOF
lead() { dump "$1" | awk '{ v = $1 + $4; if (!n++ || v > m) m = v } END { printf "%.7g", m }'; }
if (cd "$c" && "$BIN/genParticles" > log.genParticles 2>&1 \
    && "$BIN/demSolid" > log.demSolid 2>&1); then
    before="" ok=1
    for t in 0.02 0.03 0.04; do
        x=$(lead "$c/$t/dem.vtu"); before="$before $x"
        awk -v x="$x" 'BEGIN { exit !(x <= 0.0136 + 2e-5) }' || ok=0
    done
    [ $ok = 1 ] && pass "demRemove_held (leading edge at 0.02 0.03 0.04 s:$before m, gate face 0.0136)" \
                || fail demRemove_held "leading edge$before m beyond the gate face 0.0136 before removeAt"
    # wall index of the gate: 5 tank faces (zmax open) come first -> -(5+1)
    n=$(cat "$c"/0.05/demContacts "$c"/0.06/demContacts | awk '$2 == -6' | wc -l)
    [ "$n" -eq 0 ] && pass "demRemove_histories (no gate contact from 0.05 s)" \
                   || fail demRemove_histories "$n gate contacts after removeAt"
    x=$(lead "$c/0.1/dem.vtu")
    awk -v x="$x" 'BEGIN { exit !(x > 0.0163 + 0.0027) }' \
        && pass "demRemove_flow (leading edge at 0.1 s: $x m, gate's far face 0.0163)" \
        || fail demRemove_flow "leading edge at 0.1 s $x m: the column did not flow"
else
    fail demRemove "$(fatal_of "$c")"
fi

# ---- MPS: dam break with a gate -------------------------------------------------
TUT="$ROOT/tutorials/mpsFluid/damBreak2D"
# gate_case DIR MOTION-TEXT: damBreak2D to 0.1 s with a gate 4 dp thick at
# the column's face
gate_case() {
    local c="$1" mo="$2"
    cp -r "$TUT" "$c"
    sed -i 's/^endTime .*/endTime 0.1;/' "$c/system/controlDict"
    awk -v mo="$mo" '/^\);/ { print "    gate\n    {\n        type wall; shape box;\n        min (0.05715 0 0); max (0.08001 0.17145 0);\n        " mo "\n    }" } { print }' \
        "$TUT/system/particleDict" > "$c/system/particleDict"
}
run_mps() { (cd "$1" && "$BIN/genParticles" > log.genParticles 2>&1 && "$BIN/mpsFluid" > log.mpsFluid 2>&1) \
            && grep -q '^End' "$1/log.mpsFluid"; }
# gate_check DIR TIMES: per time "t err vy inside beyond" — err = lowest gate
# particle - (dp/2 + 0.5 t), fluid inside the gate, fluid past its far face
gate_check() {
    local c="$1"; shift
    for t in "$@"; do
        dump "$c/$t/fluid.vtu" | awk -v t="$t" '
            $5 == 2 { if (!n++ || $2 < m) m = $2; vy = $7 }
            $4 == 0 { fx[++nf] = $1; fy[nf] = $2 }
            END { for (i = 1; i <= nf; i++) {
                      if (fx[i] > 0.05715 && fx[i] < 0.08001 && fy[i] > m - 0.0028575) in_++
                      if (fx[i] > 0.08001) past++ }
                  printf "%s %.3g %s %d %d\n", t, m - (0.0028575 + 0.5 * t), vy, in_, past }'
    done
}

ref="$TMP/damBreak" rem="$TMP/gateRemoved"
cp -r "$TUT" "$ref"; sed -i 's/^endTime .*/endTime 0.1;/' "$ref/system/controlDict"
gate_case "$rem" "removeAt 0;"
if run_mps "$ref" && run_mps "$rem"; then
    if cmp -s "$ref/postProcessing/surge/0/front.dat" "$rem/postProcessing/surge/0/front.dat" \
       && grep -q "120 wall/dummy particle(s) of removed patches deleted" "$rem/log.mpsFluid"; then
        pass "mpsGateRemoved (front.dat identical to damBreak2D's, front at 0.1 s $(tail -1 "$rem/postProcessing/surge/0/front.dat" | awk '{ print $2 }') m)"
    else
        fail mpsGateRemoved "front differs from the dam break's or the gate was not deleted"
    fi
else
    fail mpsGateRemoved "$(fatal_of "$rem") $(fatal_of "$ref")"
fi

lift="$TMP/gateLift"
gate_case "$lift" "motion { type translation; velocity (0 0.5 0); }"
if run_mps "$lift"; then
    out=$(gate_check "$lift" 0.02 0.04 0.06 0.08 0.1)
    echo "$out" | awk '{ e = $2 < 0 ? -$2 : $2; if (e > 1e-12 || $3 != 0.5) bad = 1 } END { exit bad }' \
        && pass "mpsGateLift_position (lowest gate particle - (y0 + 0.5 t) at 0.02..0.1 s: $(echo "$out" | awk '{ printf "%s ", $2 }')m)" \
        || fail mpsGateLift_position "$(echo "$out" | tr '\n' ';')"
    echo "$out" | awk '{ n += $4 } END { exit n > 0 }' \
        && pass "mpsGateLift_tight (no fluid particle inside the gate)" \
        || fail mpsGateLift_tight "fluid inside the gate: $(echo "$out" | awk '{ printf "%s ", $4 }')"
    echo "$out" | awk '$1 == 0.02 && $5 > 0 { bad = 1 } $1 == 0.1 && $5 < 10 { bad = 1 } END { exit bad }' \
        && pass "mpsGateLift_flow (fluid particles past the gate at 0.02..0.1 s: $(echo "$out" | awk '{ printf "%s ", $5 }'))" \
        || fail mpsGateLift_flow "fluid past the gate at 0.02..0.1 s: $(echo "$out" | awk '{ printf "%s ", $5 }')"
else
    fail mpsGateLift "$(fatal_of "$lift")"
fi

tab="$TMP/gateTable"
gate_case "$tab" 'motion { type table; file "gateMotion.csv"; }'
sed -i 's/^endTime .*/endTime 0.04;/' "$tab/system/controlDict"
printf '%s\n' "t,x,y,z" "0,0,0,0" "1,0,0.5,0" > "$tab/gateMotion.csv"
if run_mps "$tab"; then
    out=$(gate_check "$tab" 0.02 0.04)
    echo "$out" | awk '{ e = $2 < 0 ? -$2 : $2; if (e > 1e-12) bad = 1 } END { exit bad }' \
        && pass "mpsGateTable (gate at y0 + 0.5 t to $(echo "$out" | awk '{ printf "%s ", $2 }')m)" \
        || fail mpsGateTable "$(echo "$out" | tr '\n' ';')"
else
    fail mpsGateTable "$(fatal_of "$tab")"
fi

rs="$TMP/gateRestart"
gate_case "$rs" "motion { type translation; velocity (0 0.5 0); }"
sed -i 's/^endTime .*/endTime 0.06;/' "$rs/system/controlDict"
if run_mps "$rs" && "$BIN/dictTool" "$rs/system/controlDict" -set endTime=0.1 -set startFrom=latestTime > /dev/null \
   && (cd "$rs" && "$BIN/mpsFluid" > log.mpsFluid.2 2>&1); then
    a=$(gate_check "$lift" 0.1) b=$(gate_check "$rs" 0.1)
    fa=$(tail -1 "$lift/postProcessing/surge/0/front.dat" | awk '{ print $2 }')
    fb=$(tail -1 "$rs/postProcessing/surge/0.06/front.dat" 2>/dev/null | awk '{ print $2 }')
    if [ "$(echo "$a" | cut -d' ' -f2-4)" = "$(echo "$b" | cut -d' ' -f2-4)" ] \
       && awk -v a="$fa" -v b="$fb" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(b != "" && d < 0.003) }'; then
        pass "mpsRestart (restarted at 0.06 s: gate error $(echo "$b" | cut -d' ' -f2) m, front $fb m vs $fa m)"
    else
        fail mpsRestart "continuous '$a' front $fa, restarted '$b' front $fb"
    fi
else
    fail mpsRestart "$(fatal_of "$rs")"
fi

# ---- coupled: beads and water behind a lifted gate ----------------------------
cg="$TMP/coupled"
case_2d "$cg" "$ROOT/system/controlDict" <<'EOD'
regions
(
    tank   { type tankWall; shape box; min (0 0 0); max (0.2 0.15 0); open (ymax); }
    column { type fluid; shape box; min (0 0 0); max (0.05 0.1 0); hydrostaticPressure yes; }
    beads  { type grains; shape box; min (0.0025 0.0005 0); max (0.0475 0.0205 0);
             diameter 0.005; lattice cubic; spacing 0.0065; }
    gate   { type wall; shape box; min (0.05 0 0); max (0.07 0.15 0);
             motion { type translation; velocity (0 0.5 0); } }
);
EOD
sed -i 's/^endTime .*/endTime 0.15;/; s/^writeFormat .*/writeFormat ascii;/' "$cg/system/controlDict"
sed -i "s/^timeout .*/timeout 30;/" "$cg/system/couplingDict"
echo "channel mpsdem-gate-$$;" >> "$cg/system/couplingDict"
if (cd "$cg" && "$BIN/genParticles" > log.genParticles 2>&1) && run_tandem "$cg"; then
    last=$(cd "$cg" && ls -d 0.* | sort -g | tail -1)
    gy=$(dump "$cg/$last/fluid.vtu" | awk '$5 == 3 { if (!n++ || $2 < m) m = $2 } END { printf "%.12g", m }')
    bx=$(dump "$cg/$last/dem.vtu" | awk '{ if (!n++ || $1 > m) m = $1 } END { print m }')
    b0=$(dump "$cg/0/dem.vtu" | awk '{ if (!n++ || $1 > m) m = $1 } END { print m }')
    # beads overlapping the DEM gate's x range must lie below its bottom
    # face 0.5 t (to 10 % of a radius of overlap)
    pen=0
    for t in 0.05 0.1 0.15; do
        k=$(dump "$cg/$t/dem.vtu" | awk -v t=$t '$1 + $4 > 0.05 && $1 - $4 < 0.07 && $2 + 0.9 * $4 > 0.5 * t { k++ } END { print k + 0 }')
        pen=$((pen + k))
    done
    if [ -n "$b0" ] && awk -v g="$gy" -v t="$last" -v b="$bx" -v b0="$b0" -v p=$pen 'BEGIN { e = g - (0.0025 + 0.5 * t); if (e < 0) e = -e
            exit !(e < 1e-12 && b > 0.07 && b0 < 0.05 && p == 0) }'; then
        pass "coupledGate (t = $last s: lowest gate particle $gy m = y0 + 0.5 t; no bead in the DEM gate; leading bead $b0 m at 0, $bx m at $last s)"
    else
        fail coupledGate "t = $last: gate $gy m (want $(awk -v t=$last 'BEGIN { print 0.0025 + 0.5 * t }')), beads in the gate $pen, leading bead $b0 -> $bx m"
    fi
else
    fail coupledGate "exit $rf/$rd: $(fatal_of "$cg")"
fi

# ---- bad input ----------------------------------------------------------------
# bad NAME PATTERN REGION-TEXT [PROGRAM]: a DEM lift case whose floor gets
# REGION-TEXT instead of its motion; genParticles (or, after a good
# generation, PROGRAM) must fail with PATTERN at file:line and write nothing
bad() {
    local name=$1 pat=$2 text=$3 prog=${4:-genParticles}
    local c="$TMP/bad_$name"
    dem_case "$c"; lift_dict "$c"
    printf '%s\n' "0.1 0 0 0" "0.05 0 0 1e-3" > "$c/nonMonotone.csv"
    printf '%s\n' "0 0 0" "1 0 0 0.1" > "$c/threeColumns.csv"
    local spoil="s|motion { type translation; velocity (0 0 0.1); start 0.05; }|$text|"
    if [ "$prog" = genParticles ]; then
        sed -i "$spoil" "$c/system/particleDict"
    else
        (cd "$c" && "$BIN/genParticles" > log.genParticles 2>&1) || { fail "bad_$name" "genParticles"; return; }
        sed -i "$spoil" "$c/system/particleDict"
    fi
    (cd "$c" && "$BIN/$prog" > log.bad 2>&1); local rc=$?
    local extra
    if [ "$prog" = genParticles ]; then
        extra=$(cd "$c" && ls -d 0 constant/particlePatches 2>/dev/null)
    else
        extra=$(cd "$c" && ls -d [0-9]* 2>/dev/null | grep -vx 0)
    fi
    if [ $rc -ne 0 ] && grep -qE -- "system/particleDict:[0-9]+:[0-9]+: .*$pat" "$c/log.bad" && [ -z "$extra" ]; then
        pass "bad_$name: $(grep -m1 -E -- "$pat" "$c/log.bad" | sed 's/^ *//')"
    else
        fail "bad_$name" "exit $rc, extra output '$extra': $(grep -A2 FATAL "$c/log.bad" | tr '\n' ' ')"
    fi
}
bad unknownType "unknown wall motion 'translaton'; valid: none translation table oscillation \(did you mean 'translation'\?\)" \
    "motion { type translaton; velocity (0 0 0.1); }"
bad noVelocity "missing.*'velocity'" "motion { type translation; }"
bad noTable "cannot open the motion table 'nofile.csv'" 'motion { type table; file \"nofile.csv\"; }'
bad nonMonotone "nonMonotone.csv:2: time 0.05 s does not follow 0.1 s" 'motion { type table; file \"nonMonotone.csv\"; }'
bad columns "threeColumns.csv:1: expected 4 numbers per row \(t x y z\), found fewer" 'motion { type table; file \"threeColumns.csv\"; }'
bad removeNegative "removeAt -1 s must be a time >= 0" "removeAt -1;"
bad startNegative "displacement must be 0 there|start -0.1 s must be a time >= 0" \
    "motion { type translation; velocity (0 0 0.1); start -0.1; }"
bad endBeforeStart "end 0.01 s must come after start 0.05 s" \
    "motion { type translation; velocity (0 0 0.1); start 0.05; end 0.01; }"
# motion on a grains region: move the motion text into the bead's region
c="$TMP/bad_grainsMotion"
dem_case "$c"; lift_dict "$c"
sed -i 's|diameter 0.0027; }|diameter 0.0027; removeAt 0.1; }|' "$c/system/particleDict"
(cd "$c" && "$BIN/genParticles" > log.bad 2>&1); rc=$?
if [ $rc -ne 0 ] && grep -qE "system/particleDict:[0-9]+:[0-9]+: 'removeAt' applies to wall and tankWall regions only" "$c/log.bad" \
   && [ ! -e "$c/0" ]; then
    pass "bad_grainsMotion: $(grep -m1 "applies to" "$c/log.bad" | sed 's/^ *//')"
else
    fail bad_grainsMotion "exit $rc: $(grep -A2 FATAL "$c/log.bad" | tr '\n' ' ')"
fi
bad demSolidUnknown "unknown wall motion 'lift'" "motion { type lift; }" demSolid
bad demSolidRemove "removeAt -0.5 s must be a time >= 0" "removeAt -0.5;" demSolid
# mpsFluid reads the same regions: spoil the lifted gate after generation
c="$TMP/bad_mpsFluid"
gate_case "$c" "motion { type translation; velocity (0 0.5 0); }"
(cd "$c" && "$BIN/genParticles" > log.genParticles 2>&1)
sed -i 's/velocity (0 0.5 0); }/velocity (0 0.5 0); start 0.2; end 0.1; }/' "$c/system/particleDict"
(cd "$c" && "$BIN/mpsFluid" > log.bad 2>&1); rc=$?
extra=$(cd "$c" && ls -d [0-9]* 2>/dev/null | grep -vx 0)
if [ $rc -ne 0 ] && grep -qE "system/particleDict:[0-9]+:[0-9]+: end 0.1 s must come after start 0.2 s" "$c/log.bad" && [ -z "$extra" ]; then
    pass "bad_mpsFluid: $(grep -m1 "must come after" "$c/log.bad" | sed 's/^ *//')"
else
    fail bad_mpsFluid "exit $rc, extra '$extra': $(grep -A2 FATAL "$c/log.bad" | tr '\n' ' ')"
fi

exit $((fails > 0))
