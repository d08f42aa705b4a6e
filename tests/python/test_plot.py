"""python3 -m sbpack.plot: the figures a results file supports, as PNG and PDF, and what they draw
is the results' data (read back from the matplotlib Axes)."""
import os

import numpy as np
import pytest

import sbpack
import sbpack.plot as plot
from sbpack import _sbpack
from conftest import DATA, FAST, cli_args, run

INPUTS = [os.path.join(DATA, "mrj-p1.5-1000.h5"), os.path.join(DATA, "mrj-spheres-5000.h5")]
OPTIONS = dict(FAST, voxels=100, pore_voxels=100, bootstrap=20)


@pytest.fixture(scope="module")
def results(sbanalyze, tmp_path_factory):
    out = tmp_path_factory.mktemp("plot") / "r.h5"
    r = run([sbanalyze, *INPUTS, "--quiet", "--out", str(out), *cli_args(OPTIONS)])
    assert r.returncode == 0, r.stderr
    return str(out)


@pytest.fixture(scope="module")
def figures(results):
    return plot.make_figures([results], slice_voxels=100)


NAMES = ["structure_factor", "spectral_density", "spreadability", "pore_size", "versus_p",
         "packing_slice"]


def test_command_writes_png_and_pdf(results, tmp_path):
    import subprocess
    import sys
    r = subprocess.run([sys.executable, "-m", "sbpack.plot", results, "--out", str(tmp_path),
                        "--slice-voxels", "100"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    for name in NAMES:
        for ext in ("png", "pdf"):
            assert os.path.getsize(tmp_path / f"{name}.{ext}") > 1000
    assert r.stdout.split() == [str(tmp_path / f"{n}.png") for n in NAMES]


def files_of(results):
    return sbpack.read_results(results)["files"]


def test_curves_are_the_results(results, figures):
    files = files_of(results)
    sq, chi = figures["structure_factor"].axes[0], figures["spectral_density"].axes[0]
    pores, spread = figures["pore_size"].axes[0], figures["spreadability"].axes[0]
    spread_lines = [line for line in spread.lines if line.get_linestyle() == "-"]
    for i, f in enumerate(files):
        assert np.array_equal(sq.lines[i].get_xdata(), f["structure_factor"]["Q_w"])
        assert np.array_equal(sq.lines[i].get_ydata(), f["structure_factor"]["S"])
        w = f["mean_width"]
        assert np.array_equal(chi.lines[i].get_ydata(), f["spectral_density"]["chi"] / w**3)
        assert np.array_equal(pores.lines[i].get_xdata(), f["pore_size"]["delta_w"])
        assert np.array_equal(pores.lines[i].get_ydata(), f["pore_size"]["F"])
        assert np.array_equal(spread_lines[i].get_ydata(), f["spreadability"]["excess"])
    debye = [line for line in spread.lines if line.get_linestyle() == "--"][0]
    assert np.array_equal(debye.get_ydata(), files[0]["spreadability_debye"]["excess"])


def test_versus_p_draws_the_ensembles_and_the_paper(results, figures):
    ensembles = sbpack.read_results(results)["ensembles"]
    phi_axis, z_axis = figures["versus_p"].axes[:2]
    drawn = sorted((tuple(c.lines[0].get_xdata()), tuple(c.lines[0].get_ydata()))
                   for c in phi_axis.containers[:2])
    assert drawn == sorted(((e["p"],), (e["phi"],)) for e in ensembles)
    paper = plot.paper_values()
    assert np.array_equal(z_axis.containers[-1].lines[0].get_ydata(), paper["Z"][1])
    assert paper["Z"][1][list(paper["Z"][0]).index(1.0)] == 6  # isostatic spheres in the table


def test_slice_is_the_pore_map(figures):
    packing = sbpack.Packing.read(INPUTS[0])
    solid, pores = _sbpack.voxel_slice(packing, 100, 50)
    image = figures["packing_slice"].axes[0].images[0].get_array()
    assert np.array_equal(image.mask, solid != 0)
    assert np.array_equal(image.data[solid == 0], (pores / packing.mean_width)[solid == 0])
    assert (pores[solid != 0] == 0).all() and (pores[solid == 0] > 0).all()


def test_one_p_has_no_versus_p(sbanalyze, tmp_path):
    out = tmp_path / "sq.h5"
    assert run([sbanalyze, INPUTS[0], "--compute", "sq", "--quiet", "--out", str(out)]
               ).returncode == 0
    assert list(plot.make_figures([str(out)], slice_voxels=0)) == ["structure_factor"]


def test_read_results_is_the_file(results):
    import h5py
    r = sbpack.read_results(results)
    with h5py.File(results) as f:
        assert r["n_files"] == f.attrs["n_files"] == len(r["files"]) == 2
        assert np.array_equal(r["files"][1]["pore_size"]["F"], f["files/1/pore_size/F"][:])
        assert r["ensembles"][0]["contacts"]["z_mean_std"] == \
            f["ensembles/0/contacts"].attrs["z_mean_std"]
        assert r["files"][0]["units"]["box_length"] == "length"
        assert r["files"][0]["structure_factor"]["units"]["Q"] == "1/length"


def test_read_results_refuses_a_fifo_at_once(tmp_path):
    """A FIFO is refused before it is opened (issue 46, defect 6): h5py would block in open()."""
    fifo = tmp_path / "results.h5"
    os.mkfifo(fifo)
    with pytest.raises(OSError, match="not a regular file"):
        sbpack.read_results(str(fifo))


def fake_inputs(ps, per_p):
    """Results-like inputs: per_p files at each p, N = 100, with S(Q) and E(t)."""
    t = np.geomspace(1e-3, 10, 20)
    spread = {"t": t, "excess": np.exp(-t), "local_alpha": np.ones_like(t), "alpha": 1.0,
              "alpha_stderr": 0.1, "t_fit_min": 0.1, "t_fit_max": 0.5, "t_cutoff": 2.0}
    return [{"p": p, "n_particles": 100, "input": f"p{p}-s{i}.h5", "mean_width": 1.0,
             "structure_factor": {"Q_w": np.arange(1.0, 5.0), "S": np.full(4, p + i)},
             "spreadability": dict(spread, t_fit_min=0.1 * (1 + 1e-4 * i))}
            for p in ps for i in range(per_p)]


def test_many_inputs_one_legend_entry_and_colour_per_series():
    """Above MANY_INPUTS inputs, one legend entry and colour per (p, N); every input still
    drawn; the alpha windows that agree to two digits shaded once (issue 43)."""
    import matplotlib.pyplot as plt
    runs = [{"files": fake_inputs([1.0, 1.5], 4)}]
    fig, ax = plt.subplots()
    plot.structure_factor(runs, ax)
    labels = ax.get_legend_handles_labels()[1]
    assert labels == ["p = 1, N = 100 (4 inputs)", "p = 1.5, N = 100 (4 inputs)"]
    colours = [line.get_color() for line in ax.lines[:8]]
    assert len(set(colours[:4])) == len(set(colours[4:])) == 1 and colours[0] != colours[4]
    fig, axes = plt.subplots(2, 1)
    plot.spreadability(runs, axes)
    assert len(axes[0].patches) == 1 and len(axes[1].lines) == 8 + 1  # 8 curves, one t_c
    plt.close("all")


def test_few_inputs_keep_their_own_labels():
    import matplotlib.pyplot as plt
    files = fake_inputs([1.0], 2)
    fig, ax = plt.subplots()
    plot.structure_factor([{"files": files}], ax)
    assert ax.get_legend_handles_labels()[1] == [plot.label(f) for f in files]
    plt.close(fig)
