#include "geometry/superball_projection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sbpack {

namespace {

constexpr int kMaxIterations = 200;

/// Projection of xi (>= 0, sum > 1) onto { u >= 0, sum u <= 1 }: u = max(xi - kappa, 0) with
/// kappa from the sorted coordinates (the l1 ball, i.e. the octahedron p = 0.5).
Vector3d projectOntoOctahedron(const Vector3d& xi) {
    std::array<double, 3> sorted = {xi[0], xi[1], xi[2]};
    std::sort(sorted.begin(), sorted.end(), std::greater<>());
    double kappa = 0.0, partial = 0.0;
    for (int k = 0; k < 3; ++k) {
        partial += sorted[k];
        const double candidate = (partial - 1.0) / (k + 1);
        if (sorted[k] > candidate) kappa = candidate;
    }
    return (xi.array() - kappa).max(0.0).matrix();
}

/// Root u in (0, min(xi, 1)] of u + kappa u^m = xi, for xi > 0 and 1 + kappa >= xi (so that
/// the root is <= 1 and u^m cannot overflow): increasing in u, bracketed Newton from the right.
/// Closed forms for m = 2 (p = 1.5), a quadratic in u, and m = 1/2 (p = 0.75), a quadratic in
/// sqrt(u), each in its cancellation-free form.
double axisRoot(double xi, double kappa, double m) {
    if (m == 2.0) return 2.0 * xi / (1.0 + std::sqrt(1.0 + 4.0 * kappa * xi));
    if (m == 0.5) {
        const double t = 2.0 * xi / (kappa + std::sqrt(kappa * kappa + 4.0 * xi));
        return t * t;
    }
    double lo = 0.0, hi = std::min(xi, 1.0), u = hi;
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        const double power = std::pow(u, m - 1.0); // u^{m-1}, u > 0
        const double residual = u + kappa * power * u - xi;
        if (residual == 0.0) return u;
        (residual > 0.0 ? hi : lo) = u;
        double next = u - residual / (1.0 + kappa * m * power);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - u) <= 4e-16 * u) return next;
        u = next;
    }
    return u;
}

/// u^{m-1} for u > 0, by a root at m = 2 and m = 1/2 (as axisRoot).
double powerMinusOne(double u, double m) {
    if (m == 2.0) return u;
    if (m == 0.5) return 1.0 / std::sqrt(u);
    return std::pow(u, m - 1.0);
}

/// y^e for y >= 0: products and roots at e = 2, 3 and 3/2 (p = 1, 1.5, 0.75), else std::pow.
double powerOf(double y, double e) {
    if (e == 2.0) return y * y;
    if (e == 3.0) return y * y * y;
    if (e == 1.5) return y * std::sqrt(y);
    return std::pow(y, e);
}

/// Newton's start for kappa from the radial point u_r = xi / g(xi) on the surface, with
/// s = sum xi_i^e = g^e: the least-squares kappa of u + kappa u^m = xi, i.e. the step from u_r
/// along the surface normal there, which is exact at the axes, on the diagonals and as the
/// point approaches the surface.
double kappaStart(const Vector3d& xi, double e, double s) {
    const double m = e - 1.0;
    const double inverseGauge = e == 3.0 ? 1.0 / std::cbrt(s) : std::pow(s, -1.0 / e);
    double along = 0.0, norm = 0.0;
    for (int i = 0; i < 3; ++i) {
        if (!(xi[i] > 0.0)) continue;
        const double u = xi[i] * inverseGauge;
        const double normal = powerMinusOne(u, m) * u; // u^m
        along += (xi[i] - u) * normal;
        norm += normal * normal;
    }
    return along / norm;
}

/// Projection of xi (>= 0, outside: s = sum xi_i^{2p} > 1) onto { u >= 0, sum u_i^{2p} <= 1 },
/// 0.5 < p: KKT u_i + kappa u_i^{2p-1} = xi_i with sum u_i^{2p} = 1; the sum falls monotonically
/// with kappa, whose root lies in [max(0, max xi - 1), 3 max xi] (the largest u_i is
/// >= 3^{-1/(2p)}). Safeguarded Newton in kappa until the sum is 1 to rounding (then u is the
/// projection onto that surface) or kappa stops moving.
Vector3d projectOntoSuperball(const Vector3d& xi, double p, double s) {
    const double e = 2.0 * p, m = e - 1.0;
    const double largest = xi.maxCoeff();
    double lo = std::max(0.0, largest - 1.0), hi = 3.0 * largest;
    Vector3d u;
    // c(kappa) = sum u_i^e - 1 and its derivative, du_i/dkappa = -u_i^m / (1 + kappa m u_i^{m-1}).
    auto evaluate = [&](double kappa, double& derivative) {
        double c = -1.0;
        derivative = 0.0;
        for (int i = 0; i < 3; ++i) {
            u[i] = xi[i] > 0.0 ? axisRoot(xi[i], kappa, m) : 0.0;
            if (u[i] == 0.0) continue;
            const double power = powerMinusOne(u[i], m);
            const double um = power * u[i];
            c += um * u[i];
            derivative -= e * um * um / (1.0 + kappa * m * power);
        }
        return c;
    };
    double kappa = std::clamp(kappaStart(xi, e, s), lo, hi);
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        double derivative = 0.0;
        const double c = evaluate(kappa, derivative);
        if (std::abs(c) <= 4e-16) break; // on the surface to rounding
        (c > 0.0 ? lo : hi) = kappa;
        double next = derivative < 0.0 ? kappa - c / derivative : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const bool converged = std::abs(next - kappa) <= 4e-16 * std::max(kappa, 1e-300);
        kappa = next;
        if (converged || !(hi > lo)) {
            evaluate(kappa, derivative);
            break;
        }
    }
    return u;
}

} // namespace

double gaugePower(const Superball& shape, const Vector3d& xBody) {
    double s = 0.0;
    for (int i = 0; i < 3; ++i)
        s += powerOf(std::abs(xBody[i]) / shape.semiAxis(), 2.0 * shape.p());
    return s;
}

Vector3d closestPoint(const Superball& shape, const Vector3d& xBody) {
    const double r = shape.semiAxis();
    if (shape.isSphere() || shape.isOctahedron()) {
        if (!(shape.gauge(xBody) > 1.0)) return xBody;
        if (shape.isSphere()) return xBody * (r / xBody.norm());
    }
    const Vector3d xi = xBody.cwiseAbs() / r;
    const double s = gaugePower(shape, xBody); // g(x)^{2p}: inside iff <= 1
    if (!shape.isOctahedron() && !(s > 1.0)) return xBody;
    const Vector3d u =
        shape.isOctahedron() ? projectOntoOctahedron(xi) : projectOntoSuperball(xi, shape.p(), s);
    Vector3d y;
    for (int i = 0; i < 3; ++i)
        y[i] = std::copysign(u[i] * r, xBody[i]);
    return y;
}

} // namespace sbpack
