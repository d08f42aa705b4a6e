#pragma once
// The CUDA side of the GPU grid analysis (cuda_kernels.cu, built with SBPACK_WITH_CUDA only):
// device memory and the kernels behind plain C++, so that neither CUDA's nor Eigen's headers
// cross between nvcc and the host compiler (docs/gpu.md). Every call throws std::runtime_error
// naming the CUDA or cuFFT call and its error.

#include "grid/voxel_rows.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
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
    /// The host's part of a staged copy: copies `bytes` from pinned memory into the target.
    using HostCopy = std::function<void(void* to, const void* from, std::size_t bytes)>;
    /// As download, for buffers of gigabytes: through two pinned chunks of `chunkBytes`, the
    /// device filling one while `copyOut` (the caller's threads) empties the other, so that the
    /// page faults and copies into fresh pageable memory overlap the transfer (docs/gpu.md,
    /// "Copies to the host").
    void downloadStaged(void* host, std::size_t chunkBytes, const HostCopy& copyOut) const;

  private:
    void* data_ = nullptr;
    std::size_t bytes_ = 0;
};

/// The solid voxels of every image, as M x M rows of wordsPerRow(M) words (grid/voxel_rows.hpp).
DeviceBuffer voxelize(const std::vector<grid::ParticleImage>& images,
                      const grid::VoxelGeometry& geometry);

/// Number of set bits of the voxel words.
std::int64_t countSolid(const DeviceBuffer& words);

/// The largest of the uint32 values in the buffer (0 when it is empty).
std::uint32_t largestValue(const DeviceBuffer& values);

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
/// (grid::kNoSite everywhere when there is none), as uint32 at (x M + y) M + z: rowDistances along
/// z, then searchedMinimum at every voxel along y (into a second M^3 buffer, freed on return) and
/// back along x (docs/gpu.md).
DeviceBuffer squaredDistances(const DeviceBuffer& words, int voxels);

/// The counts of each value 0 .. largest of the uint32 values (largestValue), the count of
/// zeros given (the solid voxels, counted with the voxels).
std::vector<std::int64_t> histogram(const DeviceBuffer& values, std::uint32_t largest,
                                    std::int64_t zeros);

} // namespace sbpack::gpu::cuda
