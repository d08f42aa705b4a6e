#include "gpu/cuda_grid.hpp"

#include "gpu/particle_images.hpp"
#include "voxels/voxelization.hpp"

#include <memory>

namespace sbpack {

CudaGrid::CudaGrid(const Packing& packing, int voxels)
    : voxels_(voxels), boxLength_(packing.boxLength) {
    const Stopwatch clock;
    Voxelizer::checkResolution(packing, voxels);
    words_ = gpu::cuda::voxelize(gpu::particleImages(packing), gpu::voxelGeometry(packing, voxels));
    solidCount_ = gpu::cuda::countSolid(words_);
    runtimeSeconds_ = clock.seconds();
}

double CudaGrid::phiVoxel() const {
    const double m = voxels_;
    return static_cast<double>(solidCount_) / (m * m * m);
}

std::vector<std::uint8_t> CudaGrid::solidMask() const {
    const std::int64_t m = voxels_, w = gpu::wordsPerRow(voxels_);
    std::vector<std::uint32_t> words(words_.bytes() / sizeof(std::uint32_t));
    words_.download(words.data());
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m * m * m));
    for (std::int64_t row = 0; row < m * m; ++row)
        for (std::int64_t k = 0; k < m; ++k)
            mask[row * m + k] =
                static_cast<std::uint8_t>((words[row * w + k / 32] >> (k % 32)) & 1);
    return mask;
}

SpectralDensityResult CudaGrid::spectralDensity(const Packing& packing,
                                                const SpectralDensityParameters& parameters,
                                                bool single, const Progress& progress) const {
    const Stopwatch clock;
    const SpectralDensity chi(parameters);
    SpectralDensityResult result = chi.start(packing, voxels_, phiVoxel());
    const int s = result.maxShell;
    const gpu::cuda::SpectrumCube cube = gpu::cuda::spectrumCube(words_, voxels_, s, single);
    result.fillSeconds = cube.fillSeconds;
    result.transformSeconds = cube.transformSeconds;
    const Stopwatch shellClock;
    const int rows = 2 * s + 1;
    const SpectrumSlab compact{cube.data.data(), voxels_, 0, rows, rows, s + 1};
    ShellAverage shells =
        spectralShellSums(compact, voxelSize(), packing.boxLength, s, progress, parameters.serial)
            .average();
    result.shellSeconds = shellClock.seconds();
    result.runtimeSeconds = clock.seconds();
    chi.finish(packing, std::move(shells), progress, result);
    return result;
}

PoreSizeMap CudaGrid::poreSizeMap(std::int64_t linesPerBatch) const {
    checkSolidCount(solidCount_, voxels_);
    const gpu::cuda::DeviceBuffer distances =
        gpu::cuda::squaredDistances(words_, voxels_, linesPerBatch);
    const std::int64_t m = voxels_;
    std::unique_ptr<std::uint32_t[]> host(new std::uint32_t[m * m * m]);
    distances.download(host.get());
    return PoreSizeMap::fromSquaredDistances(std::move(host), voxels_, voxelSize());
}

} // namespace sbpack
