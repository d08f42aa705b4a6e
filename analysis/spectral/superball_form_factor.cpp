#include "spectral/superball_form_factor.hpp"

#include "numerics/tanh_sinh.hpp"
#include "parallel/vector_clones.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

/// Remainder bound of the series relative to v1 (docs/design.md §1 for the moments).
constexpr double kSeriesTolerance = 1e-16;

/// Horner's scheme over u_x (outer), u_y, u_z (inner) of sum_{i+j+l <= N} c_ijl u_x^i u_y^j u_z^l,
/// lane by lane over a tile (the lanes are independent: the compiler vectorises across them).
SBPACK_VECTOR_CLONES
void hornerTile(const double* coefficients, int stride, int order, const double* ux,
                const double* uy, const double* uz, double* out) {
    constexpr int T = SuperballFormFactor::kTile;
    double sx[T] = {};
    for (int i = order; i >= 0; --i) {
        double sy[T] = {};
        for (int j = order - i; j >= 0; --j) {
            const double* c = coefficients + (static_cast<std::size_t>(i) * stride + j) * stride;
            double sz[T] = {};
            for (int l = order - i - j; l >= 0; --l)
                for (int t = 0; t < T; ++t)
                    sz[t] = sz[t] * uz[t] + c[l];
            for (int t = 0; t < T; ++t)
                sy[t] = sy[t] * uy[t] + sz[t];
        }
        for (int t = 0; t < T; ++t)
            sx[t] = sx[t] * ux[t] + sy[t];
    }
    for (int t = 0; t < T; ++t)
        out[t] = sx[t];
}

} // namespace

SuperballFormFactor::SuperballFormFactor(const Superball& shape)
    : shape_(shape), volume_(shape.volume()), circumradius_(shape.circumradius()),
      coefficients_(static_cast<std::size_t>(kStride) * kStride * kStride, 0.0) {
    // int over the body of x^{2i} y^{2j} z^{2l} (Dirichlet, R = 1):
    //   8 (1/2p)^3 G((2i+1)/2p) G((2j+1)/2p) G((2l+1)/2p) / G(1 + (2i+2j+2l+3)/2p),
    // divided by (2i)! (2j)! (2l)! (the Taylor series of cos(k.x), even terms by symmetry);
    // u_i = -(k_i R)^2 carries the sign (-1)^{i+j+l}.
    const long double e = 1.0L / (2.0L * shape.p());
    std::vector<long double> axis(kStride);
    for (int i = 0; i < kStride; ++i)
        axis[i] = std::lgamma(static_cast<long double>(2 * i + 1) * e) -
                  std::lgamma(static_cast<long double>(2 * i + 1));
    const long double prefactor = std::log(8.0L) + 3.0L * std::log(e);
    for (int i = 0; i <= kMaxOrder; ++i)
        for (int j = 0; i + j <= kMaxOrder; ++j)
            for (int l = 0; i + j + l <= kMaxOrder; ++l) {
                const long double total = std::lgamma(1.0L + (2 * (i + j + l) + 3) * e);
                coefficients_[(static_cast<std::size_t>(i) * kStride + j) * kStride + l] =
                    static_cast<double>(std::exp(prefactor + axis[i] + axis[j] + axis[l] - total));
            }
}

int SuperballFormFactor::order(double kNorm) const {
    const double s = kNorm * circumradius_;
    if (!(s <= kSeriesLimit))
        throw std::invalid_argument("superball form factor: |k| R_c = " + std::to_string(s) +
                                    " is beyond the series' range " + std::to_string(kSeriesLimit));
    // term_n = s^{2n} / (2n)!; the remainder after N is at most term_{N+1} / (1 - r) with
    // r = s^2 / ((2N + 3)(2N + 4)) < 1, the ratio of the terms that follow.
    double term = 1.0;
    for (int n = 0; n < kMaxOrder; ++n) {
        const double next = term * s * s / ((2.0 * n + 1.0) * (2.0 * n + 2.0));
        const double r = s * s / ((2.0 * n + 3.0) * (2.0 * n + 4.0));
        if (r < 1.0 && next / (1.0 - r) <= kSeriesTolerance) return n;
        term = next;
    }
    return kMaxOrder;
}

void SuperballFormFactor::seriesTile(int order, const double* ux, const double* uy,
                                     const double* uz, double* out) const {
    hornerTile(coefficients_.data(), kStride, order, ux, uy, uz, out);
    const double r3 = std::pow(shape_.semiAxis(), 3);
    for (int t = 0; t < kTile; ++t)
        out[t] *= r3;
}

double SuperballFormFactor::series(const Eigen::Vector3d& kBody) const {
    const double r = shape_.semiAxis();
    double ux[kTile], uy[kTile], uz[kTile], out[kTile];
    std::fill(ux, ux + kTile, -(kBody.x() * r) * (kBody.x() * r));
    std::fill(uy, uy + kTile, -(kBody.y() * r) * (kBody.y() * r));
    std::fill(uz, uz + kTile, -(kBody.z() * r) * (kBody.z() * r));
    seriesTile(order(kBody.norm()), ux, uy, uz, out);
    return out[0];
}

double SuperballFormFactor::quadrature(const Eigen::Vector3d& kBody, double tolerance) const {
    // Octant symmetry: m = 8 int_{x,y,z >= 0} cos(k1 x) cos(k2 y) cos(k3 z); permutation
    // symmetry: the largest |k_i| goes to z, integrated in closed form up to the height
    // Z(x, y) = R (1 - (x/R)^{2p} - (y/R)^{2p})^{1/(2p)}: sin(k3 Z) / k3.
    Eigen::Vector3d k = kBody.cwiseAbs();
    std::sort(k.data(), k.data() + 3);
    const double r = shape_.semiAxis(), twoP = 2.0 * shape_.p();
    auto height = [&](double rest) { return rest > 0.0 ? r * std::pow(rest, 1.0 / twoP) : 0.0; };
    auto column = [&](double z) { return k[2] == 0.0 ? z : std::sin(k[2] * z) / k[2]; };
    auto inner = [&](double x) {
        const double restX = 1.0 - std::pow(x / r, twoP);
        const double yMax = height(restX);
        if (yMax == 0.0) return 0.0;
        auto f = [&](double y) {
            return std::cos(k[1] * y) * column(height(restX - std::pow(y / r, twoP)));
        };
        return std::cos(k[0] * x) * tanhSinh(f, 0.0, yMax, tolerance);
    };
    return 8.0 * tanhSinh(inner, 0.0, r, tolerance);
}

double SuperballFormFactor::operator()(const Eigen::Vector3d& kBody) const {
    if (kBody.norm() * circumradius_ <= kSeriesLimit) return series(kBody);
    return quadrature(kBody);
}

} // namespace sbpack
