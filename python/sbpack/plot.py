"""The paper's figures from sbanalyze results files (docs/python.md, "Figures").

usage: python3 -m sbpack.plot RESULTS.h5... [--out DIR] [--packing FILE.h5] [--slice-voxels M]
                              [--form-factor-voxels M] [--threads T]

Draws every figure the results support, as PNG and PDF in DIR (default: the current directory).
Each (p, N) ensemble of each results file is one series: colour keyed to p (viridis along the
distinct p), marker to N, line style to the results file; an ensemble of two inputs or more is
drawn as its mean +- std (a band), one input as its own curve. Curves are split as the paper
splits them, p <= 1 | p >= 1.
  structure_factor   S(Q) against Q w                                     (paper Figs. 8, 9)
  spectral_density   chi_V(Q) / w^3 against Q w                           (Figs. 10, 11)
  small_q            chi_V at small Q, log axes, the fit a0 + a1 Q^alpha of `hyper` over its
                     window (one input each; degenerate fits not drawn)   (Table fit, Eq. fit)
  major_axis         S(Q) and chi_V / A^3 against Q A, A = 2R             (Figs. S3-S6)
  spreadability      E(t) with the Debye media, and the local and fitted alpha (Figs. 16, 17)
  pore_size          F(delta) (log axis) and P(delta) against delta / w   (Figs. 12, 13)
  order              g2(r) against r / w with the ideal-gas error and the neighbour cutoff, and
                     the density of the local q6 beside fcc, the verdict's threshold and the MRJ
                     range (sbanalyze --compute order; docs/order-metrics.md; not in the paper)
  contact_types      the angle theta of the contact normals to the nearest body axis beside the
                     uniform normals' (spheres'), and the pair types of the contacts' ends (axis,
                     edge, diagonal) beside two independent uniform ends' (sbanalyze --compute
                     contacts; docs/contact-types.md; the paper's closing question)
  contact_types_versus_p  with two or more p: the ends' region fractions, the superballs'
                     pair types and the mean theta against p, the uniform normals' dashed
  versus_p           with two or more p: phi, Z, phi_R, alpha, H, k, tau, T1 against p, the
                     paper's values as markers, and with order results Q6, the mean local q6,
                     T and P4 (not in the paper)                          (Figs. 4, 5, 7, 13-15, 17)
  phi_vs_width       with two or more p: phi against w / A                (Fig. 6, superballs)
  mean_width         w / A against p over [0.5, 1000]                     (Fig. 3)
  form_factor        the form factor of one superball at each p, linear and log-log (Figs. S1, S2)
  contact_forces     with sbgen's stored contact forces: P(f / <f>) per (p, N) beside e^-x
  local_phi          with --compute voronoi: the density of the set-Voronoi local packing
                     fractions per (p, N) (docs/local-structure.md; not in the paper)
  volume_fraction_variance  with --compute variance: sigma_V^2 (R / w)^3 against R / w, the
                     spectral route a line, the sampled windows points with error bars
  unjamming_motion   with --compute jamming: the collective test's opening or flex on a section
                     of its packing, per p (slice grid: --slice-voxels, default 200)
  packing_slice      a section of a packing per p, the void coloured by pore size  (Fig. 2's)
Every number drawn is sbanalyze's or sbpack's: read from the results, or (mean_width,
form_factor, packing_slice, the section under unjamming_motion) computed by the module's own
engine (figures_shape, figures_forces). Two statistics
are taken here: the mean +- std of an ensemble's F(delta) and P(delta), which the results do not
keep, and the histogram of the per-particle local q6 (an ensemble's members pooled).
draw_figures() returns the finished figures (legends, layout) and, for a figure the results call
for that would be empty (no packing file to cut, too few wave vectors to fit), the reason it is
not drawn; the command saves exactly those figures and prints the reasons. make_figures() returns
the figures alone.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.collections  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import figures_contacts as contact_figures  # noqa: E402
from . import figures_forces as force_figures  # noqa: E402
from . import figures_local as local_figures  # noqa: E402
from . import figures_order as order_figures  # noqa: E402
from . import figures_results as results_figures  # noqa: E402
from . import figures_shape as shape_figures  # noqa: E402
from . import figures_versus_p as versus  # noqa: E402
from .figures_series import Skipped, series_of  # noqa: E402
from .figures_versus_p import PANELS, paper_values  # noqa: E402  (the module's API)
from .results import read_results  # noqa: E402

__all__ = ["draw_figures", "make_figures", "Skipped", "finish", "save", "main", "FIGURES", "PANELS", "paper_values"]

LEGEND_INSIDE = 3  # a legend of more entries stands beside its axes
LEGEND_WIDTH = 2.6  # inches the figure grows by per legend beside the axes of one row
CORNERS = ["upper right", "upper left", "lower right", "lower left", "center right",
           "center left", "upper center", "lower center"]  # a legend inside, in this preference

# name -> figure function of the series (None where the results do not support it)
FIGURES = {
    "structure_factor": results_figures.structure_factor,
    "spectral_density": results_figures.spectral_density,
    "small_q": results_figures.small_q,
    "major_axis": results_figures.major_axis,
    "spreadability": results_figures.spreadability,
    "pore_size": results_figures.pore_size,
    "order": order_figures.order,
    "contact_types": contact_figures.contact_types,
    "contact_types_versus_p": contact_figures.contact_types_versus_p,
    "contact_forces": force_figures.contact_forces,
    "local_phi": local_figures.local_phi,
    "volume_fraction_variance": local_figures.volume_fraction_variance,
    "versus_p": versus.versus_p,
    "phi_vs_width": versus.phi_vs_width,
    "mean_width": shape_figures.mean_width,
}


def draw_figures(paths, packing_path=None, slice_voxels=None, form_factor_voxels=256,
                 threads=None):
    """name -> finished matplotlib Figure, or the Skipped reason it is not drawn, for every
    figure the results at `paths` call for (a figure of an analysis they lack is absent).
    slice_voxels: the slice's grid (None: the results' pore grid of that input; 0: no slice);
    form_factor_voxels: the form factors' grid (0: none); threads: of the engine's figures
    (None: every core)."""
    threads = threads or os.cpu_count() or 1
    series = series_of([read_results(p) for p in paths], paths)
    figures = {name: draw(series) for name, draw in FIGURES.items()}
    figures["form_factor"] = shape_figures.form_factor(series, form_factor_voxels, threads)
    figures["unjamming_motion"] = force_figures.unjamming_motion(series, slice_voxels or 200,
                                                                 threads)
    figures["packing_slice"] = shape_figures.packing_slice(series, packing_path, slice_voxels,
                                                           threads)
    figures = {name: fig for name, fig in figures.items() if fig is not None}
    for fig in figures.values():
        if not isinstance(fig, Skipped):
            finish(fig)
    return figures


def make_figures(paths, packing_path=None, slice_voxels=None, form_factor_voxels=256,
                 threads=None):
    """name -> finished matplotlib Figure (legends placed, constrained layout) for every figure
    the results at `paths` support (draw_figures without the ones skipped)."""
    return {name: fig for name, fig in draw_figures(paths, packing_path, slice_voxels,
                                                    form_factor_voxels, threads).items()
            if not isinstance(fig, Skipped)}


def finish(fig):
    """Every axes' legend: inside, where one of up to LEGEND_INSIDE entries fits at a corner or
    side without covering data (place_inside), else beside the axes on the right, where it hides
    no data, the figure widened by LEGEND_WIDTH per such legend in a row (constrained layout
    makes the room). Widening moves every axes, so the legends inside are placed again at the
    final width until no more go beside."""
    width, outside = fig.get_figwidth(), set()
    while True:
        before = len(outside)
        beside = {}
        for ax in fig.axes:
            entries = len(ax.get_legend_handles_labels()[0])
            if not entries or (ax not in outside and entries <= LEGEND_INSIDE
                               and place_inside(fig, ax)):
                continue
            ax.legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.02, 1.0),
                      borderaxespad=0.0)
            outside.add(ax)
            spec = getattr(ax, "get_subplotspec", lambda: None)()
            row = spec.rowspan.start if spec is not None else 0
            beside[row] = beside.get(row, 0) + 1
        final = width + LEGEND_WIDTH * max(beside.values(), default=0)
        if final == fig.get_figwidth() and len(outside) == before:
            return  # the layout the legends inside were placed on is the final one
        fig.set_figwidth(final)


def place_inside(fig, ax):
    """The axes' legend inside it at the first place of CORNERS where it covers no drawn data
    (drawn_points); False, and no legend, where it covers some everywhere. matplotlib's 'best'
    counts a line's vertices only and would lay the legend over a steep segment between two."""
    fig.canvas.draw()  # the layout that the figure is saved with: the axes' final boxes
    renderer = fig.canvas.get_renderer()
    data = drawn_points(ax)
    for loc in CORNERS:
        legend = ax.legend(fontsize=6.5, loc=loc)
        if not len(data) or legend.get_window_extent(renderer).count_contains(data) == 0:
            return True
    legend.remove()
    return False


