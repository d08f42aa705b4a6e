#!/usr/bin/env python3
"""One row of scripts/gpu-check.sh's gpu-bench.csv from an sbanalyze JSON summary, or (--figure
CSV PNG) the bar chart of wall-clock time per grid and device. Standard library only for the rows;
matplotlib for the figure (docs/gpu.md)."""
import csv
import json
import sys


def row(path, grid, device, wall, status):
    fields = {"voxels_s": "", "chi_s": "", "pores_s": "", "stages_s": "", "phi_voxel": "",
              "chi_peak": "", "pore_mean_w": ""}
    if status == "0":
        summary = json.load(open(path))["files"][0]
        chi = summary.get("spectral_density", {})
        pores = summary.get("pore_size", {})
        times = [summary.get("voxelization", {}).get("runtime_s", 0.0), chi.get("runtime_s", 0.0),
                 pores.get("map_s", 0.0) + pores.get("runtime_s", 0.0)]
        fields.update(voxels_s=times[0] or "", chi_s=times[1] or "",
                      pores_s=times[2] or "", stages_s=sum(times),
                      phi_voxel=summary.get("voxelization", {}).get("phi_voxel", ""),
                      chi_peak=repr(chi["peak"]["value"]) if chi else "",
                      pore_mean_w=repr(pores["mean_w"]) if pores else "")
    print(",".join(str(v) for v in [grid, device, f"{float(wall):.3f}", *fields.values(),
                                    "ok" if status == "0" else f"exit {status}"]))


def figure(table, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [r for r in csv.DictReader(open(table)) if r["status"] == "ok"]
    labels = sorted({r["grid"] for r in rows}, key=int)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, column, title in ((axes[0], "stages_s", "the grid stages (voxels + chi + pores)"),
                              (axes[1], "wall_s", "the whole run (start-up and reading included)")):
        for shift, device in ((-0.2, "cpu"), (0.2, "cuda")):
            times = {r["grid"]: float(r[column]) for r in rows if r["device"] == device}
            xs = [i + shift for i, g in enumerate(labels) if g in times]
            bars = ax.bar(xs, [times[g] for g in labels if g in times], width=0.4, label=device)
            ax.bar_label(bars, fmt="%.2f s", fontsize=8)
        ax.set_xticks(range(len(labels)), [f"{g}$^3$" for g in labels])
        ax.set_yscale("log")
        ax.set_ylabel("wall-clock time (s)")
        ax.set_title(title, fontsize=9)
        ax.legend()
    fig.suptitle("sbanalyze on data/mrj-p1.5-5000.h5 (2000$^3$: pores only)", fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    if sys.argv[1] == "--figure":
        figure(sys.argv[2], sys.argv[3])
    else:
        row(*sys.argv[1:6])
