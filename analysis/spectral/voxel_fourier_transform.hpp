#pragma once
// Discrete Fourier transform of the voxel indicator, F(k) = sum_v I_v exp(-2 pi i k.v / M)
// over the M^3 voxels v (I_v = 1 solid, 0 void), by FFTW's threaded in-place real-to-complex
// transform: k_x, k_y in [0, M), k_z in [0, M/2] (F(-k) is the conjugate of F(k)).

#include "spectral/fftw_wisdom.hpp"
#include "voxels/voxelization.hpp"

#include <complex>
#include <cstdint>
#include <memory>

namespace sbpack {

class VoxelFourierTransform {
  public:
    /// Plans (with the wisdom of fft.wisdomFile; without a plan there, measuring within
    /// fft.planningBudget), fills the indicator and transforms. FFTW uses the threads of the
    /// current ThreadBudget. Throws std::bad_alloc if the grid cannot be
    /// allocated and std::runtime_error if FFTW cannot plan.
    VoxelFourierTransform(const Voxelization& voxels, const FftSettings& fft,
                          const Progress& progress);
    VoxelFourierTransform(VoxelFourierTransform&&) noexcept = default;
    ~VoxelFourierTransform() = default;

    int voxels() const { return voxels_; }
    /// F(k) for 0 <= kx, ky < M and 0 <= kz <= M / 2.
    std::complex<double> coefficient(int kx, int ky, int kz) const {
        const std::int64_t i = ((std::int64_t{kx} * voxels_ + ky) * halfLength_ + kz) * 2;
        return {data_.get()[i], data_.get()[i + 1]};
    }
    /// The coefficients, interleaved (re, im), at ((kx M + ky) (M/2 + 1) + kz) 2.
    const double* data() const { return data_.get(); }
    /// |F(k)|^2.
    double power(int kx, int ky, int kz) const { return std::norm(coefficient(kx, ky, kz)); }
    /// How many wave vectors (k, -k) the stored kz stands for: 1 on the planes kz = 0 and
    /// kz = M / 2 (M even), which hold both, else 2.
    int weight(int kz) const { return kz == 0 || 2 * kz == voxels_ ? 1 : 2; }

    /// Memory of the transform (bytes): M x M x (M/2 + 1) complex numbers.
    static double memoryBytes(int voxels);

    double planSeconds() const { return planSeconds_; }
    FftPlanSource planSource() const { return planSource_; }
    double fillSeconds() const { return fillSeconds_; }
    double transformSeconds() const { return transformSeconds_; }

  private:
    struct Free {
        void operator()(double* p) const;
    };
    int voxels_;
    int halfLength_; ///< M / 2 + 1 complex numbers per row
    std::unique_ptr<double, Free> data_;
    double planSeconds_ = 0.0, fillSeconds_ = 0.0, transformSeconds_ = 0.0;
    FftPlanSource planSource_ = FftPlanSource::Estimate;
};

} // namespace sbpack
