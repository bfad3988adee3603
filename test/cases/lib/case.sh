# case.sh — sourced by the case tests (test/cases/*.sh): the repository
# root, a scratch directory removed at exit (KEEP=1 keeps it), one thread,
# the PASS/FAIL helpers and the check that the programs are built.
#
#   NAME=mpsSoil2D; . "$(dirname "$0")/lib/case.sh"; need_bins mpsFluid vtuInfo
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
TMP="$(mktemp -d)"
trap '[ -n "$KEEP" ] || rm -rf "$TMP"' EXIT
export OMP_NUM_THREADS=1
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }
# need_bins PROGRAM...: stop the test (one FAIL naming it) if a program of
# bin/ is not built
need_bins() {
    local b
    for b in "$@"; do
        [ -x "$ROOT/bin/$b" ] || { fail "$NAME" "bin/$b not built"; exit 1; }
    done
}
# expect_refusal NAME PROGRAM REGEXP: PROGRAM of bin/, run in the case $c,
# must exit non-zero with a message matching REGEXP and write no time
# directory but 0/ (no corrupted output)
expect_refusal() {
    local out rc extra
    out=$(cd "$c" && "$ROOT/bin/$2" 2>&1); rc=$?
    extra=$(cd "$c" && ls -d [0-9]* | grep -v '^0$' | tr '\n' ' ')
    if [ $rc -ne 0 ] && echo "$out" | grep -qE "$3" && [ -z "$extra" ]; then
        pass "$1"
    else
        fail "$1" "rc $rc, time dirs '$extra', message: $(echo "$out" | grep -A1 FATAL | tail -1)"
    fi
}
