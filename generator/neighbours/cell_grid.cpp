#include "neighbours/cell_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sbpack {

CellGrid::CellGrid(double boxLength, double minimumCellWidth, int particles) {
    if (!(boxLength > 0.0) || !(minimumCellWidth > 0.0))
        throw std::invalid_argument("CellGrid: box length and cell width must be positive");
    const double fit = std::floor(boxLength / minimumCellWidth);
    // More cells than ~8 per particle only cost memory and empty visits.
    const double useful = std::max(3.0, std::floor(std::cbrt(8.0 * particles)));
    n_ = fit >= 3.0 ? static_cast<int>(std::min(fit, useful)) : 1;
    width_ = boxLength / n_;
    head_.assign(static_cast<std::size_t>(n_) * n_ * n_, -1);
    next_.assign(particles, -1);
    previous_.assign(particles, -1);
    cell_.assign(particles, -1);
}

int CellGrid::cellContaining(const Eigen::Vector3d& r) const {
    int c[3];
    for (int k = 0; k < 3; ++k)
        c[k] = std::clamp(static_cast<int>(std::floor(r[k] / width_)), 0, n_ - 1);
    return (c[0] * n_ + c[1]) * n_ + c[2];
}

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
