#include "shapes/superball_shape.hpp"

#include "geometry/superball.hpp"
#include "pair/pair_geometry.hpp"
#include "shapes/first_contact_search.hpp"
#include "shapes/superball/pair_gap.hpp"
#include "shapes/superball/warm_distance.hpp"
#include "shapes/witness_bound.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace sbpack {

using superball::atNormal;
using superball::circumscribedWindow;
using superball::exactSignedDistance;
using superball::SphereWindow;
using superball::SuperballPairGap;

SuperballShape::SuperballShape(double p)
    : p_(p), c_(Superball(p, 1.0).circumradius()), cIn_(Superball(p, 1.0).inradius()),
      lever_(std::sqrt(c_ * c_ - cIn_ * cIn_)),
      witness_(p > 0.5 ? std::optional(supportHolderBound(p)) : std::nullopt),
      inertiaPerMassUnit_(Superball(p, 1.0).inertiaPerMass()) {}

double SuperballShape::inertiaPerMass(double diameter) const {
    return inertiaPerMassUnit_ * 0.25 * diameter * diameter;
}

// Tier 1: the circumscribed spheres meet before the horizon. Tier 2 (separatingPlane): no plane
// separates them up to `end`. Tier 3: the first-contact search on the pair's gap function
// (shapes/first_contact_search.hpp over superball/pair_gap.hpp); the
// witness record was of the cached normal's plane, so it goes where the normal moves on.
Prediction SuperballShape::collisionTime(const PairMotion& m, double horizon, PairMemory& memory,
                                         const PairMemory::Resolved* resolved) {
    ++stats.calls;
    Vector3d& normal = memory.normal;
    const double remembered = memory.gap;
    memory.gap = -kNoContact; // unless a bound on this normal's gap now is known below
    memory.atContact = false;
    const Prediction none{kNoContact};
    if (!(horizon > 0.0)) return none;
    const std::optional<SphereWindow> window = circumscribedWindow(m, c_, horizon);
    if (!window) {
        ++stats.sphereRejections;
        return none;
    }
    if (normal.isZero(0.0)) normal = m.displacement.normalized();
    SuperballPairGap gap(m, p_, c_, lever_, window->end, normal, limits, stats);
    const std::optional<PlaneGap> cached = separatingPlane(m, gap, window->end, remembered, memory);
    if (!cached) return none;
    const Vector3d recorded = normal;
    FirstContactSearch search(gap, window->end, m.diameter, limits, stats);
    const Found found = search.advance(window->enter, normal, *cached, resolved != nullptr,
                                       resolved ? resolved->contact : std::nullopt);
    if (found.sampled) memory.gap = -kNoContact; // the samples moved the normal on
    if (normal != recorded) memory.witness = {};
    if (found.contact && found.time < kNoContact) {
        normal = found.normal;
        memory.witness = {};
        memory.gap = -kNoContact;
        memory.atContact = true;
    }
    return {found.time, found.contact};
}

// The cached normal's plane separates the pair up to `end`: by the first-order bound from the
// remembered lower bound on its gap (no support point), by the pair's witness record
// (shapes/witness_bound.hpp: its material points, whatever either particle did since), or from
// its exact gap, then by the chord to `end`; a pair without a normal (after a rebuild) tries
// the centre line's. The exact gap's support points become the witness record; either plane
// bound, with this motion's rate, is left for the next prediction.
std::optional<PlaneGap> SuperballShape::separatingPlane(const PairMotion& m,
                                                        const SuperballPairGap& gap, double end,
                                                        double remembered, PairMemory& memory) {
    const Vector3d& normal = memory.normal;
    const double fall = std::min(0.0, gap.planeRate(normal));
    auto separatedToEnd = [&](double gap) { return gap > 0.0 && gap + fall * end > 0.0; };
    auto bound = [&](double gap) {
        memory.gap = gap;
        memory.rate = fall;
        memory.span = end;
    };
    if (separatedToEnd(remembered)) {
        ++stats.boundRejections;
        bound(remembered);
        return std::nullopt;
    }
    if (witness_ && witnessSeparates(m, normal, memory.witness, *witness_, c_, end,
                                     limits.contactGap * m.diameter)) {
        ++stats.witnessRejections;
        return std::nullopt;
    }
    const PlaneGap cached = gap.planeGap(normal, 0.0);
    bound(cached.gap);
    const double semiAxis = 0.5 * m.diameter; // the record's points are at semi-axis 1
    memory.witness = {cached.pointI / (semiAxis * m.sizeI), cached.pointJ / (semiAxis * m.sizeJ),
                      m.turnedI, m.turnedJ};
    if (separatedToEnd(cached.gap) || (cached.gap > 0.0 && end < kNoContact &&
                                       std::min(cached.gap, gap.planeGap(normal, end).gap) >
                                           0.125 * gap.planeCurvature(normal) * end * end)) {
        ++stats.planeRejections;
        return std::nullopt;
    }
    return cached;
}

bool SuperballShape::overlapping(const PairMotion& m) const {
    const SuperballPair pair{Superball(p_, 0.5 * m.diameter * m.sizeI),
                             m.orientationI.toRotationMatrix(), m.orientationJ.toRotationMatrix(),
                             m.displacement, m.sizeJ / m.sizeI};
    return !(scaleFactor(pair).scaleFactor > 1.0);
}

PairContact SuperballShape::contact(const PairMotion& m, PairMemory& memory,
                                    PairMemory::Resolved& resolved) {
    Vector3d& normal = memory.normal;
    const SuperballPair pair{Superball(p_, 0.5 * m.diameter * m.sizeI),
                             m.orientationI.toRotationMatrix(), m.orientationJ.toRotationMatrix(),
                             m.displacement, m.sizeJ / m.sizeI};
    // The prediction's normal was the optimal one at the root it found, a state within rounding
    // of this one: where its plane still touches (within the contact gap, either way), no
    // evaluation is needed (at p = 10 that evaluation is a local search: bench/RESULTS.md,
    // "The collision's contact from its prediction").
    SignedDistanceResult r;
    if (memory.atContact) r = atNormal(pair, normal);
    if (!memory.atContact || !(std::abs(r.signedDistance) <= 2.0 * limits.contactGap * m.diameter))
        r = exactSignedDistance(pair, normal, kNoContact, limits, stats).result;
    else
        ++stats.predictedContacts;
    if (normal != r.normal) memory.witness = {};
    normal = r.normal;
    memory.gap = -kNoContact; // a new normal: its gap bound is unknown
    memory.atContact = false;
    resolved = {m.displacement, r};
    const Vector3d armI = 0.5 * (r.contactA + r.contactB);
    return {r.normal, armI, armI - m.displacement, m.displacement.norm()};
}

} // namespace sbpack
