"""The scripts of examples/ run and print what they promise, in finite numbers."""
import os
import re
import subprocess
import sys

import pytest

import sbpack
from conftest import DATA, ROOT

EXAMPLES = {
    "reprocess_contacts.py": ([], r"mrj-spheres-5000.h5 +1 +5000 +5\.9"),
    "voxel_vs_exact_chi.py": (["--voxels", "80", "160"], r"M = 160: RMS"),
    # N = 40: seed 1 stops unjammed (a column wraps around the box of 3.2 D) and is left out
    "plot_ensemble.py": (["--n", "40", "--seeds", "2"], r"\d packings? of N = 40: phi = 0\.6"),
}


def run_example(script, args, folder):
    return subprocess.run([sys.executable, os.path.join(ROOT, "examples", script), *args],
                          capture_output=True, text=True, cwd=folder)


@pytest.fixture(scope="module")
def example(tmp_path_factory):
    """script -> (its completed run with EXAMPLES' arguments, its folder), each run once."""
    done = {}

    def get(script):
        if script not in done:
            folder = tmp_path_factory.mktemp(script[:-3])
            args = EXAMPLES[script][0] + ([] if script == "reprocess_contacts.py"
                                          else ["--out", str(folder)])
            done[script] = (run_example(script, args, folder), folder)
        return done[script]
    return get


@pytest.mark.parametrize("script", EXAMPLES)
def test_example_runs(script, example):
    r, folder = example(script)
    assert r.returncode == 0, r.stderr
    assert re.search(EXAMPLES[script][1], r.stdout), r.stdout
    assert "nan" not in r.stdout, r.stdout
    pngs = [f for f in os.listdir(folder) if f.endswith(".png")]
    assert len(pngs) == (0 if script == "reprocess_contacts.py" else 1)


def test_ensemble_leaves_out_the_unjammed_packings(example):
    """Only jammed packings (provenance jammed = 1) enter the ensemble; each one left out is
    named (issue 43: an unjammed one made Z = nan +- nan)."""
    r, folder = example("plot_ensemble.py")
    left_out = re.findall(r"^left out of the ensemble: (\S+) \(", r.stdout, re.M)
    members = [f["input"] for f in sbpack.read_results(str(folder / "results.h5"))["files"]]
    assert len(left_out) + len(members) == 2 and not set(left_out) & set(members)
    for path in left_out + members:
        assert sbpack.Packing.read(path).provenance["jammed"] == (path in members)
    assert re.search(rf"^{len(members)} packings? of N = 40", r.stdout, re.M), r.stdout


def test_reprocess_says_undetermined_instead_of_nan(tmp_path):
    """A packing whose gaps the paper's tolerance cuts through: the row says so, and the engine's
    warning (the gap distribution) is one RuntimeWarning."""
    r = run_example("reprocess_contacts.py", [os.path.join(DATA, "stalled-column-p10-200.h5")],
                    tmp_path)
    assert r.returncode == 0, r.stderr
    assert re.search(r"stalled-column-p10-200.h5 +10 +200 +undetermined \(needs T >= 3\.4e-08\)",
                     r.stdout), r.stdout
    assert "nan" not in r.stdout and r.stderr.count("RuntimeWarning:") == 1, r.stderr
