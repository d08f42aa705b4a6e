#include "neighbours/neighbour_lists.hpp"

#include "packing/packing.hpp"

#include <algorithm>
#include <cmath>

namespace sbpack {

double neighbourSkin(double packingFraction) {
    const double phi = std::clamp(packingFraction, 1e-3, 0.9);
    const double contact = (1.0 - 0.5 * phi) / std::pow(1.0 - phi, 3);
    const double freePath = 1.0 / (6.0 * std::sqrt(2.0) * phi * contact);
    return std::clamp(5.0 * freePath, 0.1, 0.5);
}

NeighbourLists::NeighbourLists(double boxLength, double reach, std::vector<Eigen::Vector3d> anchors)
    : box_(boxLength), reach_(reach), grid_(boxLength, reach, static_cast<int>(anchors.size())),
      anchors_(std::move(anchors)), lists_(anchors_.size()) {
    const int n = static_cast<int>(anchors_.size());
    for (int i = 0; i < n; ++i)
        grid_.insert(i, grid_.cellContaining(wrapIntoBox(anchors_[i], box_)));
    for (int i = 0; i < n; ++i)
        list(i);
}

bool NeighbourLists::near(int i, int j) const {
    return minimumImage(anchors_[j] - anchors_[i], box_).squaredNorm() < reach_ * reach_;
}

void NeighbourLists::list(int i) {
    lists_[i].clear();
    grid_.forEachNearby(grid_.cellOf(i), [&](int j) {
        if (j != i && near(i, j)) lists_[i].push_back(j);
    });
}

void NeighbourLists::reanchor(int i, const Eigen::Vector3d& anchor) {
    for (const int j : lists_[i]) {
        std::vector<int>& other = lists_[j];
        other.erase(std::find(other.begin(), other.end(), i));
    }
    anchors_[i] = anchor;
    grid_.erase(i);
    grid_.insert(i, grid_.cellContaining(wrapIntoBox(anchor, box_)));
    list(i);
    for (const int j : lists_[i])
        lists_[j].push_back(i);
}

} // namespace sbpack
