#!/usr/bin/env bash
# Refined pore sizes against the voxel method at the same grid (issue 21: "in at most 2x the
# voxel method's time"): user CPU seconds of whole `sbanalyze --compute pores --threads 1`
# processes (read, voxelization, distance or feature transform, pore sizes, largest pore),
# alternating the methods REPS times so that both see the same machine; prints the median of
# each and their ratio per packing. The refined runs take `--pore-points K` random void voxels
# (default 10^6, the paper's count; 0: every void voxel).
# usage: bench/refined_vs_voxel.sh [BUILD_DIR] [M] [REPS] [K] [PACKINGS...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build} m=${2:-300} reps=${3:-5} points=${4:-1000000}
shift $(($# < 4 ? $# : 4))
packings=("$@")
[ ${#packings[@]} -gt 0 ] || packings=("$root/data/mrj-spheres-5000.h5" "$root/data/mrj-p1.5-5000.h5")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# user NAME ARGS...: the user CPU seconds of one sbanalyze run.
user() {
    /usr/bin/time -f "%U" -o "$work/time" "$build/analysis/sbanalyze" "$@" --compute pores \
        --pore-voxels "$m" --threads 1 --quiet --out "$work/out.h5" > /dev/null
    cat "$work/time"
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
echo "| packing | M | voxel s (median of $reps) | refined s, K = $points | refined / voxel |"
echo "|---|---|---:|---:|---:|"
for packing in "${packings[@]}"; do
    : > "$work/voxel" && : > "$work/refined"
    for _ in $(seq "$reps"); do
        user "$packing" --pores voxel >> "$work/voxel"
        user "$packing" --pores refined --pore-points "$points" >> "$work/refined"
    done
    v=$(median < "$work/voxel") r=$(median < "$work/refined")
    echo "| $(basename "$packing") | $m | $v | $r | $(echo "scale=2; $r / $v" | bc) |"
done
