#include "spectral/voxel_fourier_transform.hpp"

#include <fftw3.h>
#include <sys/mman.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <new>
#include <span>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

struct PlanDeleter {
    void operator()(fftw_plan_s* plan) const { fftw_destroy_plan(plan); }
};
using Plan = std::unique_ptr<fftw_plan_s, PlanDeleter>;

/// The plan of an in-place M^3 r2c transform of `data`, by the planning policy
/// (planWithinBudget). FFTW_MEASURE overwrites the array.
Plan planTransform(int m, double* data, const FftSettings& fft, FftPlanSource& source) {
    Plan p;
    source = planWithinBudget(m, fft, false, [&](unsigned flags) {
        p.reset(fftw_plan_dft_r2c_3d(m, m, m, data, reinterpret_cast<fftw_complex*>(data), flags));
        return p != nullptr;
    });
    return p;
}

} // namespace

void VoxelFourierTransform::Free::operator()(double* p) const {
    std::free(p);
}

double VoxelFourierTransform::memoryBytes(int voxels) {
    const double m = voxels;
    return m * m * (std::floor(m / 2) + 1) * 2.0 * sizeof(double);
}

VoxelFourierTransform::VoxelFourierTransform(const Voxelization& voxels, const FftSettings& fft,
                                             const Progress& progress)
    : voxels_(voxels.voxels()), halfLength_(voxels.voxels() / 2 + 1) {
    const std::int64_t m = voxels_;
    const std::int64_t rowStride = 2 * std::int64_t{halfLength_}; // padded real row
    const std::size_t size = static_cast<std::size_t>(m * m * rowStride);
    // Aligned to 2 MiB and marked for transparent huge pages: filling a fresh grid of hundreds
    // of MB otherwise costs one page fault per 4 kB, and the transform many TLB misses.
    constexpr std::size_t kHugePage = std::size_t{1} << 21;
    const std::size_t bytes = (size * sizeof(double) + kHugePage - 1) / kHugePage * kHugePage;
    data_.reset(static_cast<double*>(std::aligned_alloc(kHugePage, bytes)));
    if (!data_) throw std::bad_alloc();
    ::madvise(data_.get(), bytes, MADV_HUGEPAGE); // advice only: failure is harmless
    double* data = data_.get();

    // Plan first: FFTW_MEASURE overwrites the array while it measures.
    Stopwatch clock;
    importWisdom(fft.wisdomFile, progress);
    const Plan plan = planTransform(voxels_, data, fft, planSource_);
    if (!plan)
        throw std::runtime_error("FFTW: cannot plan a " + std::to_string(m) + "^3 transform");
    if (planSource_ == FftPlanSource::Measured || planSource_ == FftPlanSource::MeasuredBudget)
        exportWisdom(fft.wisdomFile, progress);
    planSeconds_ = clock.seconds();

    clock = Stopwatch();
    voxels.copySolidIndicator(std::span<double>(data, size), rowStride, progress);
    fillSeconds_ = clock.seconds();
    progress.checkInterrupt();

    clock = Stopwatch();
    fftw_execute(plan.get());
    transformSeconds_ = clock.seconds();
}

} // namespace sbpack
