#!/usr/bin/env bash
# Sets everything up and runs the main job on a small default scene: a 125-particle
# simple-cubic lattice of p = 1.5 superballs (data/), converted to the HDF5 format,
# validated and analysed (phi, mean width, contacts Z = 6, rattlers; S(Q), voxels and chi(Q) into
# an HDF5 results file, the voxels as .vdb), and exported for OVITO.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p build/demo
build/analysis/sbanalyze convert data/sc-lattice-p1.5.txt build/demo/sc-lattice-p1.5.h5
build/analysis/sbanalyze info build/demo/sc-lattice-p1.5.h5
build/analysis/sbanalyze convert build/demo/sc-lattice-p1.5.h5 build/demo/sc-lattice-p1.5.xyz
build/analysis/sbanalyze build/demo/sc-lattice-p1.5.h5 --voxels 60 --qmax 15 \
  --out build/demo/sc-lattice-p1.5-results.h5 --vdb build/demo --json -
