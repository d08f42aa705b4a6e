"""How a packing moved between two states of one run (bench/RESULTS.md, "The creep of p = 10
seed 2"): phi, pressure and collisions of each, particle displacements and rotations, and the
tilt between the facing faces of near-cube neighbours (centres closer than 1.02 D), per class
of tilt, with how it changed. Faces that align would show tilts shrinking.
usage: /usr/bin/python3 bench/creep_between.py EARLIER.h5 LATER.h5"""
import sys

import h5py
import numpy as np
from scipy.spatial import cKDTree
from scipy.spatial.transform import Rotation


def read(path):
    f = h5py.File(path, "r")
    q = f["orientations"][:]  # (w, x, y, z), body to lab (README, "Output")
    axes = Rotation.from_quat(np.c_[q[:, 1:], q[:, 0]]).as_matrix()  # columns: body axes
    return dict(x=f["positions"][:], q=q, axes=axes, L=f.attrs["box_length"],
                D=2 * f.attrs["semi_axis"], phi=f.attrs["phi"], P=f.attrs["reduced_pressure"],
                collisions=f["provenance"].attrs["collisions"],
                cpu=f["provenance"].attrs["cpu_time_s"], windows=f["provenance"].attrs["windows"])


def facing_tilts(s, pairs):
    """Angle between the face of i that faces j and the face of j that faces i."""
    i, j = pairs[:, 0], pairs[:, 1]
    r = s["x"][j] - s["x"][i]
    r -= s["L"] * np.round(r / s["L"])
    r /= np.linalg.norm(r, axis=1)[:, None]
    rows = np.arange(len(pairs))

    def face(k, direction):
        c = np.einsum("nk,nkc->nc", direction, s["axes"][k])
        best = np.abs(c).argmax(1)
        return s["axes"][k][rows, :, best] * np.sign(c[rows, best])[:, None]

    cross = np.cross(face(i, r), face(j, -r))
    return np.arcsin(np.clip(np.linalg.norm(cross, axis=1), 0.0, 1.0))


def main(earlier, later):
    a, b = read(earlier), read(later)
    for name, s in (("earlier", a), ("later", b)):
        print(f"{name}: phi {s['phi']:.10f}  P {s['P']:.3e}  collisions {s['collisions']:.4g}"
              f"  windows {s['windows']}  CPU {s['cpu']:.0f} s")
    d = b["x"] - a["x"]
    d -= a["L"] * np.round(d / a["L"])
    moved = np.linalg.norm(d, axis=1) / a["D"]
    spin = 2 * np.arcsin(np.clip(np.linalg.norm(
        (Rotation.from_quat(np.c_[b["q"][:, 1:], b["q"][:, 0]])
         * Rotation.from_quat(np.c_[a["q"][:, 1:], a["q"][:, 0]]).inv()).as_quat()[:, :3],
        axis=1), 0.0, 1.0))
    print(f"displacement / D: median {np.median(moved):.2g}, max {moved.max():.2g};"
          f" mean drift / D {np.linalg.norm(d.mean(0)) / a['D']:.1g}")
    print(f"rotation (rad): median {np.median(spin):.2g}, max {spin.max():.2g}")
    tree = cKDTree(np.mod(a["x"], a["L"]), boxsize=a["L"])
    pairs = np.array(sorted(tree.query_pairs(1.02 * a["D"])))
    ta, tb = facing_tilts(a, pairs), facing_tilts(b, pairs)
    print(f"{len(pairs)} neighbour pairs closer than 1.02 D; facing-face tilt by class:")
    for lo, hi in ((0, 1e-6), (1e-6, 1e-4), (1e-4, 1e-3), (1e-3, 1e-2), (1e-2, 1.0)):
        m = (ta >= lo) & (ta < hi)
        if m.any():
            print(f"  [{lo:g}, {hi:g}) rad: {m.sum()} pairs, median {np.median(ta[m]):.2g} ->"
                  f" {np.median(tb[m]):.2g}, median |change| {np.median(abs(tb[m] - ta[m])):.2g},"
                  f" smaller after: {(tb[m] < ta[m]).mean():.0%}")


if __name__ == "__main__":
    main(*sys.argv[1:3])
