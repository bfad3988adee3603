#!/bin/bash
# Usage: validation/compare.sh RE [CASE [TIME]]
# Centre-line profiles of the cavity at TIME (default: the latest) against
# Ghia, Ghia and Shin (1982, Tables I-II; data/ghia_1982_cavity): writes
# CASE/u_Re<RE>.dat (y u on x = 0.5) and CASE/v_Re<RE>.dat (x v on
# y = 0.5) and prints, for each profile, the RMS and largest deviation at
# Ghia's points (linear interpolation between nodes; Ghia's suspected
# misprint v(Re 400, x = 0.9063) = -0.23827 is left out, data README) and
# the extrema of E3-11 (node values; position within the node spacing).
# The last line: "E3-10 Re RE rms_u rms_v max_u max_v".
set -e
re=${1:?Re}
case=${2:-.}
root=${MPSDEM_DIR:-$(cd "${0%/*}/../../../.." && pwd)}
t=${3:-$(ls -d "$case"/[0-9]* | sed 's#.*/##' | sort -g | tail -1)}
vtu="$case/$t/fluid.vtu"
[ -f "$vtu" ] || { echo "compare.sh: no $vtu" >&2; exit 1; }
data="$root/data/ghia_1982_cavity"
prof=$("$root/bin/vtuInfo" -dump "$vtu" | awk '
    /^# x / { for (k = 2; k <= NF; k++) col[$k] = k - 1; next }
    NF < 5 || $1 !~ /^[-0-9.]/ { next }
    {
        if ($1 > 0.5 - 1e-6 && $1 < 0.5 + 1e-6) print "U", $2, $col["velocity_0"]
        if ($2 > 0.5 - 1e-6 && $2 < 0.5 + 1e-6) print "V", $1, $col["velocity_1"]
    }')
{ echo "# y u   (u on x = 0.5, t = $t s)"; echo "$prof" | awk '$1 == "U" { print $2, $3 }' | sort -g; } > "$case/u_Re$re.dat"
{ echo "# x v   (v on y = 0.5, t = $t s)"; echo "$prof" | awk '$1 == "V" { print $2, $3 }' | sort -g; } > "$case/v_Re$re.dat"
[ "$(wc -l < "$case/u_Re$re.dat")" -gt 3 ] || { echo "compare.sh: no nodes on x = 0.5 in $vtu" >&2; exit 1; }
# Ghia columns: Re 100 400 1000 3200 -> 2 3 4 5
c=$(case $re in 100) echo 2;; 400) echo 3;; 1000) echo 4;; 3200) echo 5;; *) echo 0;; esac)
[ "$c" != 0 ] || { echo "compare.sh: Ghia gives Re 100, 400, 1000, 3200" >&2; exit 1; }
stats() { # profile ghia.csv label
    awk -F'[ ,]+' -v c="$c" -v label="$3" -v re="$re" '
        FNR == NR { if ($1 !~ /^#/) { n++; p[n] = $1; q[n] = $2 } ; next }
        FNR == 1 { next }
        {
            s = $1; g = $c
            if (re == 400 && label == "v" && s == 0.9063) next
            for (k = 1; k < n && p[k + 1] < s; k++) ;
            f = (s - p[k]) / (p[k + 1] - p[k]); m = q[k] + f * (q[k + 1] - q[k])
            d = m - g; ss += d * d; cnt++; if (d < 0) d = -d; if (d > mx) mx = d
        }
        END { printf "%s %.4f %.4f %d\n", label, sqrt(ss / cnt), mx, cnt }' "$1" "$2"
}
ru=$(stats "$case/u_Re$re.dat" "$data/ghia1982_u_vertical_centerline.csv" u)
rv=$(stats "$case/v_Re$re.dat" "$data/ghia1982_v_horizontal_centerline.csv" v)
echo "Re $re, t = $t s: deviation from Ghia et al. (1982) at their points"
echo "  u(y) on x = 0.5: RMS $(echo $ru | cut -d' ' -f2), max $(echo $ru | cut -d' ' -f3) ($(echo $ru | cut -d' ' -f4) points)"
echo "  v(x) on y = 0.5: RMS $(echo $rv | cut -d' ' -f2), max $(echo $rv | cut -d' ' -f3) ($(echo $rv | cut -d' ' -f4) points)"
awk '!/^#/ { if (!s || $2 < m) { m = $2; y = $1; s = 1 } } END { printf "  u_min %.4f at y = %.4f\n", m, y }' "$case/u_Re$re.dat"
awk '!/^#/ { if (!s || $2 > M) { M = $2; xM = $1 } if (!s || $2 < m) { m = $2; xm = $1 } s = 1 }
     END { printf "  v_max %.4f at x = %.4f, v_min %.4f at x = %.4f\n", M, xM, m, xm }' "$case/v_Re$re.dat"
echo "E3-10 Re $re $(echo $ru | cut -d' ' -f2) $(echo $rv | cut -d' ' -f2) $(echo $ru | cut -d' ' -f3) $(echo $rv | cut -d' ' -f3)"
