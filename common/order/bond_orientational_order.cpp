#include "order/bond_orientational_order.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace sbpack {
namespace {

/// Adds Y_lm(theta, phi) of the direction of `bond`, m = 0..l, to `sum`: Y_lm = sph_legendre(l,
/// m, theta) e^{i m phi} (libstdc++'s normalised associated Legendre function, Condon-Shortley
/// phase). theta from atan2, accurate near the poles.
void addHarmonics(const Vector3d& bond, int degree, Harmonics& sum) {
    const double theta = std::atan2(std::hypot(bond.x(), bond.y()), bond.z());
    const double phi = std::atan2(bond.y(), bond.x());
    const auto l = static_cast<unsigned>(degree);
    for (unsigned m = 0; m <= l; ++m)
        sum[m] += std::sph_legendre(l, m, theta) *
                  std::complex<double>(std::cos(m * phi), std::sin(m * phi));
}

/// sqrt(4 pi / (2l + 1) sum_{m=-l..l} |sum_m / count|^2).
double rotationalInvariant(const Harmonics& sum, double count) {
    const auto l = static_cast<double>(sum.size() - 1);
    return std::sqrt(4.0 * std::numbers::pi / (2.0 * l + 1.0) * harmonicProduct(sum, sum)) / count;
}

void checkBond(const Bond& bond, std::size_t particleCount) {
    const auto count = static_cast<long long>(particleCount);
    if (bond.i < 0 || bond.j < 0 || bond.i >= count || bond.j >= count)
        throw std::invalid_argument(
            fmt::format("Steinhardt order: bond ({}, {}) names a particle beyond the {} particles",
                        bond.i, bond.j, particleCount));
    if (!(bond.vector.norm() > 0.0))
        throw std::invalid_argument(
            fmt::format("Steinhardt order: bond ({}, {}) has no direction (length {:g})", bond.i,
                        bond.j, bond.vector.norm()));
}

} // namespace

BondHarmonics bondHarmonics(const NeighbourBonds& bonds, int degree) {
    if (degree < 0)
        throw std::invalid_argument(
            fmt::format("Steinhardt order: the degree l must be >= 0, not {}", degree));
    const std::size_t n = bonds.particleCount;
    BondHarmonics result{degree, std::vector<Harmonics>(n, Harmonics(degree + 1)),
                         std::vector<int>(n, 0)};
    for (const Bond& bond : bonds.bonds) { // each bond seen from i (r_ij) and from j (-r_ij)
        checkBond(bond, n);
        addHarmonics(bond.vector, degree, result.sums[bond.i]);
        addHarmonics(-bond.vector, degree, result.sums[bond.j]);
        ++result.neighbourCount[bond.i];
        ++result.neighbourCount[bond.j];
    }
    return result;
}

double harmonicProduct(const Harmonics& a, const Harmonics& b) {
    double product = (a[0] * std::conj(b[0])).real();
    for (std::size_t m = 1; m < a.size(); ++m) // the terms m and -m are complex conjugates
        product += 2.0 * (a[m] * std::conj(b[m])).real();
    return product;
}

SteinhardtOrder steinhardtOrder(const NeighbourBonds& bonds, int degree) {
    if (bonds.bonds.empty()) throw std::invalid_argument("Steinhardt order: there are no bonds");
    const BondHarmonics local = bondHarmonics(bonds, degree);
    const std::size_t n = bonds.particleCount;
    SteinhardtOrder result;
    result.degree = degree;
    result.bondCount = bonds.bonds.size();
    result.neighbourCount = local.neighbourCount;
    Harmonics global(degree + 1);
    result.localOrder.assign(n, std::numeric_limits<double>::quiet_NaN());
    double localSum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        if (result.neighbourCount[i] == 0) continue;
        for (int m = 0; m <= degree; ++m)
            global[m] += local.sums[i][m];
        result.localOrder[i] = rotationalInvariant(local.sums[i], result.neighbourCount[i]);
        localSum += result.localOrder[i];
        ++result.bondedParticles;
    }
    result.globalOrder = rotationalInvariant(global, 2.0 * static_cast<double>(result.bondCount));
    result.meanLocalOrder = localSum / static_cast<double>(result.bondedParticles);
    return result;
}

} // namespace sbpack
