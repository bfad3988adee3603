#!/bin/bash
# demBadInput.sh — every bad input to demSolid stops with a clear message
# naming the file (and line) and exits non-zero without writing results;
# the start-up overlap check refuses or relaxes as asked; grains leaving
# the domain are counted and removed when asked.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
TUT="$ROOT/tutorials/demSolid/bouncingSphere"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
fails=0
T="$ROOT/bin/dictTool"
n=0

# case FILE [+]KEY=VALUE... : fresh copy with edits, particles generated;
# +KEY adds a key the tutorial does not have (dictTool -new)
fresh() {
    n=$((n + 1)); c="$WORK/c$n"
    cp -r "$TUT" "$c"
    "$T" "$c/system/controlDict" -set "endTime=0.0005" -set "deltaT=1e-5" >/dev/null
    local f="$1"; shift
    for kv in "$@"; do
        case "$kv" in
            +*) "$T" "$c/$f" -new -set "${kv#+}" >/dev/null ;;
            *)  "$T" "$c/$f" -set "$kv" >/dev/null ;;
        esac
    done
    (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1)
}

# expect_fail NAME PATTERN: demSolid must fail, print PATTERN, write nothing
expect_fail() {
    (cd "$c" && "$ROOT/bin/demSolid" > log.demSolid 2>&1); rc=$?
    local extra; extra=$(cd "$c" && ls -d [0-9]* 2>/dev/null | grep -vx 0)
    if [ $rc -ne 0 ] && grep -q "FATAL" "$c/log.demSolid" \
        && grep -qE -- "$2" "$c/log.demSolid" && [ -z "$extra" ]; then
        echo "PASS badInput $1: $(grep -m1 -E -- "$2" "$c/log.demSolid" | sed 's/^ *//')"
    else
        echo "FAIL badInput $1: exit $rc, pattern '$2' $(grep -qE -- "$2" "$c/log.demSolid" && echo found || echo missing), extra output '$extra'"
        fails=$((fails + 1))
    fi
}

fresh constant/demProperties "E=-1"
expect_fail youngsModulus "constant/demProperties:[0-9]+:[0-9]+: Young's modulus E = -1 must be > 0"
fresh constant/demProperties "nu=0.5"
expect_fail poisson "constant/demProperties:[0-9]+:[0-9]+: Poisson ratio nu = 0.5"
fresh constant/demProperties "e=1.5"
expect_fail restitution "constant/demProperties:[0-9]+:[0-9]+: restitution coefficient e = 1.5"
fresh constant/demProperties "e=0"
expect_fail restitutionZero "restitution coefficient e = 0 must be in \(0, 1\]"
fresh constant/demProperties "mu=-0.1"
expect_fail friction "constant/demProperties:[0-9]+:[0-9]+: friction coefficient mu = -0.1"
fresh constant/demProperties "contact/normal=herz"
expect_fail unknownNormal "unknown DEM normal contact 'herz'; valid: hertz linear"
fresh constant/demProperties "contact/rolling=constantTorque"
expect_fail rollingNeedsCoeffs "constant/demProperties.*rollingFriction"
fresh constant/demProperties "contact/tangentialStiffness=mindlen"
expect_fail unknownStiffness "unknown DEM tangential stiffness 'mindlen'.*valid: mindlin xie2025"
fresh constant/demProperties "contact/damping=tsuij"
expect_fail unknownDamping "unknown DEM contact damping 'tsuij'.*valid: restitution xie2025 tsuji restitutionConstant none"
fresh constant/demProperties "contact/twisting=viscous"
expect_fail twistingNeedsCoeffs "constant/demProperties.*twistingViscosity"
fresh system/demSolution "integrator=rk4"
expect_fail unknownIntegrator "unknown DEM integrator 'rk4'; valid: arkode verlet"
fresh system/demSolution "integrator=verlet" "+verletCoeffs/deltaT=1e-4"
expect_fail verletAboveBound "system/demSolution:[0-9]+:[0-9]+: deltaT 0.0001 s is above the stability bound 3.613.*e-05 s"
# the bound includes the sticking tangential spring (A0-21): 3.03e-6 s
fresh constant/demProperties "contact/normal=linear"
"$T" "$c/system/demSolution" -new -set "integrator=verlet" -set "verletCoeffs/deltaT=1e-5" >/dev/null
expect_fail linearAboveBound "deltaT 1e-05 s is above the stability bound 3\\.[0-9]+e-06 s .*linear law"
fresh system/demSolution "arkodeCoeffs/rtol=0"
expect_fail rtolZero "system/demSolution:[0-9]+:[0-9]+: rtol must be > 0"
fresh system/demSolution "arkodeCoeffs/table=RK4"
expect_fail unknownTable "unknown ERK table 'RK4'"
fresh system/particleDict
rm -f "$c/0/dem.vtu"
expect_fail missingGrains "0/dem.vtu"

