"""sbpack.plot's figure of where the contacts sit on the particles (sbanalyze --compute contacts,
group `contacts`; docs/contact-types.md): the density of theta, the angle between a contact
end's body-frame normal and the nearest body axis, beside that of normals uniform on the sphere
(what spheres give), and the fractions of the six pair types beside those of two independent
uniform ends, split as the paper splits its curves (p <= 1 | p >= 1), one series per (p, N).

Every value drawn is the results' (an ensemble's pointwise mean +- std of the density, its mean
+- std of the fractions) or sbanalyze's own constants (the uniform regions' solid angles,
_sbpack.uniform_region_fractions); the independent ends' pair fractions are their products."""
import numpy as np

from . import _sbpack
from .figures_results import bands, draw_steps, new_figure, note, side_rows, with_group
from .figures_series import curve, group_label, line_style, scalar

REGIONS = ["axis", "edge", "diagonal"]
PAIRS = [(a, b) for i, a in enumerate(REGIONS) for b in REGIONS[i:]]  # the schema's order
UNIFORM = _sbpack.uniform_region_fractions  # solid angles over 4 pi (Eq. 2.4)
THETA_MAX = float(np.degrees(np.arccos(1.0 / np.sqrt(3.0))))
# theta of the symmetry directions, marked on the top axis, and what they are on each side
DIRECTIONS = [(0.0, "⟨100⟩"), (45.0, "⟨110⟩"), (THETA_MAX, "⟨111⟩")]
NAMES = {"low": ["vertex", "edge", "face"], "high": ["face", "edge", "vertex"],
         "both": ["axis", "edge", "diagonal"]}  # octahedron-like, cube-like, spheres
REFERENCE_COLOUR = "tab:red"
HEADROOM = 1.12  # the density axis's top over its highest step (the mean markers above them)


def with_types(series):
    """The series whose contacts group has the contact types (older results have none) and
    defines them (NaN where the contacts are unresolved or no two non-rattlers touch)."""
    return [s for s in with_group(series, "contacts")
            if "axis_angle_density" in s.first("contacts")
            and np.isfinite(scalar(s, "contacts", "axis_angle_mean")[0])]


def independent_pairs():
    """Fractions of the six pair types for two independent ends uniform on the sphere: f_a f_b,
    twice that for a != b."""
    return [UNIFORM[a] * UNIFORM[b] * (1 if a == b else 2) for a, b in PAIRS]


def series_text(s):
    """The series' legend entry: its label, Z and the mean theta, and the fractions of its ends'
    regions (ensembles: mean +- std)."""
    def value(name, digits=3):
        v = scalar(s, "contacts", name)
        return f"{v[0]:.{digits}f}" + (fr" $\pm$ {v[1]:.{digits}f}" if s.averaged else "")

    regions = ", ".join(f"{r} {value(r + '_fraction')}" for r in REGIONS)
    return (f"{group_label(s, 'contacts')}\nZ = {value('z_mean', 2)}, "
            fr"$\langle\theta\rangle$ = {value('axis_angle_mean', 2)}°" f"\nends: {regions}")


def draw_theta(ax, s):
    """The series' density of theta as steps, an ensemble's +- std as a band between steps, its
    mean theta marked at the top of the axes."""
    edges, density, std = curve(s, "contacts", "axis_angle_edges", "axis_angle_density")
    draw_steps(ax, s, edges, density, std)
    style = line_style(s)
    mean = scalar(s, "contacts", "axis_angle_mean")[0]
    ax.plot([mean], [0.97], style["marker"], color=style["color"], ms=6,
            transform=ax.get_xaxis_transform(), clip_on=False)


def side_names(part):
    """What the symmetry directions are on the particles of `part`: the octahedron's (p <= 1),
    the cube's (p >= 1), or the neutral names (spheres only)."""
    if all(s.p <= 1.0 for s in part) and any(s.p < 1.0 for s in part):
        return NAMES["low"]
    if all(s.p >= 1.0 for s in part) and any(s.p > 1.0 for s in part):
        return NAMES["high"]
    return NAMES["both"]


