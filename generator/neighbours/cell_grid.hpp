#pragma once
// Linked cells of a periodic box, at least as wide as an interaction range, so that points closer
// than the range lie in the same or adjacent cells; particles are inserted and moved one by one.
// The cell rule is common/geometry/periodic_cells (fewer than 3 cells per side: one cell holds
// everything, all pairs are candidates).

#include "geometry/periodic_cells.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace sbpack {

class CellGrid {
  public:
    /// Cells wider than `minimumCellWidth` (PeriodicCells' rule).
    CellGrid(double boxLength, double minimumCellWidth, int particles);

    int cellsPerSide() const { return cells_.perSide(); }
    double cellWidth() const { return cells_.width(); }
    int cellOf(int particle) const { return cell_[particle]; }
    /// The cell whose half-open box contains r (r is clamped into [0, L)).
    int cellContaining(const Eigen::Vector3d& r) const { return cells_.cellContaining(r); }

    void insert(int particle, int cell);
    void erase(int particle);

    /// Visits every particle in the 27 cells around `cell` (the whole box if one cell).
    template <class Visit> void forEachNearby(int cell, Visit&& visit) const {
        if (cells_.perSide() == 1) return forEachIn(0, visit);
        const auto c = cells_.coordinates(cell);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz)
                    forEachIn(cells_.index(c[0] + dx, c[1] + dy, c[2] + dz), visit);
    }

  private:
    template <class Visit> void forEachIn(int cell, Visit& visit) const {
        for (int j = head_[cell]; j >= 0; j = next_[j])
            visit(j);
    }

    PeriodicCells cells_;
    std::vector<int> head_;
    std::vector<int> next_, previous_, cell_;
};

} // namespace sbpack
