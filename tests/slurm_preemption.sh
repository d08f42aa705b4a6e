#!/usr/bin/env bash
# The stop, checkpoint, requeue and resume path of scripts/slurm/sbgen-array.sbatch without Slurm
# (docs/scale-out.md); tests/slurm/real_slurm.sh runs it under a real slurmctld. Array task 1 is
# stopped while sbgen runs, in the two ways Slurm stops it:
#  - usr1: SIGUSR1 to the task's shell alone, as the warning before the time limit does
#    (--signal=B:USR1@300): the shell passes one SIGTERM on;
#  - term: SIGTERM to sbgen and, 0.1 s later, to the shell, as preemption, `scontrol requeue`,
#    scancel and the time limit do (Slurm signals every process of the job): the shell must pass
#    nothing on (a second SIGTERM would stop sbgen mid-window, a window lost).
# Each must save its checkpoint (sbgen stopped at the end of its window) and write no packing;
# after USR1 the task requeues itself, after SIGTERM it leaves that to Slurm (which has requeued
# it on preemption and `scontrol requeue`, and not on scancel). The task run again must resume
# to the packing that an uninterrupted task writes, bit for bit (every dataset and attribute but
# the clocks). Then a copy to the shared folder that fails (the packing's, the checkpoint's: a
# full disk, /dev/full) must fail the task, report no success and keep the scratch folder.
# usage: slurm_preemption.sh WORK SBGEN PYTHON
set -euo pipefail
work=$1 sbgen=$2 python=$3
root=$(cd "$(dirname "$0")/.." && pwd)
array=$root/scripts/slurm/sbgen-array.sbatch
compare=$root/tests/slurm/compare_packings.py
rm -rf "$work" && mkdir -p "$work"
export SBPACK_SBGEN=$sbgen SLURM_ARRAY_JOB_ID=test SLURM_ARRAY_TASK_ID=1
export SBPACK_REQUEUE="echo requeue"
# About 7 s; windows of 5000 collisions per particle (0.4 s) so that a second SIGTERM would
# land mid-window.
export SBGEN_OPTIONS="--n 64 --gamma-slow 1e-3 --window 5000 --quiet"
fail() { echo "FAILED: $*"; exit 1; }
# The task's shell itself (exec), which Slurm's B: signals reach.
task() { SBPACK_OUT=$work/$1 SBPACK_SCRATCH=$work/scratch-$1 exec bash "$array"; }

(task reference) > "$work/reference.log" 2>&1
for how in usr1 term; do
    (task "$how") > "$work/$how-first.log" 2>&1 &
    pid=$!
    sbgen_pid=''
    for _ in $(seq 200); do # once sbgen runs
        sbgen_pid=$(pgrep -P "$pid" -x "$(basename "$sbgen")" || true)
        [[ -n $sbgen_pid ]] && break
        sleep 0.05
    done
    [[ -n $sbgen_pid ]] || fail "$how: sbgen did not start"
    sleep 2
    if [[ $how == usr1 ]]; then
        kill -USR1 "$pid"
    else # Slurm signals the job's processes in no set order: sbgen first here
        kill -TERM "$sbgen_pid"
        sleep 0.1
        # The shell may have copied the checkpoint and exited within those 0.1 s (sbgen stopped
        # near the end of its window); Slurm's signal to a finished job step does nothing either.
        kill -TERM "$pid" 2>/dev/null || true
    fi
    status=0
    wait "$pid" || status=$?
    log=$work/$how-first.log
    (( status == 0 )) || { cat "$log"; fail "$how: the stopped task exited $status"; }
    grep -q "at the end of a window; it resumes bit for bit" "$log" ||
        { cat "$log"; fail "$how: sbgen did not stop at the end of its window"; }
    if [[ $how == usr1 ]]; then # the script requeues the task
        grep -q "^requeue test_1" "$log" || { cat "$log"; fail "$how: no requeue command"; }
    else # Slurm requeues it (preemption, scontrol requeue) or it was cancelled: not here
        ! grep -q "^requeue" "$log" || { cat "$log"; fail "$how: requeued by the script"; }
        grep -q "not requeued" "$log" || { cat "$log"; fail "$how: no word on the requeue"; }
    fi
    [[ ! -e $work/$how/packing-1.h5 ]] || fail "$how: a stopped task wrote its packing"
    [[ -e $work/$how/checkpoints/packing-1.checkpoint.h5 ]] || fail "$how: no checkpoint"
    (task "$how") > "$work/$how-second.log" 2>&1
    grep -q "resuming seed 1" "$work/$how-second.log" ||
        { cat "$work/$how-second.log"; fail "$how: not resumed"; }
    "$python" "$compare" "$work/reference/packing-1.h5" "$work/$how/packing-1.h5" ||
        fail "$how: the resumed packing differs"
    echo "$how: stopped and resumed: the same packing bit for bit"
done

# A failed copy of the packing: ENOSPC from /dev/full under the temporary name.
export SBGEN_OPTIONS="--n 32 --gamma-slow 1e-2 --pressure-final 1e8 --quiet"
mkdir -p "$work/full"
ln -s /dev/full "$work/full/packing-1.h5.tmp"
status=0
(task full) > "$work/full.log" 2>&1 || status=$?
(( status != 0 )) || { cat "$work/full.log"; fail "a failed copy of the packing exited 0"; }
grep -q "FAILED to copy" "$work/full.log" || { cat "$work/full.log"; fail "no copy failure said"; }
! grep -q "wrote $work/full/packing-1.h5" "$work/full.log" || fail "a failed copy said it wrote"
[[ ! -e $work/full/packing-1.h5 ]] || fail "a failed copy left a packing"
[[ -e $work/scratch-full/sbgen-test-1/packing.h5 ]] || fail "a failed copy lost the scratch packing"
echo "a failed copy of the packing fails the task (status $status) and keeps the scratch folder"

# A failed copy of the checkpoint when stopped: the task fails and does not requeue.
export SBGEN_OPTIONS="--n 64 --gamma-slow 1e-3 --window 5000 --quiet"
mkdir -p "$work/full-checkpoint/checkpoints"
ln -s /dev/full "$work/full-checkpoint/checkpoints/packing-1.checkpoint.h5.tmp"
(task full-checkpoint) > "$work/full-checkpoint.log" 2>&1 &
pid=$!
sleep 2
kill -USR1 "$pid"
status=0
wait "$pid" || status=$?
(( status != 0 )) || { cat "$work/full-checkpoint.log"; fail "a failed checkpoint copy exited 0"; }
! grep -q "requeue" "$work/full-checkpoint.log" || fail "a failed checkpoint copy requeued"
[[ -e $work/scratch-full-checkpoint/sbgen-test-1/packing-1.checkpoint.h5 ]] ||
    fail "a failed checkpoint copy lost the scratch checkpoint"
echo "a failed copy of the checkpoint fails the task (status $status) and keeps the scratch folder"
echo "slurm_preemption: ok"
