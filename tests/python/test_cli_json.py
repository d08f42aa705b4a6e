"""sbanalyze end to end through its JSON summary (`--json -` on stdout), parsed and checked by
name (issue 45; these were regular expressions over the JSON in tests/CMakeLists.txt): the demo
scene's known answer, the text scene read by the analysis, hyper on a stored MRJ packing and on a
box too small for it, and the order verdict on an ordered packing and on the MRJ one."""
import json
import math
import os

import pytest

from conftest import DATA, run

SCENE_TXT = os.path.join(DATA, "sc-lattice-p1.5.txt")
MRJ = os.path.join(DATA, "mrj-p1.5-1000.h5")
ORDERED = os.path.join(DATA, "ordered-p1.2-40.h5")
# Cheap FFT planning, as every CLI test uses: no measuring, no wisdom file read or written.
FAST_FFT = ["--fft-plan", "estimate", "--fft-wisdom", "none"]


def analyze(sbanalyze, *args):
    """Runs `sbanalyze ARGS --json -`; returns the parsed summary and the stderr text."""
    r = run([sbanalyze, *map(str, args), "--json", "-"])
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout), r.stderr


@pytest.fixture(scope="module")
def scene(sbanalyze, tmp_path_factory):
    """The demo scene (5^3 aligned superballs p = 1.5 on a simple cubic lattice) converted from
    data/sc-lattice-p1.5.txt to HDF5 with `sbanalyze convert`."""
    path = tmp_path_factory.mktemp("scene") / "sc-lattice-p1.5.h5"
    r = run([sbanalyze, "convert", SCENE_TXT, str(path)])
    assert r.returncode == 0, r.stderr
    assert path.exists()
    return path


def test_analysis_reads_the_text_scene(sbanalyze):
    """Every documented input format is read by every reader (issue 43): the text scene by the
    analysis, with its known answer (each lattice ball touches its 6 neighbours)."""
    summary, _ = analyze(sbanalyze, SCENE_TXT, "--compute", "contacts")
    files = summary["files"]
    assert len(files) == 1
    assert files[0]["n_particles"] == 125
    assert files[0]["contacts"]["z_mean"] == 6
    assert files[0]["contacts"]["rattler_fraction"] == 0


def test_scene_known_answer(sbanalyze, scene, tmp_path):
    """The scene's S(Q), chi and voxels, the JSON summary on stdout: Z = 6, the exact voxel
    packing fraction, and the pore-size and transport groups."""
    summary, _ = analyze(sbanalyze, scene, "--voxels", 40, "--pore-voxels", 40, "--qmax", 12,
                         *FAST_FFT, "--out", tmp_path / "scene-results.h5")
    files = summary["files"]
    assert len(files) == 1
    first = files[0]
    assert first["contacts"]["z_mean"] == 6
    # At M = 40 the voxel centres of each aligned superball are 8^3 points (2i + 1) / 16 - 1/2
    # of its cell, 408 of them inside |x|^3 + |y|^3 + |z|^3 < 1/8:
    # phi_voxel = 408 / 512 = 0.796875 (exactly, a binary fraction).
    assert first["voxelization"]["voxels"] == 40
    assert first["voxelization"]["phi_voxel"] == 408 / 512
    assert first["voxelization"]["solid_voxels"] == 408 * 125
    assert first["spectral_density"]["phi_voxel"] == 408 / 512
    assert "pore_size" in first
    assert "transport" in first
    assert (tmp_path / "scene-results.h5").exists()


def test_hyper_on_mrj(sbanalyze):
    """hyper on a stored MRJ packing: alpha and its fit (spreadability) and H (hyperuniformity)
    in the summary."""
    summary, _ = analyze(sbanalyze, MRJ, "--compute", "hyper", "--voxels", 100,
                         "--bootstrap", 20, *FAST_FFT)
    first = summary["files"][0]
    assert "spreadability" in first
    alpha = first["spreadability"]["alpha"]
    assert isinstance(alpha, float) and math.isfinite(alpha)
    assert "hyperuniformity" in first
    assert "H" in first["hyperuniformity"]
    assert math.isfinite(first["hyperuniformity"]["H"])


def test_hyper_small_box_warns(sbanalyze, scene):
    """On a box of 5^3 cells no alpha window exists: a warning naming --alpha-window (which
    forces one) and no hyperuniformity groups; the run still succeeds."""
    summary, stderr = analyze(sbanalyze, scene, "--compute", "hyper", "--voxels", 40, *FAST_FFT)
    warning = "hyperuniformity skipped: alpha window"
    assert warning in stderr
    assert "--alpha-window" in stderr.split(warning, 1)[1]
    first = summary["files"][0]
    assert "spreadability" not in first
    assert "hyperuniformity" not in first


def test_order_flags_the_ordered_packing(sbanalyze):
    """The N = 40 box of issue 44 that jammed ordered: the order group calls it ordered, by its
    mean local q6 (0.572 >= 0.5, fcc 0.575)."""
    summary, stderr = analyze(sbanalyze, ORDERED, "--compute", "order")
    order = summary["files"][0]["order"]
    assert order["ordered"] == 1
    assert "mean local q6" in order["ordered_reason"]
    assert "this packing has ordered" in stderr


def test_order_passes_the_mrj_packing(sbanalyze):
    """The MRJ packing has no sign of order: not ordered, T over its 12 shells, and the nematic
    P4 of the axes near its random value (about 0.011)."""
    summary, stderr = analyze(sbanalyze, MRJ, "--compute", "order")
    order = summary["files"][0]["order"]
    assert order["ordered"] == 0
    assert order["ordered_reason"] == ""
    assert order["T_shells"] == 12
    assert order["P4"] < 0.05
    assert "has ordered" not in stderr
