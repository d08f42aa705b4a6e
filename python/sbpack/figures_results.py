"""sbpack.plot's figures of curves from results files: S(Q), chi_V(Q) (by the mean width and by
the major axis), the small-Q fit, the excess spreadability and the pore sizes, each split as the
paper splits them (p <= 1 | p >= 1), one series per (p, N): the ensemble's mean +- std (band)
or its one input's own curve (figures_series)."""
import textwrap

import matplotlib.pyplot as plt
import matplotlib.ticker as ticker
import numpy as np

from .figures_series import (Skipped, curve, grids_title, group_label, label_with_grid,
                             line_style, pooled, scalar, sides)

QW = r"$Q\bar w$"
SMALL_Q_SHELLS = 5  # a small-Q panel without a fit needs this many shells to show a trend
PACKING_TIME = r"$t\mathcal{D}/\bar w^2$"
AXIS_NOTE = "A = 2R, the extent along a body axis (tip to tip for p < 1, face to face for p > 1)"


def new_figure(columns, rows=1, width=5.0, height=3.8, **kwargs):
    """A figure of rows x columns axes (an array, squeezed never), constrained layout."""
    return plt.subplots(rows, columns, figsize=(width * columns, height * rows), squeeze=False,
                        layout="constrained", **kwargs)


def caption_title(text, longest=90):
    """The caption's first phrase, up to its first '(', ':', ';' or '. ': a title of one line."""
    cuts = [i for i in (text.find(mark) for mark in ("(", ":", ";", ". ")) if i > 0]
    title = text[:min(cuts, default=len(text))].strip().rstrip(",")
    return textwrap.shorten(title, longest, placeholder=" ...")


def note(fig, text):
    """The figure's caption: its first phrase as a one-line title above the panels, the whole
    text as fig.sbpack_caption, which plot.save() writes beside the figure (captions.md) and
    into the PNG's and PDF's metadata (issue 66 item 5: captions are text, not paragraphs drawn
    over the figure)."""
    fig.sbpack_caption = text
    fig.suptitle(caption_title(text), fontsize=10)


def draw(ax, s, xyz, label, x_scale=1.0, y_scale=1.0, step=False, log_y=False):
    """The series' curve (x, y, std) on `ax`, with its mean +- std band where std is given (on a
    log axis, `log_y`, only where mean - std > 0: below, the band has no lower edge to draw and
    would fall to the axis as a wall); the line's gid is the series' label (whether or not the
    legend shows it)."""
    x, y, std = xyz
    x, y = np.asarray(x) * x_scale, np.asarray(y) * y_scale
    ax.plot(x, y, label=label, drawstyle="steps-post" if step else "default", gid=s.label,
            **line_style(s, len(x)))
    if std is not None:
        low, high = y - std * y_scale, y + std * y_scale
        ax.fill_between(x, low, high, where=low > 0 if log_y else None, color=s.style["color"],
                        alpha=0.2, lw=0, step="post" if step else None)


def draw_steps(ax, s, edges, density, std, label=None, log_y=False):
    """A density per bin as steps in the series' style (gid: its label), an ensemble's +- std as
    a band between steps; on a log axis (`log_y`) an empty bin is a gap, not a drop to the
    axis, and the band is drawn where density - std > 0 only (as draw's)."""
    style = line_style(s)
    density = np.asarray(density, dtype=float)
    if log_y:
        density = np.where(density > 0, density, np.nan)
    ax.stairs(density, edges, color=style["color"], ls=style["ls"], lw=1.4, label=label,
              gid=s.label, baseline=None if log_y else 0)
    if std is not None:
        low, high = density - std, density + std
        if log_y:
            low, high = np.where(low > 0, low, np.nan), np.where(low > 0, high, np.nan)
        ax.stairs(high, edges, baseline=low, fill=True, color=style["color"], alpha=0.2, lw=0)


def bands(series, what="bands: ensemble mean ± std"):
    """`what` where a series is an ensemble mean (two inputs or more), else ''."""
    return f"; {what}" if any(s.averaged for s in series) else ""


def with_group(series, group):
    """The series with a member that has `group`."""
    return [s for s in series if s.members(group)]


def chi_scale(s, by_major_axis=False):
    """1 / w^3 (or 1 / A^3) of the series: the ensemble's mean w, or the input's own."""
    w = scalar(s, None, "mean_width")[0]
    length = w * (s.major_axis_over_width() if by_major_axis else 1.0)
    return 1.0 / length**3


