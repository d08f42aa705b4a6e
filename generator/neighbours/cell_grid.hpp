#pragma once
// A periodic grid of cubic cells at least as wide as an interaction range, so that points closer
// than the range lie in the same or adjacent cells. Fewer than 3 cells per side: one cell holds
// everything (all pairs are candidates).

#include <Eigen/Core>

#include <array>
#include <vector>

namespace sbpack {

class CellGrid {
  public:
    /// Cells at least `minimumCellWidth` wide (one cell if fewer than 3 fit per side).
    CellGrid(double boxLength, double minimumCellWidth, int particles);

    int cellsPerSide() const { return n_; }
    double cellWidth() const { return width_; }
    int cellOf(int particle) const { return cell_[particle]; }
    std::array<int, 3> coordinates(int cell) const {
        return {cell / (n_ * n_), cell / n_ % n_, cell % n_};
    }
    /// Cell index of integer coordinates, wrapped periodically.
    int index(int x, int y, int z) const { return (wrap(x) * n_ + wrap(y)) * n_ + wrap(z); }
    /// The cell whose half-open box contains r (r is clamped into [0, L)).
    int cellContaining(const Eigen::Vector3d& r) const;

    void insert(int particle, int cell);
    void erase(int particle);

    /// Visits every particle in the 27 cells around `cell` (the whole box if one cell).
    template <class Visit> void forEachNearby(int cell, Visit&& visit) const {
        if (n_ == 1) return forEachIn(0, visit);
        const auto c = coordinates(cell);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz)
                    forEachIn(index(c[0] + dx, c[1] + dy, c[2] + dz), visit);
    }

  private:
    int wrap(int i) const { return i < 0 ? i + n_ : (i >= n_ ? i - n_ : i); }
    template <class Visit> void forEachIn(int cell, Visit& visit) const {
        for (int j = head_[cell]; j >= 0; j = next_[j])
            visit(j);
    }

    int n_;
    double width_;
    std::vector<int> head_;
    std::vector<int> next_, previous_, cell_;
};

} // namespace sbpack
