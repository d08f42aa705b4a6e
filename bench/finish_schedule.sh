#!/usr/bin/env bash
# Issue 64 item 1: what the growth rate past a pressure P* changes. For each p and seed, sbgen's
# default run (the paper's protocol) is made as a chain that stops at each P* of P_STARS and
# goes on (--resume --pressure-final) to the final 1e12; from each stop, the run goes on to 1e12
# with the slow rate times X for each X of SPEEDS (--resume --pressure-finish P* --finish-speed
# X). Each output's provenance sums the CPU time of its whole chain (the default run's prefix
# included), so the table compares whole runs. bench/finish_schedule_summary.py then compares
# each finish with the default run of the same seed: phi, Z, phi_R, the particles whose contact
# count or rattler status differs, the largest displacement between the two packings, and the
# CPU time. With REFINE (a pressure), each finish is also made returning to the slow rate at
# REFINE (the finish to REFINE, then --resume --finish-speed 1 to 1e12; named ...-xX-slow-REFINE).
# Packings already made are kept; jobs run two at a time.
#   bench/finish_schedule.sh [BUILD] [WORK] [N] [P_LIST] [SEEDS] [P_STARS] [SPEEDS] [REFINE]
#   defaults: build /tmp/sbpack-finish 1000 "1 1.5" "1 2" "1e8 1e10" "10 100" (no REFINE)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build} work=${2:-/tmp/sbpack-finish} n=${3:-1000}
plist=${4:-"1 1.5"} seeds=${5:-"1 2"} stars=${6:-"1e8 1e10"} speeds=${7:-"10 100"}
refine=${8:-}
sbgen=$build/generator/sbgen
mkdir -p "$work"
export SBGEN=$sbgen WORK=$work N=$n STARS=$stars
# The default chain of one (p, seed): stops at each P*, then 1e12 (exit 3, not jammed, is kept).
chain() {
    local p=$1 s=$2 previous="" out
    for stop in $STARS 1e12; do
        out=$WORK/p$p-s$s-default-$stop.h5
        if [ ! -f "$out" ]; then
            if [ -z "$previous" ]; then
                "$SBGEN" --p "$p" --n "$N" --seed "$s" --pressure-final "$stop" --quiet \
                    --out "$out" 2> "$out.log" || [ $? -eq 3 ]
            else
                "$SBGEN" --resume "$previous" --pressure-final "$stop" --quiet --out "$out" \
                    2> "$out.log" || [ $? -eq 3 ]
            fi
        fi
        previous=$out
    done
}
export -f chain
for p in $plist; do for s in $seeds; do echo "$p $s"; done; done |
    xargs -r -P 2 -L 1 bash -c 'chain "$0" "$1"'
# "p seed P* X" of each finish whose output WORK/p<p>-s<seed>-finish-<P*>-x<X><SUFFIX>.h5 is missing.
missing() {
    local p s star x
    for p in $plist; do for s in $seeds; do for star in $stars; do for x in $speeds; do
        [ -f "$work/p$p-s$s-finish-$star-x$x$1.h5" ] || echo "$p $s $star $x"
    done; done; done; done
}
missing "" | xargs -r -P 2 -L 1 bash -c '
    out=$WORK/p$0-s$1-finish-$2-x$3.h5
    "$SBGEN" --resume "$WORK/p$0-s$1-default-$2.h5" --pressure-final 1e12 --pressure-finish "$2" \
        --finish-speed "$3" --quiet --out "$out" 2> "$out.log" || [ $? -eq 3 ]'
summary_speeds=$speeds
if [ -n "$refine" ]; then
    missing "-slow-$refine" | REFINE=$refine xargs -r -P 2 -L 1 bash -c '
        part=$WORK/p$0-s$1-finish-$2-x$3-to-$REFINE.h5 out=$WORK/p$0-s$1-finish-$2-x$3-slow-$REFINE.h5
        "$SBGEN" --resume "$WORK/p$0-s$1-default-$2.h5" --pressure-final "$REFINE" \
            --pressure-finish "$2" --finish-speed "$3" --quiet --out "$part" 2> "$part.log" ||
            [ $? -eq 3 ]
        "$SBGEN" --resume "$part" --pressure-final 1e12 --finish-speed 1 --quiet --out "$out" \
            2> "$out.log" || [ $? -eq 3 ]'
    for x in $speeds; do summary_speeds="$summary_speeds $x-slow-$refine"; done
fi
PYTHONPATH=$build/python /usr/bin/python3 "$root/bench/finish_schedule_summary.py" "$work" \
    "$plist" "$seeds" "$stars" "$summary_speeds"
