#include "order/translational_order.hpp"

#include "contacts/cell_list.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

namespace sbpack {
namespace {

/// Volume of the shell [r - a / 2, r + a / 2).
double shellVolume(double radius, double width) {
    return 4.0 * std::numbers::pi / 3.0 *
           (std::pow(radius + 0.5 * width, 3) - std::pow(radius - 0.5 * width, 3));
}

/// sum_i (n_i^fcc - n_i^ideal) in units where d = 1, i.e. rho = sqrt 2: the denominator of
/// Eq. 3.1, independent of the density.
double fccExcess(const std::vector<FccShell>& shells, double width) {
    double excess = 0.0;
    for (const FccShell& shell : shells)
        excess += shell.coordination - std::numbers::sqrt2 * shellVolume(shell.distance, width);
    return excess;
}

/// Mean number of centres in each shell (radii and width in length units) around a centre.
std::vector<double> shellOccupation(const Packing& packing, const std::vector<double>& radius,
                                    double width) {
    std::vector<double> lower(radius.size());
    for (std::size_t i = 0; i < radius.size(); ++i)
        lower[i] = radius[i] - 0.5 * width;
    std::vector<double> pairs(radius.size(), 0.0);
    forEachNeighbourPair(packing.positions, packing.boxLength, radius.back() + 0.5 * width,
                         [&](int, int, const Vector3d& d) {
                             const double r = d.norm();
                             const auto above = std::upper_bound(lower.begin(), lower.end(), r);
                             if (above == lower.begin()) return;
                             const auto i = static_cast<std::size_t>(above - lower.begin()) - 1;
                             if (r < radius[i] + 0.5 * width) pairs[i] += 1.0;
                         });
    for (double& n : pairs)
        n *= 2.0 / static_cast<double>(packing.size()); // each pair is a neighbour of both ends
    return pairs;
}

/// Eqs. 3.1 to 3.3 at nearest-neighbour distance d (length units) and density rho = N / L^3.
TranslationalOrderResult tabulate(const Packing& packing, const std::vector<FccShell>& shells,
                                  const TranslationalOrderParameters& parameters, double d) {
    const auto n = static_cast<double>(packing.size());
    const double rho = n / std::pow(packing.boxLength, 3);
    const double w = packing.shape().meanWidth();
    TranslationalOrderResult result;
    result.parameters = parameters;
    result.numberDensity = rho * w * w * w;
    result.nearestNeighbourDistance = d / w;
    std::vector<double> radius;
    for (const FccShell& shell : shells)
        radius.push_back(shell.distance * d);
    result.occupation = shellOccupation(packing, radius, parameters.shellWidth * d);
    double packingExcess = 0.0, crystalExcess = 0.0, idealFraction = 0.0;
    for (std::size_t i = 0; i < shells.size(); ++i) {
        const double volume = shellVolume(radius[i], parameters.shellWidth * d);
        result.shellRadius.push_back(radius[i] / w);
        result.idealOccupation.push_back(rho * volume);
        result.fccOccupation.push_back(shells[i].coordination);
        packingExcess += result.occupation[i] - result.idealOccupation[i];
        crystalExcess += shells[i].coordination - result.idealOccupation[i];
        idealFraction += volume / std::pow(packing.boxLength, 3);
    }
    result.order = std::abs(packingExcess) / crystalExcess; // Eq. 3.1
    // Eq. 3.3: the pairs in the shells of an ideal gas, C(N, 2) trials of probability p.
    result.idealGasError =
        std::sqrt(2.0 * (n - 1.0) * idealFraction * (1.0 - idealFraction) / n) / crystalExcess;
    return result;
}

} // namespace

std::vector<FccShell> fccShells(int count) {
    if (count < 1)
        throw std::invalid_argument(
            fmt::format("fcc shells: need at least 1 shell, not {}", count));
    for (int bound = 4;; bound *= 2) { // complete for s = h^2 + k^2 + l^2 <= bound^2
        std::map<int, int> points;     // s -> lattice points (h, k, l) a / 2 with |.|^2 = s a^2 / 4
        for (int h = -bound; h <= bound; ++h)
            for (int k = -bound; k <= bound; ++k)
                for (int l = -bound; l <= bound; ++l) {
                    const int s = h * h + k * k + l * l;
                    if ((h + k + l) % 2 == 0 && s > 0 && s <= bound * bound) ++points[s];
                }
        if (points.size() < static_cast<std::size_t>(count)) continue;
        std::vector<FccShell> shells;
        for (auto [s, coordination] : points) {
            if (shells.size() == static_cast<std::size_t>(count)) break;
            shells.push_back({std::sqrt(0.5 * s), coordination}); // d^2 = a^2 / 2
        }
        return shells;
    }
}

double fccNeighbourDistance(const Packing& packing) {
    const double rho = static_cast<double>(packing.size()) / std::pow(packing.boxLength, 3);
    return std::cbrt(std::numbers::sqrt2 / rho); // fcc: 4 points per a^3, d = a / sqrt 2
}

int fccShellsThatFit(const Packing& packing, const TranslationalOrderParameters& parameters) {
    const double d = fccNeighbourDistance(packing);
    const std::vector<FccShell> shells = fccShells(parameters.shellCount);
    int fit = 0;
    while (fit < parameters.shellCount &&
           (shells[fit].distance + 0.5 * parameters.shellWidth) * d <= 0.5 * packing.boxLength)
        ++fit;
    return fit;
}

TranslationalOrder::TranslationalOrder(TranslationalOrderParameters parameters)
    : parameters_(parameters) {
    shells_ = fccShells(parameters.shellCount);
    double gap = shells_.front().distance; // to r = 0
    for (std::size_t i = 1; i < shells_.size(); ++i)
        gap = std::min(gap, shells_[i].distance - shells_[i - 1].distance);
    if (!(parameters.shellWidth > 0.0) || !(parameters.shellWidth < gap))
        throw std::invalid_argument(fmt::format(
            "translational order: the shell width must be in (0, {:g}) d, the closest spacing of "
            "the first {} fcc shells, not {:g}",
            gap, parameters.shellCount, parameters.shellWidth));
    if (!(fccExcess(shells_, parameters.shellWidth) > 0.0))
        throw std::invalid_argument("translational order: the fcc shells hold no excess over "
                                    "the ideal gas at this shell width");
}

TranslationalOrderResult TranslationalOrder::compute(const Packing& packing) const {
    if (packing.size() < 2)
        throw std::invalid_argument("translational order: needs at least 2 particles");
    const double d = fccNeighbourDistance(packing);
    const double reach = shells_.back().distance * d + 0.5 * parameters_.shellWidth * d;
    if (reach > 0.5 * packing.boxLength)
        throw std::invalid_argument(fmt::format(
            "translational order: the outermost of {} fcc shells reaches {:g} d, beyond L / 2 = "
            "{:g} d; {} shells fit this box",
            parameters_.shellCount, reach / d, 0.5 * packing.boxLength / d,
            fccShellsThatFit(packing, parameters_)));
    return tabulate(packing, shells_, parameters_, d);
}

} // namespace sbpack
