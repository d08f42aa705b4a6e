"""The scripts of examples/ run and print what they promise."""
import os
import re
import subprocess
import sys

import pytest

from conftest import ROOT

EXAMPLES = {
    "reprocess_contacts.py": ([], r"mrj-spheres-5000.h5 +1 +5000 +5\.9"),
    "voxel_vs_exact_chi.py": (["--voxels", "80", "160"], r"M = 160: RMS"),
    "plot_ensemble.py": (["--n", "40", "--seeds", "2"], r"2 packings of N = 40: phi = 0\.6"),
}


@pytest.mark.parametrize("script", EXAMPLES)
def test_example_runs(script, tmp_path):
    args, expected = EXAMPLES[script]
    r = subprocess.run([sys.executable, os.path.join(ROOT, "examples", script), *args,
                        *([] if script == "reprocess_contacts.py" else ["--out", str(tmp_path)])],
                       capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert re.search(expected, r.stdout), r.stdout
    pngs = [f for f in os.listdir(tmp_path) if f.endswith(".png")]
    assert len(pngs) == (0 if script == "reprocess_contacts.py" else 1)
