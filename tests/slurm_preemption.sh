#!/usr/bin/env bash
# The preemption path of scripts/slurm/sbgen-array.sbatch without Slurm (docs/scale-out.md):
# array task 1 is sent SIGTERM while sbgen runs, as `--signal=B:TERM` does; it must save its
# checkpoint, requeue itself and write no packing; the requeued task must resume the checkpoint
# to the packing that an uninterrupted task writes, bit for bit (positions, orientations).
# usage: slurm_preemption.sh WORK SBGEN PYTHON
set -euo pipefail
work=$1 sbgen=$2 python=$3
array=$(cd "$(dirname "$0")/.." && pwd)/scripts/slurm/sbgen-array.sbatch
rm -rf "$work" && mkdir -p "$work"
export SBPACK_SBGEN=$sbgen SLURM_ARRAY_JOB_ID=test SLURM_ARRAY_TASK_ID=1
export SBPACK_REQUEUE="echo requeue" SBGEN_OPTIONS="--n 200 --gamma-slow 1e-3 --quiet"
# The task's shell itself (exec), which Slurm's B:TERM signals.
task() { SBPACK_OUT=$work/$1 SBPACK_SCRATCH=$work/scratch-$1 exec bash "$array"; }

(task reference) > "$work/reference.log"
(task preempted) > "$work/first.log" &
pid=$!
for _ in $(seq 100); do # SIGTERM once sbgen has started (the task made its scratch directory)
    [[ -d $work/scratch-preempted ]] && break
    sleep 0.05
done
sleep 1
kill -TERM "$pid"
status=0
wait "$pid" || status=$?
(( status == 0 )) || { echo "the preempted task exited $status:"; cat "$work/first.log"; exit 1; }
grep -q "requeueing" "$work/first.log" || { echo "task did not requeue:"; cat "$work/first.log"; exit 1; }
grep -q "requeue test_1" "$work/first.log" || { echo "no requeue command"; exit 1; }
[[ ! -e $work/preempted/packing-1.h5 ]] || { echo "a preempted task wrote its packing"; exit 1; }
[[ -e $work/preempted/checkpoints/packing-1.checkpoint.h5 ]] || { echo "no checkpoint"; exit 1; }
(task preempted) > "$work/second.log"
grep -q "resuming seed 1" "$work/second.log" || { echo "not resumed:"; cat "$work/second.log"; exit 1; }
"$python" - "$work/reference/packing-1.h5" "$work/preempted/packing-1.h5" <<'PY'
import sys
import h5py
import numpy as np
a, b = (h5py.File(name, "r") for name in sys.argv[1:])
for name in ("positions", "orientations"):
    if not np.array_equal(a[name][()], b[name][()]):
        sys.exit(f"{name} differ after preemption and resume")
print("preempted, requeued and resumed: the same packing bit for bit")
PY