def theta_axes(ax, part, side):
    """The uniform normals' density (dashed), the symmetry directions on a top axis, named as
    on the side's particles."""
    first = part[0].first("contacts")
    edges, uniform = first["axis_angle_edges"], first["axis_angle_uniform"]
    ax.stairs(uniform, edges, color=REFERENCE_COLOUR, ls="--", lw=1.3)
    top = ax.secondary_xaxis("top")
    top.set_xticks([t for t, _ in DIRECTIONS],
                   [f"{d}\n{name}" for (_, d), name in zip(DIRECTIONS, side_names(part))],
                   fontsize=7)
    highest = max(float(np.max(curve(s, "contacts", "axis_angle_edges", "axis_angle_density")[1]))
                  for s in part)
    ax.set(xlim=(0.0, THETA_MAX), ylim=(0.0, HEADROOM * max(highest, float(np.max(uniform)))),
           xlabel=r"$\theta$ (degrees)", ylabel="probability density (1/degree)",
           title=fr"Angle $\theta$ to the nearest body axis, {side}")


def draw_pairs(ax, part, side):
    """Bars of the six pair-type fractions per series (ensembles: their std as error bars), the
    independent uniform ends' fractions as a tick across each group; the legend of the row."""
    x, width = np.arange(len(PAIRS)), 0.8 / len(part)
    ax.plot([], [], color=REFERENCE_COLOUR, ls="--",
            label="normals uniform on the sphere (spheres):\ndensity of θ (Eqs. 2.1-2.2)")
    ax.hlines(independent_pairs(), x - 0.45, x + 0.45, color=REFERENCE_COLOUR, lw=1.8,
              label="two independent ends uniform on the\nsphere (spheres, random orientations)")
    ax.plot([], [], ls="none", marker="o", color="0.4", ms=5,
            label="marker above the densities: the mean θ")
    for k, s in enumerate(part):
        values = [scalar(s, "contacts", f"{a}_{b}_fraction") for a, b in PAIRS]
        ax.bar(x - 0.4 + (k + 0.5) * width, [v[0] for v in values], width,
               yerr=[v[1] for v in values] if s.averaged else None, color=s.style["color"],
               gid=s.label, error_kw=dict(lw=0.8, capsize=1.5), label=series_text(s))
    ax.set_xticks(x, [f"{a}–{b}" for a, b in PAIRS], fontsize=7, rotation=30, ha="right",
                  rotation_mode="anchor")
    ax.set(ylim=(0.0, None), ylabel="fraction of the contacts",
           title=f"Pair types of the contacts' ends, {side}")


def contact_types(series):
    """The density of theta beside the uniform normals', and the pair-type fractions beside two
    independent uniform ends'; p <= 1 | p >= 1."""
    series = with_types(series)
    if not series:
        return None
    fig, rows = side_rows(series, 2, width=4.8, height=3.8)
    for side, part, (theta_ax, pairs_ax) in rows:
        for s in part:
            draw_theta(theta_ax, s)
        theta_axes(theta_ax, part, side)
        draw_pairs(pairs_ax, part, side)
    note(fig, contact_types_note(series))
    return fig


def contact_types_note(series):
    """What the figure draws; for spheres, why their pair types are like pairs only."""
    text = ("Where the contacts sit on the particles (sbanalyze --compute contacts; "
            "docs/contact-types.md). Each end of a contact between non-rattlers is classified by "
            "its outward normal n in the particle's body frame: θ = arccos max |n_k| is its angle "
            "to the nearest body axis, and its region the nearest symmetry direction: ⟨100⟩ axis "
            "(θ = 0: the cube's face for p > 1, the octahedron's vertex for p < 1), ⟨110⟩ edge "
            "(θ = 45°), ⟨111⟩ diagonal (θ = 54.7°: the cube's vertex, the octahedron's face). "
            f"Left: density of θ in {len(series[0].first('contacts')['axis_angle_density'])} "
            "bins, the marker at the top its mean"
            + bands(series, "ensembles: mean ± std over the packings")
            + "; dashed: normals uniform on the sphere (spheres lie on it). Right: "
              "fractions of the contacts by the regions of their two ends; red ticks: two "
              "independent uniform ends")
    if any(s.p == 1.0 for s in series):
        text += (". Spheres (p = 1): the orientations carry no physics; where all are equal "
                 "(the packings in data/), a contact's two ends are n and -n in one frame and "
                 "share a region, so only like pairs occur")
    return text + "."


REGION_MARKERS = {"axis": "s", "edge": "D", "diagonal": "^"}
REGION_COLOURS = ["tab:blue", "tab:green", "tab:orange"]
REGION_NAMES = {"axis": "⟨100⟩ axis: face (p > 1), vertex (p < 1)", "edge": "⟨110⟩ edge",
                "diagonal": "⟨111⟩ diagonal: vertex (p > 1), face (p < 1)"}
PAIR_COLOURS = dict(zip(PAIRS, ["tab:blue", "tab:cyan", "tab:purple", "tab:green", "tab:olive",
                                "tab:orange"]))


