#pragma once
// Transport estimates from the pore-size moments in the diffusion-controlled limit (paper
// Sec. II B, Eqs. 16-20, and Sec. V A): the formation factor from the zeta_2 interpolation,
// the fluid permeability k, and the upper bounds on the mean survival time tau and the principal
// relaxation time T1, each also scaled by the mean width squared.

#include "pores/pore_size_distribution.hpp"

#include <optional>
#include <string>

namespace sbpack {

/// Three-point parameter of the paper's interpolation between sphere and cube packings
/// (Sec. V A): zeta_2 = 0.21068 phi + |p - 1| (0.11882 + 0.772236 phi).
double zeta2Interpolation(double p, double phi);

/// Formation factor estimate (Eq. 18, Torquato's bound with the four-point parameter set to zero):
/// F = (2 + phi - (1 - phi) zeta_2) / ((1 - phi)(2 - zeta_2)); zeta_2 = 0 is Hashin-Shtrikman.
/// phi is the solid (particle) fraction. Throws std::invalid_argument unless 0 <= phi < 1 and
/// 0 <= zeta_2 <= 1.
double formationFactor(double phi, double zeta2);

struct TransportParameters {
    /// D_diff of the diffusing species (length^2 / time) for tau and T1; the scaled forms tau
    /// D_diff / w^2 and T1 D_diff / w^2 do not depend on it.
    double diffusionCoefficient = 1.0;
};

/// Inputs, parameters and the estimates. Lengths in the packing's units, times in length^2 / D.
struct TransportResult {
    TransportParameters parameters;
    std::optional<double> p;   ///< the superball's exponent; nothing for another shape
    double phi = 0.0;          ///< packing fraction N v1 / L^3 (solid fraction)
    double meanWidth = 0.0;    ///< w
    double meanPoreSize = 0.0; ///< <delta> of the pore-size result used
    double secondMoment = 0.0; ///< <delta^2>
    /// Sec. V A's interpolation, Eq. 18 and Eq. 17 (k ~ <delta^2> / F, length^2): absent where
    /// the interpolation leaves (0, 1] (fitted for 0.85 <= p <= 1.5; past p of about 2 it
    /// exceeds 1), where tau and T1, pore-size moments alone, still hold.
    std::optional<double> zeta2;
    std::optional<double> formationFactor;
    std::optional<double> permeability;
    double meanSurvivalTime =
        0.0; ///< tau <= <delta>^2 / D_diff (Eq. 19, kappa -> inf), an upper bound
    double principalRelaxationTime = 0.0; ///< T1 <= <delta^2> / D_diff (Eq. 20, kappa -> inf)
    double runtimeSeconds = 0.0;

    std::optional<double> permeabilityOverWidth2() const {
        if (!permeability) return std::nullopt;
        return *permeability / (meanWidth * meanWidth);
    }
    /// Why k is absent (empty where it is given).
    std::string permeabilityOmitted;
    /// tau D_diff / w^2 (paper Fig. 14).
    double meanSurvivalTimeOverWidth2() const {
        return meanSurvivalTime * parameters.diffusionCoefficient / (meanWidth * meanWidth);
    }
    /// T1 D_diff / w^2 (paper Fig. 14).
    double principalRelaxationTimeOverWidth2() const {
        return principalRelaxationTime * parameters.diffusionCoefficient / (meanWidth * meanWidth);
    }
};

/// Compute object for Eqs. 16-20 in the diffusion-controlled limit.
class Transport {
  public:
    /// Throws std::invalid_argument unless the diffusion coefficient is finite and positive.
    explicit Transport(TransportParameters parameters);

    /// From a pore-size result (any method), the superball's exponent p (ShapeSpec::
    /// superballExponent: nothing for another shape) and phi. Throws std::invalid_argument for
    /// p < 0.5 or phi outside (0, 1). Where there is no p (the interpolation is a fit over
    /// superballs) or the interpolated zeta_2 leaves (0, 1] (it was fitted for 0.85 <= p <= 1.5),
    /// zeta_2, F and k are absent and permeabilityOmitted says why.
    TransportResult compute(const PoreSizeDistributionResult& pores, std::optional<double> p,
                            double phi) const;

    const TransportParameters& parameters() const { return parameters_; }

  private:
    TransportParameters parameters_;
};

} // namespace sbpack
