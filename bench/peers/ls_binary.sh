#!/usr/bin/env bash
# sbgen against the Skoge-Donev-Stillinger-Torquato Lubachevsky-Stillinger code's bidisperse
# version (issue 67): the same binary mixture of spheres (50:50, size ratio 1.4) compressed by the
# same protocol to the same reduced pressure, each packing checked by sbanalyze; phi, Z and
# phi_R side by side, and the CPU time of each.
#
# usage: bench/peers/ls_binary.sh LS_POLY_SOURCE [WORK_DIR] [BUILD_DIR] [SEEDS] [N] [GAMMA] [RATIO]
#   LS_POLY_SOURCE  the bidisperse LS sources (box.C ... spheres.C, vector.h; "Updated July 24,
#                   2009 ... polydisperse spheres"), e.g. Densely_packed_cylinder/spheres_poly of
#                   github.com/NYU-DiffusionMRI/monte-carlo-simulation-recipes (commit b728e74), not
#                   fetched here. Copied to WORK_DIR/ls-src, set to DIM 3 and built there with
#                   `g++ -std=gnu++98 -O3` (its 2009 C++), outside the project's build.
#   WORK_DIR default /tmp/sbpack-ls-binary; BUILD_DIR default build (sbgen, sbanalyze, python);
#   SEEDS default "1 2 3"; N default 1000; GAMMA default 0.01; RATIO (large over small diameter)
#   default 1.4, 1 for identical spheres (both codes' baseline).
#
# Protocol, matched: from phi 0.2 at one constant growth rate to reduced pressure 1e12. sbgen:
# --size-ratio RATIO --gamma-fast GAMMA --gamma-slow GAMMA --window 10 (GAMMA = dD/dt of the
# large spheres at kT = m = 1). LS: species 1 (radius r) the large spheres, bidispersityratio
# 1/RATIO (its cells are sized for r: a ratio above 1 crashes it), growthrate = GAMMA / (2 sqrt 3)
# (dr/dt at its <|v|^2> = 1, kT/m = 1/3), initialpf 0.2 / (1/2 + 1/2 RATIO^-3) (it sizes r as if every
# sphere had radius r), 20 events per sphere a cycle (about 10 collisions), maxpressure 1e12.
# The LS code seeds its generator from the clock: its runs are independent, not the same seeds.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
if [[ $# -lt 1 ]]; then
    sed -n '2,24p' "$0" >&2
    exit 1
fi
src=$(cd "$1" && pwd)
work=${2:-/tmp/sbpack-ls-binary}
build=${3:-$root/build}
seeds=${4:-"1 2 3"}
n=${5:-1000}
gamma=${6:-0.01}
ratio=${7:-1.4}
sbgen=$build/generator/sbgen
[[ -x $sbgen ]] || { echo "no $sbgen: build sbgen first" >&2; exit 1; }
[[ -f $src/box.C && -f $src/vector.h ]] || { echo "$src: not the LS sources" >&2; exit 1; }
grep -q bidispersityratio "$src/read_input.C" ||
    { echo "$src: an LS version without bidispersity" >&2; exit 1; }
mkdir -p "$work"

rm -rf "$work/ls-src"
cp -r "$src" "$work/ls-src"
sed -i 's/^#define DIM .*/#define DIM 3/' "$work/ls-src/vector.h"
(cd "$work/ls-src" && g++ -std=gnu++98 -O3 -o "$work/spheres-poly" ./*.C)

read -r ls_growth ls_initial ls_ratio < <(/usr/bin/python3 -c "import math; print(repr($gamma \
    / (2 * math.sqrt(3))), repr(0.2 / (0.5 + 0.5 / $ratio**3)), repr(1 / $ratio))")
{
    echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "sbpack commit: $(git -C "$root" rev-parse --short HEAD 2> /dev/null || echo unknown)"
    echo "LS source: sha256 of *.C *.h $(cd "$src" && cat ./*.C ./*.h | sha256sum | cut -c1-12)"
    echo "N $n, gamma $gamma, size ratio $ratio, LS growthrate $ls_growth, LS initialpf $ls_initial"
    echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$work/setup.txt"
cat "$work/setup.txt"

run_ls() {
    local dir=$1
    mkdir -p "$dir"
    cat > "$dir/input" << INPUT
int eventspercycle = 20;
int N = $n;
double initialpf = $ls_initial;
double maxpf = 0.7;
double temp = 0.3333333333333333;
double growthrate = $ls_growth;
double maxpressure = 1e12;
double maxcollisionrate = 1e300;
double bidispersityratio = $ls_ratio;
double bidispersityfraction = 0.5;
double massratio = 1;
int hardwallBC = 0;
char* readfile = new
char* writefile = write.dat
char* datafile = stats.dat
INPUT
    (cd "$dir" && /usr/bin/time -f "%U %S" -o cpu.txt "$work/spheres-poly" input > ls.log)
}

for seed in $seeds; do
    dir=$work/seed$seed
    run_ls "$dir"
    "$sbgen" --n "$n" --seed "$seed" --size-ratio "$ratio" --gamma-fast "$gamma" --gamma-slow "$gamma" \
        --window 10 --pressure-final 1e12 --quiet --out "$dir/sbgen.h5" || [[ $? -eq 3 ]]
    echo "seed $seed done ($(cut -d' ' -f1 /proc/loadavg) load)"
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)" >> "$work/setup.txt"

PYTHONPATH=$build/python /usr/bin/python3 "$here/ls_binary_summary.py" "$work" "$build" $seeds |
    tee "$work/summary.md"
