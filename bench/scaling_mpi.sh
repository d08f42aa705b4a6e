#!/usr/bin/env bash
# Strong scaling of the distributed grids (docs/scale-out.md; bench/RESULTS.md, "Scale-out"):
# sbanalyze --distribute grids on 1, 2 and 4 ranks (one thread each) at M = 256 and 512, chi and
# pores separately, with the figures that transfer to a cluster (communication, memory per rank)
# from the results file and the wall time of each stage.
#   bench/scaling_mpi.sh [BUILD] [PACKING]
set -euo pipefail
build=${1:-build} packing=${2:-data/mrj-p1.5-1000.h5}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| analysis | M | ranks | slab | memory per rank (MB) | communication (MB) | stage wall (s) |"
echo "|---|---|---|---|---|---|---|"
for m in 256 512; do
    for compute in chi pores; do
        group=$([[ $compute == chi ]] && echo spectral_density || echo pore_size)
        for np in 1 2 4; do
            mpirun -np "$np" --oversubscribe "$build/analysis/sbanalyze" "$packing" \
                --compute "$compute" --distribute grids --voxels "$m" --pore-voxels "$m" \
                --threads 1 --fft-plan estimate --fft-wisdom none --quiet --out "$work/r.h5"
            /usr/bin/python3 - "$work/r.h5" "$group" "$compute" "$m" "$np" <<'PY'
import sys, h5py
f = h5py.File(sys.argv[1]); g = f["files/0/" + sys.argv[2]].attrs
wall = g["runtime_s"] + (f["files/0/voxelization"].attrs["runtime_s"] if sys.argv[3] == "chi" else 0)
print(f"| {sys.argv[3]} | {sys.argv[4]} | {sys.argv[5]} | {g['slab']} | "
      f"{g['memory_per_rank_bytes'] / 1e6:.1f} | {g['communication_bytes'] / 1e6:.1f} | {wall:.2f} |")
PY
        done
    done
done
