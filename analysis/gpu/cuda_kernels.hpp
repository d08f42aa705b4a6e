#pragma once
// The CUDA side of the GPU grid analysis (cuda_kernels.cu, built with SBPACK_WITH_CUDA only):
// device memory and the kernels behind plain C++, so that neither CUDA's nor Eigen's headers
// cross between nvcc and the host compiler (docs/gpu.md). Every call throws std::runtime_error
// naming the CUDA or cuFFT call and its error.

#include "gpu/grid_kernels.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sbpack::gpu::cuda {

struct DeviceInfo {
    std::string name;
    int computeMajor = 0, computeMinor = 0;
    int multiprocessors = 0;
    std::size_t totalBytes = 0, freeBytes = 0;
};

/// The first CUDA device, or false with the reason in `reason` (no driver, no device).
bool probe(DeviceInfo& info, std::string& reason);

/// Device memory (cudaMalloc), freed with the object.
class DeviceBuffer {
  public:
    DeviceBuffer() = default;
    explicit DeviceBuffer(std::size_t bytes);
    DeviceBuffer(DeviceBuffer&& other) noexcept;
    DeviceBuffer& operator=(DeviceBuffer&& other) noexcept;
    DeviceBuffer(const DeviceBuffer&) = delete;
    DeviceBuffer& operator=(const DeviceBuffer&) = delete;
    ~DeviceBuffer();

    void* get() const { return data_; }
    std::size_t bytes() const { return bytes_; }
    /// Copies the whole buffer into host memory of bytes() bytes.
    void download(void* host) const;

  private:
    void* data_ = nullptr;
    std::size_t bytes_ = 0;
};

/// The solid voxels of every image, as M x M rows of wordsPerRow(M) words (grid_kernels.hpp).
DeviceBuffer voxelize(const std::vector<ParticleImage>& images, const VoxelGeometry& geometry);

/// Number of set bits of the voxel words.
std::int64_t countSolid(const DeviceBuffer& words);

/// The DFT F(k) of the voxel indicator (cuFFT, double precision unless `single`) at the wave
/// indices |n_x|, |n_y| <= s and 0 <= n_z <= s, as a compact cube: (re, im) of signed index
/// (nx, ny, nz) at (((nx mod R) R + (ny mod R)) (s + 1) + nz) 2 with R = 2s + 1. With
/// `axisFactors` (M entries, hyperuniformity/discrete_spectrum.hpp; empty: none) also the sums
/// over the whole grid per |n|^2 of w(kz) |F|^2 f[kx] f[ky] / volume f[kz] (the half space's
/// weights), 3 (M/2)^2 + 1 bins, as discrete_spectrum's gridSums but summed in no fixed order.
/// Seconds of filling the grid and of the transform in fillSeconds and transformSeconds.
struct SpectrumCube {
    std::vector<double> data;
    std::vector<double> sumByN2;
    double fillSeconds = 0.0, transformSeconds = 0.0;
};
SpectrumCube spectrumCube(const DeviceBuffer& words, int voxels, int s, bool single,
                          const std::vector<double>& axisFactors, double volume);

/// Bytes cuFFT expects to need beside the M^3 in-place transform (cufftEstimate3d).
std::size_t fftWorkBytes(int voxels, bool single);

/// The exact periodic squared distances (voxel units) from every voxel to the nearest solid one
/// (kNoSite everywhere when there is none), as uint32 at (x M + y) M + z: rowDistances along z,
/// then envelopeLine along y and along x, `linesPerBatch` lines at a time.
DeviceBuffer squaredDistances(const DeviceBuffer& words, int voxels, std::int64_t linesPerBatch);

/// Bytes of envelope scratch per line of M voxels (grid_kernels.hpp, EnvelopeScratch).
inline std::size_t envelopeScratchBytesPerLine(int voxels) {
    return (2 * static_cast<std::size_t>(voxels) + 1) *
           (sizeof(std::int32_t) + sizeof(std::uint32_t) + sizeof(std::int64_t) +
            sizeof(std::int32_t));
}

} // namespace sbpack::gpu::cuda
