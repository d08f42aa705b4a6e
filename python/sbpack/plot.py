"""The paper's figures from sbanalyze results files (docs/python.md, "Figures").

usage: python3 -m sbpack.plot RESULTS.h5... [--out DIR] [--packing FILE.h5] [--slice-voxels M]

Draws every figure the results support, as PNG and PDF in DIR (default: the current directory),
every input of every file overlaid (above MANY_INPUTS inputs, one colour and legend entry per p
and N, without the per-input fits):
  structure_factor     S(Q) against Q w                                  (paper Fig. S(Q))
  spectral_density     chi_V(Q) / w^3 against Q w, and at small Q on log axes with the fit
                       a0 + a1 Q^alpha of `hyper`                         (Figs. chi, H)
  spreadability        excess spreadability E(t) with the Debye medium, and the local alpha
                       with the fitted window                             (Figs. spread, alpha)
  pore_size            F(delta) against delta / w                         (Fig. F(delta))
  versus_p             with two or more values of p: phi, Z, phi_R, alpha, k, tau, T1 against p,
                       ensemble mean +- standard deviation, the paper's values as markers
                       (data/mst-reference-values.csv; the paper gives k, tau, T1 as a figure only)
  packing_slice        a voxel slice of a packing, the void coloured by pore size (the packing
                       of --packing, else the first input named in the results, where it exists)
Reads only; every number drawn is sbanalyze's (the slice: the pores analysis's own voxelization
and distance transform, through sbpack._sbpack.voxel_slice).
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker as ticker  # noqa: E402
import numpy as np  # noqa: E402

from .results import read_results  # noqa: E402

REFERENCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "mst-reference-values.csv")


def label(f):
    return f"p = {f['p']:g}, N = {f['n_particles']} ({os.path.basename(str(f['input']))})"


def inputs_with(runs, group):
    return [f for r in runs for f in r["files"] if group in f]


MANY_INPUTS = 6  # above this, one colour and legend entry per (p, N) series, not per input


def styles(files):
    """A line style (label, colour) per input. Up to MANY_INPUTS inputs, each its own label and
    the colour cycle's colour; above, the inputs of one (p, N) share a colour (viridis along p)
    and one legend entry, "p = 1.5, N = 1000 (5 inputs)", the others none."""
    if len(files) <= MANY_INPUTS:
        return [{"label": label(f)} for f in files]
    keys = [(f["p"], f["n_particles"]) for f in files]
    series = sorted(set(keys))
    colour = {k: plt.cm.viridis(0.9 * i / max(1, len(series) - 1)) for i, k in enumerate(series)}
    out, labelled = [], set()
    for k in keys:
        text = f"p = {k[0]:g}, N = {k[1]} ({keys.count(k)} inputs)"
        out.append({"label": "_nolegend_" if k in labelled else text, "color": colour[k]})
        labelled.add(k)
    return out


def once(drawn, key):
    """True the first time `key` is asked about (marks shared by many inputs drawn once)."""
    new = key not in drawn
    drawn.add(key)
    return new


def structure_factor(runs, ax):
    files = inputs_with(runs, "structure_factor")
    for f, style in zip(files, styles(files)):
        s = f["structure_factor"]
        ax.plot(s["Q_w"], s["S"], lw=1, **style)
    ax.axhline(1.0, color="0.7", lw=0.8, ls=":")
    ax.set(xlabel=r"$Q\bar w$ (dimensionless)", ylabel=r"$S(Q)$ (dimensionless)",
           title="Structure factor")


def small_q_fit(f, ax, colour):
    """The fit a0 + a1 Q^alpha of `hyper`, only over its window: beyond it the fit says nothing
    (and may turn negative)."""
    h, qw = f["hyperuniformity"], f["spectral_density"]["Q_w"]
    x = np.geomspace(min(qw[0], h["q_fit_max_w"]) * 0.9, h["q_fit_max_w"], 100)
    ax.loglog(x, h["a0"] + h["a1"] * x ** h["alpha"], "-", color=colour,
              label=fr"$a_0 + a_1 Q^{{{h['alpha']:.2f}}}$, $H = {h['H']:.2g} \pm "
                    fr"{h['H_stderr']:.1g}$ ({h['fit_points']} exact $\chi_V$)")
    ax.axvline(h["q_fit_max_w"], color="0.6", ls=":", lw=1)


def small_q_title(files):
    fits = sum("hyperuniformity" in f for f in files)
    if not fits:
        return r"Small $Q$ (no hyper results: no fit)"
    if len(files) > MANY_INPUTS:
        return fr"Small $Q$ ({len(files)} inputs: fits not drawn)"
    return r"Small $Q$ and the fit ($Q\bar w \leq$ fit-qmax dotted)"


def spectral_density(runs, axes):
    main, small = axes
    files = inputs_with(runs, "spectral_density")
    for f, style in zip(files, styles(files)):
        s, w = f["spectral_density"], f["mean_width"]
        qw, chi = s["Q_w"], s["chi"] / w**3
        line, = main.plot(qw, chi, lw=1, **style)
        keep = qw <= 4.0
        small.loglog(qw[keep], chi[keep], "o", ms=3, color=line.get_color())
        if "hyperuniformity" in f and len(files) <= MANY_INPUTS:
            small_q_fit(f, small, line.get_color())
    ylabel = r"$\tilde\chi_V(Q)/\bar w^3$ (dimensionless)"
    main.set(xlabel=r"$Q\bar w$ (dimensionless)", ylabel=ylabel,
             title="Spectral density (voxels, shell averages)")
    small.xaxis.set_major_locator(ticker.FixedLocator([0.1, 0.2, 0.3, 0.5, 1, 1.5, 2, 3, 4, 5, 10]))
    small.xaxis.set_major_formatter(ticker.FormatStrFormatter("%g"))
    small.xaxis.set_minor_formatter(ticker.NullFormatter())
    # chi at small Q often spans less than a decade: then the 2..9 subdivisions are labelled too
    # (else the axis has no number at all), in the decades' own notation.
    for formatter in (small.yaxis.set_major_formatter, small.yaxis.set_minor_formatter):
        formatter(ticker.LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(1.5, 0.5)))
    small.set(xlabel=r"$Q\bar w$ (dimensionless)", ylabel=ylabel, title=small_q_title(files))


def spreadability_marks(s, axes, colour, drawn):
    """The alpha window (shaded) and t_c (dotted) of one input; with many inputs (colour None),
    in grey and once per window distinct to two digits (they scale with each input's w)."""
    many = colour is None
    colour = "0.5" if many else colour
    window = tuple(f"{s[t]:.2g}" for t in ("t_fit_min", "t_fit_max"))
    for ax in axes:
        if not many or once(drawn, (ax, "window") + window):
            ax.axvspan(s["t_fit_min"], s["t_fit_max"], color=colour, alpha=0.12)
        if not many or once(drawn, (ax, "cutoff", f"{s['t_cutoff']:.2g}")):
            ax.axvline(s["t_cutoff"], color=colour, ls=":", lw=1)


def spreadability(runs, axes):
    top, bottom = axes
    debye_drawn = False
    files, drawn = inputs_with(runs, "spreadability"), set()
    many = len(files) > MANY_INPUTS
    for f, style in zip(files, styles(files)):
        s = f["spreadability"]
        line, = top.loglog(s["t"], s["excess"], lw=1.2, **style)
        c = line.get_color()
        bottom.semilogx(s["t"], s["local_alpha"], lw=1, color=c)
        if not many:  # many inputs: their alpha is versus_p's
            bottom.axhline(s["alpha"], color=c, ls="--", lw=1,
                           label=fr"$\alpha = {s['alpha']:.2f} \pm {s['alpha_stderr']:.2f}$")
        spreadability_marks(s, axes, None if many else c, drawn)
        if not debye_drawn and "spreadability_debye" in f:
            d = f["spreadability_debye"]
            top.loglog(d["t"], d["excess"], "k--", lw=1,
                       label=fr"Debye medium, $\phi = {d['phi']:.3f}$ (same $t\mathcal{{D}}/\bar w^2$)")
            debye_drawn = True
    top.set(ylabel=r"$\mathcal{S}(\infty)-\mathcal{S}(t)$ (dimensionless)", ylim=(1e-8, 2),
            title=r"Excess spreadability (shaded: $\alpha$ window; dotted: $t_c$)")
    bottom.set(xlabel=r"$t\mathcal{D}/\bar w^2$ (dimensionless)",
               ylabel=r"local $\alpha$ (dimensionless)", ylim=(-1.5, 3))


def pore_size(runs, ax):
    files = inputs_with(runs, "pore_size")
    for f, style in zip(files, styles(files)):
        s = f["pore_size"]
        ax.step(s["delta_w"], s["F"], where="post", lw=1, **style)
    ax.set(xlabel=r"$\delta/\bar w$ (dimensionless)", ylabel=r"$F(\delta)$ (dimensionless)",
           title="Pore-size distribution", ylim=(0, 1.02))


# versus_p: (results group, value, its std, the paper's column and scale, axis label)
PANELS = [
    (None, "phi", r"$\phi$", "phi", 1.0),
    ("contacts", "z_mean", r"$Z$ (over non-rattlers)", "Z", 1.0),
    ("contacts", "rattler_fraction", r"$\phi_R$ (rattler fraction)", "phi_R_percent", 0.01),
    ("spreadability", "alpha", r"$\alpha$ (from $E(t)$)", "alpha", 1.0),
    ("transport", "permeability_w2", r"$k/\bar w^2$", None, 1.0),
    ("transport", "mean_survival_time_scaled", r"$\tau\mathcal{D}/\bar w^2$ (bound)", None, 1.0),
    ("transport", "principal_relaxation_time_scaled", r"$T_1\mathcal{D}/\bar w^2$ (bound)", None,
     1.0),
]


def paper_values(path=REFERENCE):
    """The paper's table (data/mst-reference-values.csv): column -> (p, value) arrays."""
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    table = {}
    for column in rows[0]:
        pairs = [(float(r["p"]), float(r[column])) for r in rows if r[column]]
        table[column] = tuple(np.array(v) for v in zip(*pairs))
    return table


def ensemble_points(runs, group, name):
    """N -> (p, mean, std) rows, sorted by p, over every ensemble of every results file that has
    the value (one series per N: ensembles of different N are not one curve)."""
    series = {}
    for r in runs:
        for e in r["ensembles"]:
            g = e if group is None else e.get(group)
            if g is not None and name in g:
                series.setdefault(e["n_particles"], []).append(
                    (e["p"], g[name], g.get(name + "_std", 0.0)))
    return {n: np.array(sorted(rows)) for n, rows in sorted(series.items())}


def paper_markers(ax, paper, column, scale):
    p, v = paper[column]
    sd_column = (column[: -len("_percent")] + "_sd_percent" if column.endswith("_percent")
                 else column + "_sd")
    sd = paper.get(sd_column)
    yerr = sd[1] * scale if sd is not None and len(sd[1]) == len(v) else None
    ax.errorbar(p, v * scale, yerr=yerr, fmt="s", mfc="none", color="k", ms=5, capsize=2,
                label="paper (Maher et al.)")


def panels_with_data(runs):
    """The PANELS the results have values for."""
    return [panel for panel in PANELS if ensemble_points(runs, panel[0], panel[1])]


def versus_p(runs, axes, panels):
    paper = paper_values()
    sizes = sorted({e["n_particles"] for r in runs for e in r["ensembles"]})
    colour = {n: f"C{i % 10}" for i, n in enumerate(sizes)}  # one colour per N in every panel
    for ax, (group, name, ylabel, column, scale) in zip(axes, panels):
        series = ensemble_points(runs, group, name)
        for n, pts in series.items():
            ax.errorbar(pts[:, 0], pts[:, 1], yerr=pts[:, 2], fmt="o-", ms=4, lw=0.8,
                        capsize=3, color=colour[n], label=f"N = {n} (mean $\\pm$ std)")
        ps = [p for pts in series.values() for p in pts[:, 0]]
        if column is not None:
            paper_markers(ax, paper, column, scale)
            ps += list(paper[column][0])
        else:
            ax.set_title("paper: figure only, no table", fontsize=8)
        if max(ps) / min(ps) > 3.0:  # p over a decade: log axis
            ax.set_xscale("log")
            ax.xaxis.set_major_formatter(ticker.FormatStrFormatter("%g"))
            ax.xaxis.set_minor_formatter(ticker.NullFormatter())
        ax.set(xlabel=r"$p$", ylabel=ylabel)
    for ax in axes[len(panels):]:
        ax.set_axis_off()
    axes[0].figure.suptitle("Against the superball exponent $p$ (every quantity dimensionless; "
                            "markers: paper, Maher et al.)")


def has_several_p(runs):
    return len({e["p"] for r in runs for e in r["ensembles"]}) >= 2


def slice_packing(runs, packing_path):
    """The packing for the slice: --packing, else the first input named in the results that
    exists (paths as sbanalyze was given them, tried from the current directory)."""
    if packing_path:
        return packing_path
    for f in (f for r in runs for f in r["files"]):
        if os.path.isfile(str(f["input"])):
            return str(f["input"])
    return None


def packing_slice(packing, voxels, ax):
    """The plane x = L / 2 of the voxelization, the void coloured by pore size / w."""
    from . import _sbpack
    plane = voxels // 2
    solid, pores = _sbpack.voxel_slice(packing, voxels, plane, os.cpu_count() or 1)
    w, d = packing.mean_width, 2.0 * packing.semi_axis
    extent = (0.0, packing.box_length / d, 0.0, packing.box_length / d)
    # rows are y (index j), columns z (index k): z across, y up
    image = ax.imshow(np.ma.masked_where(solid != 0, pores / w), origin="lower", extent=extent,
                      cmap="viridis", interpolation="nearest")
    ax.imshow(np.ma.masked_where(solid == 0, solid), origin="lower", extent=extent,
              cmap="Greys", vmin=0, vmax=1.6, interpolation="nearest")
    plt.colorbar(image, ax=ax, label=r"pore size $\delta/\bar w$ (void voxels)")
    x = (plane + 0.5) * packing.box_length / voxels / d
    ax.set(xlabel=r"$z/D$ ($D$ = major axis)", ylabel=r"$y/D$")
    ax.set_title(f"p = {packing.p:g}, N = {len(packing)}: plane x = {x:.2f} D of {voxels}$^3$ "
                 "voxels\n(grey: particles; void coloured by pore size)", fontsize=9)


def make_figures(paths, packing_path=None, slice_voxels=200):
    """name -> matplotlib Figure for every figure the results at `paths` support."""
    runs = [read_results(p) for p in paths]
    figures = {}
    if inputs_with(runs, "structure_factor"):
        figures["structure_factor"], ax = plt.subplots(figsize=(6, 4))
        structure_factor(runs, ax)
    if inputs_with(runs, "spectral_density"):
        figures["spectral_density"], axes = plt.subplots(1, 2, figsize=(11, 4))
        spectral_density(runs, axes)
    if inputs_with(runs, "spreadability"):
        figures["spreadability"], axes = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
        spreadability(runs, axes)
    if inputs_with(runs, "pore_size"):
        figures["pore_size"], ax = plt.subplots(figsize=(6, 4))
        pore_size(runs, ax)
    if has_several_p(runs):
        panels = panels_with_data(runs)  # a grid of 4 columns, only as many rows as needed
        rows, columns = (len(panels) + 3) // 4, min(4, len(panels))
        figures["versus_p"], axes = plt.subplots(rows, columns, figsize=(3.8 * columns, 3.5 * rows),
                                                 squeeze=False)
        versus_p(runs, axes.ravel(), panels)
    packing_file = slice_packing(runs, packing_path)
    if packing_file is not None and slice_voxels > 0:
        from . import _sbpack
        figures["packing_slice"], ax = plt.subplots(figsize=(6, 5))
        packing_slice(_sbpack.Packing.read(packing_file), slice_voxels, ax)
    return figures


def legend(ax, most_inside=8):
    """The axes' legend: inside up to `most_inside` entries, else beside the axes (on the right)
    where it hides no data."""
    entries = len(ax.get_legend_handles_labels()[0])
    if entries > most_inside:
        ax.legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    elif entries:
        ax.legend(fontsize=7)


def save(figures, out):
    """Each figure as out/NAME.png and out/NAME.pdf; returns the PNG paths."""
    os.makedirs(out, exist_ok=True)
    written = []
    for name, fig in figures.items():
        for ax in fig.axes:
            legend(ax)
        fig.tight_layout()
        for ext in ("png", "pdf"):
            fig.savefig(os.path.join(out, f"{name}.{ext}"), dpi=130)
        written.append(os.path.join(out, f"{name}.png"))
        plt.close(fig)
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m sbpack.plot",
                                     description="The paper's figures from sbanalyze results "
                                                 "files, as PNG and PDF (docs/python.md).")
    parser.add_argument("results", nargs="+", metavar="RESULTS.h5")
    parser.add_argument("--out", default=".", metavar="DIR", help="output folder (default .)")
    parser.add_argument("--packing", metavar="FILE.h5",
                        help="packing of the slice figure (default: the first input that exists)")
    parser.add_argument("--slice-voxels", type=int, default=200, metavar="M",
                        help="voxels of the slice figure's grid (default 200; 0: no slice)")
    args = parser.parse_args(argv)
    try:
        figures = make_figures(args.results, args.packing, args.slice_voxels)
    except (OSError, ValueError) as e:
        parser.exit(1, f"sbpack.plot: error: {e}\n")
    for path in save(figures, args.out):
        print(path)


if __name__ == "__main__":
    main()
