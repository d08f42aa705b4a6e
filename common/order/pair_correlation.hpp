#pragma once
// Pair correlation function g2(r) of the particle centroids (docs/order-metrics.md §1) and the
// first minimum after its main peak, the neighbour cutoff of order/neighbour_bonds.hpp.

#include "packing/packing.hpp"

#include <cstdint>
#include <vector>

namespace sbpack {

struct PairCorrelationParameters {
    /// Largest distance r_max / w, w the mean width (docs/design.md §5: report r / w); r_max must
    /// not exceed L / 2.
    double maxDistance = 3.0;
    /// Bin width dr / w; the bins cover [0, n dr), n = floor(r_max / dr).
    double binWidth = 0.02;
};

struct PairCorrelationResult {
    PairCorrelationParameters parameters;
    double meanWidth = 0.0;     ///< w (length units)
    double numberDensity = 0.0; ///< rho w^3, rho = N / L^3
    std::vector<double> r;      ///< bin centres / w
    /// g2 = 2 n_pairs / (N rho V_shell) per bin (docs/order-metrics.md Eq. 1.1).
    std::vector<double> g2;
    /// Standard deviation of g2 per bin for an ideal gas of the same N and rho: 1 / sqrt of its
    /// expected pair count N rho V_shell / 2 (Eq. 1.2).
    std::vector<double> idealGasError;
    std::vector<std::int64_t> pairCount; ///< unordered pairs per bin
};

/// Compute object (docs/design.md §7): parameters validated at construction.
class PairCorrelation {
  public:
    /// Throws std::invalid_argument unless 0 < binWidth <= maxDistance < inf.
    explicit PairCorrelation(PairCorrelationParameters parameters);

    /// Histogram of the minimum-image pair distances (cell list, O(N rho r_max^3)); of a
    /// mixture, of the reduced distances r_ij / sigma_ij (sigma_ij = Packing::pairSize), over the
    /// ideal gas's count at those (docs/order-metrics.md §1, "Mixtures"). Throws
    /// std::invalid_argument for fewer than 2 particles or when n dr w exceeds L / 2.
    PairCorrelationResult compute(const Packing& packing) const;

    const PairCorrelationParameters& parameters() const { return parameters_; }

  private:
    PairCorrelationParameters parameters_;
};

/// r / w of the first minimum of g2 after its main peak (docs/order-metrics.md §1): g2 is
/// smoothed by a moving average over 2 smoothingBins + 1 bins (fewer at the ends), then from its
/// global maximum outwards the first local minimum whose value is below 1 is taken (a run of
/// equal values: its middle). Throws std::invalid_argument for smoothingBins < 0 and
/// std::runtime_error when g2 has no such minimum before r_max.
double firstMinimum(const PairCorrelationResult& result, int smoothingBins = 2);

} // namespace sbpack
