#pragma once
// DTS near-neighbour lists (the scheduler's neighbour structure): each particle has an anchor,
// its position when its list was last built, and stays within `skin / 2` of it (an exit event
// relists it). Two particles are listed iff their anchors are closer than reach = D_max + skin,
// so unlisted particles are farther apart than D_max and cannot touch while D <= D_max. Lists
// are symmetric and built from a cell grid of the anchors.

#include "neighbours/cell_grid.hpp"

#include <Eigen/Core>

#include <vector>

namespace sbpack {

/// The skin (units of D) of the lists at packing fraction phi (docs/design.md §3, "Neighbour-list
/// skin"): five mean free paths of hard spheres, D / (6 sqrt(2) phi g(phi)) with the
/// Carnahan-Starling contact value g = (1 - phi / 2) / (1 - phi)^3, within [0.1, 0.5]. A particle
/// is relisted after flying skin D / 2: a skin fixed at 0.1 D makes relisting dominate at low
/// density, a wider skin lists more pairs, and five free paths is the trade kept
/// (bench/RESULTS.md, "Where sbgen's time goes at low density", "Neighbour-list skin from the
/// packing fraction"; "Measurement history moved out of code comments"). From phi ~ 0.57 up it
/// is 0.1.
double neighbourSkin(double packingFraction);

class NeighbourLists {
  public:
    NeighbourLists() = default;
    /// Lists every pair whose anchors (any positions; wrapped internally) are closer than reach.
    NeighbourLists(double boxLength, double reach, std::vector<Eigen::Vector3d> anchors);

    double reach() const { return reach_; }
    const std::vector<int>& of(int i) const { return lists_[i]; }
    const Eigen::Vector3d& anchor(int i) const { return anchors_[i]; }

    /// Moves i's anchor and rebuilds its list (and i's entry in its old and new neighbours').
    void reanchor(int i, const Eigen::Vector3d& anchor);

  private:
    bool near(int i, int j) const;
    void list(int i); ///< fills lists_[i] from the grid (without touching other lists)

    double box_ = 1.0;
    double reach_ = 0.0;
    CellGrid grid_{1.0, 1.0, 0};
    std::vector<Eigen::Vector3d> anchors_;
    std::vector<std::vector<int>> lists_;
};

} // namespace sbpack
