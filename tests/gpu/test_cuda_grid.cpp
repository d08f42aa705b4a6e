// The GPU grid analysis against the CPU path on a real GPU (docs/gpu.md): the acceptance of the
// voxels (bit for bit), the distances (exactly) and chi_V (1e-10 relative in double precision).
// Every test reports skipped, not passed, where no CUDA device is present.
#include "../analysis/test_packings.hpp"
#include "gpu/compute_device.hpp"
#include "gpu/cuda_grid.hpp"
#include "gpu/gpu_memory.hpp"
#include "hyperuniformity/discrete_spectrum.hpp"
#include "io/packing_io.hpp"
#include "pores/distance_transform.hpp"
#include "spectral/spectral_density.hpp"
#include "spectral/voxel_fourier_transform.hpp"
#include "voxels/voxelization.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace sbpack {
namespace {

class CudaGridTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string reason;
        if (!probeCudaDevice(reason)) GTEST_SKIP() << "no CUDA device: " << reason;
    }
};

/// data/ of the source tree, or $SBPACK_DATA_DIR where the tests run from a bundle on another
/// machine (scripts/gpu-check.sh).
Packing storedPacking(const std::string& name) {
    const char* moved = std::getenv("SBPACK_DATA_DIR");
    return readPacking(std::string(moved != nullptr ? moved : SBPACK_DATA_DIR) + "/" + name);
}

struct Case {
    const char* file;
    int voxels;
};
constexpr Case kCases[] = {{"mrj-p1.5-1000.h5", 100},
                           {"mrj-p1.5-1000.h5", 257},
                           {"mrj-spheres-5000.h5", 200},
                           {"dense-p10-200.h5", 128},
                           {"mrj-p1.5-5000.h5", 500}};

std::vector<std::uint8_t> cpuMask(const Packing& packing, int m) {
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m);
    Voxelizer({m}).compute(packing, Progress()).copySolidMask(mask);
    return mask;
}

TEST_F(CudaGridTest, VoxelsEqualTheCpuBitForBit) {
    for (const Case& c : kCases) {
        const Packing packing = storedPacking(c.file);
        const CudaGrid grid(packing, c.voxels);
        const std::vector<std::uint8_t> expected = cpuMask(packing, c.voxels);
        std::vector<std::uint8_t> mask(expected.size()); // the bits as the --vdb export reads them
        Voxelizer::fromRowBits(grid.rowBits(), packing, c.voxels, 0.0).copySolidMask(mask);
        EXPECT_EQ(mask, expected) << c.file << " M " << c.voxels;
        EXPECT_EQ(grid.solidCount(), std::count(expected.begin(), expected.end(), 1));
    }
}

/// The GPU's squared distances, void count, largest distance and their histogram equal the CPU
/// transform's exactly; the seconds of the GPU's map printed.
void expectDistancesEqualTheCpu(const Packing& packing, int m, const std::string& label) {
    const CudaGrid grid(packing, m);
    const PoreSizeMap cpu = periodicDistanceTransform(cpuMask(packing, m), m, grid.voxelSize());
    const auto start = std::chrono::steady_clock::now();
    const PoreSizeMap gpu = grid.poreSizeMap().map;
    std::cout << "[ distances ] " << label << " M " << m << ": "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
              << " s on the GPU, map copied\n";
    ASSERT_TRUE(std::ranges::equal(gpu.squaredDistances(), cpu.squaredDistances()))
        << label << " M " << m;
    EXPECT_EQ(gpu.voidCount(), cpu.voidCount());
    EXPECT_EQ(gpu.maxSquaredDistance(), cpu.maxSquaredDistance());
    std::vector<std::int64_t> counts(cpu.maxSquaredDistance() + std::size_t{1}, 0);
    for (const std::uint32_t n : cpu.squaredDistances())
        ++counts[n];
    EXPECT_EQ(grid.poreHistogram(), counts) << label << " M " << m;
}

TEST_F(CudaGridTest, DistancesEqualTheCpuExactly) {
    // M = 700 beside the stored cases: pores of more voxels than at 500 (which copies back in
    // two staged chunks); odd M are 257 and the random masks of the host tests.
    std::vector<Case> cases(std::begin(kCases), std::end(kCases));
    cases.push_back({"mrj-p1.5-1000.h5", 700});
    for (const Case& c : cases)
        expectDistancesEqualTheCpu(storedPacking(c.file), c.voxels, c.file);
}

