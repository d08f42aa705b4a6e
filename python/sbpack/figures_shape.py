"""sbpack.plot's figures computed by sbpack's own engine, not read from results: the mean width
against p (paper Fig. 3: ``Packing.mean_width`` of one superball), the form factors (paper Figs.
S1, S2: ``SpectralDensity`` of one superball in a box, as the paper computed them) and a slice of
a packing (``_sbpack.voxel_slice``: the pores analysis's voxelization and distance transform).
Python computes none of these numbers itself."""
import os
from functools import lru_cache

import matplotlib.pyplot as plt
import matplotlib.ticker as ticker
import numpy as np

from .figures_results import new_figure, note
from .figures_series import Skipped, grid_of

BOX_OVER_AXIS = 8.0  # the form factors' box edge, in units of the major axis A = 2R


def one_superball(p, box=BOX_OVER_AXIS):
    """A packing of one superball of semi-axis 1/2 (A = 1) at the centre of a box of edge `box`."""
    from . import _sbpack
    return _sbpack.Packing(np.full((1, 3), box / 2.0), np.array([[1.0, 0.0, 0.0, 0.0]]), box,
                           p=p, semi_axis=0.5, source=f"one superball, p = {p:g}")


@lru_cache(maxsize=None)
def width_over_major_axis(p):
    """w / A of a superball at p: sbpack's mean width of one superball with A = 1."""
    return one_superball(float(p)).mean_width


def mean_width(series):
    """w / A against p over [0.5, 1000] on a log axis (paper Fig. 3), the octahedron (p = 1/2),
    the sphere and the cube's limit 3/2 marked, and each results series' own w / 2R."""
    fig, axes = new_figure(1, width=6.0, height=4.0)
    ax = axes[0, 0]
    ps = np.geomspace(0.5, 1000.0, 160)
    ax.plot(ps, [width_over_major_axis(p) for p in ps], "k-", lw=1.2,
            label=r"$\bar w/A$ (sbpack's mean width of one superball)")
    ax.axhline(1.5, color="0.5", ls=":", lw=1, label=r"cube ($p \to \infty$): 3/2")
    for p, text in ((0.5, "octahedron"), (1.0, "sphere")):
        ax.plot([p], [width_over_major_axis(p)], "ks", mfc="none", ms=7)
        ax.annotate(f"{text} (p = {p:g})", (p, width_over_major_axis(p)), xytext=(8, -4),
                    textcoords="offset points", fontsize=8)
    for s in series:
        ax.plot([s.p], [1.0 / s.major_axis_over_width()], s.style["marker"],
                color=s.style["color"], ms=6,
                label="the results' inputs (their w / 2R)" if s is series[0] else "_nolegend_")
    ax.set_xscale("log")
    ax.xaxis.set_major_locator(ticker.FixedLocator([0.5, 1, 2, 5, 10, 20, 50, 100, 1000]))
    ax.xaxis.set_major_formatter(ticker.FormatStrFormatter("%g"))
    ax.xaxis.set_minor_formatter(ticker.NullFormatter())
    ax.set(xlabel=r"$p$", ylabel=r"$\bar w/A$")
    note(fig, "Mean width of a superball over A = 2R, its extent along a body axis (the paper's "
              "unit-length axes); a shape function, computed by sbpack, not read from results")
    return fig


def form_factor_of(p, voxels, threads):
    """(Q D / 2 pi, <m^2>^(1/2) / v) of one superball at p: sbanalyze's spectral density of one
    particle in a box (chi_V = <|m(Q)|^2> / V over each shell: the orientation average), D the
    diameter of the sphere of the same volume v."""
    from .analysis_classes import SpectralDensity
    packing = one_superball(p)
    volume = packing.phi * packing.box_length**3
    chi = SpectralDensity(voxels=voxels, qmax=1e3, threads=threads, fft_plan="estimate",
                          fft_wisdom="none").compute(packing, f"one superball, p = {p:g}")
    diameter = (6.0 * volume / np.pi) ** (1.0 / 3.0)
    return chi.Q * diameter / (2 * np.pi), np.sqrt(chi.chi * packing.box_length**3) / volume


