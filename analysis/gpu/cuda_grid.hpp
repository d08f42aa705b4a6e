#pragma once
// A packing's voxel grid on the GPU (SBPACK_WITH_CUDA builds; docs/gpu.md): voxelised there,
// transformed there (chi_V, paper Eq. 12) and distance-transformed there (pore sizes, Eq. 13);
// only the shell sums' coefficients and the squared distances come back to the host. Each result
// is the CPU path's: the same voxels bit for bit, the same integer distances, chi_V to rounding.

#include "gpu/cuda_kernels.hpp"
#include "hyperuniformity/discrete_spectrum.hpp"
#include "packing/packing.hpp"
#include "pores/distance_transform.hpp"
#include "progress/progress.hpp"
#include "spectral/spectral_density.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace sbpack {

class CudaGrid {
  public:
    /// Voxelises `packing` on M^3 voxels as Voxelizer does (Voxelizer::checkResolution first:
    /// VoxelResolutionError for too coarse a grid); std::runtime_error from CUDA.
    CudaGrid(const Packing& packing, int voxels);

    int voxels() const { return voxels_; }
    double voxelSize() const { return boxLength_ / voxels_; }
    std::int64_t solidCount() const { return solidCount_; }
    double phiVoxel() const;
    double runtimeSeconds() const { return runtimeSeconds_; }
    /// Device memory of the voxel bits.
    std::size_t deviceBytes() const { return words_.bytes(); }

    /// The voxel bits on the host (grid/voxel_rows.hpp's rows), e.g. for Voxelizer::fromRowBits.
    std::vector<std::uint32_t> rowBits() const;

    /// chi_V(Q) as SpectralDensity::compute, the indicator transformed by cuFFT (single
    /// precision when `single`); fillSeconds and transformSeconds are the device's. With
    /// `spectrum`, also the voxel spectrum of the hyperuniformity analysis, as voxelSpectrum
    /// (hyperuniformity/discrete_spectrum.hpp) with those options: the sums per |n|^2 made on
    /// the device, the single wave vectors read from the gathered cube.
    struct Spectra {
        SpectralDensityResult chi;
        std::optional<DiscreteSpectrum> voxelSpectrum;
    };
    Spectra spectralDensity(const Packing& packing, const SpectralDensityParameters& parameters,
                            bool single, const VoxelSpectrumOptions* spectrum,
                            const Progress& progress) const;

    /// The exact periodic distance transform, as periodicDistanceTransform (std::domain_error
    /// when no voxel is solid or none void), with the seconds spent on the device and on the
    /// copy to the host.
    struct TimedPoreSizeMap {
        PoreSizeMap map;
        double deviceSeconds = 0.0, copySeconds = 0.0;
    };
    TimedPoreSizeMap poreSizeMap() const;
    /// The counts of each squared distance 0 .. max (voxel units; 0: the solid voxels) of that
    /// transform, counted on the device: all F(delta) needs when nothing asks for the map
    /// (PoreSizeDistribution::fromHistogram), without its 4 M^3 bytes' copy to the host.
    std::vector<std::int64_t> poreHistogram() const;

  private:
    int voxels_;
    double boxLength_;
    gpu::cuda::DeviceBuffer words_;
    std::int64_t solidCount_ = 0;
    double runtimeSeconds_ = 0.0;
};

} // namespace sbpack