# steps that do not advance time (issue 14 item 5)
fresh system/controlDict "deltaT=1e-300"
expect_fail tinyDeltaT "system/controlDict:[0-9]+:[0-9]+: deltaT = 1e-300 is too small for times up to 0.0005 s: t \+ deltaT == t"
fresh system/demSolution "integrator=verlet" "+verletCoeffs/deltaT=1e-300"
expect_fail tinyVerletDeltaT "system/demSolution:[0-9]+:[0-9]+: deltaT 1e-300 s is below 1e-06 of the stability bound"
fresh system/demSolution "integrator=verlet" "verletCoeffs/rayleighFraction=1e-300"
expect_fail tinyRayleighFraction "system/demSolution:[0-9]+:[0-9]+: rayleighFraction 1e-300 must be in \[1e-06, 1\]"

# a start state holding inf, and a stray grain at x = 1e300
fresh system/particleDict
sed -i '/Name="velocity"/{n;n;s/^[^ ]*/inf/}' "$c/0/dem.vtu"
expect_fail infVelocity "0/dem.vtu: point field 'velocity' holds inf at point 1 \(id 1\), component 0"
fresh system/particleDict
sed -i '/<Points>/{n;n;n;s/^[^ ]*/1e300/}' "$c/0/dem.vtu"
expect_fail strayGrain "0/dem.vtu: 1 contacts overlap .* e\.g\. grain id 1 at \(1e\+300 .*\) and wall [0-9]+ of patch tank"

# right bead 0.9 d from the left one: overlap 0.2 R > maxFraction 0.05
fresh system/particleDict "regions/right/min=(0.02108 0.00365 0.00865)" \
    "regions/right/max=(0.02378 0.00635 0.01135)"
expect_fail overlapRefused "1 contacts overlap by more than 0.05 of the smaller radius"
"$T" "$c/system/demSolution" -set "initialOverlap/action=relax" >/dev/null
if (cd "$c" && "$ROOT/bin/demSolid" > log.demSolid 2>&1) \
    && grep -q "Initial overlap: relaxed" "$c/log.demSolid"; then
    echo "PASS badInput overlapRelaxed: $(grep -m1 'relaxed' "$c/log.demSolid")"
else
    echo "FAIL badInput overlapRelaxed: run failed or did not relax"; fails=$((fails + 1))
fi

# a domain that the right bead is outside of: counted, and removed if asked
for remove in no yes; do
    fresh system/demSolution "+domain/min=(0 0 0)" "+domain/max=(0.021 0.01 0.02)" \
        "+domain/removeOutside=$remove"
    (cd "$c" && "$ROOT/bin/demSolid" > log.demSolid 2>&1)
    left=$(awk '/grains  /{print $2}' "$c/log.demSolid" | tail -1)
    want=3; [ $remove = yes ] && want=2
    if grep -q "1 grains outside the domain" "$c/log.demSolid" && [ "$left" = "$want" ]; then
        echo "PASS badInput domain removeOutside=$remove: warned, $left grains left"
    else
        echo "FAIL badInput domain removeOutside=$remove: $left grains left, want $want"
        fails=$((fails + 1))
    fi
done

# a misspelt key is warned about at its file:line
fresh system/demSolution "+arkodeCoeffs/rtoll=1e-5"
(cd "$c" && "$ROOT/bin/demSolid" > log.demSolid 2>&1)
if grep -qE "system/demSolution:[0-9]+:[0-9]+: keyword 'rtoll'.*not used" "$c/log.demSolid"; then
    echo "PASS badInput misspelt key: $(grep -m1 rtoll "$c/log.demSolid")"
else
    echo "FAIL badInput misspelt key: no warning for 'rtoll'"; fails=$((fails + 1))
fi
exit $((fails > 0))
