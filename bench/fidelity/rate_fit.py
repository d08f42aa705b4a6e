"""The fast rate at which sbgen reproduces the paper's phi at each p (bench/RESULTS.md, "Fidelity",
E8): reads the packings of bench/fidelity/rate_calibration.spec (labels pP-gG-sS in WORK_DIR, at
reduced pressure 1e7, where phi is final: resumed to 1e12 it moves by < 1e-6), fits
phi = a + b ln(gamma) per p over all seeds and rates (least squares) and solves it for the paper's
phi (data/mst-reference-values.csv). Prints one markdown row per p and the C++ table of
generator/protocol/paper_rates.cpp.

usage: /usr/bin/python3 bench/fidelity/rate_fit.py WORK_DIR [REFERENCE_CSV]"""
import csv
import glob
import math
import os
import re
import sys

import h5py
import numpy as np


def packing_fraction(path):
    with h5py.File(path) as f:
        return float(f.attrs["phi"])


def measured(work):
    runs = {}
    for path in glob.glob(os.path.join(work, "p*-g*-s*.h5")):
        m = re.match(r"p([0-9.]+)-g([0-9.]+)-s([0-9]+)\.h5$", os.path.basename(path))
        if m:
            runs.setdefault(float(m.group(1)), []).append((float(m.group(2)), packing_fraction(path)))
    return runs


def paper(reference):
    with open(reference) as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        return {float(r["p"]): (float(r["phi"]), float(r["phi_sd"])) for r in rows}


def fit(points, target):
    """gamma* of the fit phi = a + b ln gamma, and its spread from the fit's residuals."""
    x = np.log([g for g, _ in points])
    y = np.array([phi for _, phi in points])
    b, a = np.polyfit(x, y, 1)
    residual = y - (a + b * x)
    sd = math.sqrt(float(residual @ residual) / max(1, len(y) - 2))
    star = (target - a) / b
    return math.exp(star), sd, b


def main():
    work = sys.argv[1]
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    reference = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "data",
                                                                   "mst-reference-values.csv")
    runs, targets = measured(work), paper(reference)
    print("| p | runs | phi at 0.01 / 0.02 / 0.03 (mean of seeds) | slope d phi / d ln gamma | "
          "fit residual sd | paper phi | gamma that gives it |")
    print("|---|---|---|---|---|---|---|")
    table = []
    for p in sorted(runs):
        points = runs[p]
        if len({rate for rate, _ in points}) < 2:
            continue  # no slope from one rate
        means = []
        for g in (0.01, 0.02, 0.03):
            values = [phi for rate, phi in points if rate == g]
            means.append(f"{np.mean(values):.5f}" if values else "-")
        star, sd, slope = fit(points, targets[p][0])
        table.append((p, star))
        print(f"| {p:g} | {len(points)} | {' / '.join(means)} | {slope:.4f} | {sd:.4f} | "
              f"{targets[p][0]:.5f} | {star:.4f} |")
    print()
    print(",\n".join(f"    {{{p:g}, {star:.4f}}}" for p, star in table))


if __name__ == "__main__":
    main()
