// The grid computations of --distribute grids over MPI (pipeline/distributed_grids.hpp,
// docs/scale-out.md): voxel slabs, chi_V by FFTW's MPI transform, the pore sizes by the
// distributed distance transform.
#include "mpi/distributed_distance_transform.hpp"
#include "mpi/mpi_communicator.hpp"

#include "spectral/fftw_wisdom.hpp"

#include <fftw3-mpi.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

/// fftw_mpi_init once, after the ThreadBudget's fftw_init_threads (FFTW's manual, "Combining
/// MPI and Threads").
void initFftwMpi() {
    static const bool ready = [] {
        fftw_mpi_init();
        return true;
    }();
    static_cast<void>(ready);
}

/// This rank's part of FFTW's transposed r2c transform of an M^3 grid.
struct FftSlab {
    ptrdiff_t complexCount = 0;   ///< fftw_complex numbers to allocate
    ptrdiff_t n0 = 0, start0 = 0; ///< x-planes of the real input
    ptrdiff_t n1 = 0, start1 = 0; ///< y-planes of the transposed output
};

FftSlab fftSlab(int m, MPI_Comm comm) {
    initFftwMpi();
    FftSlab s;
    s.complexCount = fftw_mpi_local_size_3d_transposed(m, m, m / 2 + 1, comm, &s.n0, &s.start0,
                                                       &s.n1, &s.start1);
    return s;
}

struct FreeFftw {
    void operator()(double* p) const { fftw_free(p); }
};
struct DestroyPlan {
    void operator()(fftw_plan_s* p) const { fftw_destroy_plan(p); }
};

/// Shell sums as bytes for the allGather (exact bit patterns).
std::string encodeSums(const std::vector<double>& sums) {
    return {reinterpret_cast<const char*>(sums.data()), sums.size() * sizeof(double)};
}
std::vector<double> decodeSums(const std::string& bytes) {
    std::vector<double> sums(bytes.size() / sizeof(double));
    std::memcpy(sums.data(), bytes.data(), sums.size() * sizeof(double));
    return sums;
}

/// The largest value over the ranks.
double largestOver(const Communicator& comm, double value) {
    comm.max(std::span<double>(&value, 1));
    return value;
}
double sumOver(const Communicator& comm, double value) {
    comm.sum(std::span<double>(&value, 1));
    return value;
}

class MpiGrids final : public DistributedGrids {
  public:
    explicit MpiGrids(const MpiCommunicator& comm) : comm_(comm) {}

    SlabVoxels voxelize(const Packing& packing, int voxels,
                        const Progress& progress) const override;
    SpectralDensityResult spectralDensity(const Packing& packing, const SlabVoxels& voxels,
                                          const SpectralDensityParameters& parameters,
                                          const Progress& progress,
                                          DistributionFigures& figures) const override;
    PoreSizeDistributionResult poreSizes(const Packing& packing, int voxels,
                                         const PoreSizeParameters& parameters, double meanWidth,
                                         const Progress& progress,
                                         DistributionFigures& figures) const override;

  private:
    /// Collective: this rank's voxelization of x-planes [begin, end) and the grid's solid count.
    SlabVoxels voxelizeSlab(const Packing& packing, int voxels, int begin, int end,
                            const Progress& progress) const;
    /// FFTW's plan of the transform of `data` by the planning policy (planWithinBudget,
    /// collective), with the wisdom file read on rank 0 and shared; `source` says which plan.
    fftw_plan_s* plan(int m, double* data, const FftSettings& fft, const Progress& progress,
                      FftPlanSource& source) const;

    const MpiCommunicator& comm_;
};

SlabVoxels MpiGrids::voxelizeSlab(const Packing& packing, int voxels, int begin, int end,
                                  const Progress& progress) const {
    std::unique_ptr<Voxelization> slab;
    collectively(comm_, [&] {
        slab = std::make_unique<Voxelization>(
            Voxelizer({voxels, begin, end}).compute(packing, progress));
    });
    SlabVoxels out{std::move(*slab), slab->solidCount(), {}};
    std::int64_t solid = out.solidCount;
    comm_.sum(std::span<std::int64_t>(&solid, 1));
    out.solidCount = solid;
    out.figures.ranks = comm_.size();
    out.figures.slab = static_cast<int>(largestOver(comm_, end - begin));
    out.figures.memoryPerRankBytes =
        largestOver(comm_, static_cast<double>(out.slab.memoryBytes()));
    return out;
}

SlabVoxels MpiGrids::voxelize(const Packing& packing, int voxels, const Progress& progress) const {
    const FftSlab s = fftSlab(voxels, comm_.comm());
    return voxelizeSlab(packing, voxels, static_cast<int>(s.start0),
                        static_cast<int>(s.start0 + s.n0), progress);
}

fftw_plan_s* MpiGrids::plan(int m, double* data, const FftSettings& fft, const Progress& progress,
                            FftPlanSource& source) const {
    if (comm_.rank() == 0) importWisdom(fft.wisdomFile, progress);
    fftw_mpi_broadcast_wisdom(comm_.comm());
    fftw_plan_s* p = nullptr;
    source = planWithinBudget(m, fft, true, [&](unsigned flags) {
        p = fftw_mpi_plan_dft_r2c_3d(m, m, m, data, reinterpret_cast<fftw_complex*>(data),
                                     comm_.comm(), flags | FFTW_MPI_TRANSPOSED_OUT);
        return p != nullptr;
    });
    fftw_mpi_gather_wisdom(comm_.comm());
    if (comm_.rank() == 0 && fft.planning != FftPlanning::Estimate)
        exportWisdom(fft.wisdomFile, progress);
    return p;
}

