#pragma once
// Spectra with known exponents for the hyperuniformity tests and bench_alpha_coverage.

#include "hyperuniformity/debye_medium.hpp"
#include "hyperuniformity/discrete_spectrum.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>

namespace sbpack::testing {

/// The Debye random medium's chi_V (paper Eq. deb; alpha = 0) on the wave vectors |n_i| <= reach
/// of a box of edge `box`, without noise, its length scale a the mean width.
inline DiscreteSpectrum debyeBoxSpectrum(double phi, double a, double box, int reach) {
    DiscreteSpectrum s;
    s.source = "exact";
    s.boxLength = box;
    s.meanWidth = a;
    s.phi = phi;
    s.cutoffQ = INFINITY;
    s.sumByN2.assign(3 * static_cast<std::size_t>(reach) * reach + 1, 0.0);
    for (int x = -reach; x <= reach; ++x)
        for (int y = -reach; y <= reach; ++y)
            for (int z = -reach; z <= reach; ++z) {
                const std::int64_t n2 = x * x + y * y + z * z;
                if (n2 == 0) continue;
                const double q = 2 * std::numbers::pi * std::sqrt(static_cast<double>(n2)) / box;
                s.sumByN2[static_cast<std::size_t>(n2)] += debyeSpectralDensity(q, phi, a);
            }
    return s;
}

} // namespace sbpack::testing
