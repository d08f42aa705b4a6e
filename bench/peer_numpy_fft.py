#!/usr/bin/env python3
"""Peer of sbanalyze's spectral path in numpy, for bench/RESULTS.md.

1. Times numpy.fft.rfftn on an M^3 float64 grid (best of --repeats), the peer of sbanalyze's
   FFTW r2c step on the same grid.
2. With --check RESULTS.h5 (written by `sbanalyze PACKING.h5 --voxels M --out RESULTS.h5`):
   voxelises the packing independently (voxel centre inside a superball or a periodic image),
   computes chi(Q) = |rfftn|^2 [prod a sinc(Q_i a/2)]^2 / V shell-averaged over round(|n|), and
   S(Q) by direct summation on the first shells, and prints the largest differences from the
   results file.

usage: peer_numpy_fft.py PACKING.h5 [--voxels M] [--repeats R] [--check RESULTS.h5]
       [--sq-shells S]
"""
import argparse
import math
import time

import h5py
import numpy as np


def rotation_matrices(q):
    w, x, y, z = q.T
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ], -2)  # body to lab


def voxelize(f, m):
    p, r, box = f.attrs["p"], f.attrs["semi_axis"], f.attrs["box_length"]
    pos = f["positions"][:] % box
    rot = rotation_matrices(f["orientations"][:])
    a = box / m
    rc = r * max(1.0, 3 ** (0.5 - 1 / (2 * p)))
    grid = np.zeros((m, m, m), dtype=bool)
    half = int(math.ceil(rc / a)) + 1
    offsets = np.arange(-half, half + 1)
    for c, rt in zip(pos, rot):
        base = np.floor(c / a).astype(int)
        idx = [base[k] + offsets for k in range(3)]
        d = [(i + 0.5) * a - c[k] for k, i in enumerate(idx)]
        # minimum image of each offset (the body is smaller than half the box)
        d = [dk - box * np.round(dk / box) for dk in d]
        dx, dy, dz = np.meshgrid(*d, indexing="ij")
        body = np.einsum("ji,...j->...i", rt, np.stack([dx, dy, dz], -1))  # R^T d
        inside = (np.abs(body / r) ** (2 * p)).sum(-1) < 1
        ii, jj, kk = np.meshgrid(*[i % m for i in idx], indexing="ij")
        grid[ii[inside], jj[inside], kk[inside]] = True
    return grid


def shells_of(values, n2, weight, box, smax):
    s = np.rint(np.sqrt(n2)).astype(int)
    keep = (n2 > 0) & (s <= smax)
    q = 2 * np.pi * np.sqrt(n2[keep]) / box
    cnt = np.bincount(s[keep], weights=weight[keep], minlength=smax + 1)[1:]
    mean_q = np.bincount(s[keep], weights=weight[keep] * q, minlength=smax + 1)[1:] / cnt
    mean_v = np.bincount(s[keep], weights=weight[keep] * values[keep], minlength=smax + 1)[1:] / cnt
    return mean_q, mean_v, cnt


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("packing")
    ap.add_argument("--voxels", type=int, default=300)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--check")
    ap.add_argument("--sq-shells", type=int, default=6)
    args = ap.parse_args()
    m = args.voxels
    with h5py.File(args.packing, "r") as f:
        box = f.attrs["box_length"]
        t0 = time.perf_counter()
        grid = voxelize(f, m)
        t_vox = time.perf_counter() - t0
        pos = f["positions"][:] % box
    indicator = grid.astype(np.float64)
    times = []
    for _ in range(args.repeats):
        t0 = time.perf_counter()
        spectrum = np.fft.rfftn(indicator)
        times.append(time.perf_counter() - t0)
    print(f"numpy {np.__version__} rfftn {m}^3 float64: best {min(times):.4f} s, "
          f"median {sorted(times)[len(times) // 2]:.4f} s (single thread, pocketfft)")
    print(f"numpy voxelization (peer check, not optimised): {t_vox:.1f} s, "
          f"phi_voxel {grid.mean():.8f}")
    if not args.check:
        return
    with h5py.File(args.check, "r") as r:
        chi_file = r["spectral_density/chi"][:]
        q_file = r["spectral_density/Q"][:]
        phi_file = r["spectral_density"].attrs["phi_voxel"]
        s_file = r["structure_factor/S"][:] if "structure_factor" in r else None
    a = box / m
    k = np.fft.fftfreq(m, 1.0 / m)          # signed indices n
    kz = np.arange(m // 2 + 1)
    nx, ny, nz = np.meshgrid(k, k, kz, indexing="ij")
    n2 = nx ** 2 + ny ** 2 + nz ** 2
    sinc2 = lambda n: np.sinc(n / m) ** 2      # np.sinc(x) = sin(pi x)/(pi x)
    chi = np.abs(spectrum) ** 2 * a ** 6 * sinc2(nx) * sinc2(ny) * sinc2(nz) / box ** 3
    weight = np.where((nz == 0) | (2 * nz == m), 1.0, 2.0)
    smax = len(chi_file)
    q, chi_shell, _ = shells_of(chi.ravel(), n2.ravel(), weight.ravel(), box, smax)
    print(f"phi_voxel: sbanalyze {phi_file:.10f}, numpy {grid.mean():.10f}")
    print(f"chi shells 1..{smax}: max |rel diff| {np.max(np.abs(chi_shell / chi_file - 1)):.2e}, "
          f"max |Q diff| {np.max(np.abs(q - q_file)):.2e}")
    if s_file is not None:
        smax_s = min(args.sq_shells, len(s_file))
        rng = np.arange(-smax_s, smax_s + 1)
        n = np.array(np.meshgrid(rng, rng, rng, indexing="ij")).reshape(3, -1).T
        n = n[(n ** 2).sum(1) <= smax_s * (smax_s + 1)]
        rho = np.exp(-2j * np.pi * (pos @ n.T) / box).sum(0)
        s_vec = np.abs(rho) ** 2 / len(pos)
        _, s_shell, _ = shells_of(s_vec, (n ** 2).sum(1), np.ones(len(n)), box, smax_s)
        print(f"S shells 1..{smax_s}: max |rel diff| "
              f"{np.max(np.abs(s_shell / s_file[:smax_s] - 1)):.2e}")


if __name__ == "__main__":
    main()
