# tandem.sh — sourced by the coupled case tests (test/cases/mpsDem*.sh):
# lib/case.sh (root, scratch directory, PASS/FAIL), the programs, and one
# tandem run of mpsFluid and demSolid.
#
#   NAME=mpsDemSettling; . "$(dirname "$0")/lib/tandem.sh"
#
# MPSFLUID / DEMSOLID override the programs (default bin/).
. "$(dirname "${BASH_SOURCE[0]}")/case.sh"
MPSFLUID=${MPSFLUID:-$ROOT/bin/mpsFluid}
DEMSOLID=${DEMSOLID:-$ROOT/bin/demSolid}
for p in "$MPSFLUID" "$DEMSOLID" "$ROOT/bin/genParticles"; do
    [ -x "$p" ] || { fail "$NAME" "$p not built"; exit 1; }
done

# run_tandem DIR [SECONDS [SUFFIX]]: mpsFluid and demSolid side by side in
# DIR, logging to log.<program>[.SUFFIX]; sets rf and rd (their exit
# statuses); succeeds when both exit 0 and print End.
run_tandem()
{
    local c="$1" limit="${2:-200}" sfx="${3:+.$3}"
    (cd "$c" && timeout "$limit" "$MPSFLUID" > "log.mpsFluid$sfx" 2>&1) &
    local pf=$!
    (cd "$c" && timeout "$limit" "$DEMSOLID" > "log.demSolid$sfx" 2>&1)
    rd=$?
    wait $pf
    rf=$?
    [ $rf -eq 0 ] && [ $rd -eq 0 ] && grep -q '^End' "$c/log.mpsFluid$sfx" \
        && grep -q '^End' "$c/log.demSolid$sfx"
}

# fatal_of DIR: the first FATAL ERROR lines of the logs in DIR, one line.
fatal_of() { grep -h -A2 FATAL "$1"/log.* 2>/dev/null | head -4 | tr '\n' ' '; }

# case_2d DIR [FILE...] < REGIONS: a 2-D coupled case in DIR built from the
# root case's coupling, MPS and DEM dictionaries (plus the FILEs, copied to
# system/), gravity along -y, and a particleDict with dp = 5 mm whose
# regions list is read from standard input.
case_2d()
{
    local c="$1"; shift
    mkdir -p "$c/system" "$c/constant" "$c/0"
    cp "$ROOT"/system/{couplingDict,mpsSchemes,mpsSolution,demSolution} "$@" "$c/system/"
    cp "$ROOT"/constant/{demProperties,transportProperties} "$c/constant/"
    cp "$ROOT/tutorials/mpsFluid/damBreak2D/constant/g" "$c/constant/"
    { printf '%s\n' "FoamFile { version 2.0; format ascii; class dictionary; object particleDict; }" \
          "dimension    2;" "dp           0.005;" "kernelRadius 3.1;" "wallLayers   auto;"
      cat; } > "$c/system/particleDict"
}

# case_dam_break_2d DIR: case_2d with the quick 2-D two-phase dam break
# (the root case's set-up in 2-D): a 0.2 x 0.15 m tank, a water column
# 0.05 x 0.1 m with 21 loosely packed 5 mm beads at its bottom, the root
# case's controlDict.
case_dam_break_2d()
{
    case_2d "$1" "$ROOT/system/controlDict" <<'EOD'
regions
(
    tank   { type tankWall; shape box; min (0 0 0); max (0.2 0.15 0); open (ymax); }
    column { type fluid; shape box; min (0 0 0); max (0.05 0.1 0); hydrostaticPressure yes; }
    beads  { type grains; shape box; min (0.0025 0.0005 0); max (0.0475 0.0205 0);
             diameter 0.005; lattice cubic; spacing 0.0065; }
);
EOD
}

# case_beads_2d DIR: case_2d with the quick 2-D sedimentation set-up: a
# 0.05 x 0.15 m tank, water to 0.1 m, 15 beads of 5 mm on a 1 cm lattice
# above its floor (no controlDict: the test writes its own).
case_beads_2d()
{
    case_2d "$1" <<'EOD'
regions
(
    tank   { type tankWall; shape box; min (0 0 0); max (0.05 0.15 0); open (ymax); }
    water  { type fluid; shape box; min (0 0 0); max (0.05 0.1 0); hydrostaticPressure yes; }
    beads  { type grains; shape box; min (0.0025 0.0105 0); max (0.0475 0.0405 0);
             diameter 0.005; lattice cubic; spacing 0.01; }
);
EOD
}
