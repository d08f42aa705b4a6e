#!/usr/bin/env bash
# Error against run time (issue 21): each analysis's accuracy knob against a converged reference,
# with the wall time of `sbanalyze --threads 2` for that analysis alone (the process, file read
# included). Prints a markdown table (bench/error_vs_time_summary.py) and keeps the raw results.
#   pores, F(delta): voxel and refined at M = 100, 200, 300, 500, refined from 1e6 random void
#     voxels at M = 300 and 500, and the exact sampler at K = 1e4, 1e5, 1e6, against the exact sampler at K = 1e7 with another seed (independent);
#   chi_V (spheres): voxel M = 100, 200, 300, 500 against the exact sphere path of the chi stage
#     (exact_error: max over shells |chi - chi_exact| / peak);
#   S(Q): qmax 10, 20, 30, 60 (exact direct sums; error on the shells shared with qmax 60);
#   contacts: tolerance 1e-12 .. 1e-4 against the paper's 1e-10.
# usage: bench/error_vs_time.sh [BUILD_DIR] [WORK_DIR] [PACKINGS...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build} work=${2:-/tmp/sbpack-error-vs-time}
shift $(($# < 2 ? $# : 2))
packings=("$@")
[ ${#packings[@]} -gt 0 ] || packings=("$root/data/mrj-spheres-5000.h5" "$root/data/mrj-p1.5-5000.h5")
sbanalyze=$build/analysis/sbanalyze
mkdir -p "$work/cache"
export XDG_CACHE_HOME=$work/cache # FFT wisdom of this benchmark only
times=$work/times.tsv
: > "$times"
# run NAME ARGS...: one sbanalyze run into $work/NAME.h5, its wall time into times.tsv.
run() {
    local name=$1
    shift
    local start end
    start=$(date +%s.%N)
    "$sbanalyze" "$@" --threads 2 --quiet --out "$work/$name.h5"
    end=$(date +%s.%N)
    printf '%s\t%s\n' "$name" "$(echo "$end - $start" | bc)" >> "$times"
}
for packing in "${packings[@]}"; do
    stem=$(basename "$packing" .h5)
    run "$stem-pores-reference" "$packing" --compute pores --pores exact --pore-points 10000000 \
        --pore-seed 2
    for m in 100 200 300 500; do
        run "$stem-pores-voxel-$m" "$packing" --compute pores --pores voxel --pore-voxels "$m"
        run "$stem-pores-refined-$m" "$packing" --compute pores --pores refined --pore-voxels "$m"
    done
    for m in 300 500; do
        run "$stem-pores-refined1e6-$m" "$packing" --compute pores --pores refined \
            --pore-voxels "$m" --pore-points 1000000
    done
    for k in 10000 100000 1000000; do
        run "$stem-pores-exact-$k" "$packing" --compute pores --pores exact --pore-points "$k"
    done
    for qmax in 10 20 30 60; do
        run "$stem-sq-$qmax" "$packing" --compute sq --qmax "$qmax"
    done
    for tolerance in 1e-12 1e-10 1e-8 1e-6 1e-4; do
        run "$stem-contacts-$tolerance" "$packing" --compute contacts --tolerance "$tolerance"
    done
done
# chi_V against the exact path: spheres only (the exact shells are the chi stage's own).
for packing in "${packings[@]}"; do
    stem=$(basename "$packing" .h5)
    case $stem in *spheres*) ;; *) continue ;; esac
    for m in 100 200 300 500; do # the first run of each M may plan its FFT (budget 2 s)
        run "$stem-chi-$m-warmup" "$packing" --compute chi --voxels "$m"
        run "$stem-chi-$m" "$packing" --compute chi --voxels "$m"
    done
done
/usr/bin/python3 "$root/bench/error_vs_time_summary.py" "$work"
