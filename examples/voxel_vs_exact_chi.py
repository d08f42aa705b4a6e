#!/usr/bin/env python3
"""Compares the voxel spectral density chi_V(Q) with the exact one (spheres: no voxels) at several
grids M, as the RMS of their difference over the shells with Q w <= 3 relative to the peak of the
exact curve, and draws both (sbanalyze --compute chi).

usage: PYTHONPATH=build/python python3 examples/voxel_vs_exact_chi.py [--voxels M...] [--out DIR]
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import sbpack  # noqa: E402

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")
SMALL_QW = 3.0  # the RMS is over the shells with Q w <= this


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--packing", default=os.path.join(DATA, "mrj-spheres-5000.h5"))
    parser.add_argument("--voxels", type=int, nargs="+", default=[100, 200])
    parser.add_argument("--out", default=".")
    args = parser.parse_args()
    packing = sbpack.Packing.read(args.packing)
    if packing.p != 1.0:
        parser.error(f"{args.packing}: p = {packing.p:g}; the exact chi_V is for spheres only")
    w = packing.mean_width
    fig, ax = plt.subplots(figsize=(6, 4))
    for m in args.voxels:
        chi = sbpack.SpectralDensity(voxels=m, fft_plan="estimate", fft_wisdom="none").compute(
            packing)
        small = chi.Q_w <= SMALL_QW
        rms = np.sqrt(np.mean((chi.chi[small] - chi.chi_exact[small]) ** 2)) / chi.chi_exact.max()
        print(f"M = {m}: RMS(chi_voxel - chi_exact) / peak at Q w <= {SMALL_QW:g}: {rms:.2e}; "
              f"max over all shells (exact_error): {chi.exact_error:.2e}")
        ax.plot(chi.Q_w, chi.chi / w**3, lw=1, label=f"voxels, M = {m}")
    ax.plot(chi.Q_w, chi.chi_exact / w**3, "k--", lw=1, label="exact (no voxels)")
    ax.axvspan(0.0, SMALL_QW, color="0.92", zorder=0,
               label=rf"RMS window, $Q\bar w \leq {SMALL_QW:g}$")
    ax.set(xlabel=r"$Q\bar w$ (dimensionless)",
           ylabel=r"$\tilde\chi_V(Q)/\bar w^3$ (dimensionless)",
           title=f"Spectral density, {len(packing)} spheres: voxels against exact")
    ax.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(args.out, exist_ok=True)
    fig.savefig(os.path.join(args.out, "voxel_vs_exact_chi.png"), dpi=130)


if __name__ == "__main__":
    main()
