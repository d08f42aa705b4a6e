"""sbpack.plot's figure of the order metrics (sbanalyze --compute order, group `order`;
docs/order-metrics.md): the pair correlation g2(r) of the centroids against r / w, with the
ideal-gas error of each bin and the neighbour cutoff, and the density of the per-particle local
q6 beside fcc's value, the verdict's threshold and the MRJ range, split as the paper splits its
curves (p <= 1 | p >= 1), one series per (p, N) in the style of every other figure.

Every value drawn is the results'; the histogram of q6 is taken here from the per-particle values
(`q6_local`), pooled over an ensemble's members. The results keep no ensemble g2, and no mean of
g2 is taken here: an ensemble's members are drawn each, thin."""
import numpy as np

from . import _sbpack
from .figures_results import bands, note, side_rows, with_group
from .figures_series import group_label, line_style, scalar

FCC_Q6 = 0.575  # 13 / sqrt(512) = 0.57452: fcc's first shell (docs/order-metrics.md, section 2)
# the verdict's thresholds, sbanalyze's own (order/order_metrics.hpp): ordered at a mean local q6,
# T (over all 12 shells) or P4 at or above them (docs/order-metrics.md section 5)
Q6_ORDERED = _sbpack.order_thresholds["q6_local_mean"]
T_ORDERED = _sbpack.order_thresholds["T"]
P4_ORDERED = _sbpack.order_thresholds["P4"]
SOLID_ORDERED = _sbpack.order_thresholds["solid_like_fraction"]
CLUSTER_ORDERED = _sbpack.order_thresholds["crystal_cluster_fraction"]
MRJ_Q6 = _sbpack.mrj_local_q6  # the mean local q6 of the MRJ packings measured (section 5)
Q6_BIN = 0.01  # the histogram's bins of q6
G2_TOP = 5.0  # g2 axis: at least this high; main peaks above it are clipped, their height named
HEADROOM = 1.25  # axes' top over the highest value they show unclipped
MEAN_STRIP = 0.86  # the q6 axes' top strip, from this fraction up: the mean local q6, not a density


def order_values(s):
    """The series' members' `order` groups."""
    return [f["order"] for f in s.members("order")]


def q6_values(s):
    """The finite local q6 of every particle of the series' members (pooled; NaN: no bond)."""
    values = [np.asarray(o["q6_local"], dtype=float) for o in order_values(s) if "q6_local" in o]
    if not values:
        return None
    values = np.concatenate(values)
    return values[np.isfinite(values)]


def value_text(s, name, symbol, digits=3):
    """'symbol = 0.406' (one input) or 'symbol = 0.406 +- 0.012' (an ensemble); '' if absent."""
    v = scalar(s, "order", name)
    if v is None or not np.isfinite(v[0]):
        return ""
    spread = fr" \pm {v[1]:.{digits}f}" if s.averaged else ""
    return fr"${symbol} = {v[0]:.{digits}f}{spread}$"


def verdict_text(s):
    """'ORDERED' (every member), 'ORDERED: 1 of 3', or '' (none ordered)."""
    ordered = sum(int(o.get("ordered", 0)) for o in order_values(s))
    members = len(order_values(s))
    if not ordered:
        return ""
    return "ORDERED" if ordered == members else f"ORDERED: {ordered} of {members}"


def is_ordered(s):
    """True where a member of the series is called ordered (sbanalyze's verdict)."""
    return any(int(o.get("ordered", 0)) for o in order_values(s))


def series_text(s):
    """The series' legend entry: its label, the verdict, and its cutoff, mean local q6, T, P4,
    solid-like fraction and largest crystal (ensembles: mean +- std)."""
    verdict = verdict_text(s)
    head = group_label(s, "order") + (f": {verdict}" if verdict else "")
    shells = sorted({int(o["T_shells"]) for o in order_values(s) if "T_shells" in o})
    t = value_text(s, "T", "T")
    t += f" ({'/'.join(map(str, shells))} shells)" if t and shells else ""
    values = [value_text(s, "cutoff_w", r"r_c/\bar w", 2),
              value_text(s, "q6_local_mean", r"\langle q_6\rangle"), t,
              value_text(s, "P4", "P_4")]
    crystal = [value_text(s, "solid_like_fraction", r"f_\mathrm{solid}"),
               value_text(s, "crystal_cluster_fraction", r"n_\mathrm{crystal}/N")]
    lines = [", ".join(v for v in values if v), ", ".join(v for v in crystal if v)]
    return head + "".join("\n" + line for line in lines if line)


def g2_top(part):
    """The g2 axis's top: G2_TOP, or higher where the structure beyond a cutoff (the second
    shell and on) reaches it; the main peaks above it are clipped."""
    top = G2_TOP
    for s in part:
        for o in order_values(s):
            beyond = np.asarray(o["r_w"]) > o.get("cutoff_w", np.inf)
            if beyond.any():
                top = max(top, HEADROOM * float(np.max(np.asarray(o["g2"])[beyond])))
    return top


