#include "contacts/jam_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sbpack {

namespace {

/// Below P = gapsPerPressure / maxTolerance the load-bearing gaps exceed any contact gap: no
/// network has formed yet, so a refusal says so rather than blaming a chain of near contacts.
bool isCompressing(double reducedPressure, const JamCheckParameters& parameters) {
    return parameters.gapsPerPressure / reducedPressure > parameters.maxTolerance;
}

/// The axes along which a lattice vector wraps, e.g. "y" or "x and z".
std::string axesOf(const Vector3d& wrap) {
    std::string axes;
    for (int k = 0; k < 3; ++k)
        if (wrap[k] != 0.0) axes += (axes.empty() ? "" : " and ") + std::string(1, "xyz"[k]);
    return axes;
}

/// The path from `from` up to the breadth-first tree's root.
std::vector<int> pathToRoot(int from, const std::vector<int>& parent) {
    std::vector<int> path{from};
    while (parent[path.back()] >= 0)
        path.push_back(parent[path.back()]);
    return path;
}

/// The cycle closed by the non-tree edge (a, b): a up to the common ancestor, then down to b.
std::vector<int> closedCycle(int a, int b, const std::vector<int>& parent) {
    std::vector<int> up = pathToRoot(a, parent), down = pathToRoot(b, parent);
    while (up.size() > 1 && down.size() > 1 && up[up.size() - 2] == down[down.size() - 2]) {
        up.pop_back();
        down.pop_back();
    }
    down.pop_back(); // the common ancestor, already the last of `up`
    up.insert(up.end(), down.rbegin(), down.rend());
    return up;
}

/// The count rule's rattlers and the remaining particles not locally jammed by the others
/// that remain: the fraction of all particles. One pass, not iterated: a contact just above the
/// tolerance can leave a load-bearing particle's contacts in one hemisphere, and in a network
/// at the isostatic count removing it would cascade through the whole packing (MRJ spheres:
/// 5 such particles in 5000, then all of them when iterated). With the backbone's counts (a
/// mixture's second way to pass: backboneHoldsItsCount).
struct UntrappedCounts {
    double fraction = 0.0; ///< rattlers and untrapped particles over all particles
    int free = 0;          ///< the untrapped non-rattlers
    int backbone = 0;      ///< the non-rattlers
    int backboneContacts = 0;
};

UntrappedCounts untrappedCounts(const ContactResult& contacts) {
    UntrappedCounts counts;
    const int n = static_cast<int>(contacts.rattler.size());
    std::vector<std::vector<Vector3d>> normals(n);
    for (std::size_t k = 0; k < contacts.contacts.size(); ++k) {
        const auto [i, j] = contacts.contacts[k];
        if (contacts.rattler[i] || contacts.rattler[j]) continue;
        normals[i].push_back(contacts.normals[k]);
        normals[j].push_back(-contacts.normals[k]);
        ++counts.backboneContacts;
    }
    int removed = 0;
    for (int i = 0; i < n; ++i) {
        counts.backbone += !contacts.rattler[i];
        if (contacts.rattler[i]) {
            ++removed;
        } else if (!isLocallyTrapped(normals[i])) {
            ++removed;
            ++counts.free;
        }
    }
    counts.fraction = n > 0 ? static_cast<double>(removed) / n : 0.0;
    return counts;
}

/// A mixture's second way to pass (docs/mixtures.md, "The jam check of a mixture"): its small
/// particles can rattle in the cages of a jammed structure, so past the rattler limit the
/// backbone is judged by the contacts a jammed one needs, 3 N' - 2 (a necessary condition for
/// any shape: the particles' translations alone must be blocked), with at most the limit's
/// fraction of all particles free among the non-rattlers.
bool backboneHoldsItsCount(const JamCheck& check, int free, std::size_t particles,
                           const JamCheckParameters& parameters) {
    return check.backbone > 0 && check.backboneContacts >= 3 * check.backbone - 2 &&
           free <= parameters.maxRattlerFraction * static_cast<double>(particles);
}

std::string verdictOf(const JamCheck& check, const Packing& packing, double reducedPressure,
                      const JamCheckParameters& parameters) {
    const double rattlers = check.contacts.rattlerFraction;
    std::string network =
        fmt::format("rattler fraction {:.3f} at contact gap < {:.0e} D", rattlers, check.tolerance);
    if (check.untrappedFraction > rattlers)
        network += fmt::format(", {:.3f} with the particles not locally jammed (contacts in one "
                               "hemisphere)",
                               check.untrappedFraction);
    if (check.jammed && packing.isMixture() && rattlers > parameters.maxRattlerFraction)
        return fmt::format("jammed: the backbone of {} particles has {} contacts among them (at "
                           "least 3 N' - 2 = {}); ",
                           check.backbone, check.backboneContacts, 3 * check.backbone - 2) +
               network;
    if (check.jammed) return "jammed: " + network;
    if (isCompressing(reducedPressure, parameters))
        return fmt::format(
            "not jammed: still compressing (at reduced pressure {:.3g} the load-bearing "
            "gaps, about {:.0f} / P D, exceed the largest contact gap {:.0e} D)",
            reducedPressure, parameters.gapsPerPressure, parameters.maxTolerance);
    if (packing.isMixture()) // its rattlers, then its backbone's count (docs/mixtures.md)
        return "not jammed: " + network +
               fmt::format(" (above {:.2f}), and the backbone of {} particles has {} contacts "
                           "among them, a jammed one at least 3 N' - 2 = {}",
                           parameters.maxRattlerFraction, check.backbone, check.backboneContacts,
                           std::max(3 * check.backbone - 2, 1));
    if (check.chain) {
        const SpanningChain& c = *check.chain;
        return "not jammed: a chain of " + std::to_string(c.cycle.size()) +
               " particles in contact wraps around the periodic box along " + axesOf(c.wrap) +
               fmt::format(" (box {:.2f} D) and carries the pressure; ",
                           packing.boxLength / packing.shape().diameter()) +
               network +
               (packing.shape().stacksInColumns()
                    ? ". Near-cubes stack into such columns in boxes a few D long"
                    : ". In a box this few D across, a few particles in a row span it") +
               ": use more particles";
    }
    return "not jammed: " + network + fmt::format(" (above {:.2f})", parameters.maxRattlerFraction);
}

} // namespace