def drawn_points(ax, spacing=1.5):
    """The axes' data as display points: lines, patch outlines and collections' paths (error
    bars, bands) every `spacing` pixels along each segment between two vertices, and lone
    markers and scattered points where they are drawn."""
    paths = [line.get_transform().transform(line.get_xydata()) for line in ax.lines
             if len(line.get_xydata()) >= 2]
    paths += [p.get_transform().transform(p.get_path().vertices) for p in ax.patches]
    points = [np.empty((0, 2))]
    points += [line.get_transform().transform(line.get_xydata()) for line in ax.lines
               if len(line.get_xydata()) == 1 and line.get_marker() not in (None, "", "None")]
    for c in ax.collections:
        if isinstance(c, matplotlib.collections.PathCollection):  # scatter: markers at offsets
            points.append(c.get_offset_transform().transform(c.get_offsets()))
        else:  # error bars (LineCollection), bands (fill_between's PolyCollection)
            paths += [c.get_transform().transform(p.vertices) for p in c.get_paths()]
    for xy in paths:
        xy = xy[np.all(np.isfinite(xy), axis=1)]
        step = np.diff(xy, axis=0)  # each segment sampled at n points, t = k / n, k < n
        n = np.minimum(np.hypot(step[:, 0], step[:, 1]) / spacing, 4000).astype(int) + 1
        segment = np.repeat(np.arange(len(step)), n)
        t = (np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)) / np.repeat(n, n)
        points.append(xy[segment] + step[segment] * t[:, None])
    return np.concatenate(points)


