#!/usr/bin/env bash
# The nearest jammed packing of sbgen's packings (issue 62; docs/jamming.md §6.7): N packings per
# p on sbgen's defaults, each analysed for its jamming categories as given, with --jamming-relax on
# and with the box free (--jamming-relax box, §6.8); a markdown table of the three
# (bench/jamming_relax_summary.py). Resumable: files already written are kept.
# usage: bench/jamming_relax.sh [BUILD_DIR] [WORK_DIR] [N] [SEEDS] [P VALUES]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build} work=${2:-/tmp/sbpack-jamming-relax} n=${3:-100}
seeds=${4:-"1 2 3"} exponents=${5:-"1 1.1 1.5 0.85 3"}
mkdir -p "$work"
for p in $exponents; do
    for seed in $seeds; do
        name=p$p-s$seed
        [ -f "$work/$name.h5" ] || "$build/generator/sbgen" --p "$p" --n "$n" --seed "$seed" \
            --quiet --out "$work/$name.h5" 2> "$work/$name.log" || true
        [ -f "$work/$name.h5" ] || continue
        for mode in given relaxed box; do
            relax=off; [ $mode = relaxed ] && relax=on; [ $mode = box ] && relax=box
            [ -f "$work/$mode-$name.h5" ] || "$build/analysis/sbanalyze" "$work/$name.h5" \
                --compute contacts,jamming --jamming-relax $relax --threads 1 \
                --out "$work/$mode-$name.h5" 2> "$work/$mode-$name.log"
        done
    done
done
/usr/bin/python3 "$root/bench/jamming_relax_summary.py" "$work"
