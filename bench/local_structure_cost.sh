#!/usr/bin/env bash
# Error against run time of the local-structure analyses (issue 69; docs/local-structure.md,
# bench/RESULTS.md "Local structure: error against run time"): sbanalyze --compute voronoi at
# several --voxels (the sd of the local phi, which the voxel error inflates, and the stage's
# runtime_s) and --compute variance at several --variance-windows (the sampled route's median
# relative error bar and the stage's runtime_s), on one packing, 2 threads.
# usage: bash bench/local_structure_cost.sh [SBANALYZE] [PACKING]
#   SBANALYZE  default build/analysis/sbanalyze; PACKING  default data/mrj-p1.5-5000.h5
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
sbanalyze=${1:-$root/build/analysis/sbanalyze}
packing=${2:-$root/data/mrj-p1.5-5000.h5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
read_attrs() { # FILE GROUP EXPRESSION: a python expression of a (attributes) and d (datasets)
    /usr/bin/python3 -c "
import h5py, numpy as np
g = h5py.File('$1')['files/0/$2']; a = g.attrs; d = g
print($3)"
}
echo "voronoi: M  sd(local phi)  mean(local phi)  runtime_s (2 threads)"
for m in 150 300 450; do
    "$sbanalyze" "$packing" --compute voronoi --voxels "$m" --threads 2 --quiet \
        --out "$work/v$m.h5"
    read_attrs "$work/v$m.h5" voronoi \
        "f\"{$m:4d}  {a['local_phi_sd']:.5f}  {a['local_phi_mean']:.5f}  {a['runtime_s']:.2f}\""
done
echo "variance: K  median(error / sigma2)  largest route deviation  runtime_s (2 threads, M = 300)"
for k in 250 1000 4000; do
    "$sbanalyze" "$packing" --compute variance --variance-windows "$k" --threads 2 --quiet \
        --out "$work/s$k.h5"
    read_attrs "$work/s$k.h5" variance "f\"{$k:5d}  {np.median(d['sigma2_sampled_error'][:] / \
d['sigma2_sampled'][:]):.4f}  {a['route_deviation_max']:.2f}  {a['runtime_s']:.2f}\""
done
