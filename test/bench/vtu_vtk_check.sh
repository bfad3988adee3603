#!/usr/bin/env bash
# vtu_vtk_check.sh — manual check that VTK's own XML reader
# (vtkXMLUnstructuredGridReader, python3-vtk9: apt-get install
# python3-vtk9, ~230 MB, not in installDependencies) reads our files with
# the same numbers: clouds of 1, 2, 3 and 4 grains and 1..3 fluid particles
# (every base64 padding) and the example case, in binary and ascii; every
# coordinate and field value is compared with bin/vtuInfo -dump, exactly.
# One PASS/FAIL line per file; exits 2 when VTK is missing.
set -u
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
PY=/usr/bin/python3
if ! $PY -c 'import vtkmodules.vtkIOXML' 2> /dev/null; then
    echo "SKIP vtu_vtk_check: python3-vtk9 not installed"
    exit 2
fi
make -C "$ROOT" -s bin/genParticles bin/vtuInfo > /dev/null || exit 1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
nfail=0
check() {  # case-dir file
    local f=$1/$2 name
    name=$(basename "$1")_$(basename "$2" .vtu)
    "$ROOT/bin/vtuInfo" -dump "$f" | sed -n '/^# x y z/,$p' | grep -v -e '^End' -e '^ *$' > "$TMP/want"
    $PY - "$f" > "$TMP/got" 2> "$TMP/err" <<'PY'
import sys
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
r = vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); r.Update()
d = r.GetOutput(); pd = d.GetPointData()
arrays = [pd.GetArray(i) for i in range(pd.GetNumberOfArrays())]
head = ["# x y z"]
for a in arrays:
    k = a.GetNumberOfComponents()
    head += [a.GetName()] if k == 1 else ["%s_%d" % (a.GetName(), j) for j in range(k)]
print(" ".join(head))
def fmt(v):
    return "%.17g" % v
for i in range(d.GetNumberOfPoints()):
    row = [fmt(x) for x in d.GetPoint(i)]
    for a in arrays:
        row += [fmt(a.GetComponent(i, j)) for j in range(a.GetNumberOfComponents())]
    print(" ".join(row))
cells = d.GetNumberOfCells()
if cells != d.GetNumberOfPoints() or r.GetErrorCode():
    print("cells", cells, "error", r.GetErrorCode())
PY
    if cmp -s "$TMP/want" "$TMP/got"; then echo "PASS vtk_$name"
    else echo "FAIL vtk_$name: $(diff "$TMP/want" "$TMP/got" | head -3 | tr '\n' ' ') $(head -c 200 "$TMP/err")"
         nfail=$((nfail + 1)); fi
}
for fmt in binary ascii; do
    for n in 1 2 3 4; do
        c=$TMP/${fmt}_$n
        cp -r "$ROOT/test/cases/genParticles" "$c"
        cat > "$c/system/particleDict" <<DICT
dimension 2; dp 0.1; wallLayers 1; writeFormat $fmt;
regions ( w { shape box; min (0 0 0); max ($(( n < 4 ? n : 3 ))e-1 1e-1 0); type fluid; velocity (1e-310 -0 0); }
          g { shape box; min (0 0 0); max (${n}e-2 1e-2 0); type grains; diameter 0.01; omega (0 0 3.3e300); } );
DICT
        "$ROOT/bin/genParticles" -case "$c" > "$c.log" 2>&1 || { echo "FAIL gen_$fmt_$n"; nfail=$((nfail + 1)); continue; }
        check "$c" 0/fluid.vtu
        check "$c" 0/dem.vtu
    done
    c=$TMP/${fmt}_case
    cp -r "$ROOT/test/cases/genParticles" "$c"
    sed -i "s/^writeFormat .*/writeFormat $fmt;/" "$c/system/particleDict"
    "$ROOT/bin/genParticles" -case "$c" > "$c.log" 2>&1
    check "$c" 0/fluid.vtu
    check "$c" 0/dem.vtu
done
[ "$nfail" -eq 0 ]
