#!/usr/bin/env bash
# test/cases/genParticlesGrains.sh — grains regions of genParticles that are
# not on a lattice (issue 15 item 8):
#   lattice random   random sequential addition: the count and solid
#                    fraction reached, no two grains overlapping (every pair
#                    checked), all inside the region, same seed same
#                    grains, another seed other grains; uniform and normal
#                    diameter distributions within their bounds; 2-D; the
#                    limits refused (solidFraction above 0.35, a packing
#                    that cannot be reached)
#   shape file       csv (radius or diameter column, comments, scale),
#                    a LIGGGHTS data file written by hand in the documented
#                    write_data layout, a LIGGGHTS dump (last snapshot):
#                    the grains written are those of the file; bad files
#                    (missing column, short row, non-numeric, NaN, negative
#                    radius, outside the tank, overlapping, truncated dump,
#                    ...) refused naming the file and the line, exit 1 and
#                    no output
# One PASS/FAIL line per check; bin/vtuInfo reads the clouds back.
set -u
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BIN=${MPSDEM_BIN:-$ROOT/bin}
GEN=$BIN/genParticles
INFO=$BIN/vtuInfo
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
nfail=0

pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; nfail=$((nfail + 1)); }
expect() {  # name got want
    if [ "$2" = "$3" ]; then pass "$1 ($2)"; else fail "$1" "got '$2', want '$3'"; fi
}
for exe in "$GEN" "$INFO"; do
    [ -x "$exe" ] || { fail genParticlesGrains "$exe not built"; exit 1; }
done

# newcase NAME DIM REGION...: a case whose particleDict holds a 0.1 m tank
# (open top) and the given region lines
newcase() {
    local dir=$TMP/$1 dim=$2; shift 2
    rm -rf "$dir"; mkdir -p "$dir/system" "$dir/constant"
    cp "$ROOT/test/cases/genParticles/constant/g" "$dir/constant/"
    {
        echo "dimension $dim; dp 0.01; wallLayers 1; writeFormat ascii;"
        echo "regions"
        echo "("
        if [ "$dim" = 3 ]; then open="zmax"; else open="ymax"; fi
        echo "    tank { type tankWall; shape box; min (0 0 0); max (0.1 0.1 0.1); open ($open); }"
        for line in "$@"; do echo "    $line"; done
        echo ");"
    } > "$dir/system/particleDict"
}
run() { "$GEN" -case "$TMP/$1" > "$TMP/$1.log" 2>&1; }
# x y z radius of every grain, to 15 digits, on one line
values() { grains "$1" | awk '{ printf "%.15g %.15g %.15g %.15g;", $1, $2, $3, $4 }'; }
# x y z radius of every grain
grains() { "$INFO" -case "$TMP/$1" -dump 0/dem.vtu 2> /dev/null | awk '/^# x/ { go = 1; next } go && NF > 6 { print $1, $2, $3, $4 }'; }

# check_pack NAME DIM LO HI FRACTION: "n=N fraction=F overlaps=K outside=M"
# over every pair and every grain (brute force)
check_pack() {
    grains "$1" | awk -v dim="$2" -v lo="$3" -v hi="$4" '
        BEGIN { n = 0 }
        { x[n] = $1; y[n] = $2; z[n] = $3; r[n] = $4; n++ }
        END {
            pi = atan2(0, -1); vol = 0; out = 0; bad = 0
            for (i = 0; i < n; i++) {
                vol += (dim == 3) ? 4 / 3 * pi * r[i] ^ 3 : pi * r[i] ^ 2
                if (x[i] - r[i] < lo - 1e-12 || x[i] + r[i] > hi + 1e-12 ||
                    y[i] - r[i] < lo - 1e-12 || y[i] + r[i] > hi + 1e-12) out++
                if (dim == 3 && (z[i] - r[i] < lo - 1e-12 || z[i] + r[i] > hi + 1e-12)) out++
                if (dim == 2 && z[i] != 0) out++
                for (j = i + 1; j < n; j++) {
                    dx = x[i] - x[j]; dy = y[i] - y[j]; dz = z[i] - z[j]; s = r[i] + r[j]
                    if (dx * dx + dy * dy + dz * dz < s * s * (1 - 1e-12)) bad++
                }
            }
            printf "n=%d fraction=%.6f overlaps=%d outside=%d\n", n, vol / (hi - lo) ^ dim, bad, out
        }'
}
field() { echo "$1" | tr ' ' '\n' | sed -n "s/^$2=//p"; }

