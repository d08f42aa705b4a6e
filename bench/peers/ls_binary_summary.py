"""The table of bench/peers/ls_binary.sh: each seed's LS and sbgen packings side by side.

usage: ls_binary_summary.py WORK_DIR BUILD_DIR SEED...

Reads the LS code's write.dat (header: DIM, "N 2", the species' counts, their diameters, the box
matrix, "T T T"; then x y z diameter per sphere in the unit box) into an sbpack packing with its
semi_axes (written as WORK_DIR/seedS/ls.h5), and checks both codes' packings with sbpack's contact
network: phi, Z and phi_R at gaps below 1e-10 of each pair's R_i + R_j, the overlapping pairs,
and the CPU seconds (LS: user + system of its run; sbgen: its provenance).
"""
import statistics
import sys
from pathlib import Path

import numpy as np
import sbpack


def ls_packing(seed_dir):
    lines = (seed_dir / "write.dat").read_text().split("\n")
    n = int(lines[1].split()[0])
    rows = np.array([[float(x) for x in line.split()] for line in lines[6 : 6 + n]])
    positions = np.mod(rows[:, :3], 1.0)
    radii = rows[:, 3] / 2.0
    orientations = np.tile([1.0, 0.0, 0.0, 0.0], (n, 1))
    packing = sbpack.Packing(positions, orientations, 1.0, p=1.0, semi_axis=float(radii.max()),
                             semi_axes=radii, source=str(seed_dir / "write.dat"))
    packing.write(str(seed_dir / "ls.h5"))
    return packing


def ls_pressure(seed_dir):
    last = (seed_dir / "stats.dat").read_text().strip().split("\n")[-1].split()
    return float(last[1])


def checked(packing):
    c = sbpack.Contacts(threads=1).compute(packing)
    return {"phi": packing.phi, "Z": c.z_mean, "phi_R": c.rattler_fraction,
            "overlaps": c.overlapping_pairs}


def main():
    work, seeds = Path(sys.argv[1]), sys.argv[3:]
    rows = {"LS": [], "sbgen": []}
    print("| seed | code | phi | Z | phi_R % | overlapping pairs | final P | CPU s |")
    print("|---|---|---|---|---|---|---|---|")
    for seed in seeds:
        d = work / f"seed{seed}"
        ls = checked(ls_packing(d))
        ls["P"] = ls_pressure(d)
        ls["cpu"] = sum(float(x) for x in (d / "cpu.txt").read_text().split())
        mine = sbpack.Packing.read(str(d / "sbgen.h5"))
        sb = checked(mine)
        sb["P"] = mine.reduced_pressure
        sb["cpu"] = mine.provenance["cpu_time_s"]
        for code, r in (("LS", ls), ("sbgen", sb)):
            rows[code].append(r)
            print(f"| {seed} | {code} | {r['phi']:.5f} | {r['Z']:.3f} | {100 * r['phi_R']:.1f} | "
                  f"{r['overlaps']} | {r['P']:.2e} | {r['cpu']:.1f} |")
    print()
    print("| code | phi | Z | phi_R % | CPU s (mean) |")
    print("|---|---|---|---|---|")
    for code, rs in rows.items():
        def ms(key, scale=1.0):
            values = [scale * r[key] for r in rs]
            sd = statistics.stdev(values) if len(values) > 1 else float("nan")
            return statistics.mean(values), sd
        phi, z, rat = ms("phi"), ms("Z"), ms("phi_R", 100.0)
        print(f"| {code} | {phi[0]:.5f} +- {phi[1]:.5f} | {z[0]:.3f} +- {z[1]:.3f} | "
              f"{rat[0]:.1f} +- {rat[1]:.1f} | {statistics.mean(r['cpu'] for r in rs):.1f} |")


if __name__ == "__main__":
    main()
