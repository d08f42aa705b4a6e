#include "order/solid_like.hpp"

#include "order/bond_orientational_order.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace sbpack {

namespace {

/// Disjoint sets of particles (union by size, path halving).
class Clusters {
  public:
    explicit Clusters(std::size_t count) : parent_(count), size_(count, 1) {
        std::iota(parent_.begin(), parent_.end(), std::size_t{0});
    }
    std::size_t root(std::size_t i) {
        while (parent_[i] != i)
            i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    void join(std::size_t a, std::size_t b) {
        a = root(a);
        b = root(b);
        if (a == b) return;
        if (size_[a] < size_[b]) std::swap(a, b);
        parent_[b] = a;
        size_[a] += size_[b];
    }
    std::size_t size(std::size_t i) { return size_[root(i)]; }

  private:
    std::vector<std::size_t> parent_;
    std::vector<std::size_t> size_;
};

/// d_l(i, j) of each bond (Eq. 5.1): the normalised product of the two particles' bond harmonics,
/// the normalisation by N_b cancelling.
std::vector<double> bondCorrelations(const NeighbourBonds& bonds, const BondHarmonics& harmonics) {
    std::vector<double> norm(bonds.particleCount);
    for (std::size_t i = 0; i < norm.size(); ++i)
        norm[i] = std::sqrt(harmonicProduct(harmonics.sums[i], harmonics.sums[i]));
    std::vector<double> correlation;
    correlation.reserve(bonds.bonds.size());
    for (const Bond& b : bonds.bonds)
        correlation.push_back(harmonicProduct(harmonics.sums[b.i], harmonics.sums[b.j]) /
                              (norm[b.i] * norm[b.j]));
    return correlation;
}

/// A crystal-like bond: d_l above the threshold (NaN is not).
bool crystalLike(double correlation, const SolidLikeParameters& parameters) {
    return correlation > parameters.bondThreshold;
}

/// The largest set of solid-like particles joined by crystal-like bonds.
std::size_t largestCluster(const NeighbourBonds& bonds, const SolidLikeResult& r) {
    Clusters clusters(bonds.particleCount);
    for (std::size_t k = 0; k < bonds.bonds.size(); ++k) {
        const Bond& b = bonds.bonds[k];
        if (crystalLike(r.bondCorrelation[k], r.parameters) && r.solidLike[b.i] && r.solidLike[b.j])
            clusters.join(b.i, b.j);
    }
    std::size_t largest = 0;
    for (std::size_t i = 0; i < bonds.particleCount; ++i)
        if (r.solidLike[i]) largest = std::max(largest, clusters.size(i));
    return largest;
}

} // namespace

SolidLikeParticles::SolidLikeParticles(SolidLikeParameters parameters) : parameters_(parameters) {
    if (parameters_.degree < 1 || !(std::abs(parameters_.bondThreshold) < 1.0) ||
        parameters_.solidThreshold < 1)
        throw std::invalid_argument(fmt::format(
            "solid-like particles: need l >= 1, a bond threshold in (-1, 1) and at least one "
            "crystal-like bond, not l = {}, {:g}, {}",
            parameters_.degree, parameters_.bondThreshold, parameters_.solidThreshold));
}

SolidLikeResult SolidLikeParticles::compute(const NeighbourBonds& bonds) const {
    if (bonds.particleCount == 0)
        throw std::invalid_argument("solid-like particles: the bonds are of no particle");
    const std::size_t n = bonds.particleCount;
    SolidLikeResult r;
    r.parameters = parameters_;
    BondHarmonics harmonics = bondHarmonics(bonds, parameters_.degree);
    r.bondCorrelation = bondCorrelations(bonds, harmonics);
    r.neighbourCount = std::move(harmonics.neighbourCount);
    r.crystalBonds.assign(n, 0);
    for (std::size_t k = 0; k < bonds.bonds.size(); ++k) {
        const Bond& b = bonds.bonds[k];
        if (crystalLike(r.bondCorrelation[k], parameters_)) {
            ++r.crystalBonds[b.i];
            ++r.crystalBonds[b.j];
        }
    }
    r.solidLike.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        r.solidLike[i] = r.crystalBonds[i] >= parameters_.solidThreshold;
    r.solidCount =
        static_cast<std::size_t>(std::count(r.solidLike.begin(), r.solidLike.end(), true));
    r.solidFraction = static_cast<double>(r.solidCount) / static_cast<double>(n);
    r.largestClusterSize = largestCluster(bonds, r);
    r.largestClusterFraction = static_cast<double>(r.largestClusterSize) / static_cast<double>(n);
    return r;
}

} // namespace sbpack
