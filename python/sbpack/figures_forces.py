"""sbpack.plot's figures of a packing's mechanics (docs/jamming.md): the contact forces that
sbgen stores with a packing (group `contacts`, fields force_*, §8), the density P(x) of
x = f / <f>, one series per (p, N), on a logarithmic axis beside the exponential e^-x, with <x^2>
in the legend (<x> = 1 by construction); and the collective jamming test's unjamming motion on a
section of its packing (group `jamming_collective`, --compute jamming, §7).

Every value drawn is the results' (an ensemble's pointwise mean +- std of the density, its mean
+- std of <x^2>); packings without stored forces (from elsewhere, or from sbgen before it stored
them) have no force fields and no series here."""
import os

import numpy as np

from .figures_results import draw_steps, new_figure, note, with_group
from .figures_series import Skipped, curve, group_label, scalar
from .figures_shape import missing_packings

FLOOR = 1e-4  # the density axis's bottom


def with_forces(series):
    """The series whose contacts group has the stored forces' distribution."""
    return [s for s in with_group(series, "contacts")
            if any("force_density" in f["contacts"] for f in s.members("contacts"))]


def series_text(s):
    """The series' legend entry: its label (saying how many members store forces where not all
    do) and <x^2> (ensembles: mean +- std)."""
    mean, std = scalar(s, "contacts", "force_second_moment")
    moment = f"{mean:.3f}" + (fr" $\pm$ {std:.3f}" if s.averaged else "")
    members = s.members("contacts")
    stored = sum("force_density" in f["contacts"] for f in members)
    label = group_label(s, "contacts")
    if stored < len(members):
        label += f"; forces stored by {stored} of {len(members)}"
    return f"{label}\n" + fr"$\langle x^2 \rangle$ = {moment}"


def contact_forces(series):
    """P(f / <f>) of every series with stored forces; None where no series has them."""
    series = with_forces(series)
    if not series:
        return None
    fig, axes = new_figure(1, width=6.0, height=4.2)
    ax = axes[0][0]
    for s in series:
        edges, density, std = curve(s, "contacts", "force_edges", "force_density")
        draw_steps(ax, s, edges, density, std, label=series_text(s), log_y=True)
    x = np.linspace(0.0, float(edges[-1]), 200)
    ax.plot(x, np.exp(-x), "k--", lw=1.0, label=r"$e^{-x}$")
    ax.set_yscale("log")
    ax.set_ylim(FLOOR, None)
    ax.set_xlim(0.0, float(edges[-1]))
    ax.set_xlabel(r"$x = f / \langle f \rangle$")
    ax.set_ylabel(r"$P(x)$")
    ax.set_title("Contact forces stored by sbgen")
    return fig


MOTIONS = [("opening_displacement", "an opening"), ("flex_displacement", "a flex")]
COLUMNS = 3  # panels per row of the motion figure


def motion_of(f):
    """(dataset, what) of the input's collective motion (the opening first), or None."""
    group = f.get("jamming_collective", {})
    return next(((name, what) for name, what in MOTIONS if name in group), None)


def motion_inputs(series):
    """[(packing file, results input, dataset, what)] for the inputs whose collective jamming test
    found a motion (the first such input per p, whose packing file exists): the opening where
    there is one, else the flex."""
    found = {}
    for s in series:
        for f in s.files:
            motion = motion_of(f)
            if motion and s.p not in found and os.path.isfile(str(f["input"])):
                found[s.p] = (str(f["input"]), f, *motion)
    return [found[p] for p in sorted(found)]


def unjamming_motion(series, voxels=200, threads=1):
    """The collective test's motion on a section x ~ L/2 of its packing: the solid in grey
    (_sbpack.voxel_slice) and, for each particle whose centre lies within D/2 of the plane, its
    displacement's (z, y) components as an arrow, the largest drawn a diameter long; None where
    no input has a motion, Skipped where none of their packing files is found."""
    from . import _sbpack
    inputs = motion_inputs(series)
    if voxels == 0 or not any(motion_of(f) for s in series for f in s.files):
        return None
    if not inputs:
        return Skipped(missing_packings(series))
    columns = min(COLUMNS, len(inputs))
    rows = -(-len(inputs) // columns)
    fig, axes = new_figure(columns, rows, width=3.6, height=3.6)
    for ax in axes.flat[len(inputs):]:
        ax.remove()
    for ax, (path, f, name, what) in zip(axes.flat, inputs):
        packing = _sbpack.Packing.read(path)
        plane = section_plane(packing, voxels)
        solid, _ = _sbpack.voxel_slice(packing, voxels, plane, threads)
        L, D = packing.box_length, 2.0 * packing.semi_axis
        ax.imshow(solid != 0, origin="lower", extent=(0, L / D, 0, L / D), cmap="Greys",
                  vmin=0, vmax=1.6, interpolation="nearest")
        x = (plane + 0.5) * L / voxels
        r, u = slab_arrows(packing, np.asarray(f["jamming_collective"][name]), x)
        ax.quiver(r[:, 2] / D, r[:, 1] / D, u[:, 2], u[:, 1], angles="xy", scale_units="xy",
                  scale=1.0, color="tab:red", width=0.006, gid=f"{packing.p:g}")
        ax.set(xlim=(0, L / D), ylim=(0, L / D), xlabel="$z/D$", ylabel="$y/D$")
        ax.set_title(f"p = {packing.p:g}, N = {len(packing)}: {what}", fontsize=9)
    note(fig, "The collective jamming test's unjamming motion (sbanalyze --compute jamming, "
              "docs/jamming.md §7) on a section x = L/2 of each packing: each particle's (z, y) "
              "displacement as an arrow, the largest one D long; an opening opens contacts, a "
              "flex keeps every one.")
    return fig


def section_plane(packing, voxels):
    """The voxel plane through the centre of the particle nearest x = L/2: the section cuts a
    layer of particles through their middles (a lattice's layers, not the gaps between them)."""
    L = packing.box_length
    x = np.asarray(packing.positions)[:, 0]
    centre = x[np.argmin(np.abs(x - L / 2))]
    return min(int(centre / L * voxels), voxels - 1)


def slab_arrows(packing, displacement, x):
    """(centres, arrows) of the particles whose centre lies within D/2 of the plane at `x`, the
    arrows scaled so that the largest displacement of the packing is one D long."""
    L, D = packing.box_length, 2.0 * packing.semi_axis
    r = np.asarray(packing.positions)
    near = np.abs((r[:, 0] - x + L / 2) % L - L / 2) < D / 2
    largest = float(np.max(np.linalg.norm(displacement, axis=1)))
    return r[near], displacement[near] * (D / largest if largest > 0 else 0.0)
