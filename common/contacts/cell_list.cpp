#include "contacts/cell_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace sbpack {

CellList::CellList(const std::vector<Vector3d>& positions, double boxLength, double range)
    : positions_(positions), boxLength_(boxLength), rangeSquared_(range * range),
      cells_(boxLength, range, positions.size()) {
    if (range > 0.5 * boxLength)
        throw std::invalid_argument("cell list: interaction range " + std::to_string(range) +
                                    " exceeds half the box edge " +
                                    std::to_string(0.5 * boxLength) +
                                    "; the minimum image would be ambiguous");
    if (positions.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw std::invalid_argument("cell list: " + std::to_string(positions.size()) +
                                    " particles exceed the int index range");

    // Counting sort of the particles by cell.
    const int count = static_cast<int>(positions.size());
    std::vector<int> cellOf(count);
    cellStart_.assign(static_cast<std::size_t>(cells_.count()) + 1, 0);
    for (int i = 0; i < count; ++i) {
        if (!positions[i].allFinite())
            throw std::invalid_argument("cell list: position of particle " + std::to_string(i) +
                                        " is not finite");
        cellOf[i] = cells_.cellContaining(wrapIntoBox(positions[i], boxLength));
        ++cellStart_[cellOf[i] + 1];
    }
    std::partial_sum(cellStart_.begin(), cellStart_.end(), cellStart_.begin());
    particlesInCellOrder_.resize(count);
    std::vector<int> next(cellStart_.begin(), cellStart_.end() - 1);
    for (int i = 0; i < count; ++i)
        particlesInCellOrder_[next[cellOf[i]]++] = i;
}

} // namespace sbpack
