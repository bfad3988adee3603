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