bool isLocallyTrapped(const std::vector<Vector3d>& normals) {
    // The cone of free translations, when not {0}, has an extreme ray along some n_a x n_b, or
    // contains a line normal to every n_k: along n_a x n_b again, unless all n_k are parallel.
    constexpr double slack = 1e-12; // rounding of unit vectors
    auto isFree = [&](const Vector3d& v) {
        return std::all_of(normals.begin(), normals.end(),
                           [&](const Vector3d& n) { return v.dot(n) <= slack; });
    };
    bool spanned = false;
    for (std::size_t a = 0; a < normals.size(); ++a)
        for (std::size_t b = a + 1; b < normals.size(); ++b) {
            const Vector3d c = normals[a].cross(normals[b]);
            const double length = c.norm();
            if (length <= slack) continue;
            spanned = true;
            const Vector3d v = c / length;
            if (isFree(v) || isFree(-v)) return false;
        }
    return spanned; // all on one line: any direction normal to it is free
}

std::optional<SpanningChain> findSpanningChain(const Packing& packing,
                                               const std::vector<std::pair<int, int>>& contacts) {
    const int n = static_cast<int>(packing.size());
    const double box = packing.boxLength;
    std::vector<std::vector<int>> neighbours(n);
    for (const auto& [i, j] : contacts) {
        neighbours[i].push_back(j);
        neighbours[j].push_back(i);
    }
    std::vector<Vector3d> unwrapped(n);
    std::vector<int> parent(n, -1), component(n, -1);
    for (int root = 0; root < n; ++root) {
        if (component[root] >= 0 || neighbours[root].empty()) continue;
        std::vector<int> members{root};
        component[root] = root;
        unwrapped[root] = packing.positions[root];
        for (std::size_t next = 0; next < members.size(); ++next) {
            const int a = members[next];
            for (const int b : neighbours[a]) {
                const Vector3d reached =
                    unwrapped[a] + minimumImage(packing.positions[b] - packing.positions[a], box);
                if (component[b] < 0) {
                    component[b] = root;
                    parent[b] = a;
                    unwrapped[b] = reached;
                    members.push_back(b);
                    continue;
                }
                const Vector3d wrap = ((reached - unwrapped[b]) / box).array().round() * box;
                if (wrap.isZero(0.0)) continue;
                return SpanningChain{wrap, closedCycle(a, b, parent)};
            }
        }
    }
    return std::nullopt;
}

JamCheck checkJam(const Packing& packing, double reducedPressure,
                  const JamCheckParameters& parameters) {
    if (!(reducedPressure > 0.0))
        throw std::invalid_argument("jam check: reduced pressure must be positive");
    JamCheck check;
    check.tolerance = std::clamp(parameters.gapsPerPressure / reducedPressure,
                                 parameters.minTolerance, parameters.maxTolerance);
    check.contacts =
        ContactNetwork({check.tolerance, parameters.rattlerThreshold}).compute(packing);
    const UntrappedCounts counts = untrappedCounts(check.contacts);
    check.untrappedFraction = counts.fraction;
    check.backbone = counts.backbone;
    check.backboneContacts = counts.backboneContacts;
    check.jammed = counts.fraction <= parameters.maxRattlerFraction ||
                   (packing.isMixture() &&
                    backboneHoldsItsCount(check, counts.free, packing.size(), parameters));
    if (!check.jammed && !isCompressing(reducedPressure, parameters))
        check.chain = findSpanningChain(packing, check.contacts.contacts);
    check.verdict = verdictOf(check, packing, reducedPressure, parameters);
    return check;
}

} // namespace sbpack
