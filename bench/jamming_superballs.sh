#!/usr/bin/env bash
# Acceptance runs of sbgen on rotating superballs (issue 4): N = 1000 at the paper's p values,
# to reduced pressure 1e12 with --gamma-slow 1e-2, and the extreme runs N = 200 at p = 0.55 ..
# 10 to 1e8 (each capped at EXTREME_SECONDS, default 3600: p = 10 takes 8-20 CPU minutes).
# Prints markdown tables: phi against the paper, Z, phi_R, the worst pair gap from the exact pair
# geometry (common/pair, independent of the predictor), throughput per CPU second and the
# predictor's work.
# Several copies may run at once over the same WORK_DIR (one per core): each run is claimed by
# a lock directory before it starts.
# usage: bench/jamming_superballs.sh [BUILD_DIR] [WORK_DIR] [SEEDS] [P VALUES]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build} work=${2:-/tmp/sbpack-jamming-superballs}
seeds=${3:-"1 2 3"} exponents=${4:-"0.85 0.9 1.1 1.2 1.5"}
extreme_seconds=${EXTREME_SECONDS:-3600}
mkdir -p "$work"
claim() { [ ! -f "$1" ] && mkdir "$1.claim" 2> /dev/null; }
for seed in $seeds; do
    for p in $exponents; do
        out="$work/mrj-p$p-s$seed.h5"
        claim "$out" && "$build/generator/sbgen" --n 1000 --p "$p" --seed "$seed" \
            --gamma-slow 1e-2 --out "$out" 2> "$work/mrj-p$p-s$seed.log"
    done
done
for p in 0.55 0.7 3 5 10; do
    out="$work/extreme-p$p.h5"
    claim "$out" && { timeout -s TERM "$extreme_seconds" "$build/generator/sbgen" --n 200 --p "$p" \
        --seed 1 --gamma-slow 1e-2 --pressure-final 1e8 --out "$out" \
        2> "$work/extreme-p$p.log" || true; }
done
/usr/bin/python3 "$root/bench/jamming_superball_summary.py" "$work"
