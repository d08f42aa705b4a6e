#!/usr/bin/env python3
"""Markdown table of bench/error_vs_time.sh: each accuracy knob's error against the converged
reference and its wall time (2 threads). usage: error_vs_time_summary.py WORK_DIR"""
import csv
import os
import sys

import h5py
import numpy as np

work = sys.argv[1]
times = {}
with open(os.path.join(work, "times.tsv")) as f:
    for name, seconds in csv.reader(f, delimiter="\t"):
        times[name] = float(seconds)


def group(name, path):
    f = h5py.File(os.path.join(work, name + ".h5"), "r")
    return f["files/0/" + path], f["files/0"].attrs


def step(delta, F, x):
    """Right-continuous step function F at the points x."""
    return F[np.searchsorted(delta, x, side="right") - 1]


def gap(a, b):
    x = np.union1d(a["delta"][:], b["delta"][:])
    return np.max(np.abs(step(a["delta"][:], a["F"][:], x) - step(b["delta"][:], b["F"][:], x)))


def percent(value, reference):
    return f"{100.0 * (value - reference) / reference:+.2f} %"


rows = []
stems = sorted({n.split("-pores-")[0] for n in times if "-pores-" in n})
for stem in stems:
    ref, file_attrs = group(stem + "-pores-reference", "pore_size")
    w = file_attrs["mean_width"]
    r = ref.attrs
    rows.append((f"pores reference", stem,
                 f"exact K = {r['samples']:.0e}, seed 2",
                 f"<delta>/w = {r['mean_w']:.5f} +- {r['mean_stderr'] / w:.1e}, "
                 f"<delta^2>/w^2 = {r['second_moment_w2']:.6f} +- "
                 f"{r['second_moment_stderr'] / w**2:.1e}, max/w = {r['max_w']:.5f}",
                 times[stem + "-pores-reference"]))
    settings = [(f"voxel M = {m}", f"{stem}-pores-voxel-{m}") for m in (100, 200, 300, 500)]
    settings += [(f"refined M = {m}", f"{stem}-pores-refined-{m}") for m in (100, 200, 300, 500)]
    settings += [(f"refined M = {m}, 1e6 random voxels", f"{stem}-pores-refined1e6-{m}")
                 for m in (300, 500)]
    settings += [(f"exact K = {k:.0e}", f"{stem}-pores-exact-{k}") for k in (10000, 100000, 1000000)]
    for label, name in settings:
        g, _ = group(name, "pore_size")
        a = g.attrs
        error = (f"<delta> {percent(a['mean'], r['mean'])}, "
                 f"<delta^2> {percent(a['second_moment'], r['second_moment'])}, "
                 f"sup F {gap(g, ref):.4f}, max {(a['max'] - r['max']) / w:+.1e} w")
        if "mean_stderr" in a:
            error += f" (stderr {100 * a['mean_stderr'] / a['mean']:.2f} %)"
        rows.append(("pores, F(delta)", stem, label, error, times[name]))
    ref_sq, _ = group(f"{stem}-sq-60", "structure_factor")
    for qmax in (10, 20, 30, 60):
        g, _ = group(f"{stem}-sq-{qmax}", "structure_factor")
        n = len(g["S"])
        error = np.max(np.abs(g["S"][:] - ref_sq["S"][:n]))
        rows.append(("S(Q)", stem, f"qmax = {qmax} ({n} shells)",
                     f"max abs vs qmax 60 on its shells {error:.1e} (exact sums)",
                     times[f"{stem}-sq-{qmax}"]))
    ref_z = group(f"{stem}-contacts-1e-10", "contacts")[0].attrs["z_mean"]
    for tolerance in ("1e-12", "1e-10", "1e-8", "1e-6", "1e-4"):
        a = group(f"{stem}-contacts-{tolerance}", "contacts")[0].attrs
        resolved = {1: "resolved", 0: "NOT resolved", -1: "no pressure"}[int(a["resolved"])]
        error = (f"Z = {a['z_mean']:.4f} ({a['z_mean'] - ref_z:+.4f} vs 1e-10), "
                 f"phi_R = {100 * a['rattler_fraction']:.2f} %, {resolved}")
        rows.append(("contacts", stem, f"tolerance {tolerance} D", error,
                     times[f"{stem}-contacts-{tolerance}"]))
    for m in (100, 200, 300, 500):
        name = f"{stem}-chi-{m}"
        if name not in times:
            continue
        g, _ = group(name, "spectral_density")
        v, _ = group(name, "voxelization")
        a = g.attrs
        voxel_path = v.attrs["runtime_s"] + a["fft_plan_s"] + a["fft_s"] + a["shell_average_s"]
        rows.append(("chi_V", stem, f"voxel M = {m}",
                     f"max over shells \\|chi - chi_exact\\| / peak = {a['exact_error']:.4f} "
                     f"(voxel path {voxel_path:.2f} s, exact path {a['exact_s']:.2f} s)",
                     times[name]))

print("| analysis | packing | setting | error against the reference | wall s (2 threads) |")
print("|---|---|---|---|---:|")
for analysis, stem, label, error, seconds in rows:
    print(f"| {analysis} | {stem} | {label} | {error} | {seconds:.2f} |")
