#!/bin/sh
# soilLayer.sh CASE [WINDOW] — the checks of a soil layer under still water
# (doc/theory.md E5-02) on the fluid.vtu snapshots of the last WINDOW
# seconds (default 0.2), soil and water told apart by the field phase:
#   L2soil   relative L2 error of the time-averaged soil pressure (per
#            particle id) against rho g (h_w - h_s) + rho_s g (h_s - y),
#            h_s the top of the soil, h_w the water surface (initial
#            highest particles + dp/2); E5-02 asks < 0.05
#   L2water  the same for the water, against rho g (h_w - y)
#   maxdisp  largest displacement of a soil particle since t = 0 [dp]
#   umax     largest soil speed in the window / sqrt(g h_w)
# Writes CASE/validation/pressure.dat: id phase mean-y mean-p exact-p.
set -e
CASE=${1:-.}
WIN=${2:-0.2}
ROOT="${MPSDEM_DIR:-$(cd "$(dirname "$0")/../../../.." && pwd)}"   # MPSDEM_DIR for a copied case
VTU="$ROOT/bin/vtuInfo"
cd "$CASE"
dp=$(awk '/^dp/ {gsub(";","",$2); print $2}' constant/particlePatches)
rho=$(sed 's|//.*||' constant/transportProperties | awk '/^rho/ {gsub(";","",$NF); print $NF}')
rhos=$(sed 's|//.*||' constant/soilProperties | awk '/^rho/ {gsub(";","",$NF); print $NF}')
times=$(ls -d [0-9]* | sort -g)
last=$(echo "$times" | tail -1)
mkdir -p validation
for t in $times; do
    awk -v t=$t -v l=$last -v w=$WIN 'BEGIN { exit !(t == 0 || t >= l - w - 1e-9) }' || continue
    "$VTU" -dump "$t/fluid.vtu" 2>/dev/null | awk -v t=$t '
        /^# x/ { for (i = 2; i <= NF; i++) c[$i] = i - 1; next }
        /^#/ || NF < 5 { next }
        $c["type"] == 0 { print t, $c["id"], $c["phase"], $1, $2, $c["pressure"],
                          sqrt($c["velocity_0"]^2 + $c["velocity_1"]^2) }'
done | awk -v dp=$dp -v rho=$rho -v rhos=$rhos -v g=9.81 -v l=$last -v w=$WIN -v out=validation/pressure.dat '
    $1 == 0 { x0[$2] = $4; y0[$2] = $5; if ($3 == 1 && $5 > hs) hs = $5; if ($5 > hw) hw = $5; next }
    { id = $2; ph[id] = $3; n[id]++; ys[id] += $5; ps[id] += $6
      if ($3 == 1) { d = sqrt(($4 - x0[id])^2 + ($5 - y0[id])^2); if (d > dmax) dmax = d
                     if ($7 > umax) umax = $7 } }
    END { hs += dp / 2; hw += dp / 2
          for (id in n) { y = ys[id] / n[id]; p = ps[id] / n[id]
              e = ph[id] == 1 ? rho * g * (hw - hs) + rhos * g * (hs - y) : rho * g * (hw - y)
              printf "%d %d %.6g %.6g %.6g\n", id, ph[id], y, p, e > out
              if (ph[id] == 1) { es += (p - e)^2; rs += e^2 } else { ew += (p - e)^2; rw += e^2 } }
          printf "L2soil %.4f\nL2water %.4f\nmaxdisp %.4f\numax %.5f\nwindow %g-%g s\n",
                 sqrt(es / rs), sqrt(ew / rw), dmax / dp, umax / sqrt(g * hw), l - w, l }'
