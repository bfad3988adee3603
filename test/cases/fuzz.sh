#!/bin/bash
# fuzz.sh — the libFuzzer targets still build and survive a short run, so
# that they cannot rot unnoticed (issue 14 item 8: test/fuzz/run stopped
# linking when src/core/files.c appeared and nothing saw it).
#
# Builds test/fuzz/fuzz_dict.c and fuzz_vtu.c with clang (installed by
# bin/tools/installDependencies, so its absence is a failure, not a skip)
# and runs each for FUZZ_SECONDS (default 20) through test/fuzz/run and
# run_vtu. A clang warning fails the build check like a gcc one would.
# The PASS lines give the executions per second; the long campaigns (10^7
# executions) are run by hand with test/fuzz/run SECONDS.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
SECS=${FUZZ_SECONDS:-20}
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }

if ! command -v clang > /dev/null; then
    fail fuzz "clang not found: bin/tools/installDependencies installs it" \
              "(Debian packages clang, libclang-rt-dev)"
    exit 1
fi

# fuzz NAME SCRIPT: build and run one target; its summary line reads
# "NAME: S s, executions: N, crashes: C, ..." and comes only after the build
fuzz() {
    local name="$1" script="$2" out rc
    out=$(nice "$ROOT/test/fuzz/$script" "$SECS" 2>&1); rc=$?
    local summary; summary=$(grep "^$name: .*executions:" <<< "$out")
    if [ -z "$summary" ]; then
        fail "${name}_build" "$(grep -E 'error|undefined' <<< "$out" | head -5 | tr '\n' ' ')"
        return
    fi
    if grep -q 'warning:' <<< "$out"; then
        fail "${name}_build" "clang warnings: $(grep 'warning:' <<< "$out" | sort -u | head -5 | tr '\n' ' ')"
    else
        pass "${name}_build"
    fi
    local log="$ROOT/build-fuzz/$name.log" rate
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
    if [ $rc -eq 0 ]; then
        pass "${name}_run: ${summary#*: }, ${rate:-?} executions/s"
    else
        fail "${name}_run" "$(tr '\n' ' ' <<< "$out" | tail -c 600)"
    fi
}

fuzz fuzz_dict run
fuzz fuzz_vtu run_vtu
exit $((fails > 0))