def side_rows(series, columns=1, width=5.0, height=3.4):
    """A figure with a row per side of the paper's split (p <= 1, p >= 1) and `columns`
    quantities: (fig, [(side title, side series, row of axes)])."""
    parts = sides(series)
    fig, axes = new_figure(columns, len(parts), width=width, height=height)
    return fig, [(title, part, axes[i]) for i, (title, part) in enumerate(parts)]


def last(row, ax):
    """True for the row's last axes: the one that carries the legend (labels drawn once)."""
    return ax is row[-1]


def structure_factor(series):
    """S(Q) against Q w, p <= 1 | p >= 1 (paper Figs. 8, 9)."""
    series = with_group(series, "structure_factor")
    if not series:
        return None
    fig, rows = side_rows(series)
    for side, part, (ax,) in rows:
        for s in part:
            draw(ax, s, curve(s, "structure_factor", "Q_w", "S"),
                 group_label(s, "structure_factor"))
        ax.axhline(1.0, color="0.7", lw=0.8, ls=":")
        ax.set(xlabel=QW, ylabel=r"$S(Q)$", title=f"Structure factor, {side}")
    note(fig, "Structure factor of the centroids against Q times the mean width "
              f"(dimensionless){bands(series)}")
    return fig


def spectral_density(series):
    """chi_V(Q) / w^3 against Q w, p <= 1 | p >= 1 (paper Figs. 10, 11)."""
    series = with_group(series, "spectral_density")
    if not series:
        return None
    fig, rows = side_rows(series)
    for side, part, (ax,) in rows:
        for s in part:
            draw(ax, s, curve(s, "spectral_density", "Q_w", "chi"),
                 label_with_grid(s, series, "spectral_density"), y_scale=chi_scale(s))
        ax.set(xlabel=QW, ylabel=r"$\tilde\chi_V(Q)/\bar w^3$", title=f"Spectral density, {side}")
    note(fig, "Spectral density from the voxels (shell averages, "
              f"{grids_title(series, 'spectral_density')}), dimensionless"
              f"{bands(series, 'bands: ensemble mean ± std (χ_V / w³ with its mean w)')}")
    return fig


# major_axis's columns: (results group, y, its label, by A^3)
BY_MAJOR_AXIS = [("structure_factor", "S", r"$S(Q)$", False),
                 ("spectral_density", "chi", r"$\tilde\chi_V(Q)/A^3$", True)]


def major_axis(series):
    """S(Q) and chi_V(Q) / A^3 against Q A, A = 2R (paper Figs. S3-S6: the major-axis scaling
    the paper sets beside the mean width's)."""
    columns = [c for c in BY_MAJOR_AXIS if with_group(series, c[0])]
    series = [s for s in series if any(s.members(c[0]) for c in columns)]
    if not columns:
        return None
    fig, rows = side_rows(series, len(columns))
    for side, part, row in rows:
        for ax, (group, y, ylabel, cubed) in zip(row, columns):
            for s in with_group(part, group):
                label = group_label(s, group) if last(row, ax) else "_nolegend_"
                draw(ax, s, curve(s, group, "Q_w", y), label,
                     x_scale=s.major_axis_over_width(),
                     y_scale=chi_scale(s, by_major_axis=True) if cubed else 1.0)
            ax.set(xlabel=r"$QA$", ylabel=ylabel, title=f"By the major axis A, {side}")
    note(fig, f"Structure factor and spectral density against Q A. Against Q times {AXIS_NOTE}, "
              f"instead of the mean width; A/w from each "
              "input's own R and w")
    return fig


def fit_drawable(h):
    """True when the small-Q fit is determined: finite a0, a1, alpha, H and its error, two
    wave vectors at least. A degenerate fit (H = 0 +- inf) is not drawn."""
    values = [h.get(k, np.nan) for k in ("a0", "a1", "alpha", "H", "H_stderr")]
    return bool(np.all(np.isfinite(values))) and h.get("fit_points", 0) >= 2


