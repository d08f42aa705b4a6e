#pragma once
// The compact cube of low wave vectors that the GPU gathers from its transform
// (gpu/cuda_kernels.hpp, spectrumCube): (re, im) of signed index (nx, ny, nz), |nx|, |ny| <= s,
// 0 <= nz <= s, at (((nx mod R) R + (ny mod R)) (s + 1) + nz) 2 with R = 2s + 1; read here as
// the CPU's transform is read, so that the same shell sums and voxel spectrum follow from it.

#include "hyperuniformity/discrete_spectrum.hpp"
#include "spectral/spectral_density.hpp"

#include <vector>

namespace sbpack::gpu {

/// The cube as a slab of the shell sums (spectral/spectral_density.hpp) of an M^3 grid.
SpectrumSlab compactCubeSlab(const std::vector<double>& cube, int voxels, int s);

/// |F|^2 at DFT indices (kx, ky, kz) of the M^3 grid, |n_x|, |n_y|, kz <= s; the cube must
/// outlive the accessor.
PowerAt compactCubePower(const std::vector<double>& cube, int voxels, int s);

} // namespace sbpack::gpu
