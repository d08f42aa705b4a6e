#pragma once
// Periodic cell list of a cubic box: visits each unordered pair of particles closer than an
// interaction range exactly once, in O(N) (docs/design.md §7: the neighbour structure that picks
// pairs).

#include "geometry/periodic_cells.hpp"
#include "packing/packing.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace sbpack {

/// Cells of edge >= range in a cubic periodic box of edge L (PeriodicCells' rule). With at least 3
/// cells per side each
/// cell is paired with itself and 13 of its 26 neighbours (a half shell); smaller boxes use a
/// single cell. Pairs are found by minimum image, which is unambiguous only for range <= L / 2.
class CellList {
  public:
    /// Bins the positions (wrapped into [0, L) for binning only). Throws std::invalid_argument
    /// unless 0 < L < inf, 0 < range <= L / 2, the positions are finite and N fits an int.
    CellList(const std::vector<Vector3d>& positions, double boxLength, double range);

    int cellsPerSide() const { return cells_.perSide(); }
    /// The cells' rule (their number and width, which cell holds a point).
    const PeriodicCells& cells() const { return cells_; }

    /// Calls visit(i) for each particle i binned in `cell` (its position wrapped into [0, L)).
    template <class Visit> void forEachInCell(int cell, Visit&& visit) const {
        for (int a = cellStart_[cell]; a < cellStart_[cell + 1]; ++a)
            visit(particlesInCellOrder_[a]);
    }

    /// Calls callback(i, j, d) once for each pair i < j with |d| < range, where
    /// d = minimumImage(r_j - r_i, L).
    template <class Callback> void forEachNeighbourPair(Callback&& callback) const;

  private:
    /// Calls callback for the pair if it is within range, ordered so that i < j.
    template <class Callback> void visitPair(int a, int b, Callback& callback) const;

    std::vector<Vector3d> positions_;
    double boxLength_;
    double rangeSquared_;
    PeriodicCells cells_;
    std::vector<int> cellStart_; ///< cell c: [cellStart_[c], cellStart_[c + 1])
    std::vector<int> particlesInCellOrder_;
};

/// Each unordered pair with |minimumImage(r_j - r_i, L)| < range, once, as callback(i, j, d), i <
/// j.
template <class Callback>
void forEachNeighbourPair(const std::vector<Vector3d>& positions, double boxLength, double range,
                          Callback&& callback) {
    CellList(positions, boxLength, range).forEachNeighbourPair(callback);
}

// --- implementation of the templates ---

template <class Callback> void CellList::visitPair(int a, int b, Callback& callback) const {
    const int i = a < b ? a : b;
    const int j = a < b ? b : a;
    const Vector3d d = minimumImage(positions_[j] - positions_[i], boxLength_);
    if (d.squaredNorm() < rangeSquared_) callback(i, j, d);
}

template <class Callback> void CellList::forEachNeighbourPair(Callback&& callback) const {
    const int n = cells_.perSide();
    const int* order = particlesInCellOrder_.data();
    if (n == 1) {
        const int count = static_cast<int>(particlesInCellOrder_.size());
        for (int a = 0; a < count; ++a)
            for (int b = a + 1; b < count; ++b)
                visitPair(order[a], order[b], callback);
        return;
    }
    for (int cx = 0; cx < n; ++cx)
        for (int cy = 0; cy < n; ++cy)
            for (int cz = 0; cz < n; ++cz) {
                const int cell = (cx * n + cy) * n + cz;
                const int begin = cellStart_[cell];
                const int end = cellStart_[cell + 1];
                for (int a = begin; a < end; ++a)
                    for (int b = a + 1; b < end; ++b)
                        visitPair(order[a], order[b], callback);
                for (const auto& offset : PeriodicCells::kHalfShell) {
                    const int other = cells_.index(cx + offset[0], cy + offset[1], cz + offset[2]);
                    const int otherBegin = cellStart_[other];
                    const int otherEnd = cellStart_[other + 1];
                    for (int a = begin; a < end; ++a)
                        for (int b = otherBegin; b < otherEnd; ++b)
                            visitPair(order[a], order[b], callback);
                }
            }
}

} // namespace sbpack