def by_n(series):
    """N -> the series of that N sorted by p."""
    out = {}
    for s in series:
        out.setdefault(s.n, []).append(s)
    return {n: sorted(part, key=lambda s: s.p) for n, part in sorted(out.items())}


def draw_against_p(ax, part, name, style, label):
    """One quantity of the contacts group against p (ensembles: +- std), the points of each
    side of p = 1 joined (the cusp at p = 1 not bridged)."""
    ps = np.array([s.p for s in part])
    values = np.array([scalar(s, "contacts", name) for s in part])
    for side in (ps <= 1, ps >= 1):
        if side.sum() >= 2:
            ax.plot(ps[side], values[side, 0], lw=0.9, **style)
    ax.errorbar(ps, values[:, 0], yerr=values[:, 1] if part[0].averaged else None, ls="none",
                capsize=2, ms=5, label=label, **style)


def contact_types_versus_p(series):
    """With two or more p: the regions of the contacts' ends, the pair types and the mean theta
    against p, the uniform normals' values (the sphere limit) as dashed lines."""
    series = with_types(series)
    if len({s.p for s in series}) < 2:
        return None
    fig, axes = new_figure(3, width=4.2, height=3.6)
    ends_ax, pairs_ax, theta_ax = axes[0]
    marker_of_n = {n: m for n, m in zip(by_n(series), ["o", "s", "D", "^", "v"])}
    for n, part in by_n(series).items():
        suffix = f", N = {n}" if len(marker_of_n) > 1 else ""
        for region, colour in zip(REGIONS, REGION_COLOURS):
            draw_against_p(ends_ax, part, f"{region}_fraction",
                           dict(color=colour, marker=REGION_MARKERS[region]),
                           REGION_NAMES[region] + suffix)
        superballs = [s for s in part if s.p != 1.0]  # spheres' pairs: their orientations'
        for (a, b), colour in PAIR_COLOURS.items():
            if superballs:
                draw_against_p(pairs_ax, superballs, f"{a}_{b}_fraction",
                               dict(color=colour, marker=marker_of_n[n]), f"{a}–{b}{suffix}")
        draw_against_p(theta_ax, part, "axis_angle_mean",
                       dict(color="0.2", marker=marker_of_n[n]), f"N = {n}")
    for region, colour in zip(REGIONS, REGION_COLOURS):
        ends_ax.axhline(UNIFORM[region], color=colour, ls="--", lw=0.9)
    ends_ax.plot([], [], color="0.4", ls="--", lw=0.9, label="normals uniform on the sphere")
    theta_ax.axhline(uniform_mean_theta(series), color=REFERENCE_COLOUR, ls="--", lw=1.0,
                     label="normals uniform on the sphere")
    ends_ax.set(ylabel="fraction of the contacts' ends", title="Regions of the ends")
    pairs_ax.set(ylabel="fraction of the contacts", title="Pair types (superballs)")
    theta_ax.set(ylabel=r"$\langle\theta\rangle$ (degrees)", title="Mean angle to the nearest axis")
    for ax in axes[0]:
        ax.axvline(1.0, color="0.8", lw=0.8, zorder=0)
        ax.set(xlabel=r"$p$")
    note(fig, "Where the contacts sit on the particles against p (sbanalyze --compute contacts; "
              "docs/contact-types.md): the regions of the contacts' ends by their body-frame "
              "normals (⟨100⟩ axis: the cube's face for p > 1, the octahedron's vertex for "
              "p < 1; ⟨110⟩ edge; ⟨111⟩ diagonal: the cube's vertex, the octahedron's face), the "
              "fractions of the six pair types, and the mean angle θ to the nearest body axis; "
              "dashed: normals uniform on the sphere (Eq. 2.4 there), what spheres give"
              + bands(series, "error bars: std over the ensemble's packings")
              + ". Spheres' pair types are not drawn: their orientations carry no physics (equal "
                "ones make like pairs only). Not in the paper, which asks for it (its closing "
                "section).")
    return fig


def uniform_mean_theta(series):
    """<theta> of normals uniform on the sphere, from the results' uniform density (its bins
    exact, Eqs. 2.1-2.3; the centres' midpoint rule adds an error of order the bin width
    squared)."""
    first = series[0].first("contacts")
    edges, density = first["axis_angle_edges"], first["axis_angle_uniform"]
    centres, widths = 0.5 * (edges[1:] + edges[:-1]), np.diff(edges)
    return float(np.sum(centres * density * widths) / np.sum(density * widths))
