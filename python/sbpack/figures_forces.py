"""sbpack.plot's figure of the contact forces that sbgen stores with a packing (group `contacts`,
fields force_*; docs/jamming.md §8): the density P(x) of x = f / <f>, one series per (p, N), on a
logarithmic axis beside the exponential e^-x, with <x^2> in the legend (<x> = 1 by construction).

Every value drawn is the results' (an ensemble's pointwise mean +- std of the density, its mean
+- std of <x^2>); packings without stored forces (from elsewhere, or from sbgen before it stored
them) have no force fields and no series here."""
import numpy as np

from .figures_results import new_figure, with_group
from .figures_series import curve, group_label, line_style, scalar

FLOOR = 1e-4  # the density axis's bottom: a band's lower edge is clipped to it


def with_forces(series):
    """The series whose contacts group has the stored forces' distribution."""
    return [s for s in with_group(series, "contacts")
            if any("force_density" in f["contacts"] for f in s.members("contacts"))]


def series_text(s):
    """The series' legend entry: its label and <x^2> (ensembles: mean +- std)."""
    mean, std = scalar(s, "contacts", "force_second_moment")
    moment = f"{mean:.3f}" + (fr" $\pm$ {std:.3f}" if s.averaged else "")
    return f"{group_label(s, 'contacts')}\n" + fr"$\langle x^2 \rangle$ = {moment}"


def contact_forces(series):
    """P(f / <f>) of every series with stored forces; None where no series has them."""
    series = with_forces(series)
    if not series:
        return None
    fig, axes = new_figure(1, width=6.0, height=4.2)
    ax = axes[0][0]
    for s in series:
        edges, density, std = curve(s, "contacts", "force_edges", "force_density")
        style = line_style(s)
        ax.stairs(np.maximum(density, FLOOR), edges, color=style["color"], ls=style["ls"],
                  lw=1.4, label=series_text(s), gid=s.label)
        if std is not None:
            ax.stairs(np.maximum(density + std, FLOOR), edges,
                      baseline=np.maximum(density - std, FLOOR), fill=True,
                      color=style["color"], alpha=0.2, lw=0)
    x = np.linspace(0.0, float(edges[-1]), 200)
    ax.plot(x, np.exp(-x), "k--", lw=1.0, label=r"$e^{-x}$")
    ax.set_yscale("log")
    ax.set_ylim(FLOOR, None)
    ax.set_xlim(0.0, float(edges[-1]))
    ax.set_xlabel(r"$x = f / \langle f \rangle$")
    ax.set_ylabel(r"$P(x)$")
    ax.set_title("Contact forces stored by sbgen")
    return fig
