// The host-and-device arithmetic of the grids (analysis/grid/), the GPU kernels' per-thread code,
// run on the host against the CPU path, and the host side of --device cuda (analysis/gpu/): what
// can be tested without a GPU (docs/gpu.md).
#include "gpu/compact_cube.hpp"
#include "gpu/compute_device.hpp"
#include "gpu/gpu_memory.hpp"
#include "gpu/particle_images.hpp"
#include "grid/distance_lines.hpp"
#include "grid/voxel_rows.hpp"
#include "hyperuniformity/discrete_spectrum.hpp"
#include "io/packing_io.hpp"
#include "pipeline/run_settings.hpp"
#include "pores/distance_transform.hpp"
#include "spectral/spectral_density.hpp"
#include "spectral/voxel_fourier_transform.hpp"
#include "test_packings.hpp"
#include "voxels/voxelization.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

namespace sbpack {
namespace {

using grid::kNoSite;

/// The voxel words of a packing as the kernel voxelizeImages makes them, on the host.
std::vector<std::uint32_t> hostVoxelWords(const Packing& packing, int m) {
    const grid::VoxelGeometry g = gpu::voxelGeometry(packing, m);
    std::vector<std::uint32_t> words(static_cast<std::size_t>(m) * m * grid::wordsPerRow(m), 0);
    for (const grid::ParticleImage& image : gpu::particleImages(packing)) {
        const grid::ImageRows rows = grid::imageRows(image, g);
        for (int r = 0; r < rows.count(); ++r)
            grid::imageRow(
                image, rows.xOf(r), rows.yOf(r), g,
                [&words](std::int64_t word, std::uint32_t bits) { words[word] |= bits; });
    }
    return words;
}

std::vector<std::uint8_t> maskOfWords(const std::vector<std::uint32_t>& words, int m) {
    const std::int64_t w = grid::wordsPerRow(m);
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m);
    for (std::int64_t row = 0; row < std::int64_t{m} * m; ++row)
        for (int k = 0; k < m; ++k)
            mask[row * m + k] = (words[row * w + k / 32] >> (k % 32)) & 1u;
    return mask;
}

std::vector<std::uint32_t> wordsOfMask(const std::vector<std::uint8_t>& mask, int m) {
    const std::int64_t w = grid::wordsPerRow(m);
    std::vector<std::uint32_t> words(static_cast<std::size_t>(m) * m * w, 0);
    for (std::int64_t row = 0; row < std::int64_t{m} * m; ++row)
        for (int k = 0; k < m; ++k)
            if (mask[row * m + k] != 0) words[row * w + k / 32] |= 1u << (k % 32);
    return words;
}

/// The kernels rowPass and searchPass (along y, then x) on the host, one voxel at a time.
std::vector<std::uint32_t> hostSquaredDistances(const std::vector<std::uint32_t>& words, int m) {
    const std::int64_t mm = m, w = grid::wordsPerRow(m);
    std::vector<std::uint32_t> d(static_cast<std::size_t>(mm * mm * mm));
    for (std::int64_t row = 0; row < mm * mm; ++row)
        grid::rowDistances(words.data() + row * w, m, d.data() + row * mm);
    std::vector<std::uint32_t> e(d.size()); // the kernels' second buffer: d -> e -> d
    auto pass = [m, mm](const std::vector<std::uint32_t>& in, std::vector<std::uint32_t>& out,
                        std::int64_t stride) {
        for (std::int64_t i = 0; i < mm * mm * mm; ++i)
            out[i] = grid::searchedMinimumAt(in.data(), i, m, stride);
    };
    pass(d, e, mm);      // along y
    pass(e, d, mm * mm); // along x
    return d;
}

std::vector<std::uint8_t> cpuMask(const Packing& packing, int m) {
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m);
    Voxelizer({m}).compute(packing, Progress()).copySolidMask(mask);
    return mask;
}

Packing storedPacking(const char* name) {
    return readPacking(std::string(SBPACK_DATA_DIR) + "/" + name);
}