SpectralDensityResult MpiGrids::spectralDensity(const Packing& packing, const SlabVoxels& voxels,
                                                const SpectralDensityParameters& parameters,
                                                const Progress& progress,
                                                DistributionFigures& figures) const {
    const int m = voxels.slab.voxels();
    const FftSlab s = fftSlab(m, comm_.comm());
    const SpectralDensity chi(parameters);
    SpectralDensityResult result = chi.start(packing, m, voxels.phiVoxel());
    std::unique_ptr<double, FreeFftw> data;
    collectively(comm_, [&] {
        data.reset(fftw_alloc_real(2 * static_cast<std::size_t>(s.complexCount)));
        if (!data) throw std::bad_alloc();
    });
    Stopwatch clock;
    const std::unique_ptr<fftw_plan_s, DestroyPlan> transform(
        plan(m, data.get(), parameters.fft, progress, result.planSource));
    result.planSeconds = clock.seconds();
    clock = Stopwatch();
    const std::int64_t rowStride = 2 * (m / 2 + 1);
    collectively(comm_, [&] {
        voxels.slab.copySolidIndicator(std::span<double>(data.get(), s.n0 * m * rowStride),
                                       rowStride, progress);
        progress.checkInterrupt();
    });
    result.fillSeconds = clock.seconds();
    clock = Stopwatch();
    fftw_execute(transform.get());
    result.transformSeconds = clock.seconds();
    clock = Stopwatch();
    ShellAccumulator shells(packing.boxLength, result.maxShell);
    collectively(comm_, [&] {
        const SpectrumSlab slab{
            data.get(), m,        static_cast<int>(s.start1), static_cast<int>(s.start1 + s.n1),
            m,          m / 2 + 1};
        shells =
            spectralShellSums(slab, result.voxelSize, packing.boxLength, result.maxShell, progress);
    });
    ShellAccumulator merged(packing.boxLength, result.maxShell);
    for (const std::string& bytes : comm_.allGather(encodeSums(shells.sums())))
        merged.mergeSums(decodeSums(bytes)); // in rank order: the same on every rank
    result.shellSeconds = clock.seconds();
    result.runtimeSeconds =
        result.planSeconds + result.fillSeconds + result.transformSeconds + result.shellSeconds;
    chi.finish(packing, merged.average(), progress, result);
    const int half = m / 2 + 1; // complex numbers per row
    figures = {
        comm_.size(), static_cast<int>(largestOver(comm_, static_cast<double>(s.n0))),
        largestOver(comm_, 16.0 * static_cast<double>(s.complexCount) +
                               static_cast<double>(voxels.slab.memoryBytes())),
        sumOver(comm_, 16.0 * static_cast<double>(s.n0) * static_cast<double>(m - s.n1) * half)};
    return result;
}

PoreSizeDistributionResult MpiGrids::poreSizes(const Packing& packing, int voxels,
                                               const PoreSizeParameters& parameters,
                                               double meanWidth, const Progress& progress,
                                               DistributionFigures& figures) const {
    const Stopwatch clock;
    const int m = voxels;
    const Slab x = slabOf(m, comm_.size(), comm_.rank());
    std::vector<std::uint8_t> mask;
    double treeBytes = 0.0;
    std::int64_t solid = 0;
    {
        const SlabVoxels slab = voxelizeSlab(packing, m, x.begin, x.end, progress);
        collectively(comm_, [&] {
            mask.resize(static_cast<std::size_t>(x.size()) * m * m);
            slab.slab.copySolidMask(mask, progress);
        });
        treeBytes = static_cast<double>(slab.slab.memoryBytes());
        solid = slab.solidCount;
    }
    const std::int64_t total = std::int64_t{m} * m * m;
    if (solid == 0 || solid == total)
        throw std::domain_error("pore sizes: no " + std::string(solid == 0 ? "solid" : "void") +
                                " voxel at M = " + std::to_string(m) +
                                "; the pore sizes are undefined: use a larger M or check the "
                                "packing");
    const DistanceSlab map = distributedDistanceTransform(comm_, mask, m, progress);
    mask = {};
    std::vector<std::int64_t> histogram(static_cast<std::size_t>(map.largest) + 1, 0);
    for (std::uint32_t d : map.squared)
        ++histogram[d];
    comm_.sum(std::span<std::int64_t>(histogram));
    PoreSizeDistributionResult r =
        PoreSizeDistribution(parameters)
            .fromHistogram(histogram, m, packing.boxLength / m, meanWidth);
    r.runtimeSeconds = clock.seconds();
    figures = {
        comm_.size(), static_cast<int>(largestOver(comm_, x.size())),
        largestOver(comm_, std::max(map.peakBytes,
                                    5.0 * static_cast<double>(x.size()) * m * m + treeBytes)),
        sumOver(comm_, map.sentBytes)};
    return r;
}

} // namespace

std::unique_ptr<DistributedGrids> makeMpiGrids(const MpiCommunicator& comm) {
    return std::make_unique<MpiGrids>(comm);
}

} // namespace sbpack
