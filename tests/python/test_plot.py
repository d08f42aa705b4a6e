"""python3 -m sbpack.plot: the figures a results file supports, as PNG and PDF; what they draw is
the results' data (read back from the matplotlib Axes): one series per (p, N), its ensemble's
mean +- std as a band, legends in place, degenerate fits left out, grids named, and the figures
of make_figures() the command's own."""
import copy
import os
import subprocess
import sys

import matplotlib
import numpy as np
from matplotlib.patches import StepPatch
import pytest

import sbpack
import sbpack.plot as plot
from sbpack import _sbpack
from sbpack import (figures_contacts, figures_order, figures_results, figures_series,
                    figures_shape, figures_versus_p)
from conftest import DATA, FAST, cli_args, run

INPUTS = [os.path.join(DATA, "mrj-p1.5-1000.h5"), os.path.join(DATA, "mrj-spheres-5000.h5")]
ORDERED = os.path.join(DATA, "ordered-p1.2-40.h5")  # N = 40, p = 1.2: sbanalyze calls it ordered
OPTIONS = dict(FAST, voxels=100, pore_voxels=100, bootstrap=20)
matplotlib.rcParams["figure.max_open_warning"] = 0  # the module's fixtures hold ~40 figures
CHEAP = dict(slice_voxels=64, form_factor_voxels=64, threads=2)  # the engine's figures, small

NAMES = ["structure_factor", "spectral_density", "small_q", "major_axis", "spreadability",
                "pore_size", "order", "contact_types", "contact_types_versus_p", "local_phi",
                "volume_fraction_variance", "versus_p", "phi_vs_width", "mean_width",
                "form_factor", "packing_slice"]


def analyze(sbanalyze, paths, out):
    """sbanalyze PATHS with OPTIONS into `out`; its path."""
    r = run([sbanalyze, *paths, "--quiet", "--out", str(out), *cli_args(OPTIONS)])
    assert r.returncode == 0, r.stderr
    return str(out)


@pytest.fixture(scope="module")
def results(sbanalyze, tmp_path_factory):
    """Two inputs of two p (two one-input ensembles), every analysis."""
    return analyze(sbanalyze, INPUTS, tmp_path_factory.mktemp("plot") / "r.h5")


@pytest.fixture(scope="module")
def figures(results):
    """make_figures() of the two one-input series (every figure)."""
    figures = plot.make_figures([results], slice_voxels=100, form_factor_voxels=64, threads=2)
    assert list(figures) == NAMES  # two p, one input each: every figure too
    return figures


@pytest.fixture(scope="module")
def ensemble(sbanalyze, tmp_path_factory):
    """Two p, three inputs each (each MRJ packing of data/ translated three ways: other voxel
    grids, the same structure), every analysis: two ensembles of three."""
    folder = tmp_path_factory.mktemp("ensemble")
    paths = []
    for source in INPUTS:
        packing = sbpack.Packing.read(source)
        for i, shift in enumerate((0.0, 0.31, 0.57)):
            path = str(folder / f"{os.path.basename(source)[:-3]}-{i}.h5")
            positions = (packing.positions + shift * packing.box_length) % packing.box_length
            sbpack.Packing(positions, packing.orientations, packing.box_length, p=packing.p,
                           semi_axis=packing.semi_axis).write(path)
            paths.append(path)
    return analyze(sbanalyze, paths, folder / "r.h5")


@pytest.fixture(scope="module")
def ensemble_figures(ensemble):
    """make_figures() of the two ensembles of three."""
    return plot.make_figures([ensemble], **CHEAP)


def labelled(ax):
    """The axes' series lines, by their series' label (their gid)."""
    return {line.get_gid(): line for line in ax.lines if (line.get_gid() or "").startswith("p = ")}


def series_line(ax, f):
    """The line of the input f's series (one-input series are labelled with the input)."""
    name = os.path.basename(str(f["input"]))
    return next(line for label, line in labelled(ax).items() if name in label)


