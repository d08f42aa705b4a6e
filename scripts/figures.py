#!/usr/bin/env python3
"""Draws the paper's figures from an sbanalyze results file (docs/results-schema.md).

usage: figures.py RESULTS.h5 [OUT_DIR]      (default OUT_DIR: beside RESULTS.h5)

One PNG per figure, every input of the results file overlaid (as the paper compares p):
  structure_factor.png   S(Q) against Q w                          (paper Fig. S(Q))
  spectral_density.png   chi_V(Q) / w^3 against Q w, and at small Q on log axes with the
                         fit a0 + a1 Q^alpha of `hyper`             (Figs. chi, H)
  spreadability.png      the excess spreadability E(t) with the Debye medium, and the local
                         alpha -3 - 2 d ln E / d ln t with the fitted window   (Figs. spread, alpha)
  pore_size.png          F(delta) against delta / w               (Fig. F(delta))
A figure is left out when no input has its analysis. Reads only; the numbers are sbanalyze's.
"""
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def label(group):
    a = group.attrs
    return f"p = {a['p']:g}, N = {a['n_particles']} ({os.path.basename(str(a['input']))})"


def inputs_with(f, analysis):
    files = f["files"]
    return [files[k] for k in sorted(files, key=int) if analysis in files[k]]


def structure_factor(f, ax):
    for g in inputs_with(f, "structure_factor"):
        s = g["structure_factor"]
        ax.plot(s["Q_w"][:], s["S"][:], lw=1, label=label(g))
    ax.set(xlabel=r"$Q\bar w$", ylabel=r"$S(Q)$", title="Structure factor")


def spectral_density(f, axes):
    main, small = axes
    fitted = False
    for g in inputs_with(f, "spectral_density"):
        s, w = g["spectral_density"], g.attrs["mean_width"]
        qw, chi = s["Q_w"][:], s["chi"][:] / w**3
        line, = main.plot(qw, chi, lw=1, label=label(g))
        keep = qw <= 4.0
        small.loglog(qw[keep], chi[keep], "o", ms=3, color=line.get_color())
        if "hyperuniformity" in g:
            fitted = True
            h = g["hyperuniformity"].attrs
            x = qw[qw <= 1.5 * h["q_fit_max_w"]]
            small.loglog(x, h["a0"] + h["a1"] * x ** h["alpha"], "-", color=line.get_color(),
                         label=fr"$a_0 + a_1 Q^{{{h['alpha']:.2f}}}$, $H = {h['H']:.2g} \pm "
                               fr"{h['H_stderr']:.1g}$")
            small.axvline(h["q_fit_max_w"], color="0.6", ls=":", lw=1)
    main.set(xlabel=r"$Q\bar w$", ylabel=r"$\tilde\chi_V(Q)/\bar w^3$",
             title="Spectral density (voxels, shell averages)")
    small.set(xlabel=r"$Q\bar w$", ylabel=r"$\tilde\chi_V(Q)/\bar w^3$",
              title=r"Small $Q$ and the fit ($Q\bar w \leq$ fit-qmax dotted)" if fitted
              else r"Small $Q$ (no hyper results: no fit)")


def spreadability(f, axes):
    top, bottom = axes
    debye_drawn = False
    for g in inputs_with(f, "spreadability"):
        s = g["spreadability"]
        a = s.attrs
        t = s["t"][:]
        line, = top.loglog(t, s["excess"][:], lw=1.2, label=label(g))
        c = line.get_color()
        bottom.semilogx(t, s["local_alpha"][:], lw=1, color=c)
        bottom.axhline(a["alpha"], color=c, ls="--", lw=1,
                       label=fr"$\alpha = {a['alpha']:.2f} \pm {a['alpha_stderr']:.2f}$")
        for ax in axes:
            ax.axvspan(a["t_fit_min"], a["t_fit_max"], color=c, alpha=0.12)
            ax.axvline(a["t_cutoff"], color=c, ls=":", lw=1)
        if not debye_drawn and "spreadability_debye" in g:
            d = g["spreadability_debye"]
            top.loglog(d["t"][:], d["excess"][:], "k--", lw=1,
                       label=fr"Debye medium, $\phi = {d.attrs['phi']:.3f}$ ($t\mathcal{{D}}/a^2$)")
            debye_drawn = True
    top.set(ylabel=r"$\mathcal{S}(\infty)-\mathcal{S}(t)$", ylim=(1e-8, 2),
            title=r"Excess spreadability (shaded: $\alpha$ window; dotted: $t_c$)")
    bottom.set(xlabel=r"$t\mathcal{D}/\bar w^2$", ylabel=r"local $\alpha$", ylim=(-1.5, 3))


def pore_size(f, ax):
    for g in inputs_with(f, "pore_size"):
        s = g["pore_size"]
        ax.step(s["delta_w"][:], s["F"][:], where="post", lw=1, label=label(g))
    ax.set(xlabel=r"$\delta/\bar w$", ylabel=r"$F(\delta)$", title="Pore-size distribution")


def save(fig, axes, path):
    for ax in axes:
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    print(path)


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    results = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) == 3 else os.path.dirname(os.path.abspath(results))
    os.makedirs(out, exist_ok=True)
    with h5py.File(results, "r") as f:
        if f.attrs.get("format") != "sbpack.results" or f.attrs.get("format_version") != 2:
            sys.exit(f"figures.py: {results}: not an sbpack.results file of format_version 2")
        if inputs_with(f, "structure_factor"):
            fig, ax = plt.subplots(figsize=(6, 4))
            structure_factor(f, ax)
            save(fig, [ax], os.path.join(out, "structure_factor.png"))
        if inputs_with(f, "spectral_density"):
            fig, axes = plt.subplots(1, 2, figsize=(11, 4))
            spectral_density(f, axes)
            save(fig, axes, os.path.join(out, "spectral_density.png"))
        if inputs_with(f, "spreadability"):
            fig, axes = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
            spreadability(f, axes)
            save(fig, axes, os.path.join(out, "spreadability.png"))
        if inputs_with(f, "pore_size"):
            fig, ax = plt.subplots(figsize=(6, 4))
            pore_size(f, ax)
            save(fig, [ax], os.path.join(out, "pore_size.png"))


if __name__ == "__main__":
    main()
