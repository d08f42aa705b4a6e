#!/usr/bin/env bash
# Acceptance run of sbgen on spheres: N = 1000, default protocol, seeds 1..5 to reduced pressure
# 1e12, then seed 1 continued to 1e14. Prints a markdown table (phi, Z, phi_R, smallest gap by
# brute force, throughput, wall time) and the pressure against collisions near the end.
# usage: bench/jamming_spheres.sh [BUILD_DIR] [WORK_DIR] [SEEDS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build} work=${2:-/tmp/sbpack-jamming-spheres} seeds=${3:-"1 2 3 4 5"}
mkdir -p "$work"
for seed in $seeds; do
    "$build/generator/sbgen" --n 1000 --seed "$seed" --out "$work/seed$seed.h5" 2> "$work/seed$seed.log"
done
first=${seeds%% *}
"$build/generator/sbgen" --resume "$work/seed$first.h5" --pressure-final 1e14 \
    --out "$work/seed$first-1e14.h5" 2> "$work/seed$first-1e14.log"
/usr/bin/python3 "$root/bench/jamming_summary.py" "$work" $seeds
