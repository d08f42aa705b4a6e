"""sbpack.plot's figures against p: phi, Z, phi_R, alpha, H, k, tau, T1 (paper Figs. 4, 5, 7, 13,
15, 17), with order results Q6, the mean local q6, T and P4 (docs/order-metrics.md; not in the
paper), and phi against the mean width over the major axis (paper Fig. 6), each series' mean +-
std (or its one input's value) coloured by p, marked by N, beside the paper's values
(data/mst-reference-values.csv) where it tabulates them, and the values that Jiao, Stillinger &
Torquato 2010 state in their text (data/jst2010-reference-values.csv: Z's plateau, P4's range)
over the p they state them for."""
import csv
import os

import matplotlib.ticker as ticker
import numpy as np

from . import _sbpack
from .figures_results import new_figure, note
from .figures_series import pooled, scalar

REFERENCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "mst-reference-values.csv")
PAPER = "paper (Maher et al.)"
SECOND_REFERENCE = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "jst2010-reference-values.csv")
SECOND = "Jiao et al. 2010 (text)"
SECOND_QUANTITY = {"z_mean": "Z", "P4": "P4"}  # a results value -> its row in SECOND_REFERENCE

# (results group, value, axis label, the paper's column (None: not tabulated, NO_TABLE says
# why), its scale to the value's units)
PANELS = [
    (None, "phi", r"$\phi$", "phi", 1.0),
    ("contacts", "z_mean", r"$Z$ (over non-rattlers)", "Z", 1.0),
    ("contacts", "rattler_fraction", r"$\phi_R$ (rattler fraction)", "phi_R_percent", 0.01),
    ("spreadability", "alpha", r"$\alpha$ (from $E(t)$)", "alpha", 1.0),
    ("hyperuniformity", "H", r"$H$ (one $\tilde\chi_V$ fit of all inputs $\pm$ its error)",
     "H_e-3", 1e-3),
    ("transport", "permeability_w2", r"$k/\bar w^2$", None, 1.0),
    ("transport", "mean_survival_time_w2", r"$\tau\mathcal{D}/\bar w^2$ (bound)", None, 1.0),
    ("transport", "principal_relaxation_time_w2", r"$T_1\mathcal{D}/\bar w^2$ (bound)", None,
     1.0),
    ("order", "Q6", r"$Q_6$ (global, bonds $< r_c$)", None, 1.0),
    ("order", "q6_local_mean", r"mean local $q_6$ (bonds $< r_c$)", None, 1.0),
    ("order", "T", r"$T$ (translational order)", None, 1.0),
    ("order", "P4", r"$P_4$ (cubatic order of the axes)", None, 1.0),
]

# The title of a panel without the paper's values: by its value, else by its results group (the
# order metrics' references, fcc's values and the verdict's thresholds: docs/order-metrics.md).
NO_TABLE = {
    "transport": "paper: a figure only, no table",
    "order": "not in the paper",
}
_ORDERED = _sbpack.order_thresholds  # the verdict's thresholds, sbanalyze's own
NO_TABLE_VALUE = {
    "Q6": "not in the paper; fcc 0.575; disordered: shrinks with N",
    "q6_local_mean": fr"not in the paper; fcc 0.575, ordered $\geq {_ORDERED['q6_local_mean']:g}$",
    "T": fr"not in the paper; fcc 1, ordered $\geq {_ORDERED['T']:g}$ over its 12 shells",
    "P4": fr"not in the paper; aligned 1, random 0, ordered $\geq {_ORDERED['P4']:g}$",
}


def paper_values(path=REFERENCE):
    """The paper's table (data/mst-reference-values.csv): column -> (p, value) arrays."""
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    table = {}
    for column in rows[0]:
        pairs = [(float(r["p"]), float(r[column])) for r in rows if r[column]]
        table[column] = tuple(np.array(v) for v in zip(*pairs))
    return table


def second_values(path=SECOND_REFERENCE):
    """Jiao et al. 2010's stated values: quantity -> (p_min, p_max, low, high)."""
    with open(path) as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        return {r["quantity"]: tuple(float(r[k]) for k in ("p_min", "p_max", "low", "high"))
                for r in rows}