def form_factor(series, voxels=256, threads=1):
    """The orientation-averaged form factor of one superball at each p of the results, linear
    and log-log (paper Figs. S1, S2), `voxels`^3 in a box of 8 A (0: no figure)."""
    ps = sorted({s.p for s in series})
    if voxels <= 0 or not ps:
        return None
    fig, axes = new_figure(2, width=5.0, height=3.9)
    linear, log = axes[0]
    colours = {s.p: s.style["color"] for s in series}
    for p in ps:
        x, m = form_factor_of(p, voxels, threads)
        linear.plot(x[x <= 2.5], m[x <= 2.5], "-", color=colours[p], lw=1.2, label=f"p = {p:g}")
        log.loglog(x[x <= 6], m[x <= 6], "-", color=colours[p], lw=1.0, label=f"p = {p:g}")
    linear.set(xlabel=r"$QD/2\pi$", ylabel=r"$\langle \tilde m^2\rangle^{1/2}/v$", ylim=(0, 1.02))
    log.set(xlabel=r"$QD/2\pi$", ylabel=r"$\langle \tilde m^2\rangle^{1/2}/v$")
    log.xaxis.set_major_locator(ticker.FixedLocator([0.2, 0.5, 1, 2, 3, 4, 6]))
    log.xaxis.set_major_formatter(ticker.FormatStrFormatter("%g"))
    log.xaxis.set_minor_formatter(ticker.NullFormatter())
    note(fig, "Form factor of one superball, root mean square over directions, over its volume "
              "v; D: the diameter of the sphere of volume v. From sbpack's spectral density of "
              f"one particle in a box of {BOX_OVER_AXIS:g} A on {voxels}³ voxels (A/"
              f"{voxels / BOX_OVER_AXIS:g} per voxel; shells every 2π/{BOX_OVER_AXIS:g}A in Q), "
              "as the paper computed it")
    return fig


def slice_inputs(series, packing_path, most=4):
    """[(packing file, results input or None)] for the slice: --packing, else the first input
    of each p that exists (paths as sbanalyze was given them, from the current directory), at
    most `most`, spread over p."""
    if packing_path:
        return [(packing_path, None)]
    found = {}
    for s in series:
        f = next((f for f in s.files if os.path.isfile(str(f["input"]))), None)
        if f is not None and s.p not in found:
            found[s.p] = (str(f["input"]), f)
    keys = sorted(found)
    if len(keys) > most:
        keys = [keys[round(i * (len(keys) - 1) / (most - 1))] for i in range(most)]
    return [found[p] for p in keys]


def missing_packings(series):
    """Why no packing is cut: the inputs' paths as sbanalyze was given them, not found from here."""
    paths = [str(f["input"]) for s in series for f in s.files]
    shown = ", ".join(paths[:3]) + (f" and {len(paths) - 3} more" if len(paths) > 3 else "")
    return (f"no input's packing file is found from {os.getcwd()} ({shown}, as sbanalyze was "
            "given them); run from where sbanalyze ran, or name one with --packing")


def slice_grid(f, voxels):
    """The slice's grid: `voxels` if given, else the grid the results' pores analysis used for
    that input (its spectral density's otherwise, else 200), and where it comes from."""
    if voxels:
        return voxels, f"{voxels}³ voxels (--slice-voxels)"
    for group, name in (("pore_size", "pores"), ("spectral_density", "spectral density")):
        if f is not None and int(f.get(group, {}).get("voxels", 0)) > 0:
            return int(f[group]["voxels"]), f"{grid_of(f, group)}: the results' {name} grid"
    return 200, "200³ voxels (the results name no grid)"


def packing_slice(series, packing_path=None, voxels=None, threads=1):
    """A plane of the voxelization of a packing per p (paper Fig. 2's packings, as a section),
    the void coloured by pore size / w on one scale; None with --slice-voxels 0 or no input,
    Skipped where no input's packing file is found."""
    from . import _sbpack
    if voxels == 0 or not series:
        return None
    inputs = slice_inputs(series, packing_path)
    if not inputs:
        return Skipped(missing_packings(series))
    fig, axes = new_figure(len(inputs), width=4.2, height=4.2)
    maps = [slice_map(_sbpack.Packing.read(path), f, voxels, threads) for path, f in inputs]
    top = max(float(np.max(m[1])) for m in maps)
    for ax, (packing, pores, extent, title) in zip(axes[0], maps):
        image = ax.imshow(pores, origin="lower", extent=extent, cmap="viridis", vmin=0, vmax=top,
                          interpolation="nearest")
        ax.imshow(np.ma.masked_where(~pores.mask, pores.mask.astype(float)), origin="lower",
                  extent=extent, cmap="Greys", vmin=0, vmax=1.6, interpolation="nearest")
        ax.set_title(title, fontsize=8)
        ax.set(xlabel=r"$z/\bar w$", ylabel=r"$y/\bar w$")
    plt.colorbar(image, ax=list(axes[0]), label=r"pore size $\delta/\bar w$ (void voxels)",
                 shrink=0.8)
    note(fig, "Section x = L/2 of each packing's voxelization (grey: particles), the void "
              "coloured by pore size, as the pores analysis computes it (_sbpack.voxel_slice)")
    return fig


def slice_map(packing, f, voxels, threads):
    """(packing, pore size / w masked in the solid, extent in w, title) of the plane x = L / 2."""
    from . import _sbpack
    m, source = slice_grid(f, voxels)
    solid, pores = _sbpack.voxel_slice(packing, m, m // 2, threads)
    w = packing.mean_width
    extent = (0.0, packing.box_length / w, 0.0, packing.box_length / w)
    x = (m // 2 + 0.5) * packing.box_length / m / w
    title = (f"p = {packing.p:g}, N = {len(packing)}: x = {x:.2f} w\n{source}")
    return packing, np.ma.masked_where(solid != 0, pores / w), extent, title