# ==== lattice random ==========================================================
# 3-D, equal grains: N is the count whose volume is nearest the target,
# floor(0.3 V / v + 1/2) with V = 0.05^3, v = pi 0.004^3 / 6: 1119
newcase r3 3 "bed { type grains; shape box; min (0 0 0); max (0.05 0.05 0.05); lattice random; diameter 0.004; solidFraction 0.3; seed 3; }"
if run r3; then
    res=$(check_pack r3 3 0 0.05)
    want=$(awk 'BEGIN { pi = atan2(0, -1); v = pi * 0.004 ^ 3 / 6; printf "%d", int(0.3 * 0.05 ^ 3 / v + 0.5) }')
    expect random_count "$(field "$res" n)" "$want"
    # within half a grain of the target: |f - 0.3| <= v / (2 V) = 0.000134
    if awk -v f="$(field "$res" fraction)" 'BEGIN { d = f - 0.3; exit !(d <= 0.000134 && -d <= 0.000134) }'
    then pass "random_solid_fraction ($(field "$res" fraction), asked 0.3)"
    else fail random_solid_fraction "$(field "$res" fraction), asked 0.3"; fi
    expect random_no_overlap "overlaps=$(field "$res" overlaps)" "overlaps=0"
    expect random_inside "outside=$(field "$res" outside)" "outside=0"
    grep -q "random sequential addition of $want grains, solid fraction" "$TMP/r3.log" \
        && pass random_logged || fail random_logged "no summary line in the log"
else fail random_run "$(grep -A1 FATAL "$TMP/r3.log" | tail -1)"; fi
cp "$TMP/r3/0/dem.vtu" "$TMP/r3.first" 2> /dev/null
run r3
if cmp -s "$TMP/r3.first" "$TMP/r3/0/dem.vtu"; then pass random_same_seed_same_grains
else fail random_same_seed_same_grains "two runs with seed 3 differ"; fi
newcase r3s 3 "bed { type grains; shape box; min (0 0 0); max (0.05 0.05 0.05); lattice random; diameter 0.004; solidFraction 0.3; seed 4; }"
run r3s
a=$(grains r3 | head -5 | md5sum); b=$(grains r3s | head -5 | md5sum)
n4=$(grains r3s | wc -l)
if [ "$a" != "$b" ] && [ "$n4" = "$(grains r3 | wc -l)" ] &&
   [ "$(check_pack r3s 3 0 0.05 | cut -d' ' -f3-)" = "overlaps=0 outside=0" ]
then pass "random_other_seed_other_grains ($n4 grains, other positions)"
else fail random_other_seed_other_grains "seed 4 gives the same positions, or $n4 grains"; fi

