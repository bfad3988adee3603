#!/usr/bin/env bash
# vtu_paraview_check.sh — manual check that ParaView reads our .vtu/.pvd:
# writes the example case of test/cases/genParticles in binary and in ascii
# with bin/genParticles, opens every file with ParaView's readers under
# pvpython and compares the point count and the point-field names with
# bin/vtuInfo. Needs ParaView (apt-get install paraview; ~1.2 GiB, never
# installed by Alltest). Prints one PASS/FAIL line per file; exits 2 when
# pvpython is missing.
set -u
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
PV=$(command -v pvpython || true)
if [ -z "$PV" ]; then
    echo "SKIP vtu_paraview_check: pvpython not found (apt-get install paraview)"
    exit 2
fi
make -C "$ROOT" -s bin/genParticles bin/vtuInfo > /dev/null || exit 1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
nfail=0
for fmt in binary ascii; do
    cp -r "$ROOT/test/cases/genParticles" "$TMP/$fmt"
    sed -i "s/^writeFormat .*/writeFormat $fmt;/" "$TMP/$fmt/system/particleDict"
    "$ROOT/bin/genParticles" -case "$TMP/$fmt" > "$TMP/$fmt.log" 2>&1 || {
        echo "FAIL genParticles_$fmt"; nfail=$((nfail + 1)); continue; }
    for f in 0/fluid.vtu 0/dem.vtu fluid.pvd dem.pvd; do
        want_n=$("$ROOT/bin/vtuInfo" -case "$TMP/$fmt" "0/$(basename "${f%.pvd}" .vtu).vtu" |
                 awk '$1 == "points" { print $2 }')
        want_f=$("$ROOT/bin/vtuInfo" -case "$TMP/$fmt" "0/$(basename "${f%.pvd}" .vtu).vtu" |
                 awk '$1 == "field" { print $2 }' | sort | tr '\n' ' ')
        got=$(xvfb-run -a -s "-screen 0 640x480x24" "$PV" - 2> "$TMP/pv.err" <<PY || true
from paraview.simple import *
f = "$TMP/$fmt/$f"
r = PVDReader(FileName=f) if f.endswith(".pvd") else XMLUnstructuredGridReader(FileName=[f])
r.UpdatePipeline()
d = servermanager.Fetch(r)
pd = d.GetPointData()
names = sorted(pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays()))
print("RESULT", d.GetNumberOfPoints(), " ".join(names) + " ")
PY
)
        got=$(echo "$got" | sed -n 's/^RESULT //p')
        if [ "$got" = "$want_n $want_f" ]; then echo "PASS paraview_${fmt}_$f"
        else echo "FAIL paraview_${fmt}_$f: got '$got', want '$want_n $want_f' $(head -c 300 "$TMP/pv.err")"
             nfail=$((nfail + 1)); fi
    done
done
[ "$nfail" -eq 0 ]
