#include "order/cubatic_order.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace sbpack {
namespace {

double legendre4(double x) {
    const double x2 = x * x;
    return (35.0 * x2 * x2 - 30.0 * x2 + 3.0) / 8.0;
}

/// The box's axis tensors T = sum_a u_a (x) u_a (x) u_a (x) u_a and M = sum_a u_a (x) u_a over
/// all axes a = (i, k), and the self term sum_i sum_{k,l} P4(u_ik . u_il) (Eq. 4.3).
struct AxisMoments {
    std::array<double, 81> fourth{}; ///< T_pqrs at ((p 3 + q) 3 + r) 3 + s
    std::array<double, 9> second{};  ///< M_pq at p 3 + q
    double selfSum = 0.0;

    void add(const Eigen::Matrix3d& axes) { // columns u_k
        for (int k = 0; k < 3; ++k) {
            const Vector3d u = axes.col(k);
            for (int p = 0; p < 3; ++p)
                for (int q = 0; q < 3; ++q) {
                    second[p * 3 + q] += u[p] * u[q];
                    for (int r = 0; r < 3; ++r)
                        for (int s = 0; s < 3; ++s)
                            fourth[((p * 3 + q) * 3 + r) * 3 + s] += u[p] * u[q] * u[r] * u[s];
                }
            for (int l = 0; l < 3; ++l)
                selfSum += legendre4(u.dot(axes.col(l)));
        }
    }
};

Eigen::Matrix3d bodyAxes(const Quaterniond& q, std::size_t i) {
    const double norm = q.norm();
    if (!(norm > 0.0) || !std::isfinite(norm))
        throw std::invalid_argument(
            fmt::format("cubatic order: orientation {} is not a rotation (|q| = {:g})", i, norm));
    return q.normalized().toRotationMatrix();
}

} // namespace

CubaticOrderResult cubaticOrder(const std::vector<Quaterniond>& orientations) {
    const std::size_t count = orientations.size();
    if (count < 2)
        throw std::invalid_argument(
            fmt::format("cubatic order: needs at least 2 orientations, not {}", count));
    AxisMoments moments;
    for (std::size_t i = 0; i < count; ++i)
        moments.add(bodyAxes(orientations[i], i));
    // Eq. 4.2: sum_{a,b} P4(u_a . u_b) = (35 T:T - 30 M:M + 3 (3N)^2) / 8.
    double fourthSquares = 0.0, secondSquares = 0.0;
    for (double t : moments.fourth)
        fourthSquares += t * t;
    for (double m : moments.second)
        secondSquares += m * m;
    const auto n = static_cast<double>(count);
    const double allPairs = (35.0 * fourthSquares - 30.0 * secondSquares + 27.0 * n * n) / 8.0;
    CubaticOrderResult result;
    result.particleCount = count;
    result.order = (allPairs - moments.selfSum) / (n * (n - 1.0) * kAlignedAxisSum); // Eq. 4.1
    result.randomOrientationError = std::sqrt(2.0 / (9.0 * n * (n - 1.0)));          // Eq. 4.4
    return result;
}

} // namespace sbpack
