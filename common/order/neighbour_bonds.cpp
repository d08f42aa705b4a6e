#include "order/neighbour_bonds.hpp"

#include "contacts/cell_list.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace sbpack {

namespace {

struct Neighbour {
    double distance = 0.0;
    int index = 0;
};

/// Each particle's neighbours closer than `range` (minimum image), nearest first.
std::vector<std::vector<Neighbour>> neighboursWithin(const Packing& packing, double range) {
    std::vector<std::vector<Neighbour>> near(packing.size());
    forEachNeighbourPair(packing.positions, packing.boxLength, range,
                         [&](int i, int j, const Vector3d& d) {
                             near[i].push_back({d.norm(), j});
                             near[j].push_back({d.norm(), i});
                         });
    for (auto& list : near)
        std::sort(list.begin(), list.end(),
                  [](const Neighbour& a, const Neighbour& b) { return a.distance < b.distance; });
    return near;
}

/// The SANN shell size of one particle (van Meel et al. Eq. 3) from all its neighbours closer
/// than `range`, nearest first: the smallest m >= 3 with R(m) = sum_{k<=m} r_k / (m - 2) <
/// r_{m+1}, where past the list's end r_{m+1} >= range; 0 where the list does not decide it.
std::size_t sannShellSize(const std::vector<Neighbour>& near, double range) {
    double sum = 0.0;
    for (std::size_t m = 1; m <= near.size(); ++m) {
        sum += near[m - 1].distance;
        const double next = m < near.size() ? near[m].distance : range;
        if (m >= 3 && sum / static_cast<double>(m - 2) < next) return m;
    }
    return 0;
}

/// The pairs of each particle with the first shellSize[i] of its neighbours, each pair once.
NeighbourBonds shellBonds(const Packing& packing, const std::vector<std::vector<Neighbour>>& near,
                          const std::vector<std::size_t>& shellSize) {
    std::vector<std::pair<int, int>> pairs;
    for (std::size_t i = 0; i < near.size(); ++i)
        for (std::size_t k = 0; k < shellSize[i]; ++k) {
            const auto a = static_cast<int>(i);
            const int b = near[i][k].index;
            pairs.emplace_back(std::min(a, b), std::max(a, b));
        }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return contactBonds(packing, pairs);
}

/// Where the search for the SANN shells starts, in units of the mean spacing rho^{-1/3}: 24
/// neighbours on average, the simple-cubic shell of 18 and its radius 1.44 rho^{-1/3} inside.
constexpr double kSannFirstRange = 1.8;

} // namespace

void NeighbourBonds::add(int i, int j, const Vector3d& vector) {
    if (vector.squaredNorm() > 0.0)
        bonds.push_back({i, j, vector});
    else
        ++coincident;
}

NeighbourBonds contactBonds(const Packing& packing, const std::vector<std::pair<int, int>>& pairs) {
    const auto count = static_cast<int>(packing.size());
    NeighbourBonds result{packing.size(), {}, 0};
    result.bonds.reserve(pairs.size());
    for (auto [a, b] : pairs) {
        if (a < 0 || b < 0 || a >= count || b >= count || a == b)
            throw std::invalid_argument(
                fmt::format("neighbour bonds: pair ({}, {}) is not a pair of two of the {} "
                            "particles",
                            a, b, count));
        const int i = std::min(a, b);
        const int j = std::max(a, b);
        result.add(i, j,
                   minimumImage(packing.positions[j] - packing.positions[i], packing.boxLength));
    }
    return result;
}

NeighbourBonds distanceBonds(const Packing& packing, double cutoff) {
    const double meanWidth = packing.shape().meanWidth();
    if (!(cutoff > 0.0) || !(cutoff * meanWidth <= 0.5 * packing.boxLength))
        throw std::invalid_argument(fmt::format(
            "neighbour bonds: the cutoff must be in (0, L / 2 = {:g}] mean widths, not {:g}",
            0.5 * packing.boxLength / meanWidth, cutoff));
    NeighbourBonds result{packing.size(), {}, 0};
    forEachNeighbourPair(packing.positions, packing.boxLength, cutoff * meanWidth,
                         [&](int i, int j, const Vector3d& d) {
                             // A mixture's pair: within cutoff w sigma_ij (docs/mixtures.md).
                             const double sigma = packing.pairSize(i, j);
                             if (sigma == 1.0 || d.norm() < cutoff * meanWidth * sigma)
                                 result.add(i, j, d);
                         });
    return result;
}

NeighbourBonds sannBonds(const Packing& packing) {
    const double half = 0.5 * packing.boxLength;
    const double spacing = packing.boxLength / std::cbrt(static_cast<double>(packing.size()));
    for (double range = std::min(kSannFirstRange * spacing, half);;
         range = std::min(1.25 * range, half)) {
        const auto near = neighboursWithin(packing, range);
        std::vector<std::size_t> shellSize(near.size());
        for (std::size_t i = 0; i < near.size(); ++i)
            shellSize[i] = sannShellSize(near[i], range);
        const auto open = std::find(shellSize.begin(), shellSize.end(), 0) - shellSize.begin();
        if (open == std::ssize(shellSize)) return shellBonds(packing, near, shellSize);
        if (range == half)
            throw std::runtime_error(fmt::format(
                "SANN neighbours: the shell of particle {} does not close within L / 2 = {:g}",
                open, half));
    }
}

} // namespace sbpack
