"""Collisions over the expected ones (docs/design.md §3, "Expected cost" and "Cost limit") for
every sbgen output under the given folders: the measurement behind --cost-limit's default.
Reads provenance expected_collisions, or for outputs written before it the same model through
sbpack.expected_collisions. Checkpoints are left out (their runs are unfinished), and so are
copies of one run (the same p, N, seed and collision count).
usage: PYTHONPATH=build/python /usr/bin/python3 bench/cost_ratios.py FOLDER..."""
import pathlib
import sys

import numpy as np

import sbpack


def ratio(packing):
    a = packing.provenance
    expected = a.get("expected_collisions") or sbpack.expected_collisions(
        n=len(packing.positions), p=packing.p, gamma_slow=a["gamma_slow"],
        pressure_switch=a["pressure_switch"], pressure_final=a["pressure_final"])
    return a["collisions"] / expected


def main(folders):
    rows, seen = [], set()
    for folder in folders:
        for path in sorted(pathlib.Path(folder).rglob("*.h5")):
            if "checkpoint" in path.name or "resumed" in path.name:
                continue
            try:
                packing = sbpack.Packing.read(path)
            except (OSError, ValueError):
                continue  # not a packing
            a = packing.provenance
            if "collisions" not in a or "jammed" not in a:
                continue  # not a finished sbgen output
            run = (packing.p, len(packing.positions), a["seed"], a["collisions"])
            if run in seen:
                continue
            seen.add(run)
            rows.append((ratio(packing), packing.p, len(packing.positions), a["jammed"], path))
    rows.sort(key=lambda r: r[0])
    print(f"{len(rows)} finished sbgen runs; collisions / expected, largest last:")
    for r in rows[-12:]:
        print("  %6.2f  p = %-5g N = %-5d jammed = %d  %s" % r)
    jammed = np.array([r[0] for r in rows if r[3] == 1])
    print("not jammed: %d" % sum(r[3] != 1 for r in rows))
    if len(jammed):
        print("jammed: %d; median %.2f, 90th percentile %.2f, largest %.2f" % (
            len(jammed), np.median(jammed), np.quantile(jammed, 0.9), jammed.max()))


if __name__ == "__main__":
    main(sys.argv[1:] or ["."])