def small_q_fit(ax, s, f):
    """The one input's fit a0 + a1 Q^alpha (in units of w) over its window only, and the wave
    vectors it fitted (fit_Q_w, fit_chi; results before them have only their count)."""
    h, qw = f["hyperuniformity"], f["spectral_density"]["Q_w"]
    if "fit_Q_w" in h:
        ax.plot(h["fit_Q_w"], h["fit_chi"], "x", ms=4, color=s.style["color"], alpha=0.6,
                label=f"the {len(h['fit_Q_w'])} wave vectors fitted (one of each ±Q)")
    x = np.geomspace(min(qw[0], h["q_fit_max_w"]) * 0.8, h["q_fit_max_w"], 100)
    ax.plot(x, h["a0"] + h["a1"] * x ** h["alpha"], "-", color=s.style["color"], lw=1.5,
            label=fr"fit: $\alpha = {h['alpha']:.2f}$, $H = {h['H']:.2g} \pm "
                  fr"{h['H_stderr']:.1g}$ ({h['fit_points']} wave vectors)")


def small_q_points(ax, s, series, qmax):
    """The series' chi_V / w^3 at Q w <= qmax: the input's shell averages (and the exact ones
    of spheres), or the ensemble's mean +- std; its fit where it has one and it is drawable."""
    x, y, std = curve(s, "spectral_density", "Q_w", "chi")
    keep, scale = x <= qmax, chi_scale(s)
    f = s.files[0]
    h = scalar(s, "hyperuniformity", "H")
    one_fit = pooled(s, "hyperuniformity", "H")
    fit_text = ("" if h is None or not s.averaged else
                fr"; $H = {h[0]:.2g} \pm {h[1]:.1g}$, "
                + (f"one fit of {len(s.members('hyperuniformity'))} inputs" if one_fit else
                   f"over {len(s.members('hyperuniformity'))} fits"))
    degenerate = (not s.averaged and "hyperuniformity" in f
                  and not fit_drawable(f["hyperuniformity"]))
    label = label_with_grid(s, series, "spectral_density") + fit_text + \
        ("; fit degenerate, not drawn" if degenerate else "")
    ax.errorbar(x[keep], y[keep] * scale, yerr=None if std is None else std[keep] * scale,
                fmt=s.style["marker"], ms=4, color=s.style["color"], capsize=2, label=label)
    if not s.averaged and "chi_exact" in f["spectral_density"]:
        ax.plot(x[keep], f["spectral_density"]["chi_exact"][keep] * scale, s.style["marker"],
                mfc="none", ms=7, color=s.style["color"], label="exact (spheres), same shells")
    if not s.averaged and "hyperuniformity" in f and not degenerate:
        small_q_fit(ax, s, f)
    if one_fit:
        pooled_fit(ax, s, x[keep][0])


def pooled_fit(ax, s, qw_min):
    """The ensemble's one fit a0 + a1 Q^alpha through every input's wave vectors, at its pooled
    alpha (docs/hyperuniformity.md, "Ensembles"), over the fit window."""
    h, alpha = s.ensemble["hyperuniformity"], s.ensemble["spreadability"]["alpha_pooled"]
    x = np.geomspace(qw_min * 0.8, s.first("hyperuniformity")["q_fit_max_w"], 100)
    ax.plot(x, h["a0_pooled"] + h["a1_pooled"] * x ** alpha, "-", color=s.style["color"], lw=1.5,
            label=fr"fit of all inputs: $\alpha = {alpha:.2f}$ (pooled)")


def small_q(series, qmax=4.0):
    """chi_V / w^3 at small Q on log axes with the fit a0 + a1 Q^alpha of `hyper` and its window
    (paper Eq. fit, Table fit), p <= 1 | p >= 1."""
    series = with_group(series, "spectral_density")
    if not series:
        return None
    shown = [s for s in series if small_q_shown(s, qmax)]
    if not shown:
        most = max(small_q_shells(s, qmax) for s in series)
        return Skipped(f"at Q w̄ ≤ {qmax:g} the inputs have at most {most} wave-vector shells and "
                       f"no fit (fewer than {SMALL_Q_SHELLS} shells, nothing to see: the box's "
                       "smallest Q is 2π/L; a larger N puts more shells below it)")
    series = shown
    windows = sorted({round(f["hyperuniformity"]["q_fit_max_w"], 3) for s in series
                      for f in s.members("hyperuniformity")})
    fig, rows = side_rows(series)
    for side, part, (ax,) in rows:
        for s in part:
            small_q_points(ax, s, series, qmax)
        for q in windows:
            ax.axvline(q, color="0.5", ls=":", lw=1)
        log_axes(ax)
        ax.set(xlabel=QW, ylabel=r"$\tilde\chi_V(Q)/\bar w^3$", title=f"Small $Q$, {side}")
    note(fig, small_q_note(series, windows))
    return fig


