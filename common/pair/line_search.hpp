#pragma once
// The pair solvers' one-dimensional searches (pair_geometry.cpp's scale factor, normal_newton's
// robust ascent): an exact line search along a Newton direction, and that direction.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <optional>

namespace sbpack::pair_search {

using Vector2d = Eigen::Vector2d;
using Matrix2d = Eigen::Matrix2d;

/// A bracket [lo, hi] of the root of phi', phi'(lo) = dlo < 0 <= dhi = phi'(hi), refined by
/// Illinois regula falsi with bisection safeguards.
struct Bracket {
    double lo, dlo, hi, dhi;
    int side = 0; ///< Illinois: which end was kept last time

    /// One regula falsi step (its end's value halved when the same end is kept twice), and a
    /// bisection when the bracket shrank by less than half; the root if a step hit it exactly.
    template <class Derivative> std::optional<double> refine(Derivative& derivative) {
        double t = lo - dlo * (hi - lo) / (dhi - dlo);
        const double width = hi - lo;
        if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
        const double dt = derivative(t);
        if (dt == 0.0) return t;
        if (dt < 0.0) {
            lo = t;
            dlo = dt;
            if (side == -1) dhi *= 0.5;
            side = -1;
        } else {
            hi = t;
            dhi = dt;
            if (side == 1) dlo *= 0.5;
            side = 1;
        }
        if (hi - lo > 0.5 * width) { // slow secant progress: bisect once
            const double mid = 0.5 * (lo + hi);
            const double dm = derivative(mid);
            if (dm == 0.0) return mid;
            (dm < 0.0 ? lo : hi) = mid;
            (dm < 0.0 ? dlo : dhi) = dm;
            side = 0;
        }
        return std::nullopt;
    }
};

/// Solves phi'(t) = 0 for 0 < t <= tMax along a search direction, given phi'(0) < 0 and
/// phi' nondecreasing past its root (convex phi, or a local maximum of -phi): the full
/// Newton step t = 1 is tried first; otherwise the root is bracketed and refined (Bracket).
/// tTolerance is absolute in t.
template <class Derivative>
double exactLineSearch(Derivative&& derivative, double slope0, double tTolerance, double tMax,
                       int maxIterations) {
    Bracket b{0.0, slope0, std::min(1.0, tMax), 0.0};
    b.dhi = derivative(b.hi);
    if (std::abs(b.dhi) <= 1e-2 * std::abs(slope0)) return b.hi; // Newton's step will do
    int iteration = 0;
    while (b.dhi < 0.0 && b.hi < tMax && iteration++ < maxIterations) { // bracket the root
        b.lo = b.hi;
        b.dlo = b.dhi;
        b.hi = std::min(2.0 * b.hi, tMax);
        b.dhi = derivative(b.hi);
    }
    if (b.dhi < 0.0) return b.hi;
    while (b.hi - b.lo > tTolerance && iteration++ < maxIterations)
        if (const std::optional<double> root = b.refine(derivative)) return *root;
    return 0.5 * (b.lo + b.hi);
}

/// Newton direction for minimising a function with 2x2 Hessian h and gradient g; a tiny
/// shift keeps the octahedral (singular) Hessians solvable, steepest descent otherwise.
inline Vector2d newtonDirection(const Matrix2d& h, const Vector2d& g, double shift) {
    const Matrix2d m = h + shift * Matrix2d::Identity();
    const double det = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
    Vector2d direction(-(m(1, 1) * g[0] - m(0, 1) * g[1]) / det,
                       -(m(0, 0) * g[1] - m(1, 0) * g[0]) / det);
    if (!(direction.dot(g) < 0.0) || !direction.allFinite()) direction = -g;
    return direction;
}

} // namespace sbpack::pair_search
