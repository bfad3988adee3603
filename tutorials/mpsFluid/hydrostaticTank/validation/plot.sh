#!/bin/sh
# plot.sh [CASE] [WINDOW] [PNG] — validation/hydrostatic.png of a finished run
# (CASE default .): the 2-D and 3-D still-water tanks share one plotting
# script, ../hydrostaticTank2D/validation/plot.sh (and plot.gnuplot beside
# it), found in the repository through MPSDEM_DIR for a copied case.
ROOT="${MPSDEM_DIR:-$(cd "$(dirname "$0")/../../../.." && pwd)}"
exec "$ROOT/tutorials/mpsFluid/hydrostaticTank2D/validation/plot.sh" "$@"
