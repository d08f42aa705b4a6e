#!/usr/bin/env bash
# Small boxes order (issue 43): jam N superballs of exponent p with sbgen's defaults and print
# phi, Z and the box edge in diameters at jamming, to find the N below which a "jammed" packing
# is a crystal rather than MRJ (the paper's N = 1000 and 5000 are far above it).
# usage: bench/small_box.sh SBGEN "P..." "N..." "SEED..." [OUTDIR]
set -euo pipefail
sbgen=$1 ps=$2 ns=$3 seeds=$4 out=${5:-$(mktemp -d)}
mkdir -p "$out"
echo "p N seed phi Z box_diameters cpu_s"
for p in $ps; do
    for n in $ns; do
        for seed in $seeds; do
            file="$out/p$p-n$n-s$seed.h5"
            start=$(date +%s.%N)
            line=$("$sbgen" --p "$p" --n "$n" --seed "$seed" --out "$file" 2>&1 |
                   grep "wrote" || true)
            end=$(date +%s.%N)
            phi=$(sed -n 's/.*phi \([0-9.]*\).*/\1/p' <<<"$line")
            z=$(sed -n 's/.*Z \([0-9.]*\).*/\1/p' <<<"$line")
            box=$(/usr/bin/python3 -c "import h5py; f = h5py.File('$file'); \
print(f'{f.attrs[\"box_length\"] / (2 * f.attrs[\"semi_axis\"]):.2f}')" 2>/dev/null || echo nan)
            echo "$p $n $seed ${phi:-nan} ${z:-nan} $box $(echo "$end - $start" | bc)"
        done
    done
done