def small_q_shells(s, qmax):
    """The series' wave-vector shells at Q w <= qmax (its first member's)."""
    return int(np.count_nonzero(np.asarray(s.first("spectral_density")["Q_w"]) <= qmax))


def small_q_shown(s, qmax):
    """True where the series has something to show at small Q: a fit (one input's, drawable;
    an ensemble's pooled) or SMALL_Q_SHELLS shells at Q w <= qmax."""
    fitted = (pooled(s, "hyperuniformity", "H") if s.averaged else
              "hyperuniformity" in s.files[0] and fit_drawable(s.files[0]["hyperuniformity"]))
    return fitted or small_q_shells(s, qmax) >= SMALL_Q_SHELLS


def small_q_note(series, windows):
    """What the small-Q figure shows, and what the results do not hold."""
    text = (f"Spectral density at small Q. Points: voxel shell averages "
            f"({grids_title(series, 'spectral_density')}"
            f"{bands(series, 'ensembles: mean ± std')}). ")
    if not windows:
        return text + "No hyper results: no fit."
    return text + ("Fit χ_V = a₀ + a₁ Q^α (α from E(t)) over the "
                   f"wave vectors at Q w ≤ {', '.join(f'{q:g}' for q in windows)} (dotted): "
                   "crosses, the values fitted, exact χ_V where --chi-exact-qmax covers them."
                   + (" Ensembles: no fit line (a mean of fits is not a fit); their H against p "
                      "in versus_p." if any(s.averaged for s in series) else ""))


def log_axes(ax):
    """Log-log axes labelled at 1, 2, 3, ... in x and at every subdivision in y (chi at small Q
    often spans less than a decade, and then the axis would have no number)."""
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.xaxis.set_major_locator(ticker.FixedLocator([0.2, 0.3, 0.5, 1, 1.5, 2, 3, 4, 5, 10]))
    ax.xaxis.set_major_formatter(ticker.FormatStrFormatter("%g"))
    ax.xaxis.set_minor_formatter(ticker.NullFormatter())
    for formatter in (ax.yaxis.set_major_formatter, ax.yaxis.set_minor_formatter):
        formatter(ticker.LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(1.5, 0.5)))


def spreadability(series):
    """E(t) with each series' Debye medium (paper Fig. 16), and the local alpha with each
    series' line alpha + c / t over its window and its limit alpha (paper Fig. 17's alpha),
    p <= 1 | p >= 1. Each axis has one time scaling: the packings' t D_diff / w^2 below, the Debye
    media's t D_diff / a^2 on the top axis of E(t) (the same numbers, as in the paper's Fig. 16)."""
    series = with_group(series, "spreadability")
    if not series:
        return None
    fig, rows = side_rows(series, 2, width=4.6, height=3.4)
    for side, part, (left, right) in rows:
        for s in part:
            draw(left, s, curve(s, "spreadability", "t", "excess"), "_nolegend_", log_y=True)
            debye(left, s, first=s is part[0])
            local_alpha(right, s)
        cutoffs(part, (left, right))
        left.set(xscale="log", yscale="log", ylim=(1e-8, 2), xlabel=PACKING_TIME,
                 ylabel=r"$\mathcal{S}(\infty)-\mathcal{S}(t)$",
                 title=f"Excess spreadability, {side}")
        left.secondary_xaxis("top").set_xlabel(r"$t\mathcal{D}/\hat a^2$ (Debye media, dashed)")
        right.set(xscale="log", xlabel=PACKING_TIME, ylabel=r"local $\alpha$", ylim=(-1.5, 3),
                  xlim=(1e-2, 8 * max(cutoff_time(s) for s in part)),
                  title=f"Local exponent, {side}")
    note(fig, f"Excess spreadability{bands(series)}, and the Debye random medium at each "
              "series' φ (dashed, same colour, on the top axis's time t D/â²); right, the local "
              "α of each input (thin"
              + bands(series, "ensembles: the members' mean ± std, taken here") + "), the line "
              "α + c/t fitted to it over the window (thick) and its limit α past the window "
              "(dashed; band: the ensemble's std, or one input's bootstrap error)")
    return fig


def debye(ax, s, first):
    """The series' Debye medium (its own phi), dashed in its colour."""
    x = curve(s, "spreadability_debye", "t", "excess")
    if x is None:
        return
    ax.plot(x[0], x[1], ls="--", lw=0.9, color=s.style["color"],
            label=r"Debye media at each series' $\phi$" if first else "_nolegend_")


