"""Summarises bench/jamming_spheres.sh: one row per packing, then the 1e14 continuation."""
import sys

import h5py
import numpy as np


def smallest_gap(positions, box, diameter):
    """Brute force over all pairs (minimum image), in units of D."""
    best = np.inf
    for i in range(len(positions) - 1):
        d = positions[i + 1:] - positions[i]
        d -= box * np.round(d / box)
        best = min(best, np.sqrt((d * d).sum(1)).min())
    return (best - diameter) / diameter


def row(path):
    with h5py.File(path, "r") as f:
        a, log = f.attrs, f["provenance"].attrs
        gap = smallest_gap(f["positions"][:], a["box_length"], 2 * a["semi_axis"])
        wall = log["wall_time_s"]
        return (f"| {path.split('/')[-1]} | {a['phi']:.5f} | {log['z_mean']:.4f} | "
                f"{100 * log['rattler_fraction']:.1f} % | {gap:.1e} | {a['reduced_pressure']:.2e} | "
                f"{log['collisions'] / wall / 1e6:.3f} | {log['events'] / wall / 1e6:.3f} | {wall:.1f} |")


work, seeds = sys.argv[1], sys.argv[2:]
print("| packing | phi | Z | phi_R | smallest gap / D | P | M collisions/s | M events/s | wall s |")
print("|---|---|---|---|---|---|---|---|---|")
for seed in seeds:
    print(row(f"{work}/seed{seed}.h5"))
print(row(f"{work}/seed{seeds[0]}-1e14.h5"))
print("\nPressure against collisions at the end of the 1e14 continuation:")
lines = [l for l in open(f"{work}/seed{seeds[0]}-1e14.log") if l.startswith("sbgen: slow")]
for line in lines[-6:]:
    print("    " + line.strip())