TEST(GridKernels, ImageRowsVoxeliseAsTheCpu) {
    for (double p : {0.5, 0.75, 1.0, 1.5, 3.0, 10.0}) {
        const double spacing = 2.0 * Superball(p, 0.5).circumradius() + 0.3;
        const Packing packing = testing::latticePacking(p, 3, spacing, 0.1, 7);
        for (int m : {Voxelizer::minimumVoxels(packing), 64}) {
            const std::vector<std::uint8_t> expected = cpuMask(packing, m);
            EXPECT_EQ(maskOfWords(hostVoxelWords(packing, m), m), expected)
                << "p " << p << " M " << m;
        }
    }
    const Packing mrj = storedPacking("mrj-p1.5-1000.h5");
    EXPECT_EQ(maskOfWords(hostVoxelWords(mrj, 90), 90), cpuMask(mrj, 90));
}

/// The GPU's bits become the CPU's OpenVDB tree (the --vdb export of --device cuda).
TEST(GridKernels, RowBitsMakeTheVoxelisersTree) {
    for (double p : {1.0, 3.0}) {
        const double spacing = 2.0 * Superball(p, 0.5).circumradius() + 0.3;
        const Packing packing = testing::latticePacking(p, 3, spacing, 0.1, 9);
        for (int m : {43, 64}) { // a partial block at the edge, and none
            const Voxelization cpu = Voxelizer({m}).compute(packing, Progress());
            const Voxelization gpu =
                Voxelizer::fromRowBits(hostVoxelWords(packing, m), packing, m, 0.0);
            std::vector<std::uint8_t> a(static_cast<std::size_t>(m) * m * m), b(a.size());
            cpu.copySolidMask(a);
            gpu.copySolidMask(b);
            EXPECT_EQ(a, b) << "p " << p << " M " << m;
            EXPECT_EQ(gpu.solidCount(), cpu.solidCount());
            EXPECT_EQ(gpu.memoryBytes(), cpu.memoryBytes()); // the same leaves and tiles
        }
    }
    EXPECT_THROW(Voxelizer::fromRowBits(std::vector<std::uint32_t>(10), Packing{}, 4, 0.0),
                 std::invalid_argument);
}

TEST(GridKernels, RowDistancesWrapAroundTheBox) {
    std::uint32_t word = 1u; // one solid voxel at z = 0 of a row of 10
    std::vector<std::uint32_t> out(10);
    grid::rowDistances(&word, 10, out.data());
    EXPECT_EQ(out, (std::vector<std::uint32_t>{0, 1, 4, 9, 16, 25, 16, 9, 4, 1}));
    word = 0u;
    grid::rowDistances(&word, 10, out.data());
    EXPECT_EQ(out, std::vector<std::uint32_t>(10, kNoSite));
}

TEST(GridKernels, SearchedMinimumIsTheBruteForceMinimum) {
    std::mt19937_64 rng(3);
    for (int m : {1, 2, 3, 8, 17, 64, 201}) {
        for (int trial = 0; trial < 200; ++trial) {
            // Sparse lines too (most voxels without a site), where the search runs farthest.
            const unsigned noSite = trial % 2 == 0 ? 3 : 40;
            std::vector<std::uint32_t> f(m);
            for (auto& v : f)
                v = rng() % noSite != 0 ? kNoSite
                                        : static_cast<std::uint32_t>(rng() % (3 * m * m + 1));
            for (int p = 0; p < m; ++p) {
                std::uint32_t expected = kNoSite;
                for (int q = 0; q < m; ++q) {
                    if (f[q] == kNoSite) continue;
                    const std::int64_t d = std::min(std::abs(p - q), m - std::abs(p - q));
                    expected = std::min<std::uint32_t>(expected, f[q] + d * d);
                }
                ASSERT_EQ(grid::searchedMinimum(f.data(), 1, m, p), expected)
                    << "M " << m << " trial " << trial << " voxel " << p;
            }
        }
    }
}

