"""The speed knob's table (bench/speed_knob.sh): per (p, speed) ensemble phi, Z and phi_R (mean
+- sd over its packings) and sbgen's CPU seconds per packing (mean, from each input's provenance),
with the CPU time's ratio to speed 1 of the same p.

usage: speed_knob_summary.py RESULTS.h5..."""
import re
import sys

import h5py
import numpy as np


def row(path):
    speed = float(re.search(r"-x([0-9.e+-]+)\.h5$", path).group(1))
    with h5py.File(path) as r:
        files = list(r["files"].values())
        p = float(files[0].attrs["p"])
        phi = [float(f.attrs["phi"]) for f in files]
        z = [float(f["contacts"].attrs["z_mean"]) for f in files]
        rattlers = [100 * float(f["contacts"].attrs["rattler_fraction"]) for f in files]
        cpu = []
        for f in files:
            with h5py.File(f.attrs["input"]) as packing:
                cpu.append(float(packing["provenance"].attrs["cpu_time_s"]))
    return p, speed, len(files), phi, z, rattlers, cpu


def pm(values, digits):
    return f"{np.mean(values):.{digits}f} +- {np.std(values, ddof=1):.{digits}f}"


def main(paths):
    rows = sorted(row(path) for path in paths)
    base = {p: np.mean(cpu) for p, speed, _, _, _, _, cpu in rows if speed == 1}
    print("| p | speed | n | phi | Z | phi_R % | sbgen CPU s | CPU / speed 1 |")
    print("|---|---|---|---|---|---|---|---|")
    for p, speed, n, phi, z, rattlers, cpu in rows:
        ratio = np.mean(cpu) / base[p] if p in base else float("nan")
        print(f"| {p:g} | {speed:g} | {n} | {pm(phi, 4)} | {pm(z, 3)} | {pm(rattlers, 2)} | "
              f"{np.mean(cpu):.0f} | {ratio:.2f} |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
