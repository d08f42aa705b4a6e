#include "contacts/cell_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

/// Cells per side: the most cells whose edge L / n still exceeds range by a relative margin, so
/// that binning round-off (a few ulp of x n / L) cannot separate two particles within range by
/// more than one cell. Capped so that the cell count stays O(N) for a tiny range; below 3 cells
/// per side the 27 neighbour cells are not distinct and a single cell is used.
int chooseCellsPerSide(std::size_t particleCount, double boxLength, double range) {
    constexpr double binningMargin = 1e-12;
    const double byRange = std::floor(boxLength / (range * (1.0 + binningMargin)));
    const double byCount =
        std::max(3.0, std::floor(std::cbrt(8.0 * static_cast<double>(particleCount))));
    const int n = static_cast<int>(std::min(byRange, byCount));
    return n < 3 ? 1 : n;
}

} // namespace

CellList::CellList(const std::vector<Vector3d>& positions, double boxLength, double range)
    : positions_(positions), boxLength_(boxLength), rangeSquared_(range * range) {
    if (!(boxLength > 0.0) || !std::isfinite(boxLength))
        throw std::invalid_argument("cell list: box length " + std::to_string(boxLength) +
                                    " must be positive and finite");
    if (!(range > 0.0) || !std::isfinite(range))
        throw std::invalid_argument("cell list: interaction range " + std::to_string(range) +
                                    " must be positive and finite");
    if (range > 0.5 * boxLength)
        throw std::invalid_argument("cell list: interaction range " + std::to_string(range) +
                                    " exceeds half the box edge " +
                                    std::to_string(0.5 * boxLength) +
                                    "; the minimum image would be ambiguous");
    if (positions.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw std::invalid_argument("cell list: " + std::to_string(positions.size()) +
                                    " particles exceed the int index range");

    const int count = static_cast<int>(positions.size());
    const int n = chooseCellsPerSide(positions.size(), boxLength, range);
    cellsPerSide_ = n;

    // Counting sort of the particles by cell.
    std::vector<int> cellOf(count);
    cellStart_.assign(static_cast<std::size_t>(n) * n * n + 1, 0);
    for (int i = 0; i < count; ++i) {
        if (!positions[i].allFinite())
            throw std::invalid_argument("cell list: position of particle " + std::to_string(i) +
                                        " is not finite");
        const Vector3d r = wrapIntoBox(positions[i], boxLength);
        int cell = 0;
        for (int k = 0; k < 3; ++k)
            cell = cell * n + std::min(n - 1, static_cast<int>(r[k] * n / boxLength));
        cellOf[i] = cell;
        ++cellStart_[cell + 1];
    }
    std::partial_sum(cellStart_.begin(), cellStart_.end(), cellStart_.begin());
    particlesInCellOrder_.resize(count);
    std::vector<int> next(cellStart_.begin(), cellStart_.end() - 1);
    for (int i = 0; i < count; ++i)
        particlesInCellOrder_[next[cellOf[i]]++] = i;
}

} // namespace sbpack
