"""Summarises bench/jamming_superballs.sh: one row per packing or checkpoint, then per-p means."""
import glob
import os
import re
import sys

import h5py
import numpy as np

# Paper (Maher, Stillinger, Torquato): the raw values of its Figure 5 (phi against p), as issue 4.
PAPER_PHI = {0.85: 0.6776, 0.9: 0.6652, 1.1: 0.6635, 1.2: 0.6807, 1.5: 0.7145}


def read(path):
    with h5py.File(path, "r") as f:
        a, log = f.attrs, f["provenance"].attrs
        row = {k: log[k] for k in log if k in (
            "collisions", "rechecks", "predictor_calls", "predictor_evaluations",
            "predictor_fallbacks", "predictor_limit_hits", "predictor_robust_evaluations",
            "predictor_plane_steps", "predictor_newton_steps", "predictor_bound_rejections",
            "predictor_plane_rejections", "wall_time_s", "cpu_time_s",
            "z_mean", "rattler_fraction", "worst_gap_over_d", "overlapping_pairs")}
        row.update(p=float(a["p"]), phi=float(a["phi"]), n=int(a["n_particles"]),
                   pressure=float(a.get("reduced_pressure", np.nan)), path=path)
    return row


def fmt(r):
    cpu = r.get("cpu_time_s", r["wall_time_s"])
    paper = PAPER_PHI.get(r["p"])
    diff = f"{r['phi'] - paper:+.4f}" if paper else "-"
    z = f"{r['z_mean']:.3f}" if "z_mean" in r else "-"
    rattlers = f"{100 * r['rattler_fraction']:.1f} %" if "rattler_fraction" in r else "-"
    gap = f"{r['worst_gap_over_d']:.1e}" if "worst_gap_over_d" in r else "-"
    overlaps = r.get("overlapping_pairs", "-")

    def per(key):  # per collision; absent from files of sbgen before these counters
        return f"{r[key] / r['collisions']:.2f}" if key in r else "-"

    steps = r.get("predictor_newton_steps")
    newton = f"{steps / r['predictor_evaluations']:.2f}" if steps is not None else "-"

    return (f"| {os.path.basename(r['path'])} | {r['p']:g} | {r['n']} | {r['pressure']:.2e} | "
            f"{r['phi']:.4f} | {diff} | {z} | {rattlers} | {gap} | {overlaps} | "
            f"{r['collisions'] / 1e6:.2f} | {cpu:.0f} | {r['collisions'] / cpu:.0f} | "
            f"{r['predictor_evaluations'] / r['collisions']:.1f} | {per('predictor_robust_evaluations')} | "
            f"{newton} | "
            f"{per('predictor_plane_steps')} | {per('predictor_bound_rejections')} | "
            f"{per('predictor_plane_rejections')} | "
            f"{r['rechecks'] / r['collisions']:.3f} | {r['predictor_fallbacks']} |")


work = sys.argv[1]
print("| file | p | N | P | phi | phi - paper | Z | phi_R | worst gap / D | overlaps | "
      "M collisions | CPU s | collisions / CPU s | exact s per collision | "
      "robust s per collision | Newton steps per exact s | plane steps per collision | "
      "bound rejections per collision | plane rejections per collision | "
      "rechecks per collision | solver fallbacks |")
print("|" + "---|" * 21)
rows = []
for path in sorted(glob.glob(f"{work}/*.h5")):
    if path.endswith(".checkpoint.h5") and os.path.exists(path.replace(".checkpoint", "")):
        continue
    rows.append(read(path))
    print(fmt(rows[-1]))
print("\nPer p (finished N = 1000 runs): mean and spread over seeds")
print("| p | runs | phi | paper | Z | phi_R |")
print("|---|---|---|---|---|---|")
for p in sorted(PAPER_PHI):
    done = [r for r in rows if r["p"] == p and r["n"] == 1000 and "z_mean" in r]
    if not done:
        continue
    phi = np.array([r["phi"] for r in done])
    z = np.array([r["z_mean"] for r in done])
    rattlers = np.array([r["rattler_fraction"] for r in done])
    print(f"| {p:g} | {len(done)} | {phi.mean():.4f} ± {phi.std():.4f} | {PAPER_PHI[p]} | "
          f"{z.mean():.3f} ± {z.std():.3f} | {100 * rattlers.mean():.1f} % |")
