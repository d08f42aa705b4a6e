#!/usr/bin/env python3
"""One row of scripts/gpu-check.sh's gpu-bench.csv from an sbanalyze JSON summary, or (--figure
CSV PNG) the bar chart of wall-clock time per grid and device. Standard library only for the rows;
matplotlib for the figure (docs/gpu.md)."""
import csv
import json
import sys


def row(path, grid, device, wall, status):
    fields = {"voxels_s": "", "chi_s": "", "pores_s": "", "phi_voxel": "", "chi_peak": "",
              "pore_mean_w": ""}
    if status == "0":
        summary = json.load(open(path))["files"][0]
        chi = summary.get("spectral_density", {})
        pores = summary.get("pore_size", {})
        fields.update(voxels_s=summary.get("voxelization", {}).get("runtime_s", ""),
                      chi_s=chi.get("runtime_s", ""), pores_s=pores.get("runtime_s", ""),
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
    fig, ax = plt.subplots(figsize=(6, 4))
    for shift, device in ((-0.2, "cpu"), (0.2, "cuda")):
        walls = {r["grid"]: float(r["wall_s"]) for r in rows if r["device"] == device}
        xs = [i + shift for i, g in enumerate(labels) if g in walls]
        bars = ax.bar(xs, [walls[g] for g in labels if g in walls], width=0.4, label=device)
        ax.bar_label(bars, fmt="%.2f s", fontsize=8)
    ax.set_xticks(range(len(labels)), [f"{g}$^3$" for g in labels])
    ax.set_yscale("log")
    ax.set_ylabel("wall-clock time of the run (s)")
    ax.set_title("sbanalyze voxels + chi + pores, mrj-p1.5-5000 (2000$^3$: pores only)",
                 fontsize=9)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    if sys.argv[1] == "--figure":
        figure(sys.argv[2], sys.argv[3])
    else:
        row(*sys.argv[1:6])
