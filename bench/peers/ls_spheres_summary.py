#!/usr/bin/env python3
"""Summary of bench/peers/ls_spheres.sh: collisions per CPU second of sbgen and of the LS sphere
code per phase, medians over the repetitions and their ratio (sbgen / LS), as a markdown table.

Phase a: from phi 0.2 until two windows (LS: cycles) in a row reach --pressure-a.
Phase b: from the point where two in a row reach --pressure-b0 to where two reach --pressure-b1.
sbgen: differences of the provenance counters `collisions` and `cpu_time_s` (the engine's windows
only) between its outputs at those pressures (sbgen-a.h5, sbgen-b0.h5, sbgen-b1.h5). LS: the
patched data file's rows (cumulative collisions, events and growth-loop CPU seconds per cycle).
"""

import argparse
import statistics
import sys
from pathlib import Path

import h5py


def sbgen_point(path):
    with h5py.File(path, "r") as f:
        a = f["provenance"].attrs
        return {
            "phi": float(f.attrs["phi"]),
            "pressure": float(a["final_reduced_pressure"]),
            "collisions": int(a["collisions"]),
            "events": int(a["events"]),
            "relists": int(a["relists"]),
            "cpu": float(a["cpu_time_s"]),
            "windows": int(a["windows"]),
        }


def ls_rows(path):
    rows = []
    for line in Path(path).read_text().split("\n"):
        c = line.split()
        if len(c) < 8:
            continue
        rows.append({"phi": float(c[0]), "pressure": float(c[1]), "events": int(c[3]),
                     "collisions": int(c[4]), "transfers": int(c[5]), "checks": int(c[6]),
                     "cpu": float(c[7])})
    if not rows:
        sys.exit(f"{path}: no rows (was the LS code patched?)")
    return rows


def ls_sustained(rows, pressure):
    """The first row where this and the previous cycle's pressure reach `pressure`."""
    for i in range(1, len(rows)):
        if rows[i - 1]["pressure"] >= pressure and rows[i]["pressure"] >= pressure:
            return rows[i]
    sys.exit(f"the LS run never held reduced pressure {pressure:g} for two cycles")


START = {"phi": 0.2, "pressure": 0.0, "collisions": 0, "events": 0, "cpu": 0.0}


def phase(start, end):
    collisions = end["collisions"] - start["collisions"]
    cpu = end["cpu"] - start["cpu"]
    return {"collisions": collisions, "cpu": cpu, "rate": collisions / cpu,
            "events": end["events"] - start["events"], "phi0": start["phi"], "phi1": end["phi"],
            "p1": end["pressure"]}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("work")
    ap.add_argument("--ns", default="1000 5000")
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--pressure-a", type=float, default=30)
    ap.add_argument("--pressure-b0", type=float, default=1e3)
    ap.add_argument("--pressure-b1", type=float, default=1e6)
    args = ap.parse_args()
    work = Path(args.work)
    if (work / "setup.txt").exists():
        print("```\n" + (work / "setup.txt").read_text().rstrip() + "\n```\n")
    print("| N | phase | code | M collisions / CPU s, median (min-max) | collisions | CPU s |"
          " events / collision | phi at end | ratio sbgen / LS (median; per-seed min-max) |")
    print("|---|---|---|---:|---:|---:|---:|---:|---:|")
    for n in args.ns.split():
        runs = {"a": {"sbgen": [], "LS": []}, "b": {"sbgen": [], "LS": []}}
        for seed in range(1, args.repeats + 1):
            d = work / f"n{n}" / f"seed{seed}"
            sa, sb0, sb1 = (sbgen_point(d / f"sbgen-{x}.h5") for x in ("a", "b0", "b1"))
            rows = ls_rows(d / f"stats_{seed}.dat")
            runs["a"]["sbgen"].append(phase(START, sa))
            runs["b"]["sbgen"].append(phase(sb0, sb1))
            la = ls_sustained(rows, args.pressure_a)
            lb0 = ls_sustained(rows, args.pressure_b0)
            lb1 = ls_sustained(rows, args.pressure_b1)
            runs["a"]["LS"].append(phase(START, la))
            runs["b"]["LS"].append(phase(lb0, lb1))
        names = {"a": f"a: phi 0.2 to P {args.pressure_a:g}",
                 "b": f"b: P {args.pressure_b0:g} to {args.pressure_b1:g}"}
        for ph in ("a", "b"):
            med = {}
            for code in ("sbgen", "LS"):
                r = runs[ph][code]
                rates = [x["rate"] for x in r]
                med[code] = statistics.median(rates)
                ratio = ""
                if code == "LS":
                    per_seed = [s["rate"] / l["rate"]
                                for s, l in zip(runs[ph]["sbgen"], runs[ph]["LS"])]
                    ratio = (f"**{med['sbgen'] / med['LS']:.2f}** "
                             f"({min(per_seed):.2f}-{max(per_seed):.2f})")
                print(f"| {n} | {names[ph]} | {code} | {med[code] / 1e6:.3f} "
                      f"({min(rates) / 1e6:.3f}-{max(rates) / 1e6:.3f}) | "
                      f"{statistics.median(x['collisions'] for x in r):.4g} | "
                      f"{statistics.median(x['cpu'] for x in r):.3f} | "
                      f"{statistics.median(x['events'] / x['collisions'] for x in r):.2f} | "
                      f"{statistics.median(x['phi1'] for x in r):.4f} | {ratio} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
