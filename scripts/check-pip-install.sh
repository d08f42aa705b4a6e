#!/usr/bin/env bash
# Checks `pip install .` (pyproject.toml, scikit-build-core) in a fresh virtual environment made by
# the first python3 on PATH (e.g. a PyPI/pyenv Python, not Debian's), then imports the module
# outside the source tree and runs the programs pip put on the environment's PATH. Needs the Debian packages of scripts/install-deps.sh and PyPI (pip
# fetches scikit-build-core, pybind11, numpy, h5py and matplotlib). Not run by ctest (minutes:
# it builds the libraries again). usage: scripts/check-pip-install.sh [VENV_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
venv="${1:-$(mktemp -d)/venv}"
python3 -m venv "$venv"
echo "venv: $venv ($("$venv/bin/python" --version))"
"$venv/bin/pip" install --quiet --upgrade pip
nice -n 10 "$venv/bin/pip" install --quiet .
cd "$(mktemp -d)"
"$venv/bin/python" -c "import sbpack; print(sbpack.__version__)"
# The packings the module carries, read from here (README "Python": its block runs anywhere).
"$venv/bin/python" -c "import sbpack; print(sbpack.data_files()); \
print(sbpack.Packing.read(sbpack.data_file('mrj-p1.5-1000.h5')).phi)"
"$venv/bin/sbgen" --help | head -1
"$venv/bin/sbanalyze" --help | head -1