def draw_g2(ax, s, top):
    """The series' g2 (each member's, thin, for an ensemble), its ideal-gas band 1 +- sigma (the
    first member's: sigma depends on N and the density only; drawn where sigma <= 1, at small r
    it spans every value and would only veil the axes) and its cutoff (dotted; an ensemble's
    mean); (r / w, g2) of its highest point."""
    members = order_values(s)
    first = members[0]
    error = np.asarray(first["g2_ideal_gas_error"])
    ax.fill_between(first["r_w"], 1.0 - error, 1.0 + error, where=error <= 1.0,
                    color=s.style["color"], alpha=0.1, lw=0)
    for i, o in enumerate(members):
        style = line_style(s, len(o["r_w"]))
        if s.averaged:
            style.update(lw=0.6, alpha=0.6, marker=style["marker"] if i == 0 else "None")
        ax.plot(o["r_w"], o["g2"], gid=s.label if i == 0 else None, label="_nolegend_",
                **style)
    cutoff = scalar(s, "order", "cutoff_w")
    if cutoff is not None and np.isfinite(cutoff[0]):
        ax.axvline(cutoff[0], color=s.style["color"], ls=":", lw=1.1)
    highest = max(members, key=lambda o: float(np.max(o["g2"])))
    i = int(np.argmax(highest["g2"]))
    return (float(highest["r_w"][i]), float(highest["g2"][i]))


def q6_top(part):
    """The top of the q6 densities (the strip of the means above it): HEADROOM over the highest
    density of the series that no member calls ordered (an ordered box's narrow spike would
    flatten them), or over every series' where all are ordered."""
    def peak(s):
        return np.max(np.histogram(q6_values(s), bins=q6_bins(), density=True)[0])
    drawn = [s for s in part if (v := q6_values(s)) is not None and len(v)]
    peaks = [peak(s) for s in drawn if not is_ordered(s)] or [peak(s) for s in drawn] or [1.0]
    return HEADROOM * max(peaks)


def q6_bins():
    """The edges of the q6 histogram's bins, 0 .. 1 by Q6_BIN."""
    return np.linspace(0.0, 1.0, int(round(1.0 / Q6_BIN)) + 1)


def draw_q6(ax, s, top):
    """The density of the series' local q6 (pooled over an ensemble's members) as steps, cut at
    `top` (the strip of the means starts there), its mean local q6 marked in the strip of the
    means (MEAN_STRIP); (q6, density) of its highest bin, or None."""
    values = q6_values(s)
    if values is None or not len(values):
        return None
    density, edges = np.histogram(values, bins=q6_bins(), density=True)
    i = int(np.argmax(density))
    highest = (0.5 * (edges[i] + edges[i + 1]), float(density[i]))
    density = np.minimum(density, top)
    ax.stairs(density, edges, color=s.style["color"], ls=s.style["ls"], lw=1.3,
              fill=False, gid=s.label)
    if is_ordered(s):  # the verdict, visible without the legend
        ax.stairs(density, edges, color=s.style["color"], alpha=0.25, fill=True, lw=0)
    mean = scalar(s, "order", "q6_local_mean")
    if mean is not None and np.isfinite(mean[0]):
        ax.plot([mean[0]], [(1.0 + MEAN_STRIP) / 2], s.style["marker"], color=s.style["color"],
                ms=6, transform=ax.get_xaxis_transform(), clip_on=False)
    return highest


def q6_references(ax):
    """fcc's q6 (a particle's: over the whole axes), and in the strip of the means above the
    densities (MEAN_STRIP) the MRJ range of the mean local q6 and the verdict's threshold on it:
    a range of means drawn over a distribution would read as a range of the distribution."""
    ax.axhline(ax.get_ylim()[1] * MEAN_STRIP, color="0.3", lw=0.6)
    ax.text(0.01, (1.0 + MEAN_STRIP) / 2, "mean", transform=ax.transAxes, fontsize=7,
            va="center", ha="left", color="0.3")
    ax.axvspan(*MRJ_Q6, ymin=MEAN_STRIP, color="0.5", alpha=0.3, lw=0,
               label=fr"MRJ ($N \geq 200$): mean local $q_6$ {MRJ_Q6[0]}-{MRJ_Q6[1]}")
    ax.axvline(Q6_ORDERED, ymin=MEAN_STRIP, color="tab:red", ls="-", lw=1.6,
               label=fr"ordered: mean local $q_6 \geq {Q6_ORDERED}$")
    ax.axvline(FCC_Q6, color="k", ls="--", lw=1.1, label=fr"fcc: $q_6 = {FCC_Q6}$")


