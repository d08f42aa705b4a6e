"""The series of sbpack.plot's figures: one per (p, N) ensemble of each results file, its style
(colour keyed to p, marker to N, line style to the results file) and its curves (the ensemble's
mean +- std, or its one input's own curve).

Every number is the results file's (sbanalyze's). One exception, named where it is drawn: the
pore-size curves F(delta) and P(delta) have no ensemble statistics in the results
(docs/results-schema.md, "Ensembles"), so their mean and sample std over the members are taken
here, on a common delta / w grid (``members_mean``).
"""
import os
from dataclasses import dataclass, field

import matplotlib.pyplot as plt
import numpy as np

MARKERS = ["o", "^", "v", "D", "P", "X", "<", ">"]  # keyed to N ('s' is the paper's)
LINESTYLES = ["-", "--", "-.", ":"]  # keyed to the results file, when several are drawn


class Skipped(str):
    """Why a figure the results call for is not drawn: what a figure function returns instead
    of an empty or misleading figure, and what ``python3 -m sbpack.plot`` prints (issue 66
    item 5: panels skipped with a message, not left empty or dropped silently)."""


@dataclass
class Series:
    """The inputs of one (p, N) in one results file: `files` (dicts), `ensemble` (dict or None)
    and the style every figure draws them in."""
    p: float
    n: int
    run: int
    run_name: str
    files: list
    ensemble: dict = None
    style: dict = field(default_factory=dict)
    label: str = ""

    @property
    def averaged(self):
        """True when the series is drawn as a mean +- std (two inputs or more)."""
        return len(self.files) >= 2

    def first(self, group):
        """The first member's `group` (None if no member has it)."""
        return next((f[group] for f in self.files if group in f), None)

    def members(self, group):
        """The members that have `group`."""
        return [f for f in self.files if group in f]

    def major_axis_over_width(self):
        """A / w = 2 R / w: a shape ratio, the same for every member (their own R and w)."""
        f = self.files[0]
        return 2.0 * f["semi_axis"] / f["mean_width"]


def _grouped(run):
    """(p, N, files, ensemble) of a results file: its ensembles, or (results without them)
    its inputs grouped by (p, N)."""
    files = run["files"]
    if run.get("ensembles"):
        return [(e["p"], e["n_particles"], [files[int(m)] for m in e["members"]], e)
                for e in run["ensembles"]]
    keys = sorted({(f["p"], f["n_particles"]) for f in files})
    return [(p, n, [f for f in files if (f["p"], f["n_particles"]) == (p, n)], None)
            for p, n in keys]


def series_of(runs, names=None):
    """Every (p, N) series of `runs` (read_results dicts; `names` their file names), sorted by
    p, N and results file, each styled: a colour per p (``colour_of_p``), a marker per N, a
    line style per results file."""
    names = names or [f"results {i + 1}" for i in range(len(runs))]
    out = [Series(p, n, i, os.path.basename(str(names[i])), members, e)
           for i, run in enumerate(runs) for p, n, members, e in _grouped(run) if members]
    out.sort(key=lambda s: (s.p, s.n, s.run))
    ps, ns = sorted({s.p for s in out}), sorted({s.n for s in out})
    for s in out:
        s.style = {"color": colour_of_p(s.p, ps), "marker": MARKERS[ns.index(s.n) % len(MARKERS)],
                   "ls": LINESTYLES[s.run % len(LINESTYLES)]}
        s.label = series_label(s, several_runs=len(runs) > 1)
    return out


def colour_of_p(p, ps):
    """The colour of p among the distinct `ps`: black for spheres (p = 1), viridis from purple
    (the least p) to green for p < 1, plasma from purple-red (nearest 1) to orange for p > 1:
    the two sides of the paper's split stay apart, and each side's p stay distinguishable."""
    if p == 1.0:
        return (0.0, 0.0, 0.0, 1.0)
    side = sorted(q for q in ps if (q < 1.0) == (p < 1.0) and q != 1.0)
    t = side.index(p) / (len(side) - 1) if len(side) > 1 else 0.5
    return plt.cm.viridis(0.7 * t) if p < 1.0 else plt.cm.plasma(0.3 + 0.55 * t)


def series_label(s, several_runs=False):
    """'p = 1.5, N = 250 (mean +- std of 3)' or '... (one input: name.h5)'."""
    what = (fr"mean $\pm$ std of {len(s.files)}" if s.averaged
            else f"one input: {os.path.basename(str(s.files[0]['input']))}")
    run = f" [{s.run_name}]" if several_runs else ""
    return f"p = {s.p:g}, N = {s.n} ({what}){run}"