TEST(GridKernels, DistancePassesEqualTheCpuTransform) {
    std::mt19937_64 rng(11);
    for (int m : {2, 5, 16, 31, 40}) {
        for (double solidFraction : {0.5, 0.05, 0.002}) {
            std::vector<std::uint8_t> mask(static_cast<std::size_t>(m) * m * m);
            for (auto& v : mask)
                v = std::uniform_real_distribution<double>()(rng) < solidFraction;
            mask.front() = 1; // at least one solid and one void voxel
            mask.back() = 0;
            const PoreSizeMap cpu = periodicDistanceTransform(mask, m, 1.0);
            const std::vector<std::uint32_t> expected(cpu.squaredDistances().begin(),
                                                      cpu.squaredDistances().end());
            ASSERT_EQ(hostSquaredDistances(wordsOfMask(mask, m), m), expected)
                << "M " << m << " solid fraction " << solidFraction;
        }
    }
    const Packing mrj = storedPacking("mrj-p1.5-1000.h5");
    const std::vector<std::uint8_t> mask = cpuMask(mrj, 70);
    const PoreSizeMap cpu = periodicDistanceTransform(mask, 70, mrj.boxLength / 70);
    EXPECT_EQ(
        hostSquaredDistances(wordsOfMask(mask, 70), 70),
        std::vector<std::uint32_t>(cpu.squaredDistances().begin(), cpu.squaredDistances().end()));
}

/// The GPU's compact cube of low wave vectors (cuda_kernels.hpp, gatherCube), made here from the
/// CPU's transform.
std::vector<double> compactCube(const VoxelFourierTransform& transform, int s) {
    const int m = transform.voxels(), rows = 2 * s + 1;
    std::vector<double> cube;
    for (int ox = 0; ox < rows; ++ox)
        for (int oy = 0; oy < rows; ++oy)
            for (int kz = 0; kz <= s; ++kz) {
                const int nx = ox <= s ? ox : ox - rows, ny = oy <= s ? oy : oy - rows;
                const std::complex<double> c =
                    transform.coefficient((nx + m) % m, (ny + m) % m, kz);
                cube.push_back(c.real());
                cube.push_back(c.imag());
            }
    return cube;
}

/// The cube gives the whole grid's shells bit for bit (the same coefficients added in the same
/// order), and the voxel spectrum's single wave vectors bit for bit.
TEST(GridKernels, CompactCubeGivesTheWholeGridsShellsAndModes) {
    const Packing packing = testing::latticePacking(1.5, 3, 2.0, 0.15, 5);
    const int m = 36, s = 15; // s^2 >= the single wave vectors' largest |n|^2 (182)
    const Voxelization voxels = Voxelizer({m}).compute(packing, Progress());
    FftSettings fft;
    fft.planning = FftPlanning::Estimate;
    fft.wisdomFile.clear();
    const VoxelFourierTransform transform(voxels, fft, Progress());
    const std::vector<double> cube = compactCube(transform, s);
    const double a = voxels.voxelSize(), l = packing.boxLength;
    Progress inOrder;
    inOrder.setSerial(true);
    const ShellAverage whole =
        spectralShellSums({transform.data(), m, 0, m, m, m / 2 + 1}, a, l, s, inOrder).average();
    const ShellAverage compact =
        spectralShellSums(gpu::compactCubeSlab(cube, m, s), a, l, s, inOrder).average();
    EXPECT_EQ(compact.value, whole.value);
    EXPECT_EQ(compact.count, whole.count);
    EXPECT_EQ(compact.q, whole.q);

    const double w = packing.shape().meanWidth();
    const VoxelSpectrumOptions options;
    const std::int64_t reach2 = individualMaxN2(m, l, w, options);
    ASSERT_GT(reach2, 10);
    ASSERT_LE(reach2, std::int64_t{s} * s);
    const DiscreteSpectrum cpu = voxelSpectrum(transform, voxels, w, options, Progress());
    const DiscreteSpectrum fromCube = voxelSpectrumFrom(
        cpu.sumByN2, gpu::compactCubePower(cube, m, s), {m, l, voxels.phiVoxel()}, w, options);
    EXPECT_EQ(fromCube.modes.chi, cpu.modes.chi);
    EXPECT_EQ(fromCube.missingWeight, cpu.missingWeight);
    EXPECT_EQ(fromCube.cutoffQ, cpu.cutoffQ);
}