/// One superball in a box of 12 of its widths: most planes hold no solid, where the search passes
/// run farthest (M/2 + 1 steps a voxel, docs/gpu.md "The search passes").
TEST_F(CudaGridTest, DistancesOfADiluteSceneEqualTheCpuExactly) {
    const Packing one = testing::singleParticle(1.5, 0.5, 12.0, Vector3d(3.1, 4.2, 5.3));
    for (const int m : {97, 300})
        expectDistancesEqualTheCpu(one, m, "one superball in a box of 12 widths");
}

/// Largest |chi - chi_cpu| / chi_cpu over the shells.
double largestRelativeDifference(const ShellAverage& a, const ShellAverage& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(a.value[i] - b.value[i]) / std::abs(b.value[i]));
    return worst;
}

TEST_F(CudaGridTest, ChiAgreesWithTheCpu) {
    SpectralDensityParameters parameters;
    parameters.fft.planning = FftPlanning::Estimate;
    parameters.fft.wisdomFile.clear();
    for (const Case& c : kCases) {
        const Packing packing = storedPacking(c.file);
        const SpectralDensityResult cpu =
            SpectralDensity(parameters)
                .compute(packing, Voxelizer({c.voxels}).compute(packing, Progress()), Progress());
        const CudaGrid grid(packing, c.voxels);
        const SpectralDensityResult gpu =
            grid.spectralDensity(packing, parameters, false, nullptr, Progress()).chi;
        ASSERT_EQ(gpu.shells.count, cpu.shells.count);
        EXPECT_LE(largestRelativeDifference(gpu.shells, cpu.shells), 1e-10) << c.file;
        const SpectralDensityResult single =
            grid.spectralDensity(packing, parameters, true, nullptr, Progress()).chi;
        const double error = largestRelativeDifference(single.shells, cpu.shells);
        std::cout << "[ single precision ] " << c.file << " M " << c.voxels << ": largest relative "
                  << "error of chi over " << cpu.maxShell << " shells " << error
                  << ", double: " << largestRelativeDifference(gpu.shells, cpu.shells) << '\n';
        EXPECT_LE(error, 1e-3) << c.file;
    }
}

/// Largest |a_i - b_i| / max |b| over two equally long lists.
double largestDifferenceOverPeak(const std::vector<double>& a, const std::vector<double>& b) {
    double worst = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        worst = std::max(worst, std::abs(a[i] - b[i]));
        peak = std::max(peak, std::abs(b[i]));
    }
    return worst / peak;
}

TEST_F(CudaGridTest, HyperSpectrumAgreesWithTheCpu) {
    SpectralDensityParameters parameters;
    parameters.fft.planning = FftPlanning::Estimate;
    parameters.fft.wisdomFile.clear();
    const VoxelSpectrumOptions options;
    for (const Case& c : {kCases[0], kCases[2], kCases[4]}) {
        const Packing packing = storedPacking(c.file);
        const Voxelization voxels = Voxelizer({c.voxels}).compute(packing, Progress());
        const VoxelFourierTransform transform(voxels, parameters.fft, Progress());
        const double w = packing.shape().meanWidth();
        const DiscreteSpectrum cpu = voxelSpectrum(transform, voxels, w, options, Progress());
        const DiscreteSpectrum gpu =
            *CudaGrid(packing, c.voxels)
                 .spectralDensity(packing, parameters, false, &options, Progress())
                 .voxelSpectrum;
        ASSERT_EQ(gpu.sumByN2.size(), cpu.sumByN2.size());
        ASSERT_EQ(gpu.modes.chi.size(), cpu.modes.chi.size());
        EXPECT_LE(largestDifferenceOverPeak(gpu.sumByN2, cpu.sumByN2), 1e-10) << c.file;
        EXPECT_LE(largestDifferenceOverPeak(gpu.modes.chi, cpu.modes.chi), 1e-10) << c.file;
        EXPECT_NEAR(gpu.missingWeight, cpu.missingWeight, 1e-10) << c.file;
        EXPECT_EQ(gpu.phi, cpu.phi);
    }
}

TEST_F(CudaGridTest, PlanMatchesTheDevice) {
    std::string reason;
    const CudaDevice device = *probeCudaDevice(reason);
    const GpuMemoryPlan plan = planGpuMemory(500, 500, false, gpu::cuda::fftWorkBytes(500, false));
    EXPECT_NO_THROW(checkGpuMemory(plan, device.freeBytes, device.describe()));
    std::cout << "[ device ] " << device.describe() << ", plan at 500^3: peak "
              << plan.peakBytes / 1e9 << " GB\n";
}

} // namespace
} // namespace sbpack
