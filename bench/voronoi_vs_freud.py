"""Cross-check of sbanalyze --compute voronoi against freud's Voronoi cells (issue 69).

    bash bench/voronoi_vs_freud.sh [SBANALYZE] [PACKING]      (sets up freud's venv, runs this)
    VENV/bin/python bench/voronoi_vs_freud.py SBANALYZE PACKING [--voxels 150 300 450 600]

For equal spheres the set-Voronoi cell of a particle is the ordinary Voronoi cell of its centre
(the bisector of two equal spheres' surfaces is that of their centres; docs/local-structure.md
§1). freud.locality.Voronoi (voro++, exact polyhedra in the periodic box) gives those cells; the
script compares them with sbanalyze's voxel cells (results group voronoi, dataset cell_volume)
at each M: the relative difference per cell (rms and largest), the mean and standard deviation
of the local phi both ways, and the wall time of each (sbanalyze's process with 2 threads, the
contact network included; freud's compute on one thread).

The run fails (exit status 1) where the rms difference at the largest M exceeds RMS_TOLERANCE or
does not fall as M grows (the voxel cells converge to the exact ones).
"""
import argparse
import subprocess
import sys
import time

import freud
import h5py
import numpy as np

RMS_TOLERANCE = 0.01  # relative rms difference of the cells at the largest M


def freud_cells(positions, box_length):
    """Voronoi cell volumes of the centres in the periodic cube, and freud's time (s)."""
    freud.parallel.set_num_threads(1)
    box = freud.box.Box.cube(box_length)
    points = np.ascontiguousarray(positions - box_length / 2.0, dtype=np.float64)
    start = time.perf_counter()
    voronoi = freud.locality.Voronoi()
    voronoi.compute((box, points))
    return np.asarray(voronoi.volumes, dtype=float), time.perf_counter() - start


def sbanalyze_cells(sbanalyze, packing, voxels, out):
    """cell_volume of sbanalyze's voronoi group at M = voxels, and the process's wall time (s)."""
    start = time.perf_counter()
    subprocess.run([sbanalyze, "--compute", "voronoi", "--voxels", str(voxels), "--threads", "2",
                    "--quiet", "--out", out, packing], check=True)
    seconds = time.perf_counter() - start
    with h5py.File(out, "r") as f:
        return np.asarray(f["files/0/voronoi/cell_volume"]), seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sbanalyze")
    parser.add_argument("packing")
    parser.add_argument("--voxels", type=int, nargs="+", default=[150, 300, 450, 600])
    parser.add_argument("--work", default=".")
    args = parser.parse_args()
    with h5py.File(args.packing, "r") as f:
        if f.attrs["p"] != 1.0:
            sys.exit(f"{args.packing}: p = {f.attrs['p']}, not spheres (p = 1)")
        positions = np.asarray(f["positions"])
        box_length = float(f.attrs["box_length"])
        radius = float(f.attrs["semi_axis"])
    v1 = 4.0 / 3.0 * np.pi * radius**3
    exact, freud_seconds = freud_cells(positions, box_length)
    print(f"freud: {len(exact)} cells, sum / L^3 - 1 = {exact.sum() / box_length**3 - 1:.1e}, "
          f"local phi {np.mean(v1 / exact):.6f} +- {np.std(v1 / exact, ddof=1):.6f}, "
          f"{freud_seconds:.3f} s")
    print("   M  rms(cell/freud-1)  max|cell/freud-1|  local phi mean   sd        sbanalyze s")
    rms_by_m = []
    for m in args.voxels:
        cells, seconds = sbanalyze_cells(args.sbanalyze, args.packing, m, f"{args.work}/v{m}.h5")
        difference = cells / exact - 1.0
        rms = float(np.sqrt(np.mean(difference**2)))
        rms_by_m.append(rms)
        phi = v1 / cells
        print(f"{m:4d}  {rms:17.2e}  {np.max(np.abs(difference)):17.2e}  {np.mean(phi):14.6f}  "
              f"{np.std(phi, ddof=1):.6f}  {seconds:9.2f}")
    failures = []
    if rms_by_m[-1] > RMS_TOLERANCE:
        failures.append(f"rms {rms_by_m[-1]:.2e} > {RMS_TOLERANCE} at M = {args.voxels[-1]}")
    if any(later >= earlier for earlier, later in zip(rms_by_m, rms_by_m[1:])):
        failures.append("the rms difference does not fall as M grows")
    for failure in failures:
        print("FAIL:", failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
