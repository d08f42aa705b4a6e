#!/usr/bin/env bash
# Cross-checks sbanalyze --compute voronoi against freud's Voronoi cells of the centres on a
# sphere packing, where the set-Voronoi cells are those (issue 69; bench/RESULTS.md, "Set-Voronoi
# cells against freud"). Exits non-zero when the cells disagree beyond the tolerance stated in
# bench/voronoi_vs_freud.py.
# usage: bash bench/voronoi_vs_freud.sh [SBANALYZE] [PACKING] [M ...]
#   SBANALYZE  default build/analysis/sbanalyze; PACKING  default data/mrj-spheres-5000.h5;
#   M          the grids (default 150 300 450 600)
# environment:
#   SBPACK_FREUD_VENV  virtual environment with freud, h5py and numpy (bench/freud_venv.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
sbanalyze=${1:-$root/build/analysis/sbanalyze}
packing=${2:-$root/data/mrj-spheres-5000.h5}
shift $(($# < 2 ? $# : 2))
python=$(bash "$root/bench/freud_venv.sh")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$python" "$root/bench/voronoi_vs_freud.py" "$sbanalyze" "$packing" --work "$work" \
    ${1:+--voxels "$@"}
