#!/usr/bin/env bash
# No hidden first-run costs (issue 21): the full default analysis of one packing with no FFT
# wisdom (XDG_CACHE_HOME an empty temporary directory) against the warm run that follows, with
# the default --fft-planning-budget and with none (unlimited measuring), 2 threads.
# Prints one line per run: budget, first|warm, wall seconds, the FFT plan line.
# usage: bench/first_run.sh [BUILD_DIR] [PACKING]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build} packing=${2:-$root/data/mrj-spheres-5000.h5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for budget in default none; do
    mkdir -p "$work/cache-$budget"
    extra=()
    [ "$budget" = default ] || extra=(--fft-planning-budget "$budget")
    for run in first warm; do
        start=$(date +%s.%N)
        XDG_CACHE_HOME=$work/cache-$budget "$build/analysis/sbanalyze" "$packing" --threads 2 \
            --out "$work/out.h5" "${extra[@]}" 2> "$work/log"
        end=$(date +%s.%N)
        plan=$(grep -o 'FFT plan: .*' "$work/log" || true)
        printf '%s\t%s\t%.2f\t%s\n' "$budget" "$run" "$(echo "$end - $start" | bc)" "$plan"
    done
done