@pytest.fixture(scope="module")
def command(ensemble, tmp_path_factory):
    """python3 -m sbpack.plot on the ensemble: (its completed run, its output folder)."""
    out = tmp_path_factory.mktemp("cli")
    r = subprocess.run([sys.executable, "-m", "sbpack.plot", ensemble, "--out", str(out),
                        "--slice-voxels", "64", "--form-factor-voxels", "64", "--threads", "2"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r, out


def test_command_writes_png_and_pdf(command):
    """Two p, three inputs each: every paper figure type, as PNG and PDF."""
    r, out = command
    for name in NAMES:
        for ext in ("png", "pdf"):
            assert os.path.getsize(out / f"{name}.{ext}") > 1000
    assert r.stdout.split() == [str(out / f"{n}.png") for n in NAMES]


def test_captions_are_text_beside_the_figure(command, ensemble_figures):
    """Issue 66 item 5: a title of one line above the panels; the caption as text, in
    captions.md beside the figures and in each PNG's metadata."""
    from PIL import Image  # matplotlib's own dependency
    r, out = command
    captions = (out / "captions.md").read_text()
    described = 0
    for name in NAMES:
        description = Image.open(out / f"{name}.png").info.get("Description", "")
        if description:
            assert f"## {name}.png\n\n{description}\n" in captions
            described += 1
    assert described >= 5
    for name, fig in ensemble_figures.items():
        if fig._suptitle is not None:
            assert "\n" not in fig._suptitle.get_text(), name


def test_make_figures_are_the_commands(ensemble, ensemble_figures, command, tmp_path):
    """One code path: make_figures() returns finished figures, and the command saves exactly
    those (the same PNG bytes, figure by figure)."""
    assert list(ensemble_figures) == NAMES
    again = plot.make_figures([ensemble], **CHEAP)
    for name in plot.save(again, str(tmp_path)):
        with open(name, "rb") as a, open(command[1] / os.path.basename(name), "rb") as b:
            assert a.read() == b.read(), name


def test_every_figure_has_its_legends(ensemble_figures, figures):
    """Legends are placed by make_figures itself (not only when saving)."""
    for fig in list(ensemble_figures.values()) + list(figures.values()):
        for ax in fig.axes:
            if any(not label.startswith("_") for label in ax.get_legend_handles_labels()[1]):
                assert ax.get_legend() is not None, fig.axes[0].get_title()


def test_no_legend_covers_data(ensemble_figures, figures):
    """Issue 66 item 5: a legend inside its axes covers none of the drawn lines and outlines
    (sampled every 1.5 pixels, plot.drawn_points); one that would is placed beside the axes."""
    inside = 0
    for name, fig in list(ensemble_figures.items()) + list(figures.items()):
        fig.canvas.draw()
        for ax in fig.axes:
            legend = ax.get_legend()
            box = legend.get_window_extent() if legend is not None else None
            if box is None or not ax.get_window_extent().contains(box.x0 + 1, box.y0 + 1):
                continue  # none, or beside the axes
            inside += 1
            assert box.count_contains(plot.drawn_points(ax)) == 0, (name, ax.get_title())
    assert inside >= 5


def test_ensemble_is_one_line_and_one_band_per_series(ensemble, ensemble_figures):
    """Two p x three inputs: one line per (p, N), the ensemble's mean, in a band of +- std;
    colour keyed to p (spheres black), marker to N."""
    ensembles = sbpack.read_results(ensemble)["ensembles"]
    ax = ensemble_figures["structure_factor"].axes[0]
    lines = labelled(ax)
    assert len(lines) == 2 and len(ax.collections) == 2
    for e, band in zip(sorted(ensembles, key=lambda e: e["p"]), ax.collections):
        line = lines[f"p = {e['p']:g}, N = {e['n_particles']} (mean $\\pm$ std of 3)"]
        s = e["structure_factor"]
        assert np.array_equal(line.get_xdata(), s["Q_w"])
        assert np.array_equal(line.get_ydata(), s["S"])
        y = band.get_paths()[0].vertices[:, 1]
        assert np.isclose(y.max(), np.max(s["S"] + s["S_std"]))
        assert np.isclose(y.min(), np.min(s["S"] - s["S_std"]))
    sphere, superball = lines.values()
    assert sphere.get_color() in ("k", (0.0, 0.0, 0.0, 1.0)) and superball.get_color() != "k"
    assert sphere.get_marker() != superball.get_marker()  # N = 5000 and N = 1000


def test_ensemble_pore_sizes_are_the_members_mean(ensemble, ensemble_figures):
    """F(delta) of an ensemble: the results' own mean and std of its members' steps on one
    delta / w grid, drawn as they are; the same as the members' mean taken here."""
    r = sbpack.read_results(ensemble)
    ax = ensemble_figures["pore_size"].axes[0]
    for e in r["ensembles"]:
        members = [r["files"][int(m)] for m in e["members"]]
        stored = e["pore_size"]
        line = labelled(ax)[f"p = {e['p']:g}, N = {e['n_particles']} (mean $\\pm$ std of 3)"]
        assert np.array_equal(line.get_ydata(), stored["F"])
        assert np.array_equal(line.get_xdata(), stored["delta_w"])
        here = np.array([figures_series._at(np.asarray(m["pore_size"]["delta_w"]),
                                            np.asarray(m["pore_size"]["F"]),
                                            stored["delta_w"], True) for m in members])
        assert np.allclose(stored["F"], here.mean(axis=0), rtol=0, atol=1e-15)
        assert np.allclose(stored["F_std"], here.std(axis=0, ddof=1), rtol=0, atol=1e-15)
    assert ax.get_yscale() == "log"
    assert len(ensemble_figures["pore_size"].axes) == 2  # F and P (one side: p >= 1)
    assert ensemble_figures["pore_size"].axes[1].get_legend() is not None


def test_curves_are_the_results(results, figures):
    files = sbpack.read_results(results)["files"]
    sq, chi = figures["structure_factor"].axes[0], figures["spectral_density"].axes[0]
    pores, spread = figures["pore_size"].axes[0], figures["spreadability"].axes[0]
    for f in files:
        line = series_line(sq, f)
        assert np.array_equal(line.get_xdata(), f["structure_factor"]["Q_w"])
        assert np.array_equal(line.get_ydata(), f["structure_factor"]["S"])
        w = f["mean_width"]
        assert np.allclose(series_line(chi, f).get_ydata(), f["spectral_density"]["chi"] / w**3,
                           rtol=1e-14, atol=0)
        assert np.array_equal(series_line(pores, f).get_xdata(), f["pore_size"]["delta_w"])
        assert np.array_equal(series_line(pores, f).get_ydata(), f["pore_size"]["F"])
        assert np.array_equal(series_line(spread, f).get_ydata(), f["spreadability"]["excess"])
    debye = [line for line in spread.lines if line.get_linestyle() == "--"]
    assert len(debye) == 2  # one Debye medium per p: its own phi
    assert sorted(tuple(d.get_ydata()[:3]) for d in debye) == sorted(
        tuple(f["spreadability_debye"]["excess"][:3]) for f in files)


def test_versus_p_draws_the_ensembles_and_the_paper(ensemble, ensemble_figures):
    ensembles = sbpack.read_results(ensemble)["ensembles"]
    axes = ensemble_figures["versus_p"].axes
    phi_axis, z_axis = axes[:2]
    drawn = {(c.lines[0].get_xdata()[0], c.lines[0].get_ydata()[0])
             for c in phi_axis.containers if c.get_label() != figures_versus_p.PAPER}
    assert drawn == {(e["p"], e["phi"]) for e in ensembles}
    paper = plot.paper_values()
    paper_z = [c for c in z_axis.containers if c.get_label() == figures_versus_p.PAPER][0]
    assert np.array_equal(paper_z.lines[0].get_ydata(), paper["Z"][1])
    assert paper["Z"][1][list(paper["Z"][0]).index(1.0)] == 6  # isostatic spheres in the table
    titles = [ax.get_ylabel() for ax in axes]
    assert any(t.startswith("$H$") for t in titles)  # H against p (paper Fig. H_Xk)


def test_versus_p_h_is_the_pooled_fit_and_says_so(ensemble, ensemble_figures):
    """The H panel draws each ensemble's one fit through every member (H_pooled +- its
    standard error, docs/hyperuniformity.md "Ensembles"), and its legend says so where the
    other panels say mean +- std."""
    ensembles = sbpack.read_results(ensemble)["ensembles"]
    axes = {ax.get_ylabel(): ax for ax in ensemble_figures["versus_p"].axes if ax.axison}
    h_axis = next(ax for label, ax in axes.items() if label.startswith("$H$"))
    drawn = {c.lines[0].get_ydata()[0] for c in h_axis.containers
             if c.get_label() != figures_versus_p.PAPER}
    assert drawn == {e["hyperuniformity"]["H_pooled"] for e in ensembles}
    legend = [t.get_text() for t in h_axis.get_legend().get_texts()]
    assert any("one fit of 3 inputs" in t for t in legend), legend
    phi_legend = [t.get_text() for t in axes[r"$\phi$"].get_legend().get_texts()]
    assert any("mean $\\pm$ std of 3 inputs" in t for t in phi_legend), phi_legend


def test_versus_p_title_fits_with_hyper_only(ensemble):
    """Only hyper results (phi, alpha and H: three panels): the note above them is not
    clipped."""
    r = sbpack.read_results(ensemble)
    keep = {"spreadability", "hyperuniformity"}
    for group in r["files"] + r["ensembles"]:
        for name in [k for k, v in group.items() if isinstance(v, dict) and k != "units"]:
            if name not in keep:
                del group[name]
    fig = figures_versus_p.versus_p(figures_series.series_of([r]))
    plot.finish(fig)
    assert len([ax for ax in fig.axes if ax.axison]) == 3
    fig.canvas.draw()
    box, title = fig.bbox, fig._suptitle.get_window_extent()
    assert box.x0 <= title.x0 and title.x1 <= box.x1 and title.y1 <= box.y1


def degenerate_copy(results):
    """The results with the first input's fit made degenerate (H = 0 +- inf)."""
    r = sbpack.read_results(results)
    h = r["files"][0]["hyperuniformity"]
    h["H"], h["H_stderr"], h["a0_stderr"] = 0.0, np.inf, np.inf
    return r


def test_degenerate_fit_is_not_drawn(results):
    """A fit with H = 0 +- inf is left out and said to be; the other input's fit is drawn."""
    r = degenerate_copy(results)
    fig = figures_results.small_q(figures_series.series_of([r]))
    labels = [line.get_label() for ax in fig.axes for line in ax.lines]
    labels += [c.get_label() for ax in fig.axes for c in ax.containers]
    fits = [label for label in labels if label.startswith("fit:")]
    assert len(fits) == 1 and "inf" not in fits[0]
    bad = os.path.basename(str(r["files"][0]["input"]))
    assert any(bad in label and "degenerate, not drawn" in label for label in labels)


def test_small_q_fit_over_its_window_and_its_points(results, figures):
    files = sbpack.read_results(results)["files"]
    ax = figures["small_q"].axes[0]
    fits = [line for line in ax.lines if line.get_label().startswith("fit:")]
    assert len(fits) == 2
    for f in files:
        h = f["hyperuniformity"]
        fit = next(line for line in fits if f"{h['fit_points']} wave vectors" in line.get_label()
                   and np.isclose(line.get_xdata()[-1], h["q_fit_max_w"]))
        x = fit.get_xdata()
        assert np.allclose(fit.get_ydata(), h["a0"] + h["a1"] * x ** h["alpha"])
    exact = [line for line in ax.lines if line.get_label().startswith("exact")]
    assert len(exact) == 1  # the spheres' exact chi_V, at the voxel points' shells
    assert "crosses, the values fitted" in figures["small_q"].sbpack_caption
    for f in files:  # the wave vectors fitted, as the results keep them
        h = f["hyperuniformity"]
        crosses = [line for line in ax.lines if line.get_label().startswith(
            f"the {h['fit_points']} wave vectors fitted")]
        assert any(np.array_equal(c.get_xdata(), h["fit_Q_w"])
                   and np.array_equal(c.get_ydata(), h["fit_chi"]) for c in crosses)


def test_mixed_grids_are_named(results):
    r = sbpack.read_results(results)
    r["files"][0]["pore_size"]["voxels"], r["files"][1]["pore_size"]["voxels"] = 300, 500
    fig = figures_results.pore_size(figures_series.series_of([r]))
    labels = [line.get_label() for ax in fig.axes for line in ax.lines]
    assert any("on 300³" in label for label in labels)
    assert any("on 500³" in label for label in labels)
    assert "grids differ" in fig.sbpack_caption


def test_sides_split_at_one():
    """The paper's split: p <= 1 and p >= 1, the spheres in both."""
    series = [figures_series.Series(p, 100, 0, "r", [{}]) for p in (0.85, 1.0, 1.5)]
    (low_title, low), (high_title, high) = figures_series.sides(series)
    assert [s.p for s in low] == [0.85, 1.0] and [s.p for s in high] == [1.0, 1.5]
    assert figures_series.sides(series[1:2])[0][1] == series[1:2]


def test_slice_is_the_pore_map_on_the_results_grid(results):
    """The slice on the grid the pores analysis used (100^3 here), one panel per p."""
    fig = figures_shape.packing_slice(figures_series.series_of([sbpack.read_results(results)]),
                                      threads=2)
    ax = next(ax for ax in fig.axes if ax.get_title().startswith("p = 1.5"))
    assert "100³: the results' pores grid" in ax.get_title()
    packing = sbpack.Packing.read(INPUTS[0])
    solid, pores = _sbpack.voxel_slice(packing, 100, 50)
    image = ax.images[0].get_array()
    assert np.array_equal(image.mask, solid != 0)
    assert np.array_equal(image.data[solid == 0], (pores / packing.mean_width)[solid == 0])
    assert (pores[solid != 0] == 0).all() and (pores[solid == 0] > 0).all()
    assert ax.get_xlabel() == r"$z/\bar w$"


def test_form_factor_of_a_sphere():
    """The engine's form factor of one sphere (its spectral density in a box) against
    3 (sin x - x cos x) / x^3, x = Q D / 2, up to the first zero."""
    x, m = figures_shape.form_factor_of(1.0, 128, 2)
    keep = x < 1.2
    q = np.pi * x[keep]
    exact = 3 * (np.sin(q) - q * np.cos(q)) / q**3
    assert np.max(np.abs(m[keep] - exact)) < 0.02


def test_mean_width_is_the_engines(results, figures):
    assert figures_shape.width_over_major_axis(1.0) == pytest.approx(1.0)
    assert figures_shape.width_over_major_axis(1000.0) == pytest.approx(1.5, abs=1e-3)
    ax = figures["mean_width"].axes[0]
    curve = ax.lines[0]
    assert curve.get_xdata()[0] == 0.5 and curve.get_xdata()[-1] == 1000.0
    f = sbpack.read_results(results)["files"][0]
    assert f["mean_width"] / (2 * f["semi_axis"]) == pytest.approx(
        figures_shape.width_over_major_axis(f["p"]), rel=1e-9)


def test_one_p_has_no_versus_p(sbanalyze, tmp_path):
    out = tmp_path / "sq.h5"
    assert run([sbanalyze, INPUTS[0], "--compute", "sq", "--quiet", "--out", str(out)]
               ).returncode == 0
    names = plot.make_figures([str(out)], slice_voxels=0, form_factor_voxels=0)
    assert list(names) == ["structure_factor", "major_axis", "mean_width"]


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


def test_two_results_files_are_told_apart(results):
    """The same (p, N) in two results files: two series, one line style each, named."""
    r = sbpack.read_results(results)
    series = figures_series.series_of([r, copy.deepcopy(r)], ["a.h5", "b.h5"])
    assert len(series) == 4
    assert {s.style["ls"] for s in series} == {"-", "--"}
    assert all(s.label.endswith(f"[{s.run_name}]") for s in series)


def test_a_label_says_how_many_members_have_the_analysis():
    """An ensemble of three where hyper was skipped on one: its E(t) is the mean of two."""
    files = [{"input": f"s{i}.h5", "structure_factor": {}, "spreadability": {}}
             for i in range(2)] + [{"input": "s2.h5", "structure_factor": {}}]
    s = figures_series.Series(1.5, 250, 0, "r", files)
    s.label = figures_series.series_label(s)
    assert figures_series.group_label(s, "spreadability") == \
        "p = 1.5, N = 250 (mean $\\pm$ std of the 2 of 3 with spreadability)"
    assert figures_series.group_label(s, "structure_factor") == s.label


def steps_of(ax, f):
    """The q6 histogram (StepPatch) of the input f's series."""
    name = os.path.basename(str(f["input"]))
    return next(p for p in ax.patches if name in (p.get_gid() or ""))


def finite_q6(files):
    """The local q6 of every particle with bonds of `files`, pooled."""
    q = np.concatenate([f["order"]["q6_local"] for f in files])
    return q[np.isfinite(q)]


def test_order_is_the_results(results, figures):
    """g2 against r / w with its cutoff (dotted) and its ideal-gas band around 1; the density of
    the local q6 (particles without bonds left out) in bins of 0.01, beside fcc's 0.575, the
    verdict's 0.5 and the MRJ range; the legend names each input's values, no P4 for spheres."""
    files = sbpack.read_results(results)["files"]
    g2_axis, q6_axis = figures["order"].axes[:2]  # one side, p >= 1: g2 and q6
    assert g2_axis.get_xlabel() == r"$r/\bar w$" and q6_axis.get_xlabel() == r"local $q_6$"
    assert q6_axis.get_ylabel() == "probability density"
    for f in files:
        o = f["order"]
        line = series_line(g2_axis, f)
        assert np.array_equal(line.get_xdata(), o["r_w"])
        assert np.array_equal(line.get_ydata(), o["g2"])
        assert any(list(c.get_xdata()) == [o["cutoff_w"]] * 2 and c.get_linestyle() == ":"
                   and c.get_color() == line.get_color() for c in g2_axis.lines)
        density, edges, _ = steps_of(q6_axis, f).get_data()
        assert np.allclose(edges, np.linspace(0.0, 1.0, 101))
        assert np.array_equal(density, np.histogram(finite_q6([f]), edges, density=True)[0])
        entry = next(t.get_text() for t in q6_axis.get_legend().get_texts()
                     if os.path.basename(str(f["input"])) in t.get_text())
        assert f"{o['q6_local_mean']:.3f}" in entry and f"{o['T']:.3f}" in entry
        assert ("P_4" in entry) == (f["p"] != 1.0) and "ORDERED" not in entry
    band = np.concatenate([path.vertices[:, 1] for c in g2_axis.collections
                           for path in c.get_paths()])  # every input's 1 +- sigma
    assert band.min() >= 0.0 and band.max() <= 2.0 and band.max() > 1.0  # 1 +- sigma, sigma <= 1
    verticals = {c.get_xdata()[0] for c in q6_axis.lines if len(set(c.get_xdata())) == 1}
    assert {figures_order.Q6_ORDERED, figures_order.FCC_Q6} <= verticals
    low, high = sbpack._sbpack.mrj_local_q6  # sbanalyze's own range (order_metrics.hpp)
    assert any("MRJ" in t.get_text() and f"{low}-{high}" in t.get_text()
               for t in q6_axis.get_legend().get_texts())


def test_order_of_an_ensemble_draws_each_member(ensemble, ensemble_figures):
    """An ensemble's g2: each member's own curve (the results keep no ensemble g2); its q6
    histogram: every member's particles pooled; its legend: the ensemble's mean +- std."""
    r = sbpack.read_results(ensemble)
    g2_axis, q6_axis = ensemble_figures["order"].axes[:2]
    assert "each member's g₂ thin" in ensemble_figures["order"].sbpack_caption
    for e in r["ensembles"]:
        members = [r["files"][int(m)] for m in e["members"]]
        label = f"p = {e['p']:g}, N = {e['n_particles']} (mean $\\pm$ std of 3)"
        line = labelled(g2_axis)[label]
        drawn = [c for c in g2_axis.lines if c.get_color() == line.get_color()
                 and len(c.get_xdata()) > 2]
        assert len(drawn) == 3
        for c, f in zip(drawn, members):
            assert np.array_equal(c.get_ydata(), f["order"]["g2"])
        patch = next(p for p in q6_axis.patches if p.get_gid() == label)
        density, edges, _ = patch.get_data()
        assert np.array_equal(density, np.histogram(finite_q6(members), edges, density=True)[0])
        entry = next(t.get_text() for t in q6_axis.get_legend().get_texts()
                     if t.get_text().startswith(label))
        mean, std = e["order"]["q6_local_mean"], e["order"]["q6_local_mean_std"]
        assert f"{mean:.3f} \\pm {std:.3f}" in entry


def test_versus_p_has_the_order_metrics(ensemble, ensemble_figures):
    """With order results: Q6, the mean local q6, T and P4 against p, the ensembles' mean and
    std, no paper values (it has none), P4 only for p != 1."""
    ensembles = sbpack.read_results(ensemble)["ensembles"]
    axes = {ax.get_ylabel(): ax for ax in ensemble_figures["versus_p"].axes if ax.axison}
    for _, name, ylabel, column, _ in [p for p in plot.PANELS if p[0] == "order"]:
        assert column is None
        ax = axes[ylabel]
        assert ax.get_title().startswith("not in the paper")
        assert not [c for c in ax.containers if c.get_label() == figures_versus_p.PAPER]
        drawn = {(c.lines[0].get_xdata()[0], c.lines[0].get_ydata()[0]) for c in ax.containers}
        assert drawn == {(e["p"], e["order"][name]) for e in ensembles if name in e["order"]}
    assert {e["p"] for e in ensembles if "P4" in e["order"]} == {1.5}


def test_an_ordered_box_stands_out(sbanalyze, tmp_path):
    """The ordered N = 40 box beside MRJ: called ORDERED in the legend, its q6 filled and its
    narrow spike cut at the top of the MRJ densities, its true height written beside it in its
    own panel (as its g2 peak's in the g2 panel), the MRJ range and the verdict's threshold in
    the strip of the means above the densities; 'ordered' beside its points against p."""
    out = tmp_path / "order.h5"
    assert run([sbanalyze, ORDERED, INPUTS[0], "--compute", "order", "--quiet", "--out",
                str(out), "--threads", "1"]).returncode == 0
    r = sbpack.read_results(str(out))
    ordered, mrj = r["files"]
    assert ordered["order"]["ordered"] == 1 and mrj["order"]["ordered"] == 0
    series = figures_series.series_of([r])
    fig = figures_order.order(series)
    plot.finish(fig)
    g2_axis, q6_axis = fig.axes[:2]
    texts = {os.path.basename(str(f["input"])): next(
        t.get_text() for t in q6_axis.get_legend().get_texts()
        if os.path.basename(str(f["input"])) in t.get_text()) for f in r["files"]}
    assert "ORDERED" in texts["ordered-p1.2-40.h5"] and "ORDERED" not in texts["mrj-p1.5-1000.h5"]
    spike = np.histogram(finite_q6([ordered]), np.linspace(0, 1, 101), density=True)[0].max()
    mrj_peak = steps_of(q6_axis, mrj).get_data()[0].max()
    cut = figures_order.HEADROOM * mrj_peak
    assert steps_of(q6_axis, ordered).get_data()[0].max() == pytest.approx(cut) and cut < spike
    assert q6_axis.get_ylim()[1] == pytest.approx(cut / figures_order.MEAN_STRIP)
    assert [t.get_text() for t in q6_axis.texts if t.get_text() != "mean"] == [f"{spike:.3g}"]
    g2_peak = float(np.max(ordered["order"]["g2"]))
    assert g2_peak > g2_axis.get_ylim()[1]
    assert [t.get_text() for t in g2_axis.texts] == [f"{g2_peak:.3g}"]
    assert g2_axis.texts[0].xy[0] == pytest.approx(
        ordered["order"]["r_w"][int(np.argmax(ordered["order"]["g2"]))])
    mrj_range = next(p for p in q6_axis.patches if "MRJ" in p.get_label())
    y = mrj_range.get_path().vertices[:, 1]  # axes fraction in y
    assert y.min() == pytest.approx(figures_order.MEAN_STRIP) and y.max() == pytest.approx(1.0)
    filled = [p for p in q6_axis.patches if isinstance(p, StepPatch) and p.get_fill()]
    assert len(filled) == 1 and filled[0].get_facecolor()[:3] == \
        steps_of(q6_axis, ordered).get_edgecolor()[:3]
    versus = figures_versus_p.versus_p(series)
    marks = [t for ax in versus.axes for t in ax.texts if t.get_text() == "ordered"]
    assert len(marks) == 4 and all(t.xy[0] == 1.2 for t in marks)  # Q6, q6, T, P4


def test_spreadability_has_one_time_scaling_per_axis(ensemble, ensemble_figures):
    """Issue 66 item 5: the packings' time t D_diff / w^2 below both panels, the Debye media's
    t D_diff / a^2 on E(t)'s top axis; an ensemble's local alpha is its members' mean +- std (one
    line per series, not one per member)."""
    r = sbpack.read_results(ensemble)
    fig = ensemble_figures["spreadability"]
    left, right = fig.axes[:2]
    assert left.get_xlabel() == right.get_xlabel() == figures_results.PACKING_TIME
    assert [c.get_xlabel() for c in left.child_axes] == [
        r"$t\mathcal{D}/\hat a^2$ (Debye media, dashed)"]
    for e in r["ensembles"]:
        members = [r["files"][int(m)]["spreadability"] for m in e["members"]]
        mean = np.mean([m["local_alpha"] for m in members], axis=0)
        colour = labelled(left)[f"p = {e['p']:g}, N = {e['n_particles']} (mean $\\pm$ std of 3)"]
        drawn = [line for line in right.lines if line.get_color() == colour.get_color()
                 and len(line.get_xdata()) == len(mean)]
        assert len(drawn) == 1
        assert np.allclose(drawn[0].get_ydata(), mean, rtol=1e-12, atol=1e-12, equal_nan=True)


def test_log_bands_end_where_mean_minus_std_reaches_zero(ensemble_figures):
    """Issue 66 item 5: on F(delta)'s log axis an ensemble's band is drawn where mean - std > 0
    only; it does not fall to the axis as a wall."""
    ax = ensemble_figures["pore_size"].axes[0]
    lows = [path.vertices[:, 1] for c in ax.collections for path in c.get_paths()]
    assert lows and min(float(v.min()) for v in lows) > 1e-12


def test_an_empty_small_q_panel_is_skipped_with_its_reason(results):
    """Too few wave-vector shells at small Q and no fit: no figure, a reason that says so."""
    r = sbpack.read_results(results)
    for f in r["files"]:
        del f["hyperuniformity"]
        keep = np.asarray(f["spectral_density"]["Q_w"]) > 3.0
        f["spectral_density"]["Q_w"] = np.asarray(f["spectral_density"]["Q_w"])[keep]
        f["spectral_density"]["chi"] = np.asarray(f["spectral_density"]["chi"])[keep]
    skipped = figures_results.small_q(figures_series.series_of([r]))
    assert isinstance(skipped, figures_series.Skipped)
    assert "wave-vector shells and no fit" in skipped


def test_a_slice_without_its_packing_is_skipped_with_its_reason(results, tmp_path):
    """The inputs' packing files not found from here: the slice is not drawn, the command says
    why and names the way out (--packing); captions.md lists it as not drawn."""
    r = sbpack.read_results(results)
    for f in r["files"]:
        f["input"] = "moved-away/" + os.path.basename(str(f["input"]))
    skipped = figures_shape.packing_slice(figures_series.series_of([r]), voxels=64)
    assert isinstance(skipped, figures_series.Skipped)
    assert "moved-away/mrj-p1.5-1000.h5" in skipped and "--packing" in skipped
    plot.save({"packing_slice": skipped}, str(tmp_path))
    assert "## packing_slice.png: not drawn" in (tmp_path / "captions.md").read_text()
    assert not (tmp_path / "packing_slice.png").exists()


def bars_of(ax, label):
    """The heights of the bars of the series `label` (their gid), in the order drawn."""
    return [p.get_height() for p in ax.patches if p.get_gid() == label]


PAIR_NAMES = [f"{a}_{b}_fraction" for a, b in figures_contacts.PAIRS]


def test_contact_types_are_the_results(results, figures):
    """The density of theta (the contacts' ends' angle to the nearest body axis) as steps on the
    results' bins, beside the uniform normals' density (the sphere's); the six pair-type
    fractions as bars beside two independent uniform ends' (the products of sbanalyze's solid
    angles); the legend names Z, the mean theta and the ends' region fractions."""
    files = sbpack.read_results(results)["files"]
    theta_axis, pairs_axis = figures["contact_types"].axes[:2]  # one side, p >= 1
    assert theta_axis.get_xlabel() == r"$\theta$ (degrees)"
    uniform = [p for p in theta_axis.patches if p.get_linestyle() == "--"]
    assert len(uniform) == 1
    for f in files:
        c = f["contacts"]
        label = next(s for s in labelled_patches(theta_axis) if os.path.basename(
            str(f["input"])) in s)
        density, edges, _ = labelled_patches(theta_axis)[label].get_data()
        assert np.array_equal(density, c["axis_angle_density"])
        assert np.array_equal(edges, c["axis_angle_edges"])
        assert np.array_equal(uniform[0].get_data()[0], c["axis_angle_uniform"])
        assert bars_of(pairs_axis, label) == [c[name] for name in PAIR_NAMES]
        assert sum(c[name] for name in PAIR_NAMES) == pytest.approx(1.0, abs=1e-12)
        entry = next(t.get_text() for t in pairs_axis.get_legend().get_texts()
                     if t.get_text().startswith(label))
        assert f"axis {c['axis_fraction']:.3f}" in entry
        assert f"{c['axis_angle_mean']:.2f}°" in entry and f"Z = {c['z_mean']:.2f}" in entry
    ticks = [line for line in pairs_axis.collections if line.get_label().startswith("two ind")]
    heights = [seg[0][1] for seg in ticks[0].get_segments()]
    uniform_regions = _sbpack.uniform_region_fractions
    assert sum(uniform_regions.values()) == pytest.approx(1.0, abs=1e-15)
    assert heights == pytest.approx([uniform_regions["axis"] ** 2,
                                     2 * uniform_regions["axis"] * uniform_regions["edge"],
                                     2 * uniform_regions["axis"] * uniform_regions["diagonal"],
                                     uniform_regions["edge"] ** 2,
                                     2 * uniform_regions["edge"] * uniform_regions["diagonal"],
                                     uniform_regions["diagonal"] ** 2], abs=1e-15)
    # the physics the figure is for: at p = 1.5 the contacts sit near the faces; the spheres'
    # normals (their stored orientations are all equal: the lab frame's) are near uniform
    cube, sphere = sorted(files, key=lambda f: -f["p"])
    assert cube["contacts"]["axis_fraction"] > 2 * uniform_regions["axis"]
    assert cube["contacts"]["axis_angle_mean"] < 20.0 < 31.0 < sphere["contacts"][
        "axis_angle_mean"] < 33.0


def test_contact_types_versus_p_are_the_results(results, figures):
    """Against p: each region's fraction of the ends and the mean theta at the results' values,
    the pair types of the superballs only (spheres' are their orientations'), the uniform
    normals' fractions (sbanalyze's solid angles) and mean theta (31.90 degrees, Eqs. 2.1-2.3 of
    docs/contact-types.md) as the dashed lines."""
    files = sorted(sbpack.read_results(results)["files"], key=lambda f: f["p"])
    ends_axis, pairs_axis, theta_axis = figures["contact_types_versus_p"].axes[:3]

    def points(ax, label):
        """(p, value) of the error bars labelled `label...` (one container per N), by p."""
        xy = sorted((x, y) for c in ax.containers if c.get_label().startswith(label)
                    for x, y in zip(c.lines[0].get_xdata(), c.lines[0].get_ydata()))
        return [x for x, _ in xy], [y for _, y in xy]

    ps = [f["p"] for f in files]
    for region, name in figures_contacts.REGION_NAMES.items():
        assert points(ends_axis, name) == (ps, [f["contacts"][f"{region}_fraction"]
                                                for f in files])
    assert points(theta_axis, "N = ") == (ps, [f["contacts"]["axis_angle_mean"] for f in files])
    cube = files[-1]
    for a, b in figures_contacts.PAIRS:
        assert points(pairs_axis, f"{a}–{b}") == ([cube["p"]], [cube["contacts"][f"{a}_{b}_fraction"]])
    dashed = sorted(line.get_ydata()[0] for line in ends_axis.lines if line.get_linestyle() == "--"
                    and len(line.get_ydata()))
    assert dashed == pytest.approx(sorted(_sbpack.uniform_region_fractions.values()), abs=1e-15)
    uniform_theta = [line.get_ydata()[0] for line in theta_axis.lines
                     if line.get_linestyle() == "--"]
    assert uniform_theta == [pytest.approx(31.90, abs=0.01)]


def labelled_patches(ax):
    """The axes' series steps, by their series' label (their gid)."""
    return {p.get_gid(): p for p in ax.patches
            if (p.get_gid() or "").startswith("p = ") and isinstance(p, StepPatch)}


def test_contact_types_of_an_ensemble_are_its_means(ensemble, ensemble_figures):
    """An ensemble: the pointwise mean of its members' densities in a band of +- std, its mean
    fractions with their std as error bars (sbanalyze's reduction, checked against the
    members)."""
    r = sbpack.read_results(ensemble)
    theta_axis, pairs_axis = ensemble_figures["contact_types"].axes[:2]
    for e in r["ensembles"]:
        members = [r["files"][int(m)]["contacts"] for m in e["members"]]
        c = e["contacts"]
        assert np.allclose(c["axis_angle_density"],
                           np.mean([m["axis_angle_density"] for m in members], axis=0),
                           rtol=0, atol=1e-15)
        assert c["axis_fraction"] == pytest.approx(np.mean([m["axis_fraction"] for m in members]))
        label = f"p = {e['p']:g}, N = {e['n_particles']} (mean $\\pm$ std of 3)"
        density, edges, _ = labelled_patches(theta_axis)[label].get_data()
        assert np.array_equal(density, c["axis_angle_density"])
        assert np.array_equal(edges, c["axis_angle_edges"])
        assert bars_of(pairs_axis, label) == [c[name] for name in PAIR_NAMES]
    bands = [p for p in theta_axis.patches if p.get_fill()]
    assert len(bands) == 2  # one per ensemble


def test_contact_forces_are_the_results(sbgen, sbanalyze, tmp_path):
    """Issue 62: the stored forces' P(f / <f>) is drawn from the results (an ensemble's mean and
    band, an empty bin a gap on the log axis), beside e^-x, with <x^2> in the legend; results without stored forces (every input
    of data/) have no such figure (NAMES)."""
    paths = []
    for seed in (3, 4):
        path = str(tmp_path / f"forces-{seed}.h5")
        r = run([sbgen, "--n", "64", "--p", "1.5", "--seed", str(seed), "--gamma-slow", "0.01",
                 "--pressure-final", "1e9", "--quiet", "--out", path])
        assert r.returncode in (0, 3), r.stderr  # jammed or not, the forces are stored
        paths.append(path)
    out = tmp_path / "r.h5"
    assert run([sbanalyze, *paths, "--compute", "contacts", "--quiet", "--out", str(out)]
               ).returncode == 0
    figures = plot.make_figures([str(out)], slice_voxels=0, form_factor_voxels=0)
    ax = figures["contact_forces"].axes[0]
    ensemble = sbpack.read_results(str(out))["ensembles"][0]["contacts"]
    steps = [p for p in ax.patches if p.get_gid() == r"p = 1.5, N = 64 (mean $\pm$ std of 2)"]
    assert len(steps) == 1
    heights = steps[0].get_data()[0]
    density = np.asarray(ensemble["force_density"])
    assert np.allclose(heights[density > 0], density[density > 0])
    assert np.isnan(heights[density == 0]).all()  # an empty bin: a gap on the log axis
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any(f"{ensemble['force_second_moment']:.3f}" in t for t in legend)
    assert any("e^{-x}" in t for t in legend)


def test_local_structure_figures_are_the_results(results, figures):
    """Issue 69: the local-phi density is the results' phi_density per input, and the variance
    figure's line and points are sigma2_spectral and sigma2_sampled times (R / w)^3."""
    r = sbpack.read_results(results)
    for f in r["files"]:
        v, s = f["voronoi"], f["variance"]
        steps = [p for p in figures["local_phi"].axes[0].patches if p.get_gid() is not None
                 and p.get_gid().startswith(f"p = {f['p']:g}, N")]
        assert len(steps) == 1
        assert np.array_equal(steps[0].get_data()[0], v["phi_density"])
        lines = [line for line in figures["volume_fraction_variance"].axes[0].get_lines()
                 if line.get_label().startswith(f"p = {f['p']:g}, N")]
        assert len(lines) == 1
        radius = s["radius_w"]
        assert np.allclose(lines[0].get_xdata(), radius, rtol=0, atol=0)
        assert np.allclose(lines[0].get_ydata(), s["sigma2_spectral"] * radius**3, rtol=1e-15)


def test_unjamming_motion_is_the_results(sbanalyze, tmp_path):
    """Issue 62 item 3: the simple-cubic lattice's flex (its rows slide) drawn on a section
    through a layer of centres: one arrow per sphere of that layer, each the results' (z, y)
    displacement scaled so that the largest is one diameter."""
    from conftest import ROOT
    lattice = str(tmp_path / "sc125.txt")
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "make_lattice.py"), "1", "5",
                    lattice], check=True)
    out = tmp_path / "r.h5"
    r = run([sbanalyze, lattice, "--compute", "jamming", "--jamming-categories", "collective",
             "--quiet", "--out", str(out)])
    assert r.returncode == 0, r.stderr
    figures = plot.make_figures([str(out)], slice_voxels=100, form_factor_voxels=0)
    quiver = figures["unjamming_motion"].axes[0].collections[0]
    flex = np.asarray(sbpack.read_results(str(out))["files"][0]["jamming_collective"]
                      ["flex_displacement"])
    packing = sbpack.Packing.read(lattice)
    layer = np.isclose(packing.positions[:, 0], packing.positions[:, 0][
        np.argmin(np.abs(packing.positions[:, 0] - packing.box_length / 2))])
    assert len(quiver.U) == 25 == layer.sum()
    scale = 1.0 / np.max(np.linalg.norm(flex, axis=1))  # D = 1
    assert np.allclose(quiver.U, flex[layer, 2] * scale)
    assert np.allclose(quiver.V, flex[layer, 1] * scale)
