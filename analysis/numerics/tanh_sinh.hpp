#pragma once
// Tanh-sinh (double exponential) quadrature on a finite interval: converges double-exponentially
// for integrands analytic inside the interval, algebraic endpoint singularities |x - a|^s
// (s > -1) included, which is what the superball's height function (1 - |x|^{2p})^{1/(2p)} has
// at its rim. Nodes near either end are placed by their distance to that end, so no node rounds
// onto an endpoint.

#include <cmath>
#include <numbers>

namespace sbpack {

/// int_a^b f(x) dx, refined (halving the step, reusing the nodes) until two levels differ by at
/// most tolerance * int |f| (an absolute criterion, so that integrals that cancel to near zero
/// still converge), at most 14 halvings from a step of 1/2 (about 2^16 nodes).
template <class F> double tanhSinh(F&& f, double a, double b, double tolerance) {
    const double halfPi = 0.5 * std::numbers::pi;
    const double half = 0.5 * (b - a);
    // Sum over nodes t = k h (k = offset, offset + stride, ...) of w(t) f(x(t)) and w |f|.
    auto level = [&](double h, int offset, int stride, double& magnitude) {
        double sum = 0.0;
        for (int k = offset;; k += stride) {
            const double t = k * h;
            const double s = halfPi * std::sinh(t);
            const double cs = std::cosh(s);
            const double w = half * halfPi * std::cosh(t) / (cs * cs);
            // Distance of the nodes x(+-t) from their nearer end: (b - a) / (1 + e^{2 s}).
            const double d = (b - a) / (1.0 + std::exp(2.0 * s));
            if (w == 0.0 || b - d == b || a + d == a) break;
            const double right = f(b - d), left = k == 0 ? 0.0 : f(a + d);
            sum += w * (right + left);
            magnitude += w * (std::abs(right) + std::abs(left));
        }
        return sum;
    };
    double h = 0.5, first = 0.0;
    double estimate = h * level(h, 0, 1, first);
    double magnitude = h * first;
    for (int refinement = 0; refinement < 14; ++refinement) {
        h *= 0.5;
        double added = 0.0;
        const double refined = 0.5 * estimate + h * level(h, 1, 2, added);
        magnitude = 0.5 * magnitude + h * added;
        if (std::abs(refined - estimate) <= tolerance * magnitude && refinement >= 2)
            return refined;
        estimate = refined;
    }
    return estimate;
}

} // namespace sbpack
