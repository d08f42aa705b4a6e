#!/usr/bin/env bash
# The speed knob's cost (issue 66 item 3; docs/design.md §3, "Speed"): sbgen at --speed X (the
# default slow rate times X) for each p and seed, N particles, two runs at a time; then each
# (p, X) ensemble's phi, Z and phi_R (sbanalyze --compute contacts) against its sbgen CPU time
# (bench/speed_knob_summary.py prints the table). Packings already made are kept.
#   bench/speed_knob.sh [BUILD] [WORK] [N] [P_LIST] [SPEEDS] [SEEDS]
#   defaults: build /tmp/sbpack-speed 300 "1 1.3 3" "1 3 10" "1 2 3"
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build} work=${2:-/tmp/sbpack-speed} n=${3:-300}
plist=${4:-"1 1.3 3"} speeds=${5:-"1 3 10"} seeds=${6:-"1 2 3"}
mkdir -p "$work"
for p in $plist; do
    for x in $speeds; do
        for s in $seeds; do
            out=$work/p$p-x$x-s$s.h5
            [ -f "$out" ] || echo "$p $x $s"
        done
    done
done | SBGEN=$build/generator/sbgen WORK=$work N=$n xargs -r -P 2 -L 1 bash -c '
    "$SBGEN" --p "$0" --speed "$1" --seed "$2" --n "$N" --quiet \
        --out "$WORK/p$0-x$1-s$2.h5" 2> "$WORK/p$0-x$1-s$2.log" || [ $? -eq 3 ]'
for p in $plist; do
    for x in $speeds; do
        files=()
        for s in $seeds; do files+=("$work/p$p-x$x-s$s.h5"); done
        "$build/analysis/sbanalyze" "${files[@]}" --compute contacts --quiet \
            --out "$work/results-p$p-x$x.h5"
    done
done
/usr/bin/python3 "$root/bench/speed_knob_summary.py" "$work"/results-p*-x*.h5
