"""Fixtures of the Python tests (tests/CMakeLists.txt runs each file under ctest with PYTHONPATH at
the build's module and SBPACK_SBANALYZE / SBPACK_SBGEN naming the binaries)."""
import os
import subprocess

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DATA = os.path.join(ROOT, "data")
# Cheap settings every comparison shares (the CLI and the module get the same).
FAST = {"threads": 2, "fft_plan": "estimate", "fft_wisdom": "none"}


def binary(name):
    path = os.environ.get(f"SBPACK_{name.upper()}")
    if not path:
        pytest.skip(f"SBPACK_{name.upper()} not set (run through ctest)")
    return path


@pytest.fixture(scope="session")
def sbanalyze():
    return binary("sbanalyze")


@pytest.fixture(scope="session")
def sbgen():
    return binary("sbgen")


def cli_args(options):
    """Python keywords as sbanalyze options (the module's own spelling rule)."""
    args = []
    for name, value in options.items():
        value = ",".join(map(str, value)) if isinstance(value, (tuple, list)) else value
        args += ["--" + name.replace("_", "-"), str(value)]
    return args


def run(cmd, **kwargs):
    return subprocess.run(cmd, capture_output=True, text=True, **kwargs)
