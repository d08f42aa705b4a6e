#!/usr/bin/env bash
# Two sbgen builds side by side on whole default runs: for each p and seed, BASE and NEW run the
# same command at once (one core each, so the shared machine's load falls on both alike), first
# just past the switch pressure (the fast phase: --pressure-final must exceed the switch), then
# to the default final pressure. Prints, per run, collisions, CPU seconds and collisions per CPU
# second of each build, NEW over BASE, and each build's phi (the fast phase sets it: a change
# that alters trajectories keeps the ensemble when phi at the switch does; bench/RESULTS.md,
# "Witness-point certificates", "Pair records across windows").
# PHASES (default "fast whole"): "fast" alone for exponents whose whole runs take hours.
# usage: bench/throughput_side_by_side.sh BASE_SBGEN NEW_SBGEN "P..." "SEED..." [N] [SECONDS_CAP] [PHASES]
set -euo pipefail
if [ $# -lt 4 ]; then
    echo "usage: $0 BASE_SBGEN NEW_SBGEN \"P...\" \"SEED...\" [N] [SECONDS_CAP] [PHASES]" >&2
    exit 1
fi
base=$1 new=$2 exponents=$3 seeds=$4 n=${5:-1000} cap=${6:-36000} phases=${7:-fast whole}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| p | seed | phase | base collisions | base CPU s | base rate | new collisions | new CPU s | new rate | new / base | base phi | new phi |"
echo "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for p in $exponents; do
    for seed in $seeds; do
        for phase in $phases; do
            extra=()
            [ "$phase" = fast ] && extra=(--pressure-final 1.01e6) # just past the switch at 1e6
            for build in base new; do
                binary=$base
                [ "$build" = new ] && binary=$new
                timeout "$cap" "$binary" --p "$p" --n "$n" --seed "$seed" "${extra[@]}" \
                    --out "$work/$build.h5" --quiet > /dev/null 2>&1 &
            done
            wait || true
            /usr/bin/python3 - "$p" "$seed" "$phase" "$work/base.h5" "$work/new.h5" <<'EOF'
import sys
import h5py
p, seed, phase, *paths = sys.argv[1:]
cells = []
rates = []
phis = []
for path in paths:
    packing = h5py.File(path, "r")
    log = packing["provenance"].attrs
    phis.append(f"{packing.attrs['phi']:.6f}")
    collisions, cpu = float(log["collisions"]), float(log["cpu_time_s"])
    rates.append(collisions / cpu)
    cells += [f"{collisions / 1e6:.2f} M", f"{cpu:.1f}", f"{rates[-1]:.3g}"]
print(f"| {p} | {seed} | {phase} | " + " | ".join(cells) + f" | {rates[1] / rates[0]:.2f} | "
      + " | ".join(phis) + " |")
EOF
            rm -f "$work"/*.h5
        done
    done
done
