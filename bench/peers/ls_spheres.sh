#!/usr/bin/env bash
# sbgen against the Skoge-Donev-Stillinger-Torquato Lubachevsky-Stillinger sphere code (issue 21),
# side by side on one core: collisions per CPU second in the low-density phase (phi 0.2 to
# reduced pressure 30, phi ~ 0.59) and near jamming (reduced pressure 1e3 to 1e6).
#
# usage: bench/peers/ls_spheres.sh LS_SOURCE [WORK_DIR] [BUILD_DIR] [REPEATS] [NS]
#   LS_SOURCE  the LS code's sources: a checkout of github.com/anirban9973/spheres (commit ca77f88;
#              e.g. `git clone https://github.com/anirban9973/spheres`), not fetched here (the CI
#              machine has no network). It is copied to WORK_DIR/ls-src, patched with
#              bench/peers/ls-spheres-counters.patch and built there with `g++ -O3` (its Makefile's
#              flags; sbgen's Release build is -O3 too), outside the project's build.
#   WORK_DIR   default /tmp/sbpack-ls-peer; BUILD_DIR (with generator/sbgen) default build;
#   REPEATS    default 5 (seeds 1..REPEATS, the same seed for both codes); NS default "1000 5000".
# Environment: SBPACK_BENCH_CORE, the core both programs are pinned to (taskset), default 0.
#
# Protocol, matched (bench/RESULTS.md, "sbgen against the LS sphere code"): spheres from phi 0.2,
# constant growth gamma = dD/dt / sqrt(kT/m) = 0.01 throughout (sbgen --gamma-fast = --gamma-slow),
# which is the LS code's growthrate = dr/dt at <|v|^2> = 1 (its rescaling, kT/m = 1/3):
# growthrate = gamma / (2 sqrt 3). Thermostat: sbgen every 10 collisions per sphere (--window 10),
# LS every cycle of 22 N events + N in Synchronize (about 10 collisions per sphere). A phase ends
# where two windows (cycles) in a row reach its pressure, for both codes. Each repetition runs the
# two codes one after the other on the same core, alternating which goes first.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
if [[ $# -lt 1 ]]; then
    sed -n '2,22p' "$0" >&2
    exit 1
fi
src=$(cd "$1" && pwd)
work=${2:-/tmp/sbpack-ls-peer}
build=${3:-$root/build}
repeats=${4:-5}
ns=${5:-"1000 5000"}
core=${SBPACK_BENCH_CORE:-0}
sbgen=$build/generator/sbgen

gamma=0.01
ls_growth=$(/usr/bin/python3 -c "import math; print(repr($gamma / (2 * math.sqrt(3))))")
pressure_a=30      # end of the low-density phase (phi ~ 0.59 at this rate)
pressure_b0=1e3    # start of the near-jamming phase (phi ~ 0.643)
pressure_b1=1e6    # its end (phi ~ 0.645)
events_per_cycle=22
ls_maxpf=0.66      # the LS cell grid is sized for maxpf: just above jamming, its finest safe grid

[[ -x $sbgen ]] || { echo "no $sbgen: build sbgen first" >&2; exit 1; }
[[ -f $src/box.C && -f $src/spheres.C ]] || { echo "$src: not the LS sphere sources" >&2; exit 1; }
mkdir -p "$work"

# Build the peer outside the project's build.
rm -rf "$work/ls-src"
cp -r "$src" "$work/ls-src"
rm -rf "$work/ls-src/.git"
patch -s -p1 -d "$work/ls-src" < "$here/ls-spheres-counters.patch"
(cd "$work/ls-src" &&
    g++ -O3 neighbor.C spheres.C box.C sphere.C event.C heap.C read_input.C -o "$work/spheres")
if [[ -e $src/.git ]]; then
    peer_version="commit $(git -C "$src" rev-parse --short HEAD)"
else
    peer_version="sha256 of *.C *.h $(cd "$src" && cat ./*.C ./*.h | sha256sum | cut -c1-12)"
fi

{
    echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "sbpack commit: $(git -C "$root" rev-parse --short HEAD 2> /dev/null || echo unknown)"
    echo "LS source: $peer_version"
    echo "cpu: $(lscpu | sed -n 's/^Model name: *//p' | head -1), pinned to core $core"
    echo "compiler: $(g++ --version | head -1)"
    echo "gamma $gamma, LS growthrate $ls_growth, LS eventspercycle $events_per_cycle, LS maxpf $ls_maxpf"
    echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$work/setup.txt"
cat "$work/setup.txt"

run_ls() {
    local n=$1 seed=$2 dir=$3
    mkdir -p "$dir"
    cat > "$dir/input" << EOF
int eventspercycle = $events_per_cycle;
int N = $n;
double temp = 0.3333333333333333;
double growthrate = $ls_growth;
double maxpressure = $pressure_b1;
int equilsteps = 0
char* readfile = new
char* writefile = config.dat
char* datafile = stats.dat
EOF
    (cd "$dir" && taskset -c "$core" "$work/spheres" input "$seed" 0.2 "$ls_maxpf" > ls.log)
}

run_sbgen() {
    local n=$1 seed=$2 dir=$3 rc
    mkdir -p "$dir"
    rm -f "$dir"/sbgen-*.h5
    # Phase a from phi 0.2; then resumed to the start and to the end of phase b. Exit status 3
    # (written, not jammed) is expected below the jamming pressure.
    taskset -c "$core" "$sbgen" --n "$n" --seed "$seed" --phi-init 0.2 --gamma-fast "$gamma" \
        --gamma-slow "$gamma" --pressure-switch 2 --window 10 --pressure-final "$pressure_a" \
        --quiet --out "$dir/sbgen-a.h5" && rc=0 || rc=$?
    [[ $rc -eq 0 || $rc -eq 3 ]] || return "$rc"
    taskset -c "$core" "$sbgen" --resume "$dir/sbgen-a.h5" --pressure-final "$pressure_b0" \
        --quiet --out "$dir/sbgen-b0.h5" && rc=0 || rc=$?
    [[ $rc -eq 0 || $rc -eq 3 ]] || return "$rc"
    taskset -c "$core" "$sbgen" --resume "$dir/sbgen-b0.h5" --pressure-final "$pressure_b1" \
        --quiet --out "$dir/sbgen-b1.h5" && rc=0 || rc=$?
    [[ $rc -eq 0 || $rc -eq 3 ]] || return "$rc"
}

for n in $ns; do
    for seed in $(seq 1 "$repeats"); do
        dir=$work/n$n/seed$seed
        if ((seed % 2 == 1)); then
            run_ls "$n" "$seed" "$dir"
            run_sbgen "$n" "$seed" "$dir"
        else
            run_sbgen "$n" "$seed" "$dir"
            run_ls "$n" "$seed" "$dir"
        fi
        echo "N $n seed $seed done ($(cut -d' ' -f1 /proc/loadavg) load)"
    done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)" >> "$work/setup.txt"

/usr/bin/python3 "$here/ls_spheres_summary.py" "$work" --ns "$ns" --repeats "$repeats" \
    --pressure-a "$pressure_a" --pressure-b0 "$pressure_b0" --pressure-b1 "$pressure_b1" |
    tee "$work/summary.md"
