#pragma once
// Device memory of the GPU grid analysis (docs/gpu.md), planned before anything is allocated:
// a run whose grids do not fit the device is refused up front with the size it needs.

#include <cstddef>
#include <cstdint>
#include <string>

namespace sbpack {

struct GpuMemoryPlan {
    /// Voxels and chi on the spectral grid: voxel bits, the in-place real-to-complex grid and
    /// cuFFT's work area (0 without a spectral grid).
    double spectralBytes = 0.0;
    /// Pores on the pore grid: voxel bits and two M^3 buffers of squared distances (the
    /// search passes read one and write the other).
    double poreBytes = 0.0;
    /// The larger of the two, with the spectral grid's voxel bits kept while pores run.
    double peakBytes = 0.0;
};

/// Bytes of the voxel bits of an M^3 grid (32-bit words, rows of ceil(M / 32)).
double gpuVoxelBytes(int voxels);
/// Bytes of the in-place real-to-complex grid of an M^3 transform (double or single precision).
double gpuFftGridBytes(int voxels, bool single);

/// The plan for a spectral grid of spectralVoxels (0: none) and a pore grid of poreVoxels (0:
/// none) with cuFFT's work area `fftWorkBytes` (cuda::fftWorkBytes).
GpuMemoryPlan planGpuMemory(int spectralVoxels, int poreVoxels, bool single,
                            std::size_t fftWorkBytes);

/// Throws std::runtime_error when the plan's peak exceeds freeBytes: the bytes needed and free, and
/// what to change (--voxels, --pore-voxels, --device).
void checkGpuMemory(const GpuMemoryPlan& plan, std::size_t freeBytes, const std::string& device);

} // namespace sbpack
