#!/usr/bin/env bash
# The analysis benchmark of bench/RESULTS.md, in one run: builds the N = 5000 test packings,
# times sbanalyze's stages (bench_analysis, 1 and 2 threads), runs the numpy peer on the same
# grid (timing and a cross-check of chi, S and phi_voxel), and measures the peak memory of the
# 500^3 voxelization. Needs a Release build (scripts/build.sh) and /usr/bin/python3 with numpy
# and h5py.
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/bench-analysis
mkdir -p "$out"
sb=build/analysis/sbanalyze
for spec in "1.0 0.6 1" "1.5 0.52 2"; do
  set -- $spec
  python3 scripts/make_test_packing.py "$1" 5000 "$2" "$3" "$out/n5000-p$1.txt"
  "$sb" convert "$out/n5000-p$1.txt" "$out/n5000-p$1.h5" 2>/dev/null
done
wisdom="$out/fftw-wisdom" # planned once (FFTW_MEASURE) by the first bench_analysis call
for threads in 2 1; do
  for p in 1.5 1.0; do
    build/bench/bench_analysis "$out/n5000-p$p.h5" --threads "$threads" --repeats 7 \
      --sq-shell 40 --fft-wisdom "$wisdom"
  done
done
"$sb" "$out/n5000-p1.5.h5" --threads 2 --voxels 300 --fft-wisdom "$wisdom" --quiet \
  --out "$out/results-p1.5.h5"
/usr/bin/python3 bench/peer_numpy_fft.py "$out/n5000-p1.5.h5" --voxels 300 --repeats 5 \
  --check "$out/results-p1.5.h5"
for m in 500 100; do
  /usr/bin/time -v "$sb" "$out/n5000-p1.5.h5" --threads 2 --compute voxels --voxels "$m" \
    --out "$out/voxels-$m.h5" 2>&1 | grep -E "voxelization|Maximum resident"
done