def save(figures, out):
    """Each figure as out/NAME.png and out/NAME.pdf, as it is (draw_figures finished it), its
    caption (figures_results.note) in their metadata (PNG Description, PDF Subject) and, with
    the others' and the reasons of those Skipped, in out/captions.md; closes them; returns the
    PNG paths."""
    os.makedirs(out, exist_ok=True)
    written, captions = [], []
    for name, fig in figures.items():
        if isinstance(fig, Skipped):
            captions.append(f"## {name}.png: not drawn\n\n{fig}\n")
            continue
        caption = getattr(fig, "sbpack_caption", "")
        fig.savefig(os.path.join(out, f"{name}.png"), dpi=130,
                    metadata={"Description": caption} if caption else None)
        fig.savefig(os.path.join(out, f"{name}.pdf"), metadata={"Subject": caption})
        if caption:
            captions.append(f"## {name}.png\n\n{caption}\n")
        written.append(os.path.join(out, f"{name}.png"))
        plt.close(fig)
    if captions:
        with open(os.path.join(out, "captions.md"), "w") as f:
            f.write("# Figure captions (python3 -m sbpack.plot)\n\n" + "\n".join(captions))
    return written


def main(argv=None):
    """python3 -m sbpack.plot: make_figures() on the arguments, then save()."""
    parser = argparse.ArgumentParser(prog="python3 -m sbpack.plot",
                                     description="The paper's figures from sbanalyze results "
                                                 "files, as PNG and PDF (docs/python.md).")
    parser.add_argument("results", nargs="+", metavar="RESULTS.h5")
    parser.add_argument("--out", default=".", metavar="DIR", help="output folder (default .)")
    parser.add_argument("--packing", metavar="FILE.h5",
                        help="packing of the slice figure (default: the first input of each p "
                             "that exists)")
    parser.add_argument("--slice-voxels", type=int, default=None, metavar="M",
                        help="the slice's grid (default: the input's pore grid in the results; "
                             "0: no slice)")
    parser.add_argument("--form-factor-voxels", type=int, default=256, metavar="M",
                        help="the form factors' grid, one superball in a box of 8 A (default "
                             "256; 0: no form factors)")
    parser.add_argument("--threads", type=int, default=None, metavar="T",
                        help="threads of the slice and the form factors (default: every core)")
    args = parser.parse_args(argv)
    try:
        figures = draw_figures(args.results, args.packing, args.slice_voxels,
                               args.form_factor_voxels, args.threads)
    except (OSError, ValueError) as e:
        parser.exit(1, f"sbpack.plot: error: {e}\n")
    for name, reason in figures.items():
        if isinstance(reason, Skipped):
            print(f"sbpack.plot: {name} not drawn: {reason}", file=sys.stderr)
    for path in save(figures, args.out):
        print(path)


if __name__ == "__main__":
    main()
