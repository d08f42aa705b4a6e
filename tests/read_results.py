#!/usr/bin/env python3
"""Reads an sbanalyze results file with h5py, as the README shows: files/<i> per input, each
value's units beside it (docs/results-schema.md)."""
import sys

import h5py

with h5py.File(sys.argv[1], "r") as f:
    run = f.attrs
    first = f["files/0"]
    a = dict(first.attrs)
    sq = first["structure_factor"]
    Qw, S = sq["Q_w"][:], sq["S"][:]
    chi = first["spectral_density/chi"][:] / a["mean_width"] ** 3
    assert first["spectral_density/chi"].attrs["units"] == "length^3"
    print(f"{run['format']}: {run['n_files']} file(s), p = {a['p']}, N = {a['n_particles']}, "
          f"{len(S)} S(Q) shells up to Q w = {Qw[-1]:.3g}, {len(chi)} chi shells, "
          f"phi_voxel {first['voxelization'].attrs['phi_voxel']:.6f} (phi {a['phi']:.6f}), "
          f"<delta>/w = {first['pore_size'].attrs['mean_w']:.4f}, "
          f"k/w^2 = {first['transport'].attrs['permeability_w2']:.3g}, "
          f"ensemble <delta>/w = {f['ensembles/0/pore_size'].attrs['mean_w']:.4f}")
