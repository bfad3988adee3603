#!/bin/sh
# hydrostatic.sh CASE [WINDOW [DIR]] — the still-water checks of
# doc/theory.md E1-07/E1-08 (L2 of the time-averaged pressure, largest
# fluid speed, deep free-surface flags). The 2-D and 3-D tanks share one
# script, ../hydrostaticTank2D/validation/hydrostatic.sh (its header says
# what it prints), found in the repository through MPSDEM_DIR for a
# copied case.
ROOT="${MPSDEM_DIR:-$(cd "$(dirname "$0")/../../../.." && pwd)}"
exec "$ROOT/tutorials/mpsFluid/hydrostaticTank2D/validation/hydrostatic.sh" "$@"
