#pragma once
// The GPU voxeliser's input (docs/gpu.md): every periodic image of every particle that the CPU
// voxeliser visits (periodicImageShifts per axis), with the particle's lab-to-body rotation.

#include "grid/voxel_rows.hpp"
#include "packing/packing.hpp"

#include <vector>

namespace sbpack::gpu {

std::vector<grid::ParticleImage> particleImages(const Packing& packing);

/// The geometry of an M^3 grid of `packing` (the CPU voxeliser's reach and shape).
grid::VoxelGeometry voxelGeometry(const Packing& packing, int voxels);

} // namespace sbpack::gpu
