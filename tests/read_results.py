#!/usr/bin/env python3
"""Reads an sbanalyze results file with h5py, as the README shows (one input)."""
import sys

import h5py

with h5py.File(sys.argv[1], "r") as f:
    a = dict(f.attrs)
    sq = f["structure_factor"]
    Qw, S = sq["Q_w"][:], sq["S"][:]
    chi = f["spectral_density/chi"][:] / a["mean_width"] ** 3
    print(f"{a['format']}: p = {a['p']}, N = {a['n_particles']}, {len(S)} S(Q) shells up to "
          f"Q w = {Qw[-1]:.3g}, {len(chi)} chi shells, "
          f"phi_voxel {f['voxelization'].attrs['phi_voxel']:.6f} (phi {a['phi']:.6f}), "
          f"<delta>/w = {f['pore_size'].attrs['mean_w']:.4f}, "
          f"k/w^2 = {f['transport'].attrs['permeability_w2']:.3g}")
