#include "contacts/contact_network.hpp"

#include "contacts/cell_list.hpp"
#include "pair/pair_geometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

/// Slack, in units of D, of the check of a pair solve against the exact bounds
/// |d| - 2 circumradius <= s <= |d| - 2 inradius: far above round-off, far below any real error.
constexpr double boundSlack = 1e-9;

std::string pairName(int i, int j) {
    return "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
}

/// Iterative removal of the particles with fewer than threshold contacts among the remaining
/// ones (docs/design.md §3): the threshold-core of the contact graph. Returns the rattler flags.
std::vector<bool> findRattlers(int count, const std::vector<std::pair<int, int>>& contacts,
                               const std::vector<int>& counts, int threshold) {
    std::vector<int> neighbourStart(count + 1, 0);
    for (int i = 0; i < count; ++i)
        neighbourStart[i + 1] = neighbourStart[i] + counts[i];
    std::vector<int> neighbours(neighbourStart[count]);
    std::vector<int> next(neighbourStart.begin(), neighbourStart.end() - 1);
    for (const auto& [i, j] : contacts) {
        neighbours[next[i]++] = j;
        neighbours[next[j]++] = i;
    }

    std::vector<int> remainingContacts = counts;
    std::vector<bool> rattler(count, false);
    std::vector<int> toRemove;
    for (int i = 0; i < count; ++i)
        if (remainingContacts[i] < threshold) {
            rattler[i] = true;
            toRemove.push_back(i);
        }
    while (!toRemove.empty()) {
        const int i = toRemove.back();
        toRemove.pop_back();
        for (int k = neighbourStart[i]; k < neighbourStart[i + 1]; ++k) {
            const int j = neighbours[k];
            if (rattler[j]) continue;
            if (--remainingContacts[j] < threshold) {
                rattler[j] = true;
                toRemove.push_back(j);
            }
        }
    }
    return rattler;
}

/// The exact bounds on a pair's signed distance from its centre distance r: r - 2 R_out <= s <=
/// r - 2 R_in (below 2 R_in the pair certainly touches or overlaps), each widened by `slack`;
/// for a mixture's pair the two bodies' radii summed (`pairScale` = (R_i + R_j) / 2R).
struct SphereBounds {
    double inradius, circumradius, slack;
    explicit SphereBounds(const ParticleShape& shape, double pairScale = 1.0)
        : inradius(shape.inradius() * pairScale), circumradius(shape.circumradius() * pairScale),
          slack(boundSlack * shape.diameter() * pairScale) {}
};

/// Pair (i, j) of `packing`: A with i's shape, B scaled to j's (docs/mixtures.md).
BodyPair<ParticleShape> pairOf(const Packing& packing, const ParticleShape& shape, int i, int j,
                               const std::vector<Matrix3d>& rotations, const Vector3d& d) {
    if (!packing.isMixture()) return {shape, rotations[i], rotations[j], d};
    const double ri = packing.semiAxisOf(i), rj = packing.semiAxisOf(j);
    return {ParticleShape(packing.shapeSpec, ri), rotations[i], rotations[j], d, rj / ri};
}

/// Throws unless s of pair (i, j) at this centre distance lies within the sphere bounds.
void checkAgainstSpheres(const SphereBounds& bounds, double s, double centreDistance, int i,
                         int j) {
    if (!std::isfinite(s) || s > centreDistance - 2.0 * bounds.inradius + bounds.slack ||
        s < centreDistance - 2.0 * bounds.circumradius - bounds.slack)
        throw std::runtime_error("contact network: signed distance " + std::to_string(s) +
                                 " of pair " + pairName(i, j) + " at centre distance " +
                                 std::to_string(centreDistance) +
                                 " violates the inradius/circumradius bounds");
}

} // namespace

void removeRattlers(ContactResult& result, int threshold) {
    const int count = static_cast<int>(result.counts.size());
    result.rattler = findRattlers(count, result.contacts, result.counts, threshold);
    const long rattlers = std::count(result.rattler.begin(), result.rattler.end(), true);
    long contactsAmongRemaining = 0;
    for (const auto& [i, j] : result.contacts)
        if (!result.rattler[i] && !result.rattler[j]) ++contactsAmongRemaining;
    const long remaining = count - rattlers;
    result.meanContactNumber =
        remaining > 0 ? 2.0 * static_cast<double>(contactsAmongRemaining) / remaining : 0.0;
    result.rattlerFraction = count > 0 ? static_cast<double>(rattlers) / count : 0.0;
}

