#!/usr/bin/env bash
# Prints the python of the virtual environment with freud, h5py and numpy that the benchmarks
# against freud use (bench/order_vs_freud.sh, bench/voronoi_vs_freud.sh), creating it with the
# python3 on PATH and pip when missing.
# environment:
#   SBPACK_FREUD_VENV  the environment (default ${XDG_CACHE_HOME:-$HOME/.cache}/sbpack/freud-venv)
set -euo pipefail
venv=${SBPACK_FREUD_VENV:-${XDG_CACHE_HOME:-$HOME/.cache}/sbpack/freud-venv}
if ! "$venv/bin/python" -c 'import freud, h5py, numpy' 2> /dev/null; then
    echo "creating $venv: pip install freud-analysis h5py numpy" >&2
    python3 -m venv "$venv"
    "$venv/bin/python" -m pip install --quiet 'freud-analysis>=3,<4' h5py numpy >&2
fi
echo "$venv/bin/python"
