#pragma once
// The cells of a cubic periodic box (docs/design.md §7, "one cell rule"): how many per side for an
// interaction range, which cell holds a point, and a cell's neighbours. One rule for both cell
// structures: the generator's linked cells (generator/neighbours/cell_grid, particles move between
// cells) and the contacts' sorted cell list (common/contacts/cell_list, built once).

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace sbpack {

class PeriodicCells {
  public:
    /// The most cells per side whose edge L / n still exceeds `range` by a relative margin of
    /// 1e-12, so that binning round-off (a few ulp of x / width) cannot put two points within
    /// range more than one cell apart; capped at cbrt(8 N), since more cells only cost memory and
    /// empty visits. Below 3 per side the 27 neighbours are not distinct: one cell holds all.
    /// Throws std::invalid_argument unless L and range are positive and finite.
    PeriodicCells(double boxLength, double range, std::size_t particles) {
        if (!(boxLength > 0.0) || !std::isfinite(boxLength))
            throw std::invalid_argument("cells: box length " + std::to_string(boxLength) +
                                        " must be positive and finite");
        if (!(range > 0.0) || !std::isfinite(range))
            throw std::invalid_argument("cells: interaction range " + std::to_string(range) +
                                        " must be positive and finite");
        constexpr double kBinningMargin = 1e-12;
        const double byRange = std::floor(boxLength / (range * (1.0 + kBinningMargin)));
        const double byCount =
            std::max(3.0, std::floor(std::cbrt(8.0 * static_cast<double>(particles))));
        const double n = std::min(byRange, byCount);
        perSide_ = n >= 3.0 ? static_cast<int>(n) : 1;
        width_ = boxLength / perSide_;
    }

    int perSide() const { return perSide_; }
    int count() const { return perSide_ * perSide_ * perSide_; }
    double width() const { return width_; }

    int wrap(int i) const { return i < 0 ? i + perSide_ : (i >= perSide_ ? i - perSide_ : i); }
    /// Cell index of integer coordinates, wrapped periodically.
    int index(int x, int y, int z) const {
        return (wrap(x) * perSide_ + wrap(y)) * perSide_ + wrap(z);
    }
    std::array<int, 3> coordinates(int cell) const {
        return {cell / (perSide_ * perSide_), cell / perSide_ % perSide_, cell % perSide_};
    }
    /// The cell whose half-open box holds r, for r in [0, L) (clamped into the box).
    int cellContaining(const Eigen::Vector3d& r) const {
        std::array<int, 3> c{};
        for (int k = 0; k < 3; ++k)
            c[k] = std::clamp(static_cast<int>(std::floor(r[k] / width_)), 0, perSide_ - 1);
        return (c[0] * perSide_ + c[1]) * perSide_ + c[2];
    }

    /// Half of the 26 neighbour offsets (those whose first non-zero component is positive): a
    /// cell paired with itself and these visits each pair of adjacent cells once.
    static constexpr std::array<std::array<int, 3>, 13> kHalfShell = {{{1, -1, -1},
                                                                       {1, -1, 0},
                                                                       {1, -1, 1},
                                                                       {1, 0, -1},
                                                                       {1, 0, 0},
                                                                       {1, 0, 1},
                                                                       {1, 1, -1},
                                                                       {1, 1, 0},
                                                                       {1, 1, 1},
                                                                       {0, 1, -1},
                                                                       {0, 1, 0},
                                                                       {0, 1, 1},
                                                                       {0, 0, 1}}};

  private:
    int perSide_ = 1;
    double width_ = 0.0;
};

} // namespace sbpack