def second_markers(ax, second, name, ps):
    """Jiao et al. 2010's value of results value name over its p range clipped to the results'
    ps: a dashed line (one value) or a hatched band (a range); nothing where they do not meet."""
    if SECOND_QUANTITY.get(name) not in second:
        return
    p_min, p_max, low, high = second[SECOND_QUANTITY[name]]
    p_min, p_max = max(p_min, min(ps)), min(p_max, max(ps))
    if p_min >= p_max:
        return
    if low == high:
        ax.plot([p_min, p_max], [low, low], "--", color="k", lw=1.2, label=SECOND, zorder=1.4)
    else:
        ax.fill_between([p_min, p_max], low, high, facecolor="none", edgecolor="0.5",
                        hatch="///", lw=0.0, label=SECOND, zorder=0.5)


def points(series, group, name):
    """N -> [(p, mean, std, series)] sorted by p, over the series that have group/name; an
    ensemble of which one member alone has the group (an analysis skipped on the others) is no
    mean and std, and is left out."""
    out = {}
    for s in series:
        if s.averaged and group is not None and len(s.members(group)) < 2:
            continue
        value = scalar(s, group, name)
        if value is not None:
            out.setdefault(s.n, []).append((s.p, value[0], value[1], s))
    return {n: sorted(rows, key=lambda r: r[0]) for n, rows in sorted(out.items())}


def paper_markers(ax, paper, column, scale, x=None):
    """The paper's values (black open squares, with its sd where it gives one); at x (e.g.
    w / A) instead of p where given."""
    p, v = paper[column]
    sd_column = (column[: -len("_percent")] + "_sd_percent" if column.endswith("_percent")
                 else column + "_sd")
    sd = paper.get(sd_column)
    yerr = sd[1] * scale if sd is not None and len(sd[1]) == len(v) else None
    ax.errorbar(p if x is None else x(p), v * scale, yerr=yerr, fmt="s", mfc="none", color="k",
                ms=6, capsize=2, label=PAPER, zorder=1.5)  # behind the results' points


def draw_points(ax, rows, x_of=lambda s: s.p, label=""):
    """One (p, N) series per point: coloured by p, marked by N, error bar its std; a grey line
    joins the points of one N on each side of the sphere (p <= 1, p >= 1: the cusp at p = 1 is
    not bridged) where a side has three points or more."""
    rows = [r for r in rows if np.isfinite(r[1])]  # e.g. Z where contacts are not resolved
    if not rows:
        return
    xs = np.array([x_of(r[3]) for r in rows])
    ys = np.array([r[1] for r in rows])
    ps = np.array([r[0] for r in rows])
    for side in (ps <= 1, ps >= 1):
        if side.sum() >= 3:
            ax.plot(xs[side], ys[side], "-", color="0.6", lw=0.8, zorder=1)
    for x, (p, mean, std, s) in zip(xs, rows):
        ax.errorbar([x], [mean], yerr=[std] if np.isfinite(std) else None,
                    fmt=s.style["marker"], color=s.style["color"],
                    ms=5, capsize=3, zorder=3)
    ax.plot([], [], rows[0][3].style["marker"], ls="none", color="0.4", label=label)


def several_p(series):
    """True with two values of p or more (the figures against p need them)."""
    return len({s.p for s in series}) >= 2


def panels_with_data(series):
    """The PANELS the series have values for."""
    return [panel for panel in PANELS if points(series, panel[0], panel[1])]


def n_label(rows, group, name):
    """'N = 250 (mean +- std of 3 inputs)', '... (one fit of 3 inputs +- its error)' where
    group/name is `pooled`, or '... (one input per p)'."""
    counts = sorted({len(r[3].files) for r in rows})
    if counts == [1]:
        return f"N = {rows[0][3].n} (one input per p)"
    inputs = "/".join(map(str, counts))
    if all(pooled(r[3], group, name) for r in rows):
        return f"N = {rows[0][3].n} (one fit of {inputs} inputs $\\pm$ its error)"
    return f"N = {rows[0][3].n} (mean $\\pm$ std of {inputs} inputs)"