# uniform diameters: within their bounds, covering them
newcase ru 3 "bed { type grains; shape box; min (0.01 0.01 0.01); max (0.04 0.04 0.04); lattice random; diameterDistribution uniform (0.002 0.005); solidFraction 0.25; seed 1; }"
if run ru; then
    res=$(check_pack ru 3 0.01 0.04)
    rng=$(grains ru | awk 'NR == 1 { lo = hi = $4 } { if ($4 < lo) lo = $4; if ($4 > hi) hi = $4; s += $4 }
        END { print (lo >= 0.001 && hi <= 0.0025 && lo < 0.0011 && hi > 0.0024) ? "in" : "out", s / NR }')
    if [ "$(field "$res" overlaps) $(field "$res" outside) ${rng%% *}" = "0 0 in" ] &&
       awk -v f="$(field "$res" fraction)" 'BEGIN { d = f - 0.25; exit !(d <= 0.0006 && -d <= 0.0006) }'
    then pass "random_uniform ($res, radii in [0.001, 0.0025], mean ${rng#* })"
    else fail random_uniform "$res, radii $rng"; fi
else fail random_uniform "$(grep -A1 FATAL "$TMP/ru.log" | tail -1)"; fi

# normal (4 mm, 1 mm) clipped to (3 mm, 6 mm): truncated mean 4.23 mm
newcase rn 3 "bed { type grains; shape box; min (0 0 0); max (0.06 0.06 0.06); lattice random; diameterDistribution normal (0.004 0.001) (0.003 0.006); solidFraction 0.2; seed 2; }"
if run rn; then
    res=$(check_pack rn 3 0 0.06)
    st=$(grains rn | awk '{ d = 2 * $4; if (d < 0.003 || d > 0.006) out++; s += d } END { printf "%d %.5f", out, s / NR }')
    if [ "$(field "$res" overlaps) $(field "$res" outside) ${st%% *}" = "0 0 0" ] &&
       awk -v m="${st#* }" 'BEGIN { exit !(m > 0.0041 && m < 0.00435) }'
    then pass "random_normal ($res, diameters in [3, 6] mm, mean ${st#* } m)"
    else fail random_normal "$res, out-of-range and mean diameter: $st"; fi
else fail random_normal "$(grep -A1 FATAL "$TMP/rn.log" | tail -1)"; fi

# 2-D: disks in the x-y plane, area fraction
newcase r2 2 "bed { type grains; shape box; min (0 0 0); max (0.05 0.05 0); lattice random; diameter 0.002; solidFraction 0.45; seed 5; }"
if run r2; then
    res=$(check_pack r2 2 0 0.05)
    want=$(awk 'BEGIN { pi = atan2(0, -1); v = pi * 0.002 ^ 2 / 4; printf "%d", int(0.45 * 0.05 ^ 2 / v + 0.5) }')
    expect random_2d "$res" "n=$want fraction=$(awk -v n="$want" 'BEGIN { printf "%.6f", n * atan2(0, -1) * 0.001 ^ 2 / 0.05 ^ 2 }') overlaps=0 outside=0"
else fail random_2d "$(grep -A1 FATAL "$TMP/r2.log" | tail -1)"; fi

# ==== shape file ==============================================================
# csv: columns in any order, an extra one, comments and blank lines
newcase fcsv 3 'bed { type grains; shape file; file "constant/bed.csv"; format csv; velocity (0 0 -1); }'
cat > "$TMP/fcsv/constant/bed.csv" <<'EOF'
# three glass beads (m)
id, Radius, x, y, z
1, 0.002, 0.01, 0.01, 0.01    # touching the next one
2, 0.002, 0.014, 0.01, 0.01

3, 0.0035, 0.05, 0.05, 0.0985
EOF
if run fcsv; then
    expect file_csv "$(values fcsv)" "0.01 0.01 0.01 0.002;0.014 0.01 0.01 0.002;0.05 0.05 0.0985 0.0035;"
else fail file_csv "$(grep -A1 FATAL "$TMP/fcsv.log" | tail -1)"; fi
# diameters in millimetres
newcase fmm 3 'bed { type grains; shape file; file "constant/bed.csv"; format csv; scale 0.001; }'
printf 'x,y,z,diameter\n10,10,10,4\n50,50,50,7\n' > "$TMP/fmm/constant/bed.csv"
run fmm
expect file_csv_mm "$(values fmm)" "0.01 0.01 0.01 0.002;0.05 0.05 0.05 0.0035;"

# a settled bed rests on the floor with its contact overlap: 2.5 % of the
# radius is accepted (maxOverlap 0.05), 10 % is not (bad csv_wall_overlap)
newcase fwall 3 'bed { type grains; shape file; file "constant/bed.csv"; format csv; }'
printf 'x,y,z,radius\n0.01,0.01,0.00195,0.002\n' > "$TMP/fwall/constant/bed.csv"
if run fwall; then
    expect file_csv_wall_overlap "$(values fwall)" "0.01 0.01 0.00195 0.002;"
else fail file_csv_wall_overlap "$(grep -A1 FATAL "$TMP/fwall.log" | tail -1)"; fi

# LIGGGHTS data file (write_data, atom style sphere: id type diameter
# density x y z, image flags), written by hand
newcase fdata 3 'bed { type grains; shape file; file "constant/bed.data"; format liggghtsData; }'
cat > "$TMP/fdata/constant/bed.data" <<'EOF'
LIGGGHTS data file via write_data, version 3.8.0, timestep = 2000

3 atoms
1 atom types

0.0000000000000000e+00 1.0000000000000001e-01 xlo xhi
0.0000000000000000e+00 1.0000000000000001e-01 ylo yhi
0.0000000000000000e+00 1.0000000000000001e-01 zlo zhi

Atoms # sphere

1 1 4.0000000000000001e-03 2.5000000000000000e+03 1.0000000000000000e-02 1.0000000000000000e-02 5.0000000000000001e-03 0 0 0
3 1 6.0000000000000001e-03 2.5000000000000000e+03 5.0000000000000003e-02 2.0000000000000000e-02 5.0000000000000001e-03 0 0 0
2 1 4.0000000000000001e-03 2.5000000000000000e+03 2.0000000000000000e-02 1.0000000000000000e-02 5.0000000000000001e-03 0 0 0

Velocities

1 0 0 0 0 0 0
3 0 0 0 0 0 0
2 0 0 0 0 0 0
EOF
if run fdata; then
    expect file_liggghts_data "$(values fdata)" "0.01 0.01 0.005 0.002;0.05 0.02 0.005 0.003;0.02 0.01 0.005 0.002;"
else fail file_liggghts_data "$(grep -A1 FATAL "$TMP/fdata.log" | tail -1)"; fi

# LIGGGHTS text dump, two snapshots: the last one is read
newcase fdump 3 'bed { type grains; shape file; file "constant/post/dump.liggghts"; format liggghtsDump; }'
mkdir -p "$TMP/fdump/constant/post"
cat > "$TMP/fdump/constant/post/dump.liggghts" <<'EOF'
ITEM: TIMESTEP
0
ITEM: NUMBER OF ATOMS
2
ITEM: BOX BOUNDS ff ff ff
0 0.1
0 0.1
0 0.1
ITEM: ATOMS id type x y z radius
1 1 0.05 0.05 0.08 0.002
2 1 0.06 0.05 0.08 0.002
ITEM: TIMESTEP
5000
ITEM: NUMBER OF ATOMS
2
ITEM: BOX BOUNDS ff ff ff
0 0.1
0 0.1
0 0.1
ITEM: ATOMS id type vx vy vz radius x y z
1 1 0 0 0 0.002 0.05 0.05 0.002
2 1 0 0 0 0.002 0.06 0.05 0.002
EOF
if run fdump; then
    expect file_liggghts_dump "$(values fdump)" "0.05 0.05 0.002 0.002;0.06 0.05 0.002 0.002;"
else fail file_liggghts_dump "$(grep -A1 FATAL "$TMP/fdump.log" | tail -1)"; fi

# ==== bad input: exit 1, particleDict:line:col, the file:line, no output ====
# bad NAME PHRASE DIM REGION [FILE CONTENT]
bad() {
    local name=$1 phrase=$2 dim=$3 region=$4
    newcase "$name" "$dim" "$region"
    [ $# -ge 6 ] && printf '%b' "$6" > "$TMP/$name/$5"
    if run "$name"; then fail "bad_$name" "exit status 0"; return; fi
    if ! grep -q -- "system/particleDict:[0-9]*:[0-9]*: .*$phrase" "$TMP/$name.log"; then
        fail "bad_$name" "no 'particleDict:line:col: ...$phrase' in: $(grep -A1 FATAL "$TMP/$name.log" | tail -1)"
        return
    fi
    local out
    out=$(cd "$TMP/$name" && ls -d 0/* *.pvd constant/particlePatches 2> /dev/null)
    [ -z "$out" ] || { fail "bad_$name" "files written: $out"; return; }
    pass "bad_$name: $(grep -A1 FATAL "$TMP/$name.log" | tail -1 | sed "s|$TMP/||g; s/^ *//")"
}
CSV='bed { type grains; shape file; file "constant/bed.csv"; format csv; }'
bad csv_missing_column "bed.csv:2: no column 'z' in the header 'x,y,radius'" 3 "$CSV" \
    constant/bed.csv '# beads\nx,y,radius\n0.01,0.01,0.002\n'
bad csv_short_row "bed.csv:3: 3 values, the header (line 1) names 4 columns" 3 "$CSV" \
    constant/bed.csv 'x,y,z,radius\n0.01,0.01,0.01,0.002\n0.02,0.01,0.002\n'
bad csv_not_a_number "bed.csv:2: column 'y': '0.0l' is not a number" 3 "$CSV" \
    constant/bed.csv 'x,y,z,radius\n0.01,0.0l,0.01,0.002\n'
bad csv_nan "bed.csv:3: column 'z': 'NaN' is not a finite number" 3 "$CSV" \
    constant/bed.csv 'x,y,z,radius\n0.01,0.01,0.01,0.002\n0.02,0.02,NaN,0.002\n'
bad csv_negative_radius "bed.csv:2: radius -0.002 (diameter -0.004) must be positive" 3 "$CSV" \
    constant/bed.csv 'x,y,z,radius\n0.01,0.01,0.01,-0.002\n'
bad csv_no_header "bed.csv:1: no column 'x' in the header '0.01,0.01,0.01,0.002' .*is the header line missing" 3 "$CSV" \
    constant/bed.csv '0.01,0.01,0.01,0.002\n'
bad csv_outside "bed.csv:3: grain at (0.01 0.01 0.001), radius 0.002, is not inside the tank 'tank'" 3 "$CSV" \
    constant/bed.csv 'x,y,z,radius\n0.01,0.01,0.01,0.002\n0.01,0.01,0.001,0.002\n'
bad csv_wall_overlap "bed.csv:2: grain at (0.01 0.01 0.0018), radius 0.002, is not inside the tank 'tank'.*maxOverlap 0.05" 3 "$CSV" \
    constant/bed.csv 'x,y,z,radius\n0.01,0.01,0.0018,0.002\n'
bad csv_overlap "bed.csv:2: the grain of this line and that of line 4 overlap by 0.25 of the smaller radius, more than maxOverlap 0.05" 3 "$CSV" \
    constant/bed.csv 'x,y,z,radius\n0.01,0.01,0.01,0.002\n0.05,0.05,0.05,0.002\n0.0135,0.01,0.01,0.002\n'
bad csv_2d_z "bed.csv:2: z = 0.01 in a 2-D case" 2 "$CSV" \
    constant/bed.csv 'x,y,z,radius\n0.01,0.01,0.01,0.002\n'
bad csv_missing_file "bed.csv: cannot open: No such file or directory" 3 "$CSV"
bad unknown_format "unknown grain file format 'vtk'; valid: csv liggghtsData liggghtsDump" 3 \
    'bed { type grains; shape file; file "constant/bed.csv"; format vtk; }'
bad file_shape_fluid "shape file is for grains regions" 3 \
    'water { type fluid; shape file; file "constant/bed.csv"; format csv; }'
DATA='bed { type grains; shape file; file "constant/bed.data"; format liggghtsData; }'
bad data_values "bed.data:7: 6 values: atom style sphere has 7" 3 "$DATA" \
    constant/bed.data 'title\n\n1 atoms\n\nAtoms\n\n1 1 0.004 2500 0.01 0.01\n'
bad data_too_few "bed.data:9: the Atoms section ends after 1 of the 2 atoms of the header (line 3)" 3 "$DATA" \
    constant/bed.data 'title\n\n2 atoms\n\nAtoms # sphere\n\n1 1 0.004 2500 0.01 0.01 0.01\n\nVelocities\n\n1 0 0 0 0 0 0\n'
bad data_no_atoms "bed.data: no Atoms section" 3 "$DATA" \
    constant/bed.data 'title\n\n1 atoms\n\nVelocities\n\n1 0 0 0 0 0 0\n'
bad data_style "bed.data:5: Atoms section of atom style 'atomic'" 3 "$DATA" \
    constant/bed.data 'title\n\n1 atoms\n\nAtoms # atomic\n\n1 1 0.01 0.01 0.01\n'
bad data_nan "bed.data:7: column 'y': 'nan' is not a finite number" 3 "$DATA" \
    constant/bed.data 'title\n\n1 atoms\n\nAtoms\n\n1 1 0.004 2500 0.01 nan 0.01\n'
DUMP='bed { type grains; shape file; file "constant/bed.dump"; format liggghtsDump; }'
bad dump_truncated "bed.dump:9: the last snapshot (timestep 100) ends after 1 of its 2 atoms: a truncated dump?" 3 "$DUMP" \
    constant/bed.dump 'ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\nITEM: ATOMS id x y z radius\n1 0.01 0.01 0.01 0.002\n'
bad dump_no_radius "bed.dump:9: no column radius (or diameter) in 'ITEM: ATOMS id x y z'" 3 "$DUMP" \
    constant/bed.dump 'ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\nITEM: ATOMS id x y z\n1 0.01 0.01 0.01\n'
bad dump_negative "bed.dump:10: radius -0.002 (diameter -0.004) must be positive" 3 "$DUMP" \
    constant/bed.dump 'ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\nITEM: ATOMS id x y z radius\n1 0.01 0.01 0.01 -0.002\n'
bad dump_not_a_dump "bed.dump: no 'ITEM: TIMESTEP' line" 3 "$DUMP" \
    constant/bed.dump 'x,y,z,radius\n'

RND='bed { type grains; shape box; min (0 0 0); max (0.05 0.05 0.05); lattice random;'
bad random_too_dense "solidFraction 0.36 is not in (0, 0.35\]" 3 "$RND diameter 0.004; solidFraction 0.36; }"
bad random_too_dense_2d "solidFraction 0.55 is not in (0, 0.5\]" 2 \
    'bed { type grains; shape box; min (0 0 0); max (0.05 0.05 0); lattice random; diameter 0.004; solidFraction 0.55; }'
bad random_unreachable "random sequential addition placed [0-9]* of 1306 grains .*saturates near 0.383 x 0.779 = 0.298 here" 3 \
    "$RND diameter 0.004; solidFraction 0.35; maxAttempts 2000; }"
bad random_both_sizes "give diameter (all grains alike) or diameterDistribution, not both" 3 \
    "$RND diameter 0.004; diameterDistribution uniform (0.003 0.005); solidFraction 0.3; }"
bad random_no_size "lattice random needs diameter" 3 "$RND solidFraction 0.3; }"
bad random_unknown_distribution "unknown grain diameter distribution 'gaussian'; valid: uniform normal" 3 \
    "$RND diameterDistribution gaussian (0.003 0.005); solidFraction 0.3; }"
bad random_uniform_order "uniform (min max): max 0.003 is below min 0.005" 3 \
    "$RND diameterDistribution uniform (0.005 0.003); solidFraction 0.3; }"
bad random_normal_clip "normal needs the clip range (min max) after its name" 3 \
    "$RND diameterDistribution normal (0.004 0.001); solidFraction 0.3; }"
bad lattice_distribution "a diameter distribution needs lattice random" 3 \
    'bed { type grains; shape box; min (0 0 0); max (0.05 0.05 0.05); diameter 0.004; diameterDistribution uniform (0.003 0.005); }'

# with MPSDEM_BIN=bin-san: a sanitizer report anywhere is a failure, even in
# the runs that were expected to exit 1
san=$(grep -l -E 'ERROR: (Address|Leak)Sanitizer|runtime error:' "$TMP"/*.log 2> /dev/null | head -3)
if [ -n "$san" ]; then fail sanitizer "reports in $(echo $san)"; fi

[ "$nfail" -eq 0 ]
