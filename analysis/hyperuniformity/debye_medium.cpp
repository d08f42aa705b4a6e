#include "hyperuniformity/debye_medium.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sbpack {

namespace {

/// Beyond this s the closed form loses more than about 1e-12 to cancellation (s^2 eps).
constexpr double kAsymptoticFrom = 50.0;

/// h(s) = (1/2 + s) e^s erfc(sqrt s) - sqrt(s / pi) by the asymptotic series of erfc:
/// e^s erfc(sqrt s) = (pi s)^{-1/2} sum_n c_n s^{-n}, c_n = (-1)^n (2n - 1)!! / 2^n, so
/// h = (pi s)^{-1/2} sum_{m >= 1} (c_{m+1} + c_m / 2) s^{-m} (the m = 0 term vanishes). Summed
/// while the terms shrink; at s >= 50 that is far below 1e-16 relative.
double asymptotic(double s) {
    double c = 1.0, sum = 0.0, power = 1.0, previous = INFINITY;
    for (int m = 0; m < 200; ++m) {
        const double next = -c * (2.0 * m + 1.0) / 2.0; // c_{m+1}
        const double term = (next + 0.5 * c) * power;
        if (m >= 1) {
            if (std::abs(term) >= previous) break;
            sum += term;
            previous = std::abs(term);
        }
        c = next;
        power /= s;
    }
    return sum / std::sqrt(std::numbers::pi * s);
}

} // namespace

double debyeSpectralDensity(double k, double phi, double a) {
    const double ka2 = (k * a) * (k * a);
    return 8.0 * std::numbers::pi * phi * (1.0 - phi) * a * a * a / ((1.0 + ka2) * (1.0 + ka2));
}

double debyeExcessSpreadability(double s, double phi) {
    if (!(s >= 0.0)) throw std::invalid_argument("Debye spreadability: time must be >= 0");
    const double h = s < kAsymptoticFrom ? (0.5 + s) * std::exp(s) * std::erfc(std::sqrt(s)) -
                                               std::sqrt(s / std::numbers::pi)
                                         : asymptotic(s);
    return 2.0 * (1.0 - phi) * h;
}

} // namespace sbpack
