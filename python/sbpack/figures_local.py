"""sbpack.plot's figures of local structure (docs/local-structure.md): the density of the local
packing fractions phi_i of the set-Voronoi cells (group `voronoi`), one series per (p, N) with
an ensemble's pointwise mean +- std; and the local volume-fraction variance sigma_V^2(R) (group
`variance`) as sigma_V^2 (R / w)^3 against R / w, the spectral route as a line and the sampled
route as points with their error bars, which a Poisson-like medium holds flat at large R and a
hyperuniform one bends down. Every value drawn is the results'; an ensemble's variance curves are
averaged here over the radii its members share."""
import matplotlib.ticker as ticker
import numpy as np

from .figures_results import draw_steps, new_figure, with_group
from .figures_series import curve, group_label, line_style


def local_phi(series):
    """The density of phi_i per series; None where no series has set-Voronoi cells."""
    series = with_group(series, "voronoi")
    if not series:
        return None
    fig, axes = new_figure(1, width=6.0, height=4.2)
    ax = axes[0][0]
    low, high = 1.0, 0.0
    for s in series:
        centres, density, std = curve(s, "voronoi", "phi_bins", "phi_density")
        width = centres[1] - centres[0]
        edges = np.append(centres - width / 2, centres[-1] + width / 2)
        draw_steps(ax, s, edges, density, std, label=group_label(s, "voronoi"))
        filled = np.nonzero(density > 0)[0]
        low, high = min(low, edges[filled[0]]), max(high, edges[filled[-1] + 1])
    ax.set_xlim(low - 0.01, high + 0.01)
    ax.set_xlabel(r"local packing fraction $\phi_i = v_1 / v_{cell}$")
    ax.set_ylabel(r"density of $\phi_i$")
    ax.set_title("Set-Voronoi cells")
    return fig


def variance_curves(s):
    """(R / w, spectral, sampled, sampled error) over the radii every member of the series has,
    averaged over its members (sampled None where a member has no sampled route)."""
    members = [f["variance"] for f in s.members("variance")]
    n = min(len(g["radius_w"]) for g in members)
    radius = np.asarray(members[0]["radius_w"][:n])
    spectral = np.mean([np.asarray(g["sigma2_spectral"][:n]) for g in members], axis=0)
    if not all("sigma2_sampled" in g for g in members):
        return radius, spectral, None, None
    sampled = np.mean([np.asarray(g["sigma2_sampled"][:n]) for g in members], axis=0)
    error = np.sqrt(np.sum([np.asarray(g["sigma2_sampled_error"][:n]) ** 2 for g in members],
                           axis=0)) / len(members)
    return radius, spectral, sampled, error


def volume_fraction_variance(series):
    """sigma_V^2 (R / w)^3 against R / w per series, the tail fit's window shaded and the two
    pure tails as guides (flat: R^-3, a Poisson-like volume term; slope -1: R^-4, the windows'
    surface term); None where no series has the variance."""
    series = with_group(series, "variance")
    if not series:
        return None
    fig, axes = new_figure(1, width=6.0, height=4.2)
    ax = axes[0][0]
    windows = []
    for k, s in enumerate(series):
        radius, spectral, sampled, error = variance_curves(s)
        style = line_style(s)
        ax.plot(radius, spectral * radius**3, color=style["color"], ls=style["ls"], lw=1.3,
                label=group_label(s, "variance"))
        if sampled is not None:
            ax.errorbar(radius, sampled * radius**3, yerr=error * radius**3, fmt="o", ms=2.5,
                        color=style["color"], elinewidth=0.8,
                        label="sampled windows (points)" if k == 0 else None)
        windows += [(g["fit_min_w"], g["fit_max_w"]) for g in
                    (f["variance"] for f in s.members("variance")) if "fit_min_w" in g]
    if windows:
        ax.axvspan(min(w[0] for w in windows), max(w[1] for w in windows), color="0.9",
                   zorder=0, label="tail fit's radii")
    r0, y0 = radius[-1], spectral[-1] * radius[-1] ** 3
    guide = np.array([r0 / 4.0, r0])
    ax.plot(guide, np.full(2, y0), "k:", lw=0.9, label=r"$\propto R^{-3}$")
    ax.plot(guide, y0 * r0 / guide, "k--", lw=0.9, label=r"$\propto R^{-4}$")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.xaxis.set_major_formatter(ticker.FormatStrFormatter("%g"))
    ax.xaxis.set_minor_formatter(ticker.FormatStrFormatter("%g"))
    ax.set_xlabel(r"window radius $R / w$")
    ax.set_ylabel(r"$\sigma_V^2(R)\,(R / w)^3$")
    ax.set_title("Local volume-fraction variance: spectral route (lines), sampled (points)",
                 fontsize=9)
    return fig
