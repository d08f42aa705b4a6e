#!/usr/bin/env bash
# Writes docs/python-api/, the Python API pages of sbpack (pdoc, from PyPI, in a virtual
# environment over Debian's python3 and its numpy, h5py and matplotlib), from the built module's
# docstrings and signatures: the analysis classes and their result classes as
# python/generate_analysis_classes.py writes them (docs/python.md, "Analyses").
#   scripts/make_python_api_doc.sh [BUILD]    BUILD: the build folder (default build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
if [[ ! -f "$build/python/sbpack/analysis_classes.py" ]]; then
    echo "make_python_api_doc.sh: no built module in $build/python (scripts/build.sh first)" >&2
    exit 2
fi
venv="$build/venv-pdoc"
if [[ ! -x "$venv/bin/pdoc" ]]; then
    /usr/bin/python3 -m venv --system-site-packages "$venv"
    "$venv/bin/pip" install --quiet "pdoc==15.0.1"
fi
rm -rf docs/python-api
PYTHONPATH="$build/python" "$venv/bin/pdoc" --no-search --no-show-source -o docs/python-api \
    sbpack.analysis_classes sbpack.analysis_base sbpack.results
echo "wrote docs/python-api/ ($(find docs/python-api -name '*.html' | wc -l) pages)"
