#!/usr/bin/env bash
# Stiff cases of sbgen (issue 25): near-cubes p = 2, 3, 5, 10 at N = 200 and 1000, three seeds,
# defaults but --gamma-slow 1e-2, to reduced pressure 1e12. Each output is either jammed (exit 0)
# or refused (exit 3, provenance jammed = 0 with the reason); the summary checks every output
# sbgen calls jammed with `sbanalyze info` at a gap tolerance of 1e-8 D (mean contacts per
# particle >= 5, rattler fraction < 10 %, no overlap) and tabulates the predictor's work per
# collision and the CPU time. Runs go over the cores with xargs -P (JOBS, default nproc); each
# run is capped at SECONDS_CAP seconds of wall time (default 3600) and checkpoints every 600 s; a
# capped or killed run is reported with the state of its checkpoint, and running the script again
# resumes it.
# usage: bench/jamming_stiff.sh [BUILD_DIR] [WORK_DIR] [SEEDS] [P VALUES] [N VALUES]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build} work=${2:-/tmp/sbpack-jamming-stiff}
seeds=${3:-"1 2 3"} exponents=${4:-"2 3 5 10"} sizes=${5:-"200 1000"}
cap=${SECONDS_CAP:-3600} jobs=${JOBS:-$(nproc)}
mkdir -p "$work"
run_one() { # work cap p n seed build
    local out="$1/stiff-p$3-n$4-s$5.h5"
    [ -f "$out" ] && return 0
    # Every run writes a checkpoint beside OUT every 600 s, and a capped run's SIGTERM one more:
    # running the script again resumes the newest (bit for bit from a SIGTERM's), and CPU times
    # accumulate in OUT.time. sbgen refuses to overwrite its --resume input, so the checkpoint
    # to resume is moved aside first (and kept there until a newer one is written).
    local checkpoint="${out%.h5}.checkpoint.h5" rc=0
    local resumed="${out%.h5}.resumed.h5"
    local start=(--p "$3" --n "$4" --seed "$5" --gamma-slow 1e-2)
    [ -f "$checkpoint" ] && mv "$checkpoint" "$resumed"
    [ -f "$resumed" ] && start=(--resume "$resumed")
    /usr/bin/time -f "%U %S" -a -o "$out.time" timeout -s TERM "$2" "$6/generator/sbgen" \
        "${start[@]}" --out "$out" --checkpoint "$checkpoint" --quiet 2>> "$out.log" || rc=$?
    echo "$rc" > "$out.rc"
}
export -f run_one
for n in $sizes; do for p in $exponents; do for s in $seeds; do
    echo "$work $cap $p $n $s $build"
done; done; done | xargs -P "$jobs" -L 1 bash -c 'run_one "$@"' _
/usr/bin/python3 "$root/bench/jamming_stiff_summary.py" "$work" "$build/analysis/sbanalyze"
