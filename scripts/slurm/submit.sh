#!/usr/bin/env bash
# Submits an ensemble: COUNT sbgen packings as an array, then their MPI analysis once all
# succeeded (docs/scale-out.md, "Slurm").
#   SBPACK_OUT=/shared/run SBGEN_OPTIONS="--p 1.5 --n 1000" scripts/slurm/submit.sh COUNT
set -euo pipefail
count=${1:?usage: submit.sh COUNT}
here=$(cd "$(dirname "$0")" && pwd)
: "${SBPACK_OUT:?set SBPACK_OUT, the shared directory of the packings}"
mkdir -p "$SBPACK_OUT"
array=$(sbatch --parsable --export=ALL --array="1-$count" "$here/sbgen-array.sbatch")
analysis=$(sbatch --parsable --export=ALL --dependency="afterok:${array%%;*}" \
    "$here/sbanalyze-mpi.sbatch")
echo "array job $array, analysis job $analysis (after the array)"
