#!/usr/bin/env bash
# scripts/slurm/ against a REAL Slurm (docs/scale-out.md, "Testing against a real Slurm"): a
# private single-node cluster (tests/slurm/cluster.sh: Debian's slurm-wlm and munge, installed if
# missing; 2 CPUs, MpiDefault=none; partitions low and high, high preempting low by requeue).
#  1. submit.sh refuses, submitting nothing, an analysis job or an array the node cannot hold.
#  2. submit.sh 3 sizes the analysis for the node; the array runs one task at a time. Each task
#     is stopped once while sbgen runs: task 1 preempted by a job in the high partition, task 2
#     by `scontrol requeue`, task 3 by the time-limit warning (scancel --signal=USR1 --batch, as
#     --signal=B:USR1@300 does). Each must resume; the analysis must run (srun --mpi=pmix chosen
#     for the missing MPI default) over the 3 packings; and each packing must equal sbgen's
#     uninterrupted run bit for bit (tests/slurm/compare_packings.py: every dataset, every
#     attribute but the clocks).
#  3. The analysis runs with SBPACK_LAUNCH=mpirun and with the cluster's MPI default (pmix);
#     plain srun without a default fails, as Open MPI needs PMIx.
#  4. A scancelled task is not requeued; submitting again resumes it, bit for bit.
#  5. A copy of the packing to the shared folder that fails (/dev/full) fails the task, and the
#     analysis job is removed (--kill-on-invalid-dep) instead of pending for good.
# usage: real_slurm.sh WORK SBGEN SBANALYZE [PYTHON]    (as root; about 3 minutes on 2 cores)
# Exit status 77: skipped, no private cluster can start here (not root, or no slurm-wlm and munge:
# scripts/install-deps.sh --mpi installs them).
set -euo pipefail
work=$(mkdir -p "$1" && cd "$1" && pwd) sbgen=$2 sbanalyze=$3 python=${4:-python3}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
scripts=$root/scripts/slurm
compare=$here/compare_packings.py
# shellcheck source-path=SCRIPTDIR source=cluster.sh
source "$here/cluster.sh"

started=$SECONDS
say() { printf '[%4ds] %s\n' $((SECONDS - started)) "$*"; }
clusterdir=$(mktemp -d "${TMPDIR:-/tmp}/sbpack-slurm.XXXXXX")
finish() {
    local status=$?
    cluster_stop
    if (( status != 0 && status != 77 )); then
        echo "the cluster's logs are kept in $clusterdir; the runs in $work"
    else
        rm -rf "$clusterdir"
    fi
}
trap finish EXIT
fail() {
    echo "FAILED: $*"
    tail -n 5 "$clusterdir"/slurmctld.log "$clusterdir"/slurmd.log 2>/dev/null || true
    exit 1
}

status=0
cluster_start "$clusterdir" 2 || status=$?
if (( status != 0 )); then
    echo "SKIPPED: no private Slurm cluster can start here (status $status)"
    exit 77
fi
say "cluster up: $SLURM_CONF"

rm -rf "$work"/run "$work"/cancel "$work"/full "$work"/refused "$work"/references
mkdir -p "$work/references"
cd "$work"
export SBPACK_SBGEN=$sbgen SBPACK_SBANALYZE=$sbanalyze SBPACK_SCRATCH=$work/scratch
export SBPACK_ARRAY_LIMIT=1 # one sbgen at a time: the node's second CPU stays free
# About 9 s a packing; windows of 5000 collisions per particle (0.4 s), so that a second SIGTERM
# would stop sbgen mid-window.
sbgen_options="--n 64 --gamma-slow 3e-4 --window 5000 --quiet"
export SBGEN_OPTIONS=$sbgen_options
export SBANALYZE_OPTIONS="--compute contacts,sq,chi --voxels 32 --fft-plan estimate --fft-wisdom none --quiet"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 # mpirun, as root here
mpi=1
if ! ldd "$sbanalyze" | grep -q libmpi; then
    mpi=0
    export SBPACK_ANALYSIS_TASKS=1 # a plain build: one process