def line_style(s, points=0):
    """matplotlib keywords of the series' line: its colour, line style and marker (every
    ~12th of `points` points, so markers stay legible on long curves)."""
    return {"color": s.style["color"], "ls": s.style["ls"], "marker": s.style["marker"],
            "ms": 3.5, "markevery": max(1, points // 12), "lw": 1.2}


def curve(s, group, x, y):
    """(x, y, std) of the series' `group`: the ensemble's mean and std (std None for one input,
    whose own curve is drawn); None if no member has the group."""
    if not s.members(group):
        return None
    if not s.averaged:
        g = s.first(group)
        return np.asarray(g[x]), np.asarray(g[y]), None
    g = (s.ensemble or {}).get(group)
    if g is not None and y + "_std" in g:
        return np.asarray(g[x]), np.asarray(g[y]), np.asarray(g[y + "_std"])
    return members_mean(s.members(group), group, x, y)


def members_mean(files, group, x, y, points=400):
    """Mean and sample std over `files` of the curve group/y against group/x, each member read
    at the same x (a step function, right-continuous, where y is F; else linear between its
    points; 0 beyond its last point): for the curves the results keep no ensemble of (P, and F
    in results of format_version 2)."""
    grid = np.linspace(0.0, max(float(np.max(f[group][x])) for f in files), points)
    step = y == "F"
    rows = [_at(np.asarray(f[group][x]), np.asarray(f[group][y]), grid, step) for f in files]
    rows = np.array(rows)
    return grid, rows.mean(axis=0), rows.std(axis=0, ddof=1)


def _at(xs, ys, grid, step):
    """ys(xs) read at `grid`: a right-continuous step, or linear (0 past the last point)."""
    if step:
        i = np.searchsorted(xs, grid, side="right") - 1
        return np.where(i >= 0, ys[np.clip(i, 0, None)], ys[0])
    return np.interp(grid, xs, ys, left=ys[0], right=0.0)


def _ensemble_group(s, group):
    """The series' ensemble record (group None) or its `group`; None where absent."""
    return s.ensemble if group is None else (s.ensemble or {}).get(group)


def pooled(s, group, name):
    """True where the series' ensemble has NAME_pooled and NAME_pooled_stderr in `group` (e.g.
    H: its one fit through every input's data, docs/hyperuniformity.md "Ensembles")."""
    g = _ensemble_group(s, group)
    return s.averaged and g is not None and name + "_pooled_stderr" in g


def scalar(s, group, name):
    """(mean, std) of the series' group/name: its ensemble's (two inputs or more; where it is
    `pooled`, that one fit's value and error instead), or its one input's (std 0); None where
    absent."""
    if s.averaged:
        g = _ensemble_group(s, group)
        if pooled(s, group, name):
            return g[name + "_pooled"], g[name + "_pooled_stderr"]
        return (g[name], g.get(name + "_std", 0.0)) if g is not None and name in g else None
    f = s.files[0] if group is None else s.first(group)
    return (f[name], 0.0) if f is not None and name in f else None


def group_label(s, group):
    """The series' label, saying how many members have `group` where not all do (an analysis
    skipped on some inputs)."""
    k = len(s.members(group))
    if not s.averaged or k == len(s.files):
        return s.label
    return s.label.replace(f"std of {len(s.files)}", f"std of the {k} of {len(s.files)} with "
                                                      f"{group.replace('_', ' ')}")


def sides(series):
    """The paper's split of the curves: [(title, series)] for p <= 1 and p >= 1 (p = 1 in both),
    the sides that have a p != 1; one panel 'p = 1' for spheres only."""
    low = [s for s in series if s.p <= 1.0]
    high = [s for s in series if s.p >= 1.0]
    out = []
    if any(s.p < 1.0 for s in series):
        out.append((r"$p \leq 1$", low))
    if any(s.p > 1.0 for s in series):
        out.append((r"$p \geq 1$", high))
    return out or [(r"$p = 1$", series)]


def grid_of(f, group):
    """The grid of one input's `group`: '300^3 voxels', the pores' method on it ('voxels on
    500^3', 'refined on 500^3') or 'exact' (no grid)."""
    g = f[group]
    m = int(g.get("voxels", 0))
    if group != "pore_size":
        return f"{m}³ voxels"
    method = str(g.get("method", "voxels"))
    return method if m == 0 else f"{method} on {m}³"


def series_grid(s, group):
    """The grids of the series' members, joined: '500³ voxels', or '300³ voxels /
    500³ voxels' where members differ."""
    return " / ".join(sorted({grid_of(f, group) for f in s.members(group)}))


def grids_title(series, group):
    """The grid(s) of `group` over `series` for a title: the one grid, or 'grids differ: see
    legend' (the legend then names each series' grid, ``label_with_grid``)."""
    names = {grid_of(f, group) for s in series for f in s.members(group)}
    return names.pop() if len(names) == 1 else "grids differ: see legend"


def label_with_grid(s, series, group):
    """The series' label, with its grid where the grids of `series` differ."""
    names = {grid_of(f, group) for t in series for f in t.members(group)}
    return group_label(s, group) + (f"; {series_grid(s, group)}" if len(names) > 1 else "")
