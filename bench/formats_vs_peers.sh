#!/usr/bin/env bash
# sbpack's GSD against gsd.hoomd (the reference reader and writer), freud and OVITO, and its
# LAMMPS dump and data file against OVITO's importers (bench/formats_vs_peers.py;
# bench/RESULTS.md, "GSD and LAMMPS against gsd.hoomd, freud and OVITO"), in a virtual
# environment made with the python3 on PATH and pip when missing.
#   bench/formats_vs_peers.sh [BUILD] [PACKING.h5]   (defaults: build, data/mrj-p1.5-1000.h5)
# environment:
#   SBPACK_GSD_VENV  the environment (default ${XDG_CACHE_HOME:-$HOME/.cache}/sbpack/gsd-venv)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
packing=${2:-$root/data/mrj-p1.5-1000.h5}
venv=${SBPACK_GSD_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/sbpack/gsd-venv}
if ! "$venv/bin/python" -c 'import gsd.hoomd, freud, h5py, numpy, ovito' 2> /dev/null; then
    echo "creating $venv: pip install gsd freud-analysis h5py numpy ovito" >&2
    python3 -m venv "$venv"
    "$venv/bin/python" -m pip install --quiet gsd freud-analysis h5py numpy ovito >&2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$venv/bin/python" "$root/bench/formats_vs_peers.py" "$build/analysis/sbanalyze" "$packing" "$work"
