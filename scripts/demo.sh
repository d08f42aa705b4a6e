#!/usr/bin/env bash
# Sets everything up and runs the main job on a small default scene: sbgen jams 250 spheres
# (seed 1, a quick slow phase with --speed 10) to reduced pressure 1e12 in about ten
# seconds; sbanalyze validates the packing, reports phi, the mean width, contacts Z and
# rattlers, computes S(Q), the voxels, chi(Q), the pore sizes F(delta) and the transport
# estimates into an HDF5 results file (the voxels and pore sizes also as .vdb), and exports the
# packing for OVITO, then draws the figures (S(Q), chi(Q), F(delta) as PNG; the box of 250 is
# too small for the spreadability's long-time window, which sbanalyze says in a warning).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p build/demo
build/generator/sbgen --n 250 --seed 1 --speed 10 --pressure-final 1e12 --out build/demo/mrj-spheres-250.h5
build/analysis/sbanalyze info build/demo/mrj-spheres-250.h5
build/analysis/sbanalyze build/demo/mrj-spheres-250.h5 --voxels 100 --pore-voxels 200 --qmax 15 \
  --out build/demo/mrj-spheres-250-results.h5 --vdb build/demo --json -
build/analysis/sbanalyze convert build/demo/mrj-spheres-250.h5 build/demo/mrj-spheres-250.xyz
PYTHONPATH=build/python /usr/bin/python3 -m sbpack.plot build/demo/mrj-spheres-250-results.h5 --out build/demo
