#include "transport/transport.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sbpack {

double zeta2Interpolation(double p, double phi) {
    return 0.21068 * phi + std::abs(p - 1.0) * (0.11882 + 0.772236 * phi); // Sec. V A
}

double formationFactor(double phi, double zeta2) {
    if (!(phi >= 0.0 && phi < 1.0) || !(zeta2 >= 0.0 && zeta2 <= 1.0))
        throw std::invalid_argument("formation factor: phi = " + std::to_string(phi) +
                                    ", zeta_2 = " + std::to_string(zeta2) +
                                    " (need 0 <= phi < 1, 0 <= zeta_2 <= 1)");
    return (2.0 + phi - (1.0 - phi) * zeta2) / ((1.0 - phi) * (2.0 - zeta2)); // Eq. 18
}

Transport::Transport(TransportParameters parameters) : parameters_(parameters) {
    const double d = parameters_.diffusionCoefficient;
    if (!(std::isfinite(d) && d > 0.0))
        throw std::invalid_argument("transport: diffusion coefficient " + std::to_string(d) +
                                    " is not finite and positive");
}

namespace {

/// zeta_2, F and k (Sec. V A, Eqs. 17-18) into r where the interpolation holds: a superball
/// (r.p) whose zeta_2 lies in (0, 1]; else permeabilityOmitted says why.
void fitPermeability(TransportResult& r) {
    if (!r.p) {
        r.permeabilityOmitted = "the zeta_2 interpolation of Sec. V A is a fit over superballs "
                                "and the particles are not superballs";
        return;
    }
    const double zeta2 = zeta2Interpolation(*r.p, r.phi);
    if (zeta2 > 0.0 && zeta2 <= 1.0) {
        r.zeta2 = zeta2;
        r.formationFactor = formationFactor(r.phi, zeta2);
        r.permeability = r.secondMoment / *r.formationFactor; // Eq. 17: L^2 ~ <delta^2>
    } else {
        r.permeabilityOmitted = "the zeta_2 interpolation of Sec. V A gives " +
                                std::to_string(zeta2) + " for p = " + std::to_string(*r.p) +
                                ", phi = " + std::to_string(r.phi) +
                                ", outside (0, 1] (it was fitted for 0.85 <= p <= 1.5)";
    }
}

} // namespace

TransportResult Transport::compute(const PoreSizeDistributionResult& pores, std::optional<double> p,
                                   double phi) const {
    const auto started = std::chrono::steady_clock::now();
    if (p && !(std::isfinite(*p) && *p >= 0.5))
        throw std::invalid_argument("transport: p = " + std::to_string(*p) + " (need >= 0.5)");
    if (!(phi > 0.0 && phi < 1.0))
        throw std::invalid_argument("transport: phi = " + std::to_string(phi) +
                                    " (need 0 < phi < 1)");
    if (!(pores.mean > 0.0 && pores.secondMoment > 0.0 && pores.meanWidth > 0.0))
        throw std::invalid_argument("transport: the pore-size result has no positive moments");
    TransportResult r;
    r.parameters = parameters_;
    r.p = p;
    r.phi = phi;
    r.meanWidth = pores.meanWidth;
    r.meanPoreSize = pores.mean;
    r.secondMoment = pores.secondMoment;
    fitPermeability(r);
    const double d = parameters_.diffusionCoefficient;
    r.meanSurvivalTime = pores.mean * pores.mean / d;   // Eq. 19, kappa -> inf
    r.principalRelaxationTime = pores.secondMoment / d; // Eq. 20, kappa -> inf
    r.runtimeSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return r;
}

} // namespace sbpack