std::string describeOverlaps(const ContactResult& contacts, double diameter) {
    if (contacts.overlappingPairs == 0) return "";
    char depth[32];
    std::snprintf(depth, sizeof depth, "%.3g", -contacts.worstGap / diameter);
    return std::to_string(contacts.overlappingPairs) + " overlapping pair(s), the worst (" +
           std::to_string(contacts.worstPairA) + ", " + std::to_string(contacts.worstPairB) +
           ") by " + depth + " D";
}

ContactNetwork::ContactNetwork(ContactParameters parameters) : parameters_(parameters) {
    const double largest = parameters_.neighbours ? ContactParameters::kMaxNeighbourTolerance
                                                  : ContactParameters::kMaxTolerance;
    if (!(parameters_.tolerance >= 0.0 && parameters_.tolerance <= largest))
        throw std::invalid_argument(
            fmt::format("contact network: tolerance {:g} must be in [0, {:g}] (a gap in units of "
                        "D{})",
                        parameters_.tolerance, largest,
                        parameters_.neighbours ? "; the jamming finite-gap test's pairs" : ""));
    if (parameters_.rattlerThreshold < 1)
        throw std::invalid_argument("contact network: rattler threshold " +
                                    std::to_string(parameters_.rattlerThreshold) +
                                    " must be at least 1");
}

ContactResult ContactNetwork::compute(const Packing& packing) const {
    const std::size_t size = packing.size();
    if (packing.orientations.size() != size)
        throw std::invalid_argument("contact network: packing has " + std::to_string(size) +
                                    " positions but " +
                                    std::to_string(packing.orientations.size()) + " orientations");
    const ParticleShape shape = packing.shape();
    const double diameter = shape.diameter();
    const double contactGap = parameters_.tolerance * diameter;
    const SphereBounds bounds(shape);
    // Beyond this centre distance the gap is at least contactGap.
    const double range = 2.0 * bounds.circumradius + contactGap;

    std::vector<Matrix3d> rotations(size);
    for (std::size_t i = 0; i < size; ++i)
        rotations[i] = packing.orientations[i].normalized().toRotationMatrix();

    ContactResult result;
    result.parameters = parameters_;
    result.counts.assign(size, 0);
    result.worstGap = std::numeric_limits<double>::infinity();
    struct Found {
        std::pair<int, int> pair;
        double gap; ///< / D
        Vector3d normal;
        Vector3d point;
    };
    std::vector<Found> found;
    if (range > 0.5 * packing.boxLength)
        throw std::invalid_argument(fmt::format(
            "contact network: the box edge L = {:g} D is too small: a particle reaches {:g} D "
            "(its circumscribed diameter and the tolerance), and pairs by the minimum image need "
            "L > {:g} D, one image of each neighbour",
            packing.boxLength / diameter, range / diameter, 2.0 * range / diameter));
    const CellList cells(packing.positions, packing.boxLength, range);
    cells.forEachNeighbourPair([&](int i, int j, const Vector3d& d) {
        // A mixture's pair: its own diameter R_i + R_j sizes the tolerance and the gap's unit.
        const double scale = packing.pairSize(i, j);
        const double pairDiameter = diameter * scale, pairGap = contactGap * scale;
        const SignedDistanceResult pair =
            signedDistance(pairOf(packing, shape, i, j, rotations, d));
        const double s = pair.signedDistance;
        checkAgainstSpheres(scale == 1.0 ? bounds : SphereBounds(shape, scale), s, d.norm(), i, j);
        result.pairIterations += pair.iterations;
        if (s < result.worstGap) {
            result.worstGap = s;
            result.worstPairA = i;
            result.worstPairB = j;
        }
        if (s < -pairGap) ++result.overlappingPairs;
        if (s < pairGap) { // paper Sec. III A
            found.push_back({{i, j}, s / pairDiameter, pair.normal, contactPoint(pair)});
            ++result.counts[i];
            ++result.counts[j];
        }
    });
    std::sort(found.begin(), found.end(),
              [](const Found& a, const Found& b) { return a.pair < b.pair; });
    for (const Found& contact : found) {
        result.contacts.push_back(contact.pair);
        result.gaps.push_back(contact.gap);
        result.normals.push_back(contact.normal);
        result.points.push_back(contact.point);
    }
    removeRattlers(result, parameters_.rattlerThreshold);
    return result;
}

} // namespace sbpack
