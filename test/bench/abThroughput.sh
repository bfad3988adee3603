#!/usr/bin/env bash
# abThroughput.sh OLD_BIN_DIR NEW_BIN_DIR [REPEAT] — is a refactoring slower?
# Runs two builds side by side on one core (OMP_NUM_THREADS=1), alternating
# old/new (ABBA order, so that a slow phase of a shared machine hits both),
# on the same prepared cases:
#   mps  the 3-D Kleefsman dam break of mpsThroughput.sh at dp = 0.035 m
#        (~50k particles, r_e 2.1 dp, fixed dt, STEPS_MPS steps, default
#        30; renumbering and neighbour builds included)
#   dem  the dense bed of demThroughput/run, NX x NY x NZ touching 2.7 mm
#        beads (default 24 x 24 x 20 = 11520), Verlet, STEPS_DEM steps
#        (default 1000)
# and prints, per case and build, the CPU seconds (user + system of the
# whole process) and the solver's particle-steps per wall second: minimum
# and median over REPEAT runs (default 5), the new/old ratio of the
# minimum CPU times, and the load average before and after.
set -u
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
[ $# -ge 2 ] || { sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
OLD="$(cd "$1" && pwd)" || exit 2
NEW="$(cd "$2" && pwd)" || exit 2
REPEAT=${3:-5}
STEPS_MPS=${STEPS_MPS:-30}
STEPS_DEM=${STEPS_DEM:-1000}
NX=${NX:-24}; NY=${NY:-24}; NZ=${NZ:-20}
export OMP_NUM_THREADS=1
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
LOAD0=$(cut -d' ' -f1-3 /proc/loadavg)

# --- mps case (as mpsThroughput.sh's kleefsman_50k) ----------------------
set_key() { sed -i "s|^\(\s*$2\) .*|\1 $3;|" "$1"; }
M="$W/mps"
cp -r "$ROOT/tutorials/mpsFluid/damBreakObstacle" "$M"
set_key "$M/system/particleDict" dp 0.035
for k in reNumberDensity reGradient reLaplacian; do
    set_key "$M/system/mpsSchemes" $k 2.1
done
DTM=$(awk 'BEGIN { printf "%.3g", 0.1 * 0.035 / 3 }')
set_key "$M/system/controlDict" adjustTimeStep no
set_key "$M/system/controlDict" deltaT "$DTM"
set_key "$M/system/controlDict" endTime "$(awk -v d=$DTM -v n=$STEPS_MPS 'BEGIN { printf "%.6g", d * n }')"
set_key "$M/system/controlDict" writeInterval 1000
sed -i '/^functions/,$d' "$M/system/controlDict"
(cd "$M" && "$OLD/genParticles" > log.genParticles 2>&1) || { echo "mps set-up failed"; exit 1; }

# --- dem case (as demThroughput/run) --------------------------------------
D=0.0027 DT=5e-6
LX=$(awk -v n=$NX -v d=$D 'BEGIN{printf "%.6g", n*d}')
LY=$(awk -v n=$NY -v d=$D 'BEGIN{printf "%.6g", n*d}')
LZ=$(awk -v n=$NZ -v d=$D 'BEGIN{printf "%.6g", n*d}')
HZ=$(awk -v l=$LZ 'BEGIN{printf "%.6g", 2*l}')
TEND=$(awk -v s=$STEPS_DEM -v dt=$DT 'BEGIN{printf "%.9g", s*dt}')
G="$W/dem"
mkdir -p "$G/system" "$G/constant"
cat > "$G/system/particleDict" <<PD
dimension 3; dp $D; wallLayers 1; writeFormat binary;
regions
{
    tank  { type tankWall; shape box; min (0 0 0); max ($LX $LY $HZ); open (zmax); }
    bed   { type grains; shape box; min (0 0 0); max ($LX $LY $LZ); diameter $D; spacing $D; }
}
PD
cat > "$G/system/controlDict" <<CD
startFrom startTime; startTime 0; endTime $TEND; deltaT $TEND;
writeControl adjustableRunTime; writeInterval $TEND; writeFormat binary;
CD
cat > "$G/system/demSolution" <<DS
integrator verlet; verletCoeffs { deltaT $DT; } neighbour { skin 0.00027; }
DS
cat > "$G/constant/demProperties" <<DP
rho 2500; E 1e8; nu 0.2; mu 0.2; e 0.9;
contact { normal hertz; damping restitution; tangential coulomb; rolling none; }
DP
(cd "$G" && "$OLD/genParticles" > log.genParticles 2>&1) || { echo "dem set-up failed"; exit 1; }

# run CASE_DIR PROGRAM BIN TAG: appends "cpu rate" to $W/TAG
run() {
    local c=$1 prog=$2 bin=$3 tag=$4
    (cd "$c" && rm -rf [1-9]* 0.* ./*.pvd postProcessing log.$prog \
        && /usr/bin/time -f "%U %S" -o cpu.txt "$bin/$prog" > log.$prog 2>&1) \
        || { echo "$tag failed:"; tail -5 "$c/log.$prog"; exit 1; }
    local rate
    rate=$(awk '/particle-steps\/s/ { for (i = 1; i <= NF; i++) if ($i ~ /^[0-9.e+]+$/) { print $i; exit } }' "$c/log.$prog")
    echo "$(awk '{ print $1 + $2 }' "$c/cpu.txt") $rate" >> "$W/$tag"
}
for r in $(seq "$REPEAT"); do
    if [ $((r % 2)) = 1 ]; then order="old new"; else order="new old"; fi
    for side in $order; do
        bin=$OLD; [ $side = new ] && bin=$NEW
        run "$M" mpsFluid "$bin" mps.$side
        run "$G" demSolid "$bin" dem.$side
    done
done
stats() {   # FILE COLUMN: min median
    cut -d' ' -f"$2" "$1" | sort -g | awk '{ c[NR] = $1 }
        END { m = NR % 2 ? c[(NR + 1) / 2] : (c[NR / 2] + c[NR / 2 + 1]) / 2; print c[1], m }'
}
echo "# $REPEAT interleaved runs per build, 1 thread; load before: $LOAD0, after: $(cut -d' ' -f1-3 /proc/loadavg)"
printf "%-5s %-4s %10s %10s %14s %14s\n" case side "CPU min" "CPU med" "rate max" "rate med"
for c in mps dem; do
    for side in old new; do
        read -r cmin cmed < <(stats "$W/$c.$side" 1)
        read -r rmin rmed < <(stats "$W/$c.$side" 2)
        rmax=$(cut -d' ' -f2 "$W/$c.$side" | sort -g | tail -n 1)
        printf "%-5s %-4s %10s %10s %14s %14s\n" $c $side "$cmin" "$cmed" "$rmax" "$rmed"
    done
    read -r a _ < <(stats "$W/$c.old" 1)
    read -r b _ < <(stats "$W/$c.new" 1)
    awk -v c=$c -v a=$a -v b=$b 'BEGIN { printf "%s: new/old CPU (minimum) = %.3f\n", c, b / a }'
done
echo "(CPU = user + system seconds of the whole process, set-up included; rate = the solver's"
echo " particle-steps per wall second from its final statistics)"
