#!/usr/bin/env bash
# Issue 65 item 3's acceptance matrix (docs/reliability.md, "Signals"): sbgen stopped by two
# SIGTERMs 50 ms apart, the first T s after its start, for each N and T. Every stop must exit with
# 143 (128 + SIGTERM); where it wrote a checkpoint, that checkpoint resumed must give the
# uninterrupted run's packing bit for bit (compared through sbanalyze's 17-digit text export);
# where it wrote none (a stop in the set-up or the first window), nothing may be left. A run that
# ends before the first signal is reported, not failed.
# usage: double_signal_matrix.sh SBGEN SBANALYZE WORKDIR ["N ..."] ["T ..."]
set -euo pipefail
sbgen=$(realpath "$1") analyze=$(realpath "$2") work=$3
ns=${4:-"30 1000 1000000"} times=${5:-"0.1 0.3 1 3"}
# Short runs (p = 1.5: the rotating engine) so the references end in seconds to a minute: to
# P = 1e5, or for N < 100 to the paper's 1e12 (about 2 s at N = 30).
args=(--p 1.5 --seed 4 --gamma-slow 0.01 --pressure-switch 1e3 --quiet)
final() { if [[ $1 -lt 100 ]]; then echo 1e12; else echo 1e5; fi; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"
failed=0

# The uninterrupted run of N particles as text, made once per N when first needed.
reference() {
    [[ -f ref-$1.txt ]] && return
    "$sbgen" "${args[@]}" --n "$1" --pressure-final "$(final "$1")" --out "ref-$1.h5" 2>/dev/null
    "$analyze" convert "ref-$1.h5" "ref-$1.txt" 2>/dev/null
}

for n in $ns; do
    for t in $times; do
        name=run-$n-$t
        start=$(date +%s.%N)
        "$sbgen" "${args[@]}" --n "$n" --pressure-final "$(final "$n")" --out "$name.h5" \
            2> "$name.log" &
        pid=$!
        sleep "$t"
        kill -TERM "$pid" 2>/dev/null || true
        sleep 0.05
        kill -TERM "$pid" 2>/dev/null || true
        sent=$(date +%s.%N)
        status=0; wait "$pid" || status=$?
        latency=$(awk -v a="$sent" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
        line="N=$n T=$t s: exit $status, $latency s after the second signal"
        if [[ $status -eq 0 ]]; then
            echo "$line; finished before the signals"
            continue
        fi
        [[ $status -eq 143 ]] || { echo "$line: FAILED (expected 143)"; failed=1; continue; }
        if [[ -f $name.checkpoint.h5 ]]; then
            "$sbgen" --resume "$name.checkpoint.h5" --out "$name.h5" --quiet 2>/dev/null
            reference "$n"
            "$analyze" convert "$name.h5" "$name.txt" 2>/dev/null
            if cmp -s "ref-$n.txt" "$name.txt"; then
                echo "$line; checkpoint resumed: identical ($(grep -o '[0-9]* collisions back' "$name.log" || echo 'at a window end'))"
            else
                echo "$line; checkpoint resumed: DIFFERS"; failed=1
            fi
        elif ls "$name".* 2>/dev/null | grep -qv '\.log$'; then
            echo "$line; no checkpoint but files left: FAILED"; failed=1
        else
            echo "$line; nothing written ($(grep -o 'before the first window ended' "$name.log"))"
        fi
    done
done
[[ $failed -eq 0 ]] && echo "double signal matrix: ok"
