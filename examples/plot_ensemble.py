#!/usr/bin/env python3
"""An ensemble from Python: jams a few small sphere packings (sbgen's protocol in-process), analyses
the jammed ones in one sbanalyze run (the ensemble's mean and standard deviation of each curve and
scalar) and draws the ensemble's S(Q) with its spread.

A packing that fails sbgen's jam check (provenance ``jammed`` = 0, e.g. a column of particles
wrapping around a small box) is still written, but left out of the ensemble with a note naming it:
its contacts are undetermined (Z = nan) and its structure is not a jammed one. The default N = 250
is the smallest that sbgen does not warn about (smaller boxes jam partly ordered or stop on such
columns: 2 of 6 seeds at N = 100).

usage: PYTHONPATH=build/python python3 examples/plot_ensemble.py [--n N] [--seeds K] [--out DIR]
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import sbpack  # noqa: E402

PRESSURE = 1e9  # final reduced pressure: gaps ~1e-9 D; contacts at gap < 100 / P D (the jam check)


def jam(n, seeds, out):
    """Jams one packing per seed and writes each; returns (jammed paths, [(path, packing)] of the
    ones not jammed)."""
    jammed, not_jammed = [], []
    for seed in seeds:
        packing = sbpack.generate(n=n, seed=seed, speed=10, pressure_final=PRESSURE)
        path = os.path.join(out, f"spheres-{n}-seed{seed}.h5")
        packing.write(path)
        if packing.provenance.get("jammed") == 1:
            jammed.append(path)
        else:
            not_jammed.append((path, packing))
    return jammed, not_jammed


def note_excluded(not_jammed):
    """Names each packing left out of the ensemble, with where it stopped and why (the first
    clause of its jam check, provenance 'jam_check')."""
    for path, packing in not_jammed:
        why = packing.provenance.get("jam_check", "no jam check").split("; ")[0]
        print(f"left out of the ensemble: {path} (reduced pressure "
              f"{packing.reduced_pressure:.2g}; {why})")


def summary(e):
    """phi and Z of the ensemble, with the standard deviation where there is a spread."""
    c = e["contacts"]
    if e["n_files"] < 2:
        return (f"1 packing of N = {e['n_particles']}: phi = {e['phi']:.4f}, "
                f"Z = {c['z_mean']:.3f} (one packing: no standard deviation)")
    return (f"{e['n_files']} packings of N = {e['n_particles']}: phi = {e['phi']:.4f} +- "
            f"{e['phi_std']:.4f}, Z = {c['z_mean']:.3f} +- {c['z_mean_std']:.3f}")


def draw(e, excluded, path):
    """The ensemble's S(Q), mean and spread, at its shells (the points)."""
    s = e["structure_factor"]
    fig, ax = plt.subplots(figsize=(6, 4))
    drawn = f"mean of {e['n_files']} jammed packings" if e["n_files"] > 1 else "one jammed packing"
    ax.plot(s["Q_w"], s["S"], "o-", ms=3, lw=1.2,
            label=drawn + (f" ({excluded} not jammed, left out)" if excluded else ""))
    if e["n_files"] > 1:
        ax.fill_between(s["Q_w"], s["S"] - s["S_std"], s["S"] + s["S_std"], alpha=0.3,
                        label="$\\pm$ standard deviation")
    ax.axhline(1.0, color="0.7", lw=0.8, ls=":")
    ax.set(xlabel=r"$Q\bar w$ (dimensionless)", ylabel=r"$S(Q)$ (dimensionless)",
           title=f"Ensemble structure factor, N = {e['n_particles']} spheres")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=130)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=250)
    parser.add_argument("--seeds", type=int, default=3, help="seeds 1..K")
    parser.add_argument("--out", default="ensemble")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    paths, not_jammed = jam(args.n, range(1, args.seeds + 1), args.out)
    note_excluded(not_jammed)
    if not paths:
        sys.exit("no packing jammed: no ensemble (more particles, or other seeds)")
    r = sbpack.analyze(paths, os.path.join(args.out, "results.h5"), compute="sq,contacts",
                       qmax=20, tolerance=100 / PRESSURE)
    e = r["ensembles"][0]
    print(summary(e))
    draw(e, len(not_jammed), os.path.join(args.out, "ensemble_structure_factor.png"))


if __name__ == "__main__":
    main()
