#!/usr/bin/env bash
# Submits an ensemble: COUNT sbgen packings as an array, then their MPI analysis once all
# succeeded (docs/scale-out.md, "Slurm").
#   SBPACK_OUT=/shared/run SBGEN_OPTIONS="--p 1.5 --n 1000" scripts/slurm/submit.sh COUNT
# Both jobs are checked with `sbatch --test-only` first: nothing is submitted unless both can run
# on this cluster. Variables (all optional but SBPACK_OUT):
#   SBPACK_SBATCH_OPTIONS           sbatch options of both jobs ("--partition=x --account=y")
#   SBPACK_ARRAY_SBATCH_OPTIONS     of the array alone ("--time=1:00:00 --mem=1G")
#   SBPACK_ANALYSIS_SBATCH_OPTIONS  of the analysis alone
#   SBPACK_ARRAY_LIMIT              at most this many tasks at once (--array=1-COUNT%LIMIT)
#   SBPACK_ANALYSIS_TASKS, SBPACK_ANALYSIS_CPUS  MPI tasks and CPUs per task of the analysis
#       (default: the largest size that the cluster accepts, from min(COUNT, 4) tasks x 4 CPUs
#       down to 1 x 1)
#   SBPACK_ANALYSIS_MEM_PER_CPU     (default 2G), SBPACK_ANALYSIS_TIME (default, in minutes:
#       10 + 2 ceil(COUNT / tasks))
#   SBPACK_LOGS                     the jobs' logs (default $SBPACK_OUT/logs)
set -euo pipefail
count=${1:?usage: submit.sh COUNT}
[[ $count =~ ^[1-9][0-9]*$ ]] || { echo "submit.sh: COUNT must be a positive number" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
: "${SBPACK_OUT:?set SBPACK_OUT, the shared directory of the packings}"
SBPACK_OUT=$(mkdir -p "$SBPACK_OUT" && cd "$SBPACK_OUT" && pwd)
logs=${SBPACK_LOGS:-$SBPACK_OUT/logs}
mkdir -p "$logs"
export SBPACK_OUT SBPACK_COUNT=$count
read -r -a common <<< "${SBPACK_SBATCH_OPTIONS:-}"
read -r -a array_extra <<< "${SBPACK_ARRAY_SBATCH_OPTIONS:-}"
read -r -a analysis_extra <<< "${SBPACK_ANALYSIS_SBATCH_OPTIONS:-}"

array_args=(--export=ALL --array="1-$count${SBPACK_ARRAY_LIMIT:+%$SBPACK_ARRAY_LIMIT}"
            --output="$logs/sbgen-%A_%a.log" "${common[@]}" "${array_extra[@]}"
            "$here/sbgen-array.sbatch")
# analysis_args TASKS CPUS: the analysis job's sbatch arguments at that size.
analysis_args() {
    local minutes=$(( 10 + 2 * ((count + $1 - 1) / $1) ))
    args=(--export=ALL --kill-on-invalid-dep=yes --ntasks="$1" --cpus-per-task="$2"
          --mem-per-cpu="${SBPACK_ANALYSIS_MEM_PER_CPU:-2G}"
          --time="${SBPACK_ANALYSIS_TIME:-$minutes}" --output="$logs/sbanalyze-%j.log"
          "${common[@]}" "${analysis_extra[@]}")
}

# --test-only: whether the job could ever run here (partition, node sizes, limits), not when.
if ! answer=$(sbatch --test-only "${array_args[@]}" 2>&1); then
    echo "submit.sh: the sbgen array cannot run on this cluster (nothing submitted): $answer" >&2
    echo "  (resources: SBPACK_ARRAY_SBATCH_OPTIONS, SBPACK_SBATCH_OPTIONS)" >&2
    exit 1
fi

# The analysis: the largest size (CPUs in all, then tasks) that the cluster accepts, among
# tasks <= min(COUNT, 4) and 4, 2 or 1 CPUs per task, or exactly the size given.
most=$(( count < 4 ? count : 4 ))
tasks_choices=$(seq "$most" -1 1)
cpus_choices="4 2 1"
if [[ -n ${SBPACK_ANALYSIS_TASKS:-} ]]; then tasks_choices=$SBPACK_ANALYSIS_TASKS; fi
if [[ -n ${SBPACK_ANALYSIS_CPUS:-} ]]; then cpus_choices=$SBPACK_ANALYSIS_CPUS; fi
sizes=()
for tasks in $tasks_choices; do
    for cpus in $cpus_choices; do sizes+=("$(( tasks * cpus )) $tasks $cpus"); done
done
mapfile -t sizes < <(printf '%s\n' "${sizes[@]}" | sort -k1,1nr -k2,2nr)
size=''
for candidate in "${sizes[@]}"; do
    read -r _ tasks cpus <<< "$candidate"
    analysis_args "$tasks" "$cpus"
    if answer=$(sbatch --test-only "${args[@]}" "$here/sbanalyze-mpi.sbatch" 2>&1); then
        size="$tasks $cpus"
        break
    fi
done
if [[ -z $size ]]; then
    echo "submit.sh: the analysis job cannot run on this cluster at" \
         "$(printf '%s\n' "${sizes[@]}" | awk '{ printf "%s%s x %s", (NR > 1 ? ", " : ""), $2, $3 }')" \
         "tasks x CPUs, ${SBPACK_ANALYSIS_MEM_PER_CPU:-2G} per CPU (nothing submitted): $answer" >&2
    echo "  (size: SBPACK_ANALYSIS_TASKS, _CPUS, _MEM_PER_CPU, _TIME, SBPACK_ANALYSIS_SBATCH_OPTIONS)" >&2
    exit 1
fi
read -r tasks cpus <<< "$size"
analysis_args "$tasks" "$cpus"

array=$(sbatch --parsable "${array_args[@]}")
array=${array%%;*}
if ! analysis=$(sbatch --parsable --dependency="afterok:$array" "${args[@]}" \
        "$here/sbanalyze-mpi.sbatch"); then
    echo "submit.sh: array job $array submitted, but not its analysis; submit it by hand" \
         "(sbatch --dependency=afterok:$array ${args[*]} $here/sbanalyze-mpi.sbatch)" >&2
    exit 1
fi
analysis=${analysis%%;*}
echo "array job $array ($count packings in $SBPACK_OUT), analysis job $analysis ($tasks tasks" \
     "x $cpus CPUs, after the array); logs in $logs"
