#!/usr/bin/env bash
# Runs sbgen experiments for the fidelity study (bench/RESULTS.md, "Fidelity"): each line of
# SPEC is "LABEL SBGEN-OPTIONS...", run two at a time (one per core); a run whose output exists is
# skipped (resumable). Then prints a markdown table per run from `sbanalyze info`: phi, Z, phi_R,
# final pressure, collisions, CPU s.
# usage: bench/fidelity_experiments.sh SPEC [WORK_DIR] [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
spec=$1 work=${2:-/tmp/sbpack-fidelity} build=${3:-$root/build}
mkdir -p "$work"
grep -v '^\s*\(#\|$\)' "$spec" | while read -r label options; do
    [ -f "$work/$label.h5" ] || printf '%s\n' "$label $options"
done | xargs -r -P 2 -L 1 bash -c 'label=$0; "'"$build"'/generator/sbgen" "$@" --quiet \
    --out "'"$work"'/$label.h5" 2> "'"$work"'/$label.log" || echo "$label: exit $?" >&2'
echo "| run | options | phi | Z | phi_R | P | M collisions | CPU s |"
echo "|---|---|---|---|---|---|---|---|"
grep -v '^\s*\(#\|$\)' "$spec" | while read -r label options; do
    f="$work/$label.h5"
    [ -f "$f" ] || { echo "| $label | $options | (missing) |"; continue; }
    /usr/bin/python3 "$root/bench/fidelity_summary.py" "$build/analysis/sbanalyze" "$f" "$label" $options
done