def q6_range(part):
    """The q6 axis: the series' values and fcc's, a margin around them, within [0, 1]."""
    values = [v for s in part if (v := q6_values(s)) is not None and len(v)]
    low = min([float(np.min(v)) for v in values] + [MRJ_Q6[0]])
    high = max([float(np.max(v)) for v in values] + [FCC_Q6])
    return max(0.0, low - 0.05), min(1.0, high + 0.05)


def order(series):
    """g2(r) against r / w with the ideal-gas band and the cutoff, and the density of the local
    q6 with fcc, below a strip of the means with the verdict's threshold and the MRJ range;
    p <= 1 | p >= 1. A peak beyond an axes' top is clipped and its height named at it."""
    series = with_group(series, "order")
    if not series:
        return None
    with_q6 = any(q6_values(s) is not None for s in series)
    fig, rows = side_rows(series, 2 if with_q6 else 1, width=4.8, height=3.6)
    for side, part, row in rows:
        g2_ax, top = row[0], g2_top(part)
        g2_ax.axhline(1.0, color="0.3", ls="--", lw=0.8, label=r"$g_2 = 1$ (ideal gas)")
        g2_ax.fill_between([], [], [], color="0.5", alpha=0.15, lw=0,
                           label=r"$1 \pm$ ideal-gas error per bin")
        g2_ax.plot([], [], ":", color="0.3", lw=1.1, label=r"cutoff $r_c$: first minimum")
        peaks = [(s, draw_g2(g2_ax, s, top)) for s in part]
        name_peaks(g2_ax, [(s, *h) for s, h in peaks if h[1] > top], 0.98)
        g2_ax.set(xlim=(0.0, None), ylim=(0.0, top), xlabel=r"$r/\bar w$",
                  ylabel=r"$g_2(r)$", title=f"Pair correlation, {side}")
        if with_q6:
            q6_part(row[1], part, side)
        for s in part:  # the series' entries, in its style, on the row's last axes
            row[-1].plot([], [], **line_style(s, 1), label=series_text(s))
    note(fig, order_note(series, with_q6))
    return fig


def name_peaks(ax, clipped, y):
    """Names each peak clipped at the axes' top where it is: (series, x, height) its height, in
    the series' colour, at abscissa x, the names stacked down from axes height y (issue 66 item
    5: the height in the panel that clips it, not in another's legend)."""
    for k, (s, x, height) in enumerate(clipped):
        ax.annotate(f"{height:.3g}", xy=(x, y - 0.07 * k), xycoords=ax.get_xaxis_transform(),
                    xytext=(3, 0), textcoords="offset points", ha="left", va="top", fontsize=7,
                    color=s.style["color"], clip_on=True)


def q6_part(ax, part, side):
    """The side's q6 densities below the strip of the means (MEAN_STRIP of the axes' height)."""
    top = q6_top(part)
    highest = [(s, draw_q6(ax, s, top)) for s in part]
    ax.set(xlim=q6_range(part), ylim=(0.0, top / MEAN_STRIP), xlabel=r"local $q_6$",
           ylabel="probability density", title=f"Local $q_6$, {side}")
    name_peaks(ax, [(s, *h) for s, h in highest if h is not None and h[1] > top],
               MEAN_STRIP - 0.02)
    q6_references(ax)


def order_note(series, with_q6):
    """What the order figure draws, and what it takes here."""
    text = ("Order metrics (sbanalyze --compute order; docs/order-metrics.md), lengths over the "
            "mean width. Left: pair correlation of the centroids (bins of 0.02 w̄); the faint "
            "band 1 ± the ideal-gas error per bin at the same N and density (Eq. 1.2; where it "
            "stays above 0); dotted the neighbour cutoff r_c, the first minimum of g₂"
            + bands(series, "ensembles: each member's g₂ thin (the results keep no ensemble "
                            "g₂), the band the first member's, r_c their mean"))
    if with_q6:
        text += (". Right: density of the local q₆ of each particle with bonds shorter than r_c "
                 f"(bins of {Q6_BIN:g}"
                 + bands(series, "ensembles: every member's particles pooled")
                 + f"); dashed fcc's q₆ = {FCC_Q6}; an ordered series (ordered: mean "
                 f"local q₆ ≥ {Q6_ORDERED}, T ≥ {T_ORDERED} over 12 shells, P4 ≥ {P4_ORDERED}, "
                 f"solid-like fraction f_solid ≥ {SOLID_ORDERED} or largest crystal "
                 f"≥ {CLUSTER_ORDERED} N (ten Wolde-Frenkel, SANN neighbours); "
                 "drawn filled). The strip above the densities is of means, not densities: each "
                 "series' mean local q₆ (its marker), the MRJ range of the mean local q₆ (grey) "
                 f"and the verdict's threshold on it, {Q6_ORDERED} (red)")
    return text + ". A peak beyond the axes is clipped; its height is written beside it."
