#!/usr/bin/env python3
"""An ensemble from Python: jams a few small sphere packings (sbgen's protocol in-process), analyses
them in one sbanalyze run (the ensemble's mean and standard deviation of each curve and scalar)
and draws the ensemble's S(Q) with its spread.

usage: PYTHONPATH=build/python python3 examples/plot_ensemble.py [--n N] [--seeds K] [--out DIR]
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import sbpack  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100)
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--out", default="ensemble")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    paths = []
    for seed in range(1, args.seeds + 1):
        packing = sbpack.generate(n=args.n, seed=seed, gamma_slow=1e-3, pressure_final=1e9)
        paths.append(os.path.join(args.out, f"spheres-{args.n}-seed{seed}.h5"))
        packing.write(paths[-1])
    # At P = 1e9 the gaps are ~1e-9 D: contacts at gap < 100 / P D, as sbgen's jam check.
    r = sbpack.analyze(paths, os.path.join(args.out, "results.h5"), compute="sq,contacts",
                       qmax=20, tolerance=100 / 1e9)
    e = r["ensembles"][0]
    print(f"{e['n_files']} packings of N = {e['n_particles']}: phi = {e['phi']:.4f} +- "
          f"{e['phi_std']:.4f}, Z = {e['contacts']['z_mean']:.3f} +- "
          f"{e['contacts']['z_mean_std']:.3f}")
    s = e["structure_factor"]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(s["Q_w"], s["S"], lw=1.2, label=f"mean of {e['n_files']} packings")
    ax.fill_between(s["Q_w"], s["S"] - s["S_std"], s["S"] + s["S_std"], alpha=0.3,
                    label="$\\pm$ standard deviation")
    ax.set(xlabel=r"$Q\bar w$ (dimensionless)", ylabel=r"$S(Q)$ (dimensionless)",
           title=f"Ensemble structure factor, N = {e['n_particles']} spheres")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "ensemble_structure_factor.png"), dpi=130)


if __name__ == "__main__":
    main()
