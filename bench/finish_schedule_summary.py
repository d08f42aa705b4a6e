"""Summary of bench/finish_schedule.sh (issue 64 item 1): each finish against the default run of
the same seed, and the seed-to-seed sd of the default runs, as markdown tables.
usage: finish_schedule_summary.py WORK "P_LIST" "SEEDS" "P_STARS" "SPEEDS"
Contacts at sbanalyze's default tolerance (1e-10 D) by the module's own Contacts; the largest
displacement between the two packings is the minimum-image distance over the particles, in units
of the mean width w; CPU s and collisions are the provenance's, summed over each chain; the
category is sbanalyze's jamming test's (docs/jamming.md)."""
import os
import sys

import numpy as np

import sbpack

# The contact network's tolerance: gaps the run leaves at P* ~ 1e8 (1e-8..1e-6 D) count; the
# default 1e-10 D counts only gaps refined by the last decades (bench/RESULTS.md, "The finish").
NETWORK_TOLERANCE = 1e-6


def measured(path):
    """phi, Z, phi_R, the per-particle contact counts and rattlers, CPU s, collisions."""
    packing = sbpack.Packing.read(path)
    contacts = sbpack.Contacts(threads=2).compute(packing)
    network = sbpack.Contacts(threads=2, tolerance=NETWORK_TOLERANCE).compute(packing)
    return {"packing": packing, "phi": packing.phi, "z": contacts.z_mean,
            "z_network": network.z_mean, "phi_r_network": network.rattler_fraction,
            "phi_r": contacts.rattler_fraction, "counts": np.asarray(contacts.counts),
            "rattler": np.asarray(contacts.rattler),
            "cpu": float(packing.provenance["cpu_time_s"]),
            "collisions": float(packing.provenance["collisions"]),
            "jammed": int(packing.provenance.get("jammed", -1)),
            "category": str(sbpack.Jamming(threads=2).compute(packing).category)}


def displacement(a, b):
    """The largest minimum-image distance between the same particle of a and b, over w."""
    d = np.asarray(a.positions) - np.asarray(b.positions)
    d -= a.box_length * np.round(d / a.box_length)
    return float(np.max(np.linalg.norm(d, axis=1))) / a.mean_width


def row(p, s, star, x, f, d):
    """A finish's row against the default run d of its seed."""
    changed = int(np.count_nonzero((f["counts"] != d["counts"]) | (f["rattler"] != d["rattler"])))
    return (f"| {p} | {s} | {star} | {x} | {f['phi'] - d['phi']:+.2e} | {f['z']:.4f} "
            f"({f['z'] - d['z']:+.4f}) | {100 * f['phi_r']:.2f} ({100 * (f['phi_r'] - d['phi_r']):+.2f}) "
            f"| {f['z_network']:.4f} ({f['z_network'] - d['z_network']:+.4f}) "
            f"| {changed} | {displacement(f['packing'], d['packing']):.2e} | {f['cpu']:.0f} | "
            f"{f['cpu'] / d['cpu']:.2f} | {f['collisions'] / d['collisions']:.2f} | {f['jammed']} | "
            f"{f['category']} |")


def main(work, plist, seeds, stars, speeds):
    print("| p | seed | P* | X | phi - default | Z (- default) | phi_R % (- default) "
          "| Z at 1e-6 D (- default) | particles "
          "changed | max displacement / w | CPU s | CPU / default | collisions / default | "
          "jammed | category |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    spread = []
    for p in plist.split():
        defaults = {}
        for s in seeds.split():
            d = measured(os.path.join(work, f"p{p}-s{s}-default-1e12.h5"))
            defaults[s] = d
            print(f"| {p} | {s} | - | 1 | 0 | {d['z']:.4f} | {100 * d['phi_r']:.2f} | "
                  f"{d['z_network']:.4f} | - | - | "
                  f"{d['cpu']:.0f} | 1 | 1 | {d['jammed']} | {d['category']} |")
            for star in stars.split():
                for x in speeds.split():
                    path = os.path.join(work, f"p{p}-s{s}-finish-{star}-x{x}.h5")
                    if os.path.exists(path):
                        print(row(p, s, star, x, measured(path), d))
        values = list(defaults.values())
        if len(values) >= 2:
            spread.append((p, *(np.std([v[k] for v in values], ddof=1)
                                for k in ("phi", "z", "phi_r", "z_network"))))
    print("\nSeed-to-seed sd of the default runs:\n\n| p | sd phi | sd Z | sd phi_R % | "
          "sd Z at 1e-6 D |\n|---|---|---|---|---|")
    for p, phi, z, phi_r, z_network in spread:
        print(f"| {p} | {phi:.2e} | {z:.4f} | {100 * phi_r:.2f} | {z_network:.4f} |")


if __name__ == "__main__":
    main(*sys.argv[1:6])