fi

state() { scontrol show job -o "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2; }
# wait_for SECONDS WHAT COMMAND...: polls COMMAND every half second.
wait_for() {
    local limit=$1 what=$2 i
    shift 2
    for ((i = 0; i < limit * 2; ++i)); do
        if "$@"; then return 0; fi
        sleep 0.5
    done
    squeue || true
    fail "waited ${limit} s for $what"
}
idle() { [[ -z $(squeue -h) ]]; }
running() { [[ $(squeue -h -j "$1" -t R -o %t 2>/dev/null) == R ]]; }
has() { grep -q -- "$2" "$1" 2>/dev/null; }
ended() { [[ $(state "$1") =~ ^(COMPLETED|FAILED|CANCELLED|TIMEOUT|OUT_OF_MEMORY|NODE_FAIL)$ ]]; }

# 1. Jobs that the node cannot hold: refused, nothing submitted.
for refused in "SBPACK_ANALYSIS_TASKS=4 SBPACK_ANALYSIS_CPUS=4" \
               "SBPACK_ARRAY_SBATCH_OPTIONS=--mem=100G"; do
    status=0
    # shellcheck disable=SC2086 # VAR=VALUE words
    answer=$(env $refused SBPACK_OUT="$work/refused" "$scripts/submit.sh" 3 2>&1) || status=$?
    (( status != 0 )) || fail "submit.sh accepted what the node cannot hold ($refused): $answer"
    [[ $answer == *"cannot run on this cluster"* ]] || fail "no reason given ($refused): $answer"
    idle || fail "submit.sh submitted a job that the node cannot hold ($refused)"
    say "refused ($refused): ${answer%%$'\n'*}"
done

# 2. The ensemble, each task stopped once.
export SBPACK_OUT=$work/run
answer=$("$scripts/submit.sh" 3)
say "$answer"
[[ $answer =~ array\ job\ ([0-9]+).*analysis\ job\ ([0-9]+) ]] || fail "submit.sh said: $answer"
array=${BASH_REMATCH[1]} analysis=${BASH_REMATCH[2]}
if (( mpi )); then
    [[ $answer == *"(2 tasks x 1 CPUs"* ]] || fail "the analysis is not sized 2 x 1 for the node"
fi
log() { echo "$SBPACK_OUT/logs/sbgen-${array}_$1.log"; }
sbgen_runs() { pgrep -f -- "--checkpoint $SBPACK_SCRATCH/sbgen-${array}-$1/" > /dev/null; }
# first_run TASK: waits until the task's first run has run sbgen for a second.
first_run() {
    wait_for 120 "task $1 to run" running "${array}_$1"
    wait_for 30 "task $1's sbgen to start" sbgen_runs "$1"
    sleep 1
    [[ ! -e $SBPACK_OUT/packing-$1.h5 ]] || fail "task $1 ended before it could be stopped"
    has "$(log "$1")" "run 1 on" || fail "task $1 ran before"
}
first_run 1
high=$(sbatch --parsable --partition=high --cpus-per-task=2 --mem=100M \
       --output="$work/high-%j.log" --wrap "sleep 2")
say "task 1 running; job $high in the high partition preempts it"
wait_for 60 "task 1 to be requeued" has "$(log 1)" "requeued by Slurm"
has "$(log 1)" "DUE TO PREEMPTION" || fail "task 1 was not preempted"

first_run 2
scontrol requeue "${array}_2"
say "task 2 running; scontrol requeue ${array}_2"
wait_for 60 "task 2 to be requeued" has "$(log 2)" "requeued by Slurm"
has "$(log 2)" "DUE TO JOB REQUEUE" || fail "task 2 was not requeued by scontrol"

first_run 3
scancel --signal=USR1 --batch "${array}_3"
say "task 3 running; its batch shell sent SIGUSR1 (the time-limit warning)"
wait_for 60 "task 3 to requeue itself" has "$(log 3)" "requeued (scontrol requeue"

wait_for 300 "the array and the analysis to end" ended "$analysis"
say "array and analysis ended: analysis $(state "$analysis")"
for task in 1 2 3; do
    [[ $(state "${array}_$task") == COMPLETED ]] ||
        { cat "$(log "$task")"; fail "task $task: $(state "${array}_$task")"; }
    has "$(log "$task")" "resuming seed $task" || fail "task $task did not resume"
    ! has "$(log "$task")" "twice: mid-window" || fail "task $task: sbgen signalled twice"
    ! has "$(log "$task")" "FAILED" || fail "task $task: $(grep FAILED "$(log "$task")")"
    ! has "$(log "$task")" "pending execution" || fail "task $task: requeued twice"
    [[ $(grep -c "at the end of a window; it resumes bit for bit" "$(log "$task")") == 1 ]] ||
        fail "task $task was not stopped exactly once at the end of a window"
done
analysis_log=$SBPACK_OUT/logs/sbanalyze-$analysis.log
[[ $(state "$analysis") == COMPLETED ]] || { cat "$analysis_log"; fail "the analysis failed"; }
has "$analysis_log" "wrote $SBPACK_OUT/results.h5 (3 packings)" || fail "no results"
if (( mpi )); then
    has "$analysis_log" "srun --cpus-per-task=1 --mpi=pmix" || fail "not launched with pmix"
fi
grep -h "stopped\|requeued" "$(log 1)" "$(log 2)" "$(log 3)" | sed 's/^/    /'
ranks() { "$python" -c 'import h5py, sys; print(int(h5py.File(sys.argv[1], "r").attrs["ranks"]))' "$1"; }
(( mpi == 0 )) || [[ $(ranks "$SBPACK_OUT/results.h5") == 2 ]] || fail "the analysis did not run 2 ranks"

say "sbgen's uninterrupted runs of seeds 1, 2, 3"
read -r -a options <<< "$sbgen_options"
for seed in 1 2 3; do
    nice -n 10 "$sbgen" "${options[@]}" --seed "$seed" --out "$work/references/packing-$seed.h5" \
        2>/dev/null
done
"$python" "$compare" "$work"/references/packing-1.h5 "$SBPACK_OUT"/packing-1.h5 \
    "$work"/references/packing-2.h5 "$SBPACK_OUT"/packing-2.h5 \
    "$work"/references/packing-3.h5 "$SBPACK_OUT"/packing-3.h5 ||
    fail "a stopped and resumed packing differs from the uninterrupted run"
say "preempted, requeued and warned: every packing the same bit for bit"

# 3. The MPI launch: mpirun, the cluster's default, and plain srun without one.
if (( mpi )); then
    # analyse NAME [VAR=VALUE...]: the analysis job alone on the 3 packings; prints its state.
    analyse() {
        local name=$1 job
        shift
        job=$(env "$@" SBPACK_COUNT=3 sbatch --parsable --export=ALL --ntasks=2 \
              --cpus-per-task=1 --mem-per-cpu=500M --time=5 \
              --output="$work/analysis-$name.log" "$scripts/sbanalyze-mpi.sbatch")
        wait_for 120 "the analysis with $name" ended "$job"
        state "$job"
    }
    [[ $(analyse mpirun SBPACK_LAUNCH="mpirun --bind-to none") == COMPLETED ]] ||
        { cat "$work/analysis-mpirun.log"; fail "the analysis under mpirun failed"; }
    [[ $(analyse plain SBPACK_MPI=none) != COMPLETED ]] ||
        fail "plain srun without an MPI default worked: the test's premise is wrong"
    say "plain srun (--mpi=none): fails as expected: $(grep -m1 -o 'OMPI was not built.*support' \
        "$work/analysis-plain.log" || tail -n 1 "$work/analysis-plain.log")"
    sed -i 's/^MpiDefault=none/MpiDefault=pmix/' "$SLURM_CONF"
    scontrol reconfigure
    [[ $(analyse default) == COMPLETED ]] ||
        { cat "$work/analysis-default.log"; fail "the analysis with MpiDefault=pmix failed"; }
    grep -q "srun --cpus-per-task=1 $sbanalyze" "$work/analysis-default.log" ||
        fail "the cluster's MPI default was not left to srun"
    sed -i 's/^MpiDefault=pmix/MpiDefault=none/' "$SLURM_CONF"
    scontrol reconfigure
    say "the analysis ran with SBPACK_LAUNCH=mpirun and with MpiDefault=pmix"
fi

# 4. scancel: not requeued; submitting again resumes.
export SBPACK_OUT=$work/cancel
answer=$("$scripts/submit.sh" 1)
[[ $answer =~ array\ job\ ([0-9]+).*analysis\ job\ ([0-9]+) ]] || fail "submit.sh said: $answer"
array=${BASH_REMATCH[1]} analysis=${BASH_REMATCH[2]}
first_run 1
scancel "${array}_1"
wait_for 60 "task 1 to be cancelled" ended "${array}_1"
wait_for 60 "the analysis to be removed" ended "$analysis"
sleep 1
has "$(log 1)" "not requeued" || { cat "$(log 1)"; fail "the cancelled task said nothing"; }
[[ $(state "${array}_1") == CANCELLED ]] || fail "the cancelled task is $(state "${array}_1")"
[[ -e $SBPACK_OUT/checkpoints/packing-1.checkpoint.h5 ]] || fail "no checkpoint saved"
answer=$("$scripts/submit.sh" 1)
say "task 1 cancelled, not requeued; submitted again: $answer"
[[ $answer =~ array\ job\ ([0-9]+).*analysis\ job\ ([0-9]+) ]] || fail "submit.sh said: $answer"
array=${BASH_REMATCH[1]} analysis=${BASH_REMATCH[2]}
wait_for 120 "the second submission to end" ended "$analysis"
has "$(log 1)" "resuming seed 1" || fail "the second submission did not resume"
[[ $(state "$analysis") == COMPLETED ]] || fail "the analysis after resubmission failed"
"$python" "$compare" "$work"/references/packing-1.h5 "$SBPACK_OUT"/packing-1.h5 ||
    fail "the cancelled and resubmitted packing differs"

# 5. A failed copy to the shared folder fails the task; the analysis is removed.
export SBPACK_OUT=$work/full SBGEN_OPTIONS="--n 32 --gamma-slow 1e-2 --pressure-final 1e8 --quiet"
mkdir -p "$SBPACK_OUT"
ln -s /dev/full "$SBPACK_OUT/packing-1.h5.tmp"
answer=$("$scripts/submit.sh" 1)
[[ $answer =~ array\ job\ ([0-9]+).*analysis\ job\ ([0-9]+) ]] || fail "submit.sh said: $answer"
array=${BASH_REMATCH[1]} analysis=${BASH_REMATCH[2]}
wait_for 60 "the task with the full disk to end" ended "${array}_1"
wait_for 60 "its analysis to be removed" ended "$analysis"
[[ $(state "${array}_1") == FAILED ]] || fail "a failed copy left the task $(state "${array}_1")"
has "$(log 1)" "FAILED to copy" || fail "the failed copy was not said"
! has "$(log 1)" "wrote $SBPACK_OUT/packing-1.h5" || fail "a failed copy said it wrote the packing"
[[ ! -e $SBPACK_OUT/packing-1.h5 ]] || fail "a failed copy left a packing"
[[ $(state "$analysis") != COMPLETED ]] || fail "the analysis ran without the packing"
say "a failed copy: task $(state "${array}_1"), $(grep -m1 -o 'cp: .*' "$(log 1)");" \
    "analysis $(state "$analysis")"
idle || fail "jobs left over"
say "real_slurm: ok"
