#!/usr/bin/env bash
# Cross-checks sbanalyze --compute order against the peer freud (freud.order.Steinhardt,
# freud.density.RDF) on one packing and times both on one thread (issue 44; bench/RESULTS.md,
# "Order metrics against freud"). Exits non-zero when q_l(i), Q_l or g2 disagree beyond the
# tolerances stated in bench/order_vs_freud.py. Then bench/solid_like_vs_freud.py checks the
# solid-like particles against freud.order.SolidLiquid on PACKING and on eight lattices (issue 63;
# bench/RESULTS.md, "Solid-like particles against freud").
# usage: bash bench/order_vs_freud.sh [SBANALYZE] [PACKING]
#   SBANALYZE  default build/analysis/sbanalyze; PACKING  default data/mrj-spheres-5000.h5
# environment:
#   SBPACK_FREUD_VENV  virtual environment with freud, h5py and numpy (bench/freud_venv.sh)
#   REPEATS            timed runs of each side, median reported (default 5)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
sbanalyze=${1:-$root/build/analysis/sbanalyze}
packing=${2:-$root/data/mrj-spheres-5000.h5}
python=$(bash "$root/bench/freud_venv.sh")

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$python" "$root/bench/order_vs_freud.py" "$sbanalyze" "$packing" \
    --repeats "${REPEATS:-5}" --work "$work"
"$python" "$root/bench/solid_like_vs_freud.py" "$sbanalyze" "$packing" --lattices \
    --work "$work"
