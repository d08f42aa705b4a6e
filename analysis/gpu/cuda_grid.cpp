#include "gpu/cuda_grid.hpp"

#include "gpu/compact_cube.hpp"
#include "gpu/particle_images.hpp"
#include "parallel/parallel.hpp"
#include "voxels/voxelization.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
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

std::vector<std::uint32_t> CudaGrid::rowBits() const {
    std::vector<std::uint32_t> words(words_.bytes() / sizeof(std::uint32_t));
    words_.download(words.data());
    return words;
}

CudaGrid::Spectra CudaGrid::spectralDensity(const Packing& packing,
                                            const SpectralDensityParameters& parameters,
                                            bool single, const VoxelSpectrumOptions* spectrum,
                                            const Progress& progress) const {
    const Stopwatch clock;
    const SpectralDensity chi(parameters);
    Spectra out{chi.start(packing, voxels_, phiVoxel()), std::nullopt};
    int s = out.chi.maxShell;
    std::vector<double> f;
    const double meanWidth = packing.shape().meanWidth();
    if (spectrum != nullptr) { // the cube reaches the single wave vectors too
        const auto reach = static_cast<int>(std::ceil(std::sqrt(
            static_cast<double>(individualMaxN2(voxels_, boxLength_, meanWidth, *spectrum)))));
        s = std::max(s, reach);
        f = axisFactors(voxels_, voxelSize(), spectrum->cubeFormFactor);
    }
    gpu::cuda::SpectrumCube cube =
        gpu::cuda::spectrumCube(words_, voxels_, s, single, f, std::pow(boxLength_, 3));
    out.chi.fillSeconds = cube.fillSeconds;
    out.chi.transformSeconds = cube.transformSeconds;
    const Stopwatch shellClock;
    ShellAverage shells =
        spectralShellSums(gpu::compactCubeSlab(cube.data, voxels_, s), voxelSize(),
                          packing.boxLength, out.chi.maxShell, progress)
            .average();
    out.chi.shellSeconds = shellClock.seconds();
    if (spectrum != nullptr)
        out.voxelSpectrum =
            voxelSpectrumFrom(std::move(cube.sumByN2), gpu::compactCubePower(cube.data, voxels_, s),
                              {voxels_, boxLength_, phiVoxel()}, meanWidth, *spectrum);
    out.chi.runtimeSeconds = clock.seconds();
    chi.finish(packing, std::move(shells), progress, out.chi);
    return out;
}

namespace {

/// The host's half of a staged copy: the chunk's pages shared out over the run's threads
/// (parallelFor), so that the first touches of the fresh host pages (page faults) run in
/// parallel.
void parallelCopy(void* to, const void* from, std::size_t bytes) {
    constexpr std::int64_t kPage = 4096, kPagesPerTask = 256;
    const auto size = static_cast<std::int64_t>(bytes);
    parallelFor(0, (size + kPage - 1) / kPage, kPagesPerTask, [&](std::int64_t b, std::int64_t e) {
        std::memcpy(static_cast<char*>(to) + b * kPage, static_cast<const char*>(from) + b * kPage,
                    static_cast<std::size_t>(std::min(e * kPage, size) - b * kPage));
    });
}

} // namespace

CudaGrid::TimedPoreSizeMap CudaGrid::poreSizeMap() const {
    checkSolidCount(solidCount_, voxels_);
    const Stopwatch deviceClock;
    const gpu::cuda::DeviceBuffer distances = gpu::cuda::squaredDistances(words_, voxels_);
    const std::uint32_t largest = gpu::cuda::largestValue(distances);
    const double deviceSeconds = deviceClock.seconds();
    const Stopwatch copyClock;
    const std::int64_t m = voxels_;
    std::unique_ptr<std::uint32_t[]> host(new std::uint32_t[m * m * m]);
    distances.downloadStaged(host.get(), std::size_t{256} << 20, parallelCopy);
    const double copySeconds = copyClock.seconds();
    return {PoreSizeMap::fromSquaredDistances(std::move(host), voxels_, voxelSize(),
                                              m * m * m - solidCount_, largest),
            deviceSeconds, copySeconds};
}

std::vector<std::int64_t> CudaGrid::poreHistogram() const {
    checkSolidCount(solidCount_, voxels_);
    const gpu::cuda::DeviceBuffer distances = gpu::cuda::squaredDistances(words_, voxels_);
    return gpu::cuda::histogram(distances, gpu::cuda::largestValue(distances), solidCount_);
}

} // namespace sbpack
