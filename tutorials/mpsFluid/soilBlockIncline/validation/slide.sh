#!/bin/sh
# slide.sh RUN — how far the middle of the soil block of one run of
# soilBlockIncline slides (RUN: a copy theta<THETA>/ made by ../Allrun):
# the soil particles that lie in the middle fifth of the block at 0.3 s
# (x within a tenth of the block's length of its centre), their mean x
# at 0.3 s and at the end (0.5 s). Its ends slump at any angle (a free
# face of cohesionless soil cannot stand) and, near the threshold, the
# slumping reaches far along the layer (~ h/tan(atan(mu) - theta)); its
# middle is the infinite slope of E5-04. Prints "theta dx_m speed_m_per_s": dx the travel of
# those particles, speed = dx over that time. E5-04 calls the block at
# rest when dx < 0.5 dp (validation/bisect).
set -e
RUN=${1:?usage: slide.sh RUN}
ROOT="${MPSDEM_DIR:-$(cd "$(dirname "$0")/../../../.." && pwd)}"
[ -x "$ROOT/bin/vtuInfo" ] || { echo "slide.sh: $ROOT/bin/vtuInfo not found: build mpsdem or set MPSDEM_DIR" >&2; exit 1; }
cd "$RUN"
th=${PWD##*/theta}
last=$(ls -d [0-9]* | sort -g | tail -1)
[ -f 0.3/fluid.vtu ] && [ "$last" != 0.3 ] || { echo "slide.sh: $RUN has no 0.3 s and later snapshot" >&2; exit 1; }
soil() { "$ROOT/bin/vtuInfo" -dump "$1/fluid.vtu" 2>/dev/null | awk '
    /^# x/ { for (i = 2; i <= NF; i++) k[$i] = i - 1; next } /^#/ || NF < 5 { next }
    $k["type"] == 0 && $k["phase"] == 1 { print $k["id"], $1 }'; }
soil 0.3 > slide.a
soil "$last" > slide.b
awk -v th="$th" -v t="$last" '
    FNR == NR { x[$1] = $2; if (NR == 1 || $2 < lo) lo = $2; if (NR == 1 || $2 > hi) hi = $2; next }
    { y[$1] = $2 }
    END { c = (lo + hi) / 2; q = (hi - lo) / 10
          for (i in x) if (x[i] > c - q && x[i] < c + q && (i in y)) { n++; d += y[i] - x[i] }
          if (n == 0) { print "slide.sh: no soil in the middle of the block" > "/dev/stderr"; exit 1 }
          printf "%s %.6f %.5f\n", th, d / n, d / n / (t - 0.3) }' slide.a slide.b
rm -f slide.a slide.b
