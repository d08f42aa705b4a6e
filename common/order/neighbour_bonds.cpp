#include "order/neighbour_bonds.hpp"

#include "contacts/cell_list.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sbpack {

NeighbourBonds contactBonds(const Packing& packing, const std::vector<std::pair<int, int>>& pairs) {
    const auto count = static_cast<int>(packing.size());
    NeighbourBonds result{packing.size(), {}};
    result.bonds.reserve(pairs.size());
    for (auto [a, b] : pairs) {
        if (a < 0 || b < 0 || a >= count || b >= count || a == b)
            throw std::invalid_argument(
                fmt::format("neighbour bonds: pair ({}, {}) is not a pair of two of the {} "
                            "particles",
                            a, b, count));
        const int i = std::min(a, b);
        const int j = std::max(a, b);
        result.bonds.push_back(
            {i, j, minimumImage(packing.positions[j] - packing.positions[i], packing.boxLength)});
    }
    return result;
}

NeighbourBonds distanceBonds(const Packing& packing, double cutoff) {
    const double meanWidth = packing.shape().meanWidth();
    if (!(cutoff > 0.0) || !(cutoff * meanWidth <= 0.5 * packing.boxLength))
        throw std::invalid_argument(fmt::format(
            "neighbour bonds: the cutoff must be in (0, L / 2 = {:g}] mean widths, not {:g}",
            0.5 * packing.boxLength / meanWidth, cutoff));
    NeighbourBonds result{packing.size(), {}};
    forEachNeighbourPair(packing.positions, packing.boxLength, cutoff * meanWidth,
                         [&](int i, int j, const Vector3d& d) {
                             result.bonds.push_back({i, j, d});
                         });
    return result;
}

} // namespace sbpack