def versus_p(series):
    """Every PANELS quantity the results have against p, with two or more p."""
    panels = panels_with_data(series) if several_p(series) else []
    if not panels:
        return None
    paper, second = paper_values(), second_values()
    rows, columns = (len(panels) + 3) // 4, min(4, len(panels))
    fig, axes = new_figure(columns, rows, width=3.9, height=3.3)
    for ax, (group, name, ylabel, column, scale) in zip(axes.ravel(), panels):
        for n, rows_n in points(series, group, name).items():
            draw_points(ax, rows_n, label=n_label(rows_n, group, name))
            if group == "order":
                mark_ordered(ax, rows_n)
        if column is not None:
            paper_markers(ax, paper, column, scale)
        else:
            ax.set_title(NO_TABLE_VALUE.get(name, NO_TABLE.get(group, "")), fontsize=8)
        second_markers(ax, second, name, [s.p for s in series])
        ax.set(xlabel=r"$p$", ylabel=ylabel)
    ps = [s.p for s in series] + [p for panel in panels if panel[3] is not None
                                  for p in paper[panel[3]][0]]
    for ax in axes.ravel()[:len(panels)]:
        p_axis(ax, ps)
    for ax in axes.ravel()[len(panels):]:
        ax.set_axis_off()
    note(fig, "Against the superball exponent p (every quantity dimensionless): points coloured "
              "by p as in the other figures, marked by N, error bars the ensemble's std (H: the "
              "standard error of its one fit through every input), grey lines joining three "
              "points or more on one side of p = 1; squares: the paper (Maher et al.); dashed line "
              "and hatched band: the Z plateau and the P4 range Jiao, Stillinger & Torquato 2010 "
              "state in their text for the p they span"
              + ("; the order metrics (cutoff bonds: shorter than the first minimum of g₂) are "
                 "not in the paper, and Q₆ and T depend on N (compare one N)"
                 if any(p[0] == "order" for p in panels) else ""))
    return fig


def mark_ordered(ax, rows):
    """'ordered' beside the points of the series whose members sbanalyze calls ordered (all,
    or 'k of n')."""
    from .figures_order import verdict_text
    for p, mean, _, s in rows:
        verdict = verdict_text(s)
        if verdict:
            ax.annotate(verdict.lower(), (p, mean), xytext=(6, -3), textcoords="offset points",
                        fontsize=7, color=s.style["color"])


P_TICKS = (0.5, 0.6, 0.7, 0.8, 0.9, 1, 1.5, 2, 3, 5, 10, 20, 50, 100, 200, 500, 1000)


def spaced_ticks(low, high, ratio=1.2):
    """P_TICKS within [low, high], 1 first, then outwards, each kept only at a factor `ratio`
    or more from those kept (labels that do not run into each other on a log axis)."""
    kept = [1.0] if low <= 1.0 <= high else []
    for t in sorted((t for t in P_TICKS if low <= t <= high), key=lambda t: abs(np.log(t))):
        if all(max(t, k) / min(t, k) >= ratio for k in kept):
            kept.append(t)
    return sorted(kept) or [low, high]


def p_axis(ax, ps):
    """One p axis for every panel of a figure: over all of ps (the results' p and the references'
    drawn), log where p spans more than a factor 3, labelled in plain numbers at P_TICKS."""
    low, high = min(ps), max(ps)
    if high / low > 3.0:
        ax.set_xscale("log")
        ax.set_xlim(low / 1.08, high * 1.08)
        ax.xaxis.set_major_locator(ticker.FixedLocator(spaced_ticks(low, high)))
        ax.xaxis.set_major_formatter(ticker.FormatStrFormatter("%g"))
        ax.xaxis.set_minor_formatter(ticker.NullFormatter())
    else:
        margin = 0.05 * (high - low) or 0.05 * high
        ax.set_xlim(low - margin, high + margin)


def phi_vs_width(series):
    """phi against w / A, the mean width over the major axis A = 2R (paper Fig. 6, superballs;
    the paper's spheroids are Donev et al.'s data, not in this project)."""
    from .figures_shape import width_over_major_axis
    rows = points(series, None, "phi")
    if not several_p(series) or not rows:
        return None
    fig, axes = new_figure(1, width=6.0, height=4.2)
    ax = axes[0, 0]
    for n, rows_n in rows.items():
        draw_points(ax, rows_n, x_of=lambda s: 1.0 / s.major_axis_over_width(),
                    label=n_label(rows_n, None, "phi"))
    paper_markers(ax, paper_values(), "phi", 1.0,
                  x=lambda p: np.array([width_over_major_axis(q) for q in p]))
    ax.set(xlabel=r"$\bar w/A$ ($A = 2R$)", ylabel=r"$\phi$")
    note(fig, "Packing fraction against the mean width over A = 2R (the paper's major axis), "
              "lines joining p ≤ 1 and p ≥ 1 separately (three points or more); the "
              "paper's points at the w/A of their p (sbpack's mean width). The paper's oblate "
              "and prolate spheroids are not drawn (their data, Donev et al., are not in this "
              "project)")
    return fig
