#!/usr/bin/env bash
# Does the fast phase align near-cubes? For each seed and fast rate, sbgen's fast phase alone:
# the default run at that fast rate throughout (--gamma-slow the same), stopped at the switch
# pressure (--pressure-final 1.01e6: the slow phase's pressure can fall after the switch and
# creep), then sbanalyze's cubatic order P4 and phi of the output (bench/RESULTS.md, "The fast
# phase's alignment"). Outputs kept; runs one at a time.
#   bench/fast_phase_alignment.sh BUILD WORK P "SEEDS" "GAMMA_FASTS"
set -euo pipefail
build=$1 work=$2 p=$3 seeds=$4 rates=$5
mkdir -p "$work"
printf '| p | seed | gamma_fast | phi | P4 | collisions |\n|---|---|---|---|---|---|\n'
for rate in $rates; do
    for s in $seeds; do
        out=$work/p$p-s$s-fast$rate.h5
        [ -f "$out" ] || "$build/generator/sbgen" --p "$p" --n 1000 --seed "$s" --gamma-fast "$rate" \
            --gamma-slow "$rate" --pressure-final 1.01e6 --quiet --out "$out" 2> "$out.log" || [ $? -eq 3 ]
        "$build/analysis/sbanalyze" "$out" --compute order --threads 1 --quiet \
            --out "$work/order-$(basename "$out")" > /dev/null 2>&1
        /usr/bin/python3 - "$out" "$work/order-$(basename "$out")" "$p" "$s" "$rate" <<'PY'
import sys, h5py
packing, results, p, s, rate = sys.argv[1:]
f, r = h5py.File(packing), h5py.File(results)
print(f"| {p} | {s} | {rate} | {f.attrs['phi']:.4f} | {r['files/0/order'].attrs['P4']:.3f} | "
      f"{f['provenance'].attrs['collisions'] / 1e6:.2f} M |")
PY
    done
done
