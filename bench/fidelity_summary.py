"""One markdown row per sbgen output: phi, Z and phi_R from `sbanalyze info`, the final pressure,
collisions and CPU seconds from the file's provenance (bench/fidelity_experiments.sh)."""
import re
import subprocess
import sys

import h5py


def row(sbanalyze, path, label, options):
    text = subprocess.run([sbanalyze, "info", path], capture_output=True, text=True).stdout
    def field(pattern):
        found = re.search(pattern, text)
        return found.group(1) if found else "nan"  # Z and phi_R: absent when not resolved
    with h5py.File(path) as f:
        prov = f["provenance"].attrs
        collisions = float(prov.get("collisions", 0)) / 1e6
        cpu = float(prov.get("cpu_time_s", 0))
        pressure = float(f.attrs["reduced_pressure"])
    phi = float(field(r"phi = ([0-9.]+)"))
    z = field(r"Z\s+= ([0-9.]+)")
    rattlers = 100 * float(field(r"phi_R = ([0-9.]+)"))
    return (f"| {label} | `{options}` | {phi:.5f} | {z} | {rattlers:.2f} % | {pressure:.2g} | "
            f"{collisions:.2f} | {cpu:.0f} |")


if __name__ == "__main__":
    sbanalyze, path, label = sys.argv[1:4]
    print(row(sbanalyze, path, label, " ".join(sys.argv[4:])))
