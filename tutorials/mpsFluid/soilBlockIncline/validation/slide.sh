#!/bin/sh
# slide.sh RUN — how far the soil block of one run of soilBlockIncline
# (RUN: a copy theta<THETA>/ made by ../Allrun) slides: the centroid of the
# soil particles along the incline (x) at 0.3 s and at the end (0.5 s).
# Prints "theta dx_m speed_m_per_s": dx the centroid's travel from 0.3 s
# to the end, speed = dx over that time. E5-04 calls the block at rest
# when dx < 0.5 dp (validation/bisect); a block slumping on a flat floor
# (0 deg) moves its centroid by up to 0.19 dp (measured), hence not 0.1 dp. at 0 deg the slumping block
# moves its centroid by 0.19 dp (measured), hence not 0.1 dp.
set -e
RUN=${1:?usage: slide.sh RUN}
ROOT="${MPSDEM_DIR:-$(cd "$(dirname "$0")/../../../.." && pwd)}"
cd "$RUN"
th=${PWD##*/theta}
last=$(ls -d [0-9]* | sort -g | tail -1)
cx() { "$ROOT/bin/vtuInfo" -dump "$1/fluid.vtu" 2>/dev/null | awk '
    /^# x/ { for (i = 2; i <= NF; i++) k[$i] = i - 1; next } /^#/ || NF < 5 { next }
    $k["type"] == 0 && $k["phase"] == 1 { s += $1; n++ } END { printf "%.9f", n ? s / n : 0 }'; }
awk -v th="$th" -v a="$(cx 0.3)" -v b="$(cx "$last")" -v t="$last" \
    'BEGIN { printf "%s %.6f %.5f\n", th, b - a, (b - a) / (t - 0.3) }'
