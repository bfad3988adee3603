#!/usr/bin/env bash
# bitIdentical.sh OLD_BIN_DIR NEW_BIN_DIR [CASE[:ENDTIME] ...]
#
# Are two builds' results identical to the bit? Runs short copies of
# tutorial cases with the programs of OLD_BIN_DIR and of NEW_BIN_DIR (each
# uses its own genParticles, mpsFluid, demSolid) and compares every .vtu
# both runs wrote. For a refactoring that must not change results (issue
# 16: one particle layer under every solver).
#
# CASE is a tutorial path relative to tutorials/ (or an absolute case
# directory); ENDTIME [s] shortens it (bin/dictTool -set endTime=...).
# Default cases:
#   mpsFluid/hydrostaticTank2D:0.05 mpsFluid/damBreak2D:0.02
#   mpsFluid/damBreakObstacle:0.01 mpsDem/singleGrainSettling:0.02
# A case whose Allrun uses runTandem runs coupled (mpsFluid + demSolid),
# one whose Allrun runs demSolid runs demSolid alone (tutorials/demSolid).
#
# Output, one line per case and field (cloud.field_component, summed over
# every written file of that cloud):
#   CASE  CLOUD.FIELD  identical
#   CASE  CLOUD.FIELD  max relative difference 3.1e-16 (2 of 5 files)
# then one line per case: files compared, byte-identical (cmp), missing.
# Relative difference |a - b| / max(|a|, |b|) (0 when both are 0); a
# different point count is reported as such. Exit status 0 when every
# field of every case is identical, 1 otherwise, 2 on a failed run.
#
# Environment: OMP_NUM_THREADS (default 1: OpenMP reductions may combine
# partial sums in thread-arrival order, which alone breaks bit identity),
# KEEP=DIR keeps the runs in DIR/{old,new}/CASE,
# SET='system/mpsSchemes:pressureGradient=minimum ...' changes entries of
# every copied case first (bin/dictTool -set), to cover other models.
set -u
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
[ $# -ge 2 ] || { sed -n '2,30p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
OLD="$(cd "$1" && pwd)" || exit 2
NEW="$(cd "$2" && pwd)" || exit 2
shift 2
[ $# -gt 0 ] || set -- mpsFluid/hydrostaticTank2D:0.05 mpsFluid/damBreak2D:0.02 \
    mpsFluid/damBreakObstacle:0.01 mpsDem/singleGrainSettling:0.02
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
W=${KEEP:-$(mktemp -d)}
[ -n "${KEEP:-}" ] || trap 'rm -rf "$W"' EXIT

# run_case BIN_DIR SRC DEST ENDTIME
run_case()
{
    local bin=$1 src=$2 dst=$3 end=$4
    rm -rf "$dst"; mkdir -p "${dst%/*}"; cp -r "$src" "$dst" || return 1
    (
        cd "$dst" || exit 1
        [ -x ./Allclean ] && ./Allclean > /dev/null 2>&1
        rm -rf validation/*.png
        # RunFunctions puts its own tree's bin first: ours goes before it
        . "$ROOT/bin/tools/RunFunctions" || exit 1
        export PATH="$bin:$PATH"
        for kv in ${SET:-}; do
            dictTool "${kv%%:*}" -set "${kv#*:}" > /dev/null || exit 1
        done
        if [ -n "$end" ]; then
            dictTool system/controlDict -set "endTime=$end" > /dev/null || exit 1
        fi
        runApplication genParticles > /dev/null || exit 1
        if grep -qs '^[^#]*runTandem' Allrun; then
            runTandem mpsFluid demSolid > /dev/null || exit 1
        elif grep -qs '^[^#]*runApplication demSolid' Allrun; then
            runApplication demSolid > /dev/null || exit 1
        else
            runApplication mpsFluid > /dev/null || exit 1
        fi
    )
}

# dump FILE: the numbers of vtuInfo -dump, header line first
dump()
{
    "$NEW/vtuInfo" -dump "$1" 2>/dev/null | awk '/^# x y z/ { h = 1; print; next } h && NF >= 3'
}

status=0
for spec in "$@"; do
    c=${spec%%:*} end=""
    [ "$c" != "$spec" ] && end=${spec#*:}
    case "$c" in /*) src=$c ;; *) src="$ROOT/tutorials/$c" ;; esac
    name=${c#"$ROOT/tutorials/"}
    [ -d "$src" ] || { echo "$name  no such case"; status=2; continue; }
    ran=1
    for side in old new; do
        bin=$OLD; [ $side = new ] && bin=$NEW
        run_case "$bin" "$src" "$W/$side/$name" "$end" \
            || { echo "$name  the $side run failed (see $W/$side/$name/log.*)"; status=2; ran=0; }
    done
    [ $ran -eq 1 ] || continue
    nfiles=0 nbytes=0 missing=0
    diffs="$W/${name////_}.diffs"; : > "$diffs"
    while IFS= read -r rel; do
        nfiles=$((nfiles + 1))
        a="$W/old/$name/$rel" b="$W/new/$name/$rel"
        [ -f "$a" ] || { missing=$((missing + 1)); echo "$name  $rel only in the new run"; continue; }
        cmp -s "$a" "$b" && nbytes=$((nbytes + 1))
        cloud=$(basename "$rel" .vtu)
        paste -d'|' <(dump "$a") <(dump "$b") | awk -F'|' -v cloud="$cloud" '
            NR == 1 { n = split(substr($1, 3), hd, " "); next }
            {
                na = split($1, a, " "); nb = split($2, b, " ")
                if (na != nb || na == 0) { bad = 1; next }
                for (k = 1; k <= na; k++) {
                    d = a[k] - b[k]; if (d < 0) d = -d
                    m = a[k] < 0 ? -a[k] : a[k]; mb = b[k] < 0 ? -b[k] : b[k]
                    if (mb > m) m = mb
                    r = m > 0 ? d / m : (d > 0 ? 1 : 0)
                    if (a[k] != b[k] && r == 0) r = 1e-300
                    if (r > mx[k]) mx[k] = r
                }
            }
            END {
                if (bad) print cloud ".points", "count"
                for (k = 1; k <= n; k++) print cloud "." hd[k], mx[k] + 0
            }' >> "$diffs"
    done < <(cd "$W/new/$name" && find . -name '*.vtu' | sed 's|^\./||' | sort)
    while IFS= read -r rel; do
        [ -f "$W/new/$name/$rel" ] || { missing=$((missing + 1)); echo "$name  $rel only in the old run"; }
    done < <(cd "$W/old/$name" && find . -name '*.vtu' | sed 's|^\./||' | sort)
    awk -v c="$name" '
        { f = $1; if (!(f in n)) { order[++k] = f; n[f] = 0; d[f] = 0; mx[f] = 0 }
          n[f]++
          if ($2 == "count") { cnt[f] = 1; next }
          if ($2 + 0 > 0) { d[f]++; if ($2 + 0 > mx[f]) mx[f] = $2 + 0 } }
        END {
            for (i = 1; i <= k; i++) {
                f = order[i]
                if (cnt[f]) printf "%s  %s  point counts differ\n", c, f
                else if (d[f] == 0) printf "%s  %s  identical\n", c, f
                else printf "%s  %s  max relative difference %.3g (%d of %d files)\n",
                            c, f, mx[f], d[f], n[f]
            }
        }' "$diffs"
    awk '$2 != "0" { e = 1 } END { exit !e }' "$diffs" \
        && status=$((status > 1 ? status : 1))
    [ $missing -gt 0 ] && status=$((status > 1 ? status : 1))
    echo "$name  $nfiles files compared, $nbytes byte-identical (cmp), $missing missing"
done
exit $status
