#!/usr/bin/env bash
# Runs the Slurm workflow on this machine without Slurm (docs/scale-out.md): the array's tasks
# one after the other under a fake SLURM_ARRAY_TASK_ID, then the analysis job (under mpirun -np 2
# when MPI is given, else one process).
#   dry-run.sh COUNT WORK SBGEN SBANALYZE [MPIRUN]   (SBGEN_OPTIONS: e.g. "--n 32")
set -euo pipefail
count=$1 work=$2 sbgen=$3 sbanalyze=$4 mpirun=${5:-}
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work"
export SBPACK_OUT=$work/out SBPACK_SCRATCH=$work/scratch SBPACK_SBGEN=$sbgen
export SBPACK_SBANALYZE=$sbanalyze SLURM_ARRAY_JOB_ID=dry SBPACK_REQUEUE=echo SBPACK_COUNT=$count
mkdir -p "$SBPACK_OUT"
for ((task = 1; task <= count; ++task)); do
    SLURM_ARRAY_TASK_ID=$task bash "$here/sbgen-array.sbatch"
done
if [[ -n $mpirun ]]; then
    export SBPACK_LAUNCH="$mpirun -np 2 --oversubscribe" OMPI_ALLOW_RUN_AS_ROOT=1
    export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
else
    export SBPACK_LAUNCH=env
fi
SLURM_CPUS_PER_TASK=1 bash "$here/sbanalyze-mpi.sbatch"
