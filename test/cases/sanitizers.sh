#!/usr/bin/env bash
# sanitizers.sh — the library unit tests again, built with AddressSanitizer,
# LeakSanitizer and UBSan (make SAN=1): no invalid access, no undefined
# behaviour, no leak. One PASS/FAIL line per test program.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$ROOT" || exit 1
libs="core io particles linsolve functionObjects coupling coupled solver dem mlpg isph"
targets=$(for l in $libs; do
    for f in test/unit/$l/*.c; do [ -f "$f" ] && echo "build-san/test/unit/$l/$(basename "$f" .c)"; done
done)
if ! make SAN=1 -j"$(nproc)" $targets > build-san.log 2>&1; then
    echo "FAIL sanitizers: build failed"; grep -m5 error build-san.log; exit 1
fi
rm -f build-san.log
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:halt_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export OMP_NUM_THREADS=1   # libgomp's thread pool is reported as reachable, not leaked; keep it simple
status=0
for t in $targets; do
    name="asan:${t#build-san/test/}"
    out=$("$t" 2>&1); rc=$?
    if [ $rc -eq 0 ] && ! grep -qE 'ERROR: (Address|Leak)Sanitizer|runtime error:' <<<"$out"; then
        echo "PASS $name"
    else
        echo "FAIL $name: exit $rc"
        grep -m8 -E 'ERROR|runtime error|FAILED|#[0-4] ' <<<"$out"
        status=1
    fi
done
exit $status
