#include "neighbours/cell_grid.hpp"

#include <algorithm>

namespace sbpack {

CellGrid::CellGrid(double boxLength, double minimumCellWidth, int particles)
    : cells_(boxLength, minimumCellWidth, static_cast<std::size_t>(std::max(particles, 0))),
      head_(static_cast<std::size_t>(cells_.count()), -1), next_(particles, -1),
      previous_(particles, -1), cell_(particles, -1) {}

void CellGrid::insert(int particle, int cell) {
    cell_[particle] = cell;
    previous_[particle] = -1;
    next_[particle] = head_[cell];
    if (head_[cell] >= 0) previous_[head_[cell]] = particle;
    head_[cell] = particle;
}

void CellGrid::erase(int particle) {
    const int before = previous_[particle], after = next_[particle];
    if (before >= 0)
        next_[before] = after;
    else
        head_[cell_[particle]] = after;
    if (after >= 0) previous_[after] = before;
    cell_[particle] = -1;
}

} // namespace sbpack