def local_alpha(ax, s):
    """The series' local alpha (one input's own, thin; an ensemble's mean +- std over its
    members, taken here: the results keep no ensemble local alpha), its line alpha + c / t
    through it over the window (thick) and its limit alpha from the window's end on (with its
    std over the ensemble, or the input's bootstrap stderr, as a band; docs/hyperuniformity.md,
    "alpha")."""
    t, mean, std = members_local_alpha(s.members("spreadability"))
    ax.plot(t, mean, lw=0.9, color=s.style["color"], ls=s.style["ls"])
    if std is not None:
        ax.fill_between(t, mean - std, mean + std, color=s.style["color"], alpha=0.15, lw=0)
    alpha = scalar(s, "spreadability", "alpha")
    slope = scalar(s, "spreadability", "alpha_slope")[0]
    t0, t1 = (scalar(s, "spreadability", k)[0] for k in ("t_fit_min", "t_fit_max"))
    spread = alpha[1] if s.averaged else s.first("spreadability")["alpha_stderr"]
    t = np.geomspace(t0, t1, 32)
    ax.plot(t, alpha[0] + slope / t, lw=3, color=s.style["color"], solid_capstyle="butt",
            label=fr"$\alpha = {alpha[0]:.2f} \pm {spread:.2f}$ (p = {s.p:g}, N = {s.n})")
    ax.plot([t1, 4 * t1], [alpha[0]] * 2, lw=1.5, ls="--", color=s.style["color"])
    ax.fill_between([t1, 4 * t1], alpha[0] - spread, alpha[0] + spread, color=s.style["color"],
                    alpha=0.25, lw=0)


def members_local_alpha(files):
    """(t, mean, std) of the members' local alpha read at the first member's times (log-linear
    between each member's own; std None for one member)."""
    t = np.asarray(files[0]["spreadability"]["t"])
    rows = np.array([np.interp(np.log(t), np.log(f["spreadability"]["t"]),
                               f["spreadability"]["local_alpha"]) for f in files])
    if len(files) == 1:
        return t, rows[0], None
    return t, rows.mean(axis=0), rows.std(axis=0, ddof=1)


def cutoff_time(s):
    """The series' box cutoff time t_c: its inputs' median (t_c scales with each box's L / w)."""
    return float(np.median([f["spreadability"]["t_cutoff"] for f in s.members("spreadability")]))


def cutoffs(series, axes):
    """Each series' box cutoff time t_c (cutoff_time), dotted in its colour."""
    for s in series:
        t = cutoff_time(s)
        for i, ax in enumerate(axes):
            first = i == 0 and s is series[0]
            ax.axvline(t, color=s.style["color"], ls=":", lw=1,
                       label="box cutoff $t_c$ (dotted)" if first else "_nolegend_")


def pore_size(series):
    """F(delta) on a log axis (the tail) and P(delta) against delta / w, p <= 1 | p >= 1
    (paper Figs. 12, 13 and the density of Eq. 13)."""
    series = with_group(series, "pore_size")
    if not series:
        return None
    fig, rows = side_rows(series, 2, width=4.6)
    least = 1.0
    for side, part, (left, right) in rows:
        for s in part:
            f = curve(s, "pore_size", "delta_w", "F")
            draw(left, s, f, "_nolegend_", step=not s.averaged, log_y=True)
            least = min(least, np.min(f[1][f[1] > 0], initial=1.0))
            draw(right, s, curve(s, "pore_size", "P_delta_w", "P_w"),
                 label_with_grid(s, series, "pore_size"))
        left.set(yscale="log", xlabel=r"$\delta/\bar w$", ylabel=r"$F(\delta)$",
                 title=f"Pore sizes, {side}")
        right.set(xlabel=r"$\delta/\bar w$", ylabel=r"$P(\delta)\,\bar w$", ylim=(0, None),
                  title=f"Their density, {side}")
    for _, _, (left, _) in rows:
        left.set_ylim(max(least / 2, 1e-7), 1.5)
    note(fig, f"Pore-size distribution ({grids_title(series, 'pore_size')}): F(δ), the void "
              "fraction with pore size > δ (log axis), and its density P" + bands(
                  series, "ensembles: mean ± std over the members, F the results' own on their "
                          "δ/w grid, P averaged here (the results keep no ensemble P); on the log axis "
                          "of F the band ends where mean − std reaches 0"))
    return fig
