#!/usr/bin/env bash
# How fast SIGTERM ends what a user can start (issue 46; docs/reliability.md, "Runs"): each
# command below is started TRIES times, sent SIGTERM after a random delay (while it computes),
# and timed until it exits. Prints one row per command: the exit codes seen, the slowest end
# after the signal, and whether a temporary (.NAME.tmp-PID) or a changed earlier output was
# left. A command that outlives the signal by LIMIT seconds is killed and reported as a hang.
#   bash bench/sigterm_sweep.sh [BUILD_DIR] [TRIES] [LIMIT]
# The fast slice in ctest (cli_sigterm_ends_every_stage) runs it with TRIES = 1.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build} tries=${2:-3} limit=${3:-5}
sbanalyze=$build/analysis/sbanalyze sbgen=$build/generator/sbgen
work=$(mktemp -d /tmp/sbpack-sigterm-XXXXXX)
trap 'rm -rf "$work"' EXIT
big=data/mrj-p1.5-5000.h5
export XDG_CACHE_HOME="$work/cache" # no shared wisdom: plans are made in the run

# name | command (OUT is the output path; it holds an earlier file that must survive)
commands=(
    "voxels M=1000|$sbanalyze $big --compute voxels --voxels 1000 --out OUT"
    "chi M=640|$sbanalyze $big --compute chi --voxels 640 --fft-plan estimate --out OUT"
    # measured within the budget: FFTW's planner cannot be interrupted (docs/reliability.md)
    "chi M=128 measured plan|$sbanalyze $big --compute chi --voxels 128 --out OUT"
    "sq qmax=200|$sbanalyze $big --compute sq --qmax 200 --out OUT"
    "pores voxel M=600|$sbanalyze $big --compute pores --pores voxel --pore-voxels 600 --out OUT"
    "pores refined M=600|$sbanalyze $big --compute pores --pores refined --pore-voxels 600 --out OUT"
    "pores exact K=1e7|$sbanalyze $big --compute pores --pores exact --pore-points 10000000 --out OUT"
    "hyper|$sbanalyze $big --compute hyper --voxels 300 --fft-plan estimate --chi-exact-qmax 6 --out OUT"
    "all|$sbanalyze $big --voxels 300 --fft-plan estimate --out OUT"
    "sbgen p=1.5 N=1000|$sbgen --p 1.5 --n 1000 --seed 1 --out OUT"
    "sbgen p=10 N=1000|$sbgen --p 10 --n 1000 --seed 1 --out OUT"
)

now() { date +%s.%N; }
status=0
printf '| command | exit codes | slowest end after SIGTERM (s) | temporaries left | earlier output |\n'
printf '|---|---|---:|---|---|\n'
for entry in "${commands[@]}"; do
    name=${entry%%|*} template=${entry#*|}
    codes="" slowest=0 leftovers=no kept=yes
    for ((t = 0; t < tries; t++)); do
        dir="$work/run$t" && rm -rf "$dir" && mkdir -p "$dir"
        echo "earlier" > "$dir/out.h5"
        cmd=${template//OUT/$dir/out.h5}
        $cmd > "$dir/log" 2>&1 &
        pid=$!
        sleep "$(awk -v s="$RANDOM" 'BEGIN { print 0.5 + 3.0 * s / 32767 }')"
        sent=$(now)
        kill -TERM "$pid" 2> /dev/null
        ended=""
        while kill -0 "$pid" 2> /dev/null; do
            if awk -v a="$(now)" -v b="$sent" -v l="$limit" 'BEGIN { exit !(a - b > l) }'; then
                kill -KILL "$pid"; ended=hang; break
            fi
            sleep 0.02
        done
        wait "$pid"; code=$?
        took=$(awk -v a="$(now)" -v b="$sent" 'BEGIN { printf "%.2f", a - b }')
        [ "$ended" = hang ] && { code="hang"; status=1; }
        codes="$codes $code"
        slowest=$(awk -v a="$slowest" -v b="$took" 'BEGIN { print (b > a ? b : a) }')
        compgen -G "$dir/.out.h5.tmp-*" > /dev/null && { leftovers=yes; status=1; }
        # sbgen's checkpoint replaces nothing of out.h5; sbanalyze must leave it as it was, unless
        # the run had finished before the signal (exit 0).
        if [ "$code" != 0 ] && [ "$(head -c 8 "$dir/out.h5")" != "earlier" ]; then
            kept=no; status=1
        fi
    done
    printf '| %s |%s | %s | %s | %s |\n' "$name" "$codes" "$slowest" "$leftovers" "$kept"
done
exit $status
