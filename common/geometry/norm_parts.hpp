#pragma once
// The parts of the l_e norm ||u||_e = (sum |u_i|^e)^{1/e} (paper Eq. 1: the gauge of a superball
// is ||x / R||_{2p}, its support function R ||n||_q), in plain doubles so that the host and the
// CUDA kernels of sbanalyze (analysis/grid/, docs/gpu.md) evaluate the same arithmetic: one
// definition of the inside test on every device.

#include <cmath>

#if defined(__CUDACC__)
#define SBPACK_HD __host__ __device__
#else
#define SBPACK_HD
#endif

namespace sbpack::norm {

/// y^e for 0 < y <= 1 (or a sum in [1, 3]) as exp2(e log2 y): about 1e-16 relative where it
/// matters (y^e |log2 y^e| <= 0.53, so the absolute error of a sum of such terms stays at
/// rounding), and cheaper than std::pow in the predictor's inner loop (bench/RESULTS.md,
/// "Predictor speed-ups"; "Measurement history moved out of code comments").
SBPACK_HD inline double power(double y, double e) {
    return std::exp2(e * std::log2(y));
}

/// x^{1/3} for 1 <= x <= 3: a quadratic first guess (within 0.6 %), then two Halley steps
/// z <- z + z (x - z^3) / (2z^3 + x), each cubing the relative error; written as a correction,
/// the last one rounds to within one ulp and keeps 1^{1/3} = 1 exact (libm's cbrt reduces any x
/// first and is the slower: bench/RESULTS.md, "Roots instead of exp2/log2 at p = 1.5").
SBPACK_HD inline double cubeRootOf1To3(double x) {
    double z = 0.6747968821859316 + x * (0.36905165677595114 - 0.03816218708648547 * x);
    for (int step = 0; step < 2; ++step) {
        const double z3 = z * z * z;
        z += z * (x - z3) / (2.0 * z3 + x);
    }
    return z;
}

/// The parts of ||u||_e for finite e and u != 0, normalised by m = max |u_i| before any power
/// (no overflow): y_i = |u_i| / m, t_i = y_i^{e-1} (the gradient's powers), a_i = t_i y_i = y_i^e,
/// sum = sum a_i (in [1, 3]) and norm = sum^{1/e} (= ||u||_e / m), from one power for each
/// component below the largest and one for the norm. The exponents of p = 1.5 (e = 3 for the
/// gauge, e = 3/2 for the support function) and of p = 0.75 (the same two, swapped) take roots
/// instead: y^{1/2} = sqrt(y), y^2, and the norm's root from a cube root, as accurate as
/// exp2/log2 (a few ulp) with neither.
struct Parts {
    double m, sum, norm;
    double y[3], t[3];
};

SBPACK_HD inline double largestMagnitude(const double u[3]) {
    const double a = std::abs(u[0]), b = std::abs(u[1]), c = std::abs(u[2]);
    const double ab = a < b ? b : a;
    return ab < c ? c : ab;
}

SBPACK_HD inline Parts parts(const double u[3], double e) {
    Parts n{largestMagnitude(u), 0.0, 0.0, {}, {}};
    for (int i = 0; i < 3; ++i) {
        const double y = std::abs(u[i]) / n.m;
        n.y[i] = y;
        n.t[i] = y == 1.0   ? 1.0 // the largest: one power fewer
                 : y == 0.0 ? 0.0 // 0^{e-1}, or a subgradient for e = 1 (no 0 * log2 0)
                 : e == 1.5 ? std::sqrt(y)
                 : e == 3.0 ? y * y
                            : power(y, e - 1.0);
        n.sum += n.t[i] * y;
    }
    if (e == 1.5)
        n.norm = n.sum / cubeRootOf1To3(n.sum); // sum^{2/3}, within ~1.5 ulp (root squared: 2.6)
    else if (e == 3.0)
        n.norm = cubeRootOf1To3(n.sum);
    else
        n.norm = power(n.sum, 1.0 / e);
    return n;
}

/// ||u||_e for 1 <= e <= inf.
SBPACK_HD inline double lpNorm(const double u[3], double e) {
    const double m = largestMagnitude(u);
    if (m == 0.0 || e == INFINITY) return m;
    return m * parts(u, e).norm;
}

/// The superball's inside test (Superball::contains): ||x / R||_{2p} < 1 for the body-frame
/// point x (x / R computed component by component, as Eigen's x / R).
SBPACK_HD inline bool insideSuperball(const double xBody[3], double semiAxis, double p) {
    const double u[3] = {xBody[0] / semiAxis, xBody[1] / semiAxis, xBody[2] / semiAxis};
    return lpNorm(u, 2.0 * p) < 1.0;
}

} // namespace sbpack::norm
