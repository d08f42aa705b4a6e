#pragma once
// Spectral density chi_V(Q) of the particle phase (paper Eq. 12, eq:spD, with the cube form
// factor, docs/design.md §5): from the voxel indicator by FFT, and for spheres exactly from the
// centroids.

#include "packing/packing.hpp"
#include "progress/progress.hpp"
#include "shells/shell_average.hpp"
#include "spectral/fftw_wisdom.hpp"
#include "spectral/voxel_fourier_transform.hpp"
#include "structure/structure_factor.hpp"
#include "voxels/voxelization.hpp"

#include <Eigen/Core>

#include <optional>

namespace sbpack {

/// Form factor of a cube of edge a centred at the origin: prod_i a sinc(Q_i a / 2).
double cubeFormFactor(const Eigen::Vector3d& q, double edge);
/// Form factor of a sphere of radius R: m(Q) = 4 pi (sin QR - QR cos QR) / Q^3 (4 pi R^3 / 3 at 0).
double sphereFormFactor(double q, double radius);

struct SpectralDensityParameters {
    /// Shells up to Q w <= maxQw (w the mean width), and below the grid's Nyquist limit; by
    /// default S(Q)'s range, as --qmax sets both.
    double maxQw = StructureFactorParameters{}.maxQw;
    FftSettings fft;
};

/// The voxel path against the exact one, for spheres.
struct SphereComparison {
    ShellAverage exact; ///< chi from the centroids and the sphere form factor, same shells
    /// max over shells of |chi_voxel - chi_exact|, over max over shells of chi_exact.
    double maxErrorOverPeak = 0.0;
};

struct SpectralDensityResult {
    SpectralDensityParameters parameters;
    int voxels = 0;
    double voxelSize = 0.0;
    double phiVoxel = 0.0;
    double boxLength = 0.0;
    double meanWidth = 0.0;
    int maxShell = 0;
    /// Q, chi_V(Q) (value, length^3) and the number of wave vectors per shell.
    ShellAverage shells;
    /// Present for spheres (p = 1).
    std::optional<SphereComparison> exactSphere;
    /// Where the time went: FFTW planning, filling the grid with the indicator, the transform,
    /// the shell average, and the exact sphere path (0 unless p = 1); runtimeSeconds is all.
    double planSeconds = 0.0;
    /// Where the FFT plan came from (the MPI transform: estimate or measured, no budget).
    FftPlanSource planSource = FftPlanSource::Estimate;
    double fillSeconds = 0.0;
    double transformSeconds = 0.0;
    double shellSeconds = 0.0;
    double exactSeconds = 0.0;
    double runtimeSeconds = 0.0;
};

/// The wave vectors of a real-to-complex transform of an M^3 grid, or of one slab of it: planes
/// [outerBegin, outerEnd) of the outer index, coefficient (outer, inner, kz) interleaved at
/// (((outer - outerBegin) rows + inner) rowLength + kz) 2. The whole transform has outer = kx,
/// inner = ky, rows = M and rowLength = M/2 + 1; a rank of FFTW's MPI transform with transposed
/// output outer = ky, inner = kx (docs/scale-out.md). Eq. 12 is symmetric in the two, so one
/// shell sum serves both. A compact cube of the low wave vectors (the GPU's, gpu/cuda_grid.hpp)
/// has rows = 2s + 1 outer and inner indices, the signed index n at n mod rows, and rowLength
/// s + 1: the index period is `rows`, the voxels' form factors those of M.
struct SpectrumSlab {
    const double* data;
    int voxels;
    int outerBegin, outerEnd;
    int rows, rowLength;
};

/// The shell sums of Eq. 12 over the wave vectors of `slab`, shells 1..maxShell: |F|^2
/// [prod_i a sinc(Q_i a / 2)]^2 / V over the half space kz <= M/2 with its weights. Each outer
/// plane sums into its own accumulator, merged in order (independent of the threads).
ShellAccumulator spectralShellSums(const SpectrumSlab& slab, double voxelSize, double boxLength,
                                   int maxShell, const Progress& progress);

/// Compute object (docs/design.md §7): parameters validated at construction.
class SpectralDensity {
  public:
    /// Throws std::invalid_argument unless 0 < maxQw < inf.
    explicit SpectralDensity(SpectralDensityParameters parameters);

    /// Largest shell with Q w <= maxQw that the grid resolves without aliasing: also
    /// |n| < maxShell + 1/2 <= M / 2.
    static int maxShellFor(double maxQw, double boxLength, double meanWidth, int voxels);
    /// Memory of compute() beyond the voxelization (bytes): the FFT grid.
    static double memoryEstimateBytes(int voxels);

    /// chi_V(Q) = |F(k)|^2 [prod_i a sinc(Q_i a / 2)]^2 / V at Q = 2 pi n / L, n = k mod M,
    /// 0 < |n| < maxShell + 1/2: Eq. 12 applied to the voxels, each a cube of edge a; F is the
    /// DFT of the indicator (VoxelFourierTransform). Shell-averaged over the half space kept by
    /// the real-to-complex transform with its weights. For spheres also the exact path
    /// (sphereSpectralDensity) on the same shells. Throws std::invalid_argument if the
    /// voxelization is not of this packing's box or maxQw admits no shell.
    SpectralDensityResult compute(const Packing& packing, const Voxelization& voxels,
                                  const Progress& progress) const;
    /// The same from a transform of these voxels made by the caller (who may use it for more,
    /// e.g. the hyperuniformity analysis's wave-vector spectrum): no second FFT.
    SpectralDensityResult compute(const Packing& packing, const Voxelization& voxels,
                                  const VoxelFourierTransform& transform,
                                  const Progress& progress) const;

    /// The parts of compute() around the shell sums, for a distributed transform: start() fills
    /// the grid's figures and maxShell (std::invalid_argument when no shell fits), finish() takes
    /// the shells and adds the exact sphere path and the runtime.
    SpectralDensityResult start(const Packing& packing, int voxels, double phiVoxel) const;
    void finish(const Packing& packing, ShellAverage shells, const Progress& progress,
                SpectralDensityResult& result) const;

    const SpectralDensityParameters& parameters() const { return parameters_; }

  private:
    SpectralDensityParameters parameters_;
};

/// Exact chi_V(Q) of a sphere packing without voxels (Eq. 12 with the sphere's form factor):
/// |sum_j exp(-i Q.r_j)|^2 m(Q)^2 / V, shells 1..maxShell, by the collective-density kernel of
/// S(Q). Throws std::invalid_argument unless the packing is of spheres and maxShell >= 1.
ShellAverage sphereSpectralDensity(const Packing& packing, int maxShell, const Progress& progress);

} // namespace sbpack