TEST(GpuMemory, PlanAddsTheGrids) {
    constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
    EXPECT_EQ(gpuVoxelBytes(500), 500.0 * 500 * 16 * 4);
    EXPECT_EQ(gpuFftGridBytes(500, false), 500.0 * 500 * 251 * 16);
    EXPECT_EQ(gpuFftGridBytes(500, true), 500.0 * 500 * 251 * 8);
    const auto big = static_cast<std::size_t>(80 * kGiB);
    const GpuMemoryPlan plan = planGpuMemory(500, 500, false, 1000);
    EXPECT_EQ(plan.spectralBytes, gpuVoxelBytes(500) + gpuFftGridBytes(500, false) + 1000);
    EXPECT_EQ(plan.poreBytes, gpuVoxelBytes(500) + 2 * 500.0 * 500 * 500 * 4);
    EXPECT_EQ(plan.peakBytes, std::max(plan.spectralBytes, gpuVoxelBytes(500) + plan.poreBytes));
    EXPECT_NO_THROW(checkGpuMemory(plan, big, "test GPU"));
    // A small device: a refusal naming the sizes and the options.
    const GpuMemoryPlan small = planGpuMemory(0, 500, false, 0);
    try {
        checkGpuMemory(small, static_cast<std::size_t>(0.1 * kGiB), "test GPU");
        FAIL() << "no refusal";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("0.10 GiB free"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("--pore-voxels"), std::string::npos) << e.what();
    }
}

TEST(ComputeDevice, RefinedPoresKeepAutoOnTheGpuAndRefuseCuda) {
    // Refined pore sizes (the default) run on the CPU beside the GPU's grids under auto; cuda,
    // which asks for every grid on the GPU, refuses them and names the way out.
    RunSettings s;
    s.analyses = {Analysis::PoreSizes, Analysis::SpectralDensity};
    s.pores.method = PoreMethod::Refined;
    EXPECT_EQ(s.cpuOnlyReason(), "");
    EXPECT_NE(s.cudaRefusal().find("--pores voxel"), std::string::npos) << s.cudaRefusal();
    s.pores.method = PoreMethod::Voxel;
    EXPECT_EQ(s.cudaRefusal(), "");
    s.distribute = Distribution::Grids; // the whole run stays on the CPU, auto or not
    EXPECT_NE(s.cpuOnlyReason(), "");
    EXPECT_EQ(s.cudaRefusal(), s.cpuOnlyReason());
}

TEST(ComputeDevice, NamesAndRefusals) {
    EXPECT_EQ(computeDeviceFromName("cpu"), ComputeDevice::Cpu);
    EXPECT_EQ(computeDeviceFromName("cuda"), ComputeDevice::Cuda);
    EXPECT_EQ(computeDeviceFromName("auto"), ComputeDevice::Auto);
    EXPECT_THROW(computeDeviceFromName("gpu"), std::invalid_argument);
    EXPECT_EQ(resolveComputeDevice(ComputeDevice::Cpu, "").description(), "cpu");
    // An analysis the GPU does not run keeps auto on the CPU and refuses cuda, naming it.
    EXPECT_EQ(resolveComputeDevice(ComputeDevice::Auto, "hyper needs it").device,
              ComputeDevice::Cpu);
    try {
        resolveComputeDevice(ComputeDevice::Cuda, "hyper needs it");
        FAIL() << "no refusal";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("--device cuda: hyper needs it"), std::string::npos);
    }
    std::string reason;
    if (probeCudaDevice(reason)) GTEST_SKIP() << "a CUDA device is present: nothing refused";
    EXPECT_FALSE(reason.empty());
    if (!builtWithCuda()) {
        EXPECT_NE(reason.find("SBPACK_WITH_CUDA=ON"), std::string::npos);
    }
    EXPECT_EQ(resolveComputeDevice(ComputeDevice::Auto, "").device, ComputeDevice::Cpu);
    EXPECT_THROW(resolveComputeDevice(ComputeDevice::Cuda, ""), std::invalid_argument);
}

} // namespace
} // namespace sbpack
