#include "order/order_metrics.hpp"

#include "order/neighbour_bonds.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sbpack {

namespace {

BondOrder bondOrder(const NeighbourBonds& bonds) {
    return {steinhardtOrder(bonds, 4), steinhardtOrder(bonds, 6)};
}

/// g2 up to 3 w or the largest whole number of bins within L / 2.
PairCorrelationResult pairCorrelation(const Packing& packing) {
    PairCorrelationParameters parameters;
    const double half = 0.5 * packing.boxLength / packing.shape().meanWidth();
    const double bins = std::floor(std::min(parameters.maxDistance, half) / parameters.binWidth);
    parameters.maxDistance = bins * parameters.binWidth;
    return PairCorrelation(parameters).compute(packing);
}

std::optional<double> firstMinimumOf(const PairCorrelationResult& g2) {
    try {
        return firstMinimum(g2);
    } catch (const std::runtime_error&) {
        return std::nullopt; // no minimum below 1 within the box
    }
}

/// The solid-like particles over the SANN bonds; none where a SANN shell does not close in the box.
std::optional<SolidLikeResult> solidLikeParticles(const Packing& packing) {
    try {
        return SolidLikeParticles().compute(sannBonds(packing));
    } catch (const std::runtime_error&) {
        return std::nullopt; // a box too small for the rule
    }
}

} // namespace

OrderMetrics measureOrder(const Packing& packing,
                          const std::vector<std::pair<int, int>>* contacts) {
    if (packing.size() < 2)
        throw std::invalid_argument(fmt::format(
            "order metrics: a packing of {} particle has no pairs; they need 2 or more (leave "
            "order out of --compute)",
            packing.size()));
    OrderMetrics m;
    m.pairCorrelation = pairCorrelation(packing);
    m.cutoff = firstMinimumOf(m.pairCorrelation);
    if (m.cutoff) {
        const NeighbourBonds bonds = distanceBonds(packing, *m.cutoff);
        if (!bonds.bonds.empty()) m.cutoffBonds = bondOrder(bonds);
    }
    if (contacts != nullptr && !contacts->empty())
        m.contactBonds = bondOrder(contactBonds(packing, *contacts));
    TranslationalOrderParameters t;
    t.shellCount = fccShellsThatFit(packing, t);
    if (t.shellCount > 0) m.translational = TranslationalOrder(t).compute(packing);
    if (packing.shape().hasCubicAxes()) m.cubatic = cubaticOrder(packing.orientations);
    m.solidLike = solidLikeParticles(packing);
    return m;
}

OrderVerdict orderVerdict(const OrderMetrics& metrics) {
    std::string reason;
    auto because = [&reason](const std::string& why) {
        reason += (reason.empty() ? "" : "; ") + why;
    };
    if (metrics.cutoffBonds && metrics.cutoffBonds->q6.meanLocalOrder >= kOrderedLocalQ6)
        because(fmt::format("mean local q6 = {:.3f} >= {} (fcc 0.575, MRJ {}-{})",
                            metrics.cutoffBonds->q6.meanLocalOrder, kOrderedLocalQ6, kMrjLocalQ6Low,
                            kMrjLocalQ6High));
    // T over fewer than its 12 shells is dominated by the contact shell (a dense disordered
    // box of N = 40 spheres reaches 0.46 over 2): not evidence of order.
    const TranslationalOrderParameters full;
    if (metrics.translational && metrics.translational->parameters.shellCount == full.shellCount &&
        metrics.translational->order >= kOrderedT)
        because(fmt::format("T = {:.3f} >= {} (fcc 1, MRJ 0.04-0.09)", metrics.translational->order,
                            kOrderedT));
    if (metrics.cubatic && metrics.cubatic->order >= kOrderedP4)
        because(fmt::format("P4 = {:.3f} >= {} (aligned axes 1, MRJ 0.00-0.06)",
                            metrics.cubatic->order, kOrderedP4));
    if (const auto& s = metrics.solidLike; s && s->solidFraction >= kOrderedSolidFraction)
        because(fmt::format("solid-like fraction = {:.3f} >= {} (lattices 1, MRJ 0.006-0.09)",
                            s->solidFraction, kOrderedSolidFraction));
    if (const auto& s = metrics.solidLike; s && s->largestClusterFraction >= kOrderedCrystalCluster)
        because(fmt::format("largest crystalline cluster = {:.3f} N >= {} N (MRJ <= 0.031 N)",
                            s->largestClusterFraction, kOrderedCrystalCluster));
    return {!reason.empty(), reason};
}

} // namespace sbpack
