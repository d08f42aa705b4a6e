#pragma once
// Structure factor S(Q) of the particle centroids (paper Eq. 4, eq:ScattInt: the scattering
// intensity of one periodic configuration), angular-averaged in shells (docs/design.md §5).

#include "packing/packing.hpp"
#include "progress/progress.hpp"
#include "shells/shell_average.hpp"

#include <optional>
#include <vector>

namespace sbpack {

struct StructureFactorParameters {
    /// Shells up to Q w <= maxQw, w the mean width (docs/design.md §5: report Q w).
    double maxQw = 30.0;
};

/// A binary mixture's partial structure factors (Ashcroft-Langreth; docs/mixtures.md): species
/// A the large particles, B the small, S_ab(Q) = Re(rho_a(Q) rho_b(Q)*) / sqrt(N_a N_b),
/// shell-averaged on S's shells; the total is x_A S_AA + x_B S_BB + 2 sqrt(x_A x_B) S_AB.
struct PartialStructureFactors {
    double fractionA = 0.0; ///< x_A = N_A / N
    std::vector<double> aa, bb, ab;
};

struct StructureFactorResult {
    StructureFactorParameters parameters;
    double boxLength = 0.0;
    double meanWidth = 0.0;
    /// Shells 1..maxShell of width 2 pi / L; the wave vectors used are those with
    /// |n| < maxShell + 1/2 (shells/shell_average.hpp).
    int maxShell = 0;
    /// Q, S(Q) (value) and the number of wave vectors per shell.
    ShellAverage shells;
    /// Of a binary mixture only (two sizes); absent otherwise.
    std::optional<PartialStructureFactors> partials;
    double runtimeSeconds = 0.0;
};

/// Compute object (docs/design.md §7): parameters validated at construction.
class StructureFactor {
  public:
    /// Throws std::invalid_argument unless 0 < maxQw < inf.
    explicit StructureFactor(StructureFactorParameters parameters);

    /// Shell s of width 2 pi / L whose Q w is at most maxQw: floor(maxQw L / (2 pi w)).
    static int maxShellFor(double maxQw, double boxLength, double meanWidth);

    /// S(Q) = |sum_j exp(-i Q.r_j)|^2 / N at Q = 2 pi n / L != 0 (paper Eq. 4), shell-averaged
    /// (number-weighted for a mixture, whose partials it adds where it has two sizes).
    /// Throws std::invalid_argument if maxQw admits no shell in this box.
    StructureFactorResult compute(const Packing& packing, const Progress& progress) const;

    const StructureFactorParameters& parameters() const { return parameters_; }

  private:
    StructureFactorParameters parameters_;
};

} // namespace sbpack
