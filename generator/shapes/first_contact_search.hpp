#pragma once
// The certified first-contact search of a pair of convex bodies (docs/design.md §3, tier 3 of
// the superball predictor), over any gap function (the concept GapFunction below): conservative
// advancement along separating planes (first-order and chord steps on cheap plane gaps),
// refreshed by samples of the signed distance s; near contact, Newton steps in time until one
// touches or brackets the root, a safeguarded Newton refinement of the bracket, and the root
// accepted as the first only when its normal's plane certifies the interval before it. It
// knows nothing of the bodies' shapes: the superball's gap function is
// shapes/superball/pair_gap.hpp, and tests/generator/test_first_contact_search.cpp runs it on
// analytic ones.

#include "pair/pair_geometry.hpp"
#include "shapes/first_contact_limits.hpp"
#include "shapes/predictor_stats.hpp"

#include <algorithm>
#include <cmath>
#include <concepts>
#include <optional>
#include <variant>

namespace sbpack {

/// A separating plane's gap g_n(tau) = n.d(tau) - h_i(n) - h_j(n), its exact rate, and the two
/// support points of n in the bodies' frames (for the superball at its semi-axis then: a
/// witness record's points once scaled to semi-axis 1).
struct PlaneGap {
    double gap = 0.0;
    double rate = 0.0;
    Vector3d pointI = Vector3d::Zero(), pointJ = Vector3d::Zero();
};

/// s, its exact rate ds/dtau and the normal of the pair after tau, with that normal's plane gap
/// rate (ds/dtau but for where the impulse's point lies).
struct Sample {
    double tau = 0.0;
    double gap = 0.0;
    double rate = 0.0;
    Vector3d normal = Vector3d::Zero();
    double planeRate = 0.0;
    bool exact = true; ///< false: gap is a lower bound on s (a plane that separates them)
};

/// What the search finds: a Prediction, with the contact normal at the root where it found a
/// contact (zero otherwise); `sampled`: s was sampled on the way, so the pair's normal moved on.
struct Found {
    double time;
    bool contact = true;
    Vector3d normal = Vector3d::Zero();
    bool sampled = false;
};

/// The gap function of a pair along its present motion, over [0, end] (end fixed by the
/// gap): for unit normals n, the plane gap g_n(tau) with its exact rate, a lower bound on
/// dg_n/dtau and an upper bound on d2g_n/dtau2 over [0, end]; and s(tau) = max_n g_n(tau)
/// sampled (exact, or a lower bound that proves the pair apart), the normal of each sample the
/// warm start of the next; `given` takes a sample at tau = 0 evaluated elsewhere.
template <class G>
concept GapFunction = requires(G& g, const G& c, const Vector3d& n, double tau,
                               const SignedDistanceResult& r) {
    { c.planeGap(n, tau) } -> std::same_as<PlaneGap>;
    { c.planeRate(n) } -> std::same_as<double>;
    { c.planeCurvature(n) } -> std::same_as<double>;
    { g.at(tau) } -> std::same_as<Sample>;
    { g.given(r) } -> std::same_as<Sample>;
};

/// One prediction of a pair over [0, end] along its gap function.
template <GapFunction Gap> class FirstContactSearch {
  public:
    /// `diameter`: the length the limits' gaps are relative to.
    FirstContactSearch(Gap& gap, double end, double diameter, const FirstContactLimits& limits,
                       PredictorStats& stats)
        : gap_(gap), end_(end), limits_(limits), stats_(stats),
          touching_(limits.contactGap * diameter), near_(limits.nearGap * diameter) {}

    /// From `start` (the plane of `normal` with gap `cached` at tau = 0 known): advancement along
    /// that plane, then from samples along their planes, Newton steps in time near contact, and
    /// the certificate of the root they reach. `resolved`: the pair was resolved at this very
    /// state (touching now is no contact), whose contact seen from i is `contact` where known
    /// (the sample at tau = 0 without an evaluation).
    Found advance(double start, const Vector3d& normal, PlaneGap cached, bool resolved,
                  const std::optional<SignedDistanceResult>& contact);

  private:
    Found fromSample(Sample now, bool resolved);
    Sample refine(Sample left, Sample right);
    std::variant<double, Found> alongPlane(const Vector3d& n, double tau, PlaneGap g,
                                           double reference);
    std::optional<Sample> newtonInTime(const Sample& from);
    std::optional<Found> rootNear(const Sample& now);
    /// A chord step from (tau, g) along n that certifies, if any (step false otherwise).
    struct Chord {
        bool step = false;
        bool reachedEnd = false;
        double tau = 0.0;
        PlaneGap gap;
    };
    Chord chordStep(const Vector3d& n, double tau, const PlaneGap& g, double firstOrder,
                    double curvature);

    Gap& gap_;
    double end_; ///< no contact is looked for beyond (shortened to an uncertified root)
    const FirstContactLimits& limits_;
    PredictorStats& stats_;
    double touching_, near_;
    int steps_ = 0;
    Found atEnd_{kNoContact}; ///< what reaching `end` means: no contact, or a known one there
};

// --- implementation of the template ---

// Safeguarded Newton on s over a bracket gap(left) > 0 >= gap(right): the Newton step from
// the end nearer to zero (s has an exact rate), regula falsi when it leaves the bracket and
// bisection when that stalls. Returns the safe (left) end once it touches, so an overlap is
// never accepted (or the right end at a rounding-level overlap). If it stalls (s jumps where
// the pair solver's kinks make it inconsistent), the left end, not touching, becomes a safe
// recheck time.
template <GapFunction Gap> Sample FirstContactSearch<Gap>::refine(Sample left, Sample right) {
    for (int k = 0; k < limits_.maxRefinementSteps; ++k) {
        const double width = right.tau - left.tau;
        if (left.gap <= touching_ || width <= limits_.bracketWidth * (1.0 + right.tau)) return left;
        if (right.gap >= -touching_) return right; // touching at rounding
        const Sample& nearer = left.gap < -right.gap ? left : right;
        double tau = nearer.rate < 0.0 ? nearer.tau - nearer.gap / nearer.rate : -1.0;
        if (!(tau > left.tau && tau < right.tau))
            tau = (left.tau * right.gap - right.tau * left.gap) / (right.gap - left.gap);
        if (!(tau > left.tau + limits_.stallFraction * width &&
              tau < right.tau - limits_.stallFraction * width) &&
            k % limits_.bisectEvery == limits_.bisectEvery - 1)
            tau = 0.5 * (left.tau + right.tau);
        const Sample mid = gap_.at(tau);
        ++stats_.refinementSteps;
        (mid.gap > 0.0 ? left : right) = mid;
    }
    ++stats_.limitHits;
    return left;
}

// The chord step where it certifies (up to `end`, or 0.9 of its reach sqrt(8 gap / M), then
// eighths of that while longer than the first-order step): g_n'' <= M, so on [t0, t1] g_n lies
// above its chord minus M (t - t0)(t1 - t) / 2 >= min(g0, g1) - M (t1 - t0)^2 / 8, and one plane
// gap at t1 certifies the whole step. The first chord tried: where the plane's tangent g + r t
// is still k = 32 times the chord's margin M t^2 / 8, the root of (k M / 8) t^2 - r t - g (a
// guess from the exact rate, since g'' has no lower bound; only the chord certifies).
template <GapFunction Gap>
typename FirstContactSearch<Gap>::Chord
FirstContactSearch<Gap>::chordStep(const Vector3d& n, double tau, const PlaneGap& g,
                                   double firstOrder, double curvature) {
    const double chord = curvature > 0.0 ? std::sqrt(8.0 * g.gap / curvature) : kNoContact;
    const double margin = std::sqrt(g.rate * g.rate + 16.0 * curvature * g.gap);
    const double likely =
        g.rate > 0.0 ? (g.rate + margin) / (8.0 * curvature) : 2.0 * g.gap / (margin - g.rate);
    for (double tryStep = std::min({end_ - tau, limits_.chordReach * chord, likely});
         g.gap > 0.0 && tryStep > firstOrder; tryStep *= limits_.chordShrink) {
        const PlaneGap far = gap_.planeGap(n, tau + tryStep);
        ++stats_.planeSteps;
        if (std::min(g.gap, far.gap) > 0.125 * curvature * tryStep * tryStep) {
            ++stats_.chordSteps;
            return {true, tau + tryStep >= end_, tau + tryStep, far};
        }
    }
    return {};
}

// Advancement along the plane of unit n from (tau, gap), each step ending at a cheap plane
// gap: a chord step where one certifies, else the first-order step gap / |plane rate|; until
// the gap drops below half of `reference`. Returns the time reached, or the prediction when the
// plane separates them up to `end` or the step limit is reached (a safe recheck time).
template <GapFunction Gap>
std::variant<double, Found> FirstContactSearch<Gap>::alongPlane(const Vector3d& n, double tau,
                                                                PlaneGap g, double reference) {
    const double rate = gap_.planeRate(n), curvature = gap_.planeCurvature(n);
    do {
        if (rate >= 0.0) return atEnd_; // this plane separates them up to `end`
        if (++steps_ > limits_.maxAdvancementSteps) {
            ++stats_.rechecks;
            return Found{tau, false};
        }
        const double firstOrder = std::max(g.gap, touching_) / -rate;
        const Chord chord = chordStep(n, tau, g, firstOrder, curvature);
        if (chord.step) {
            if (chord.reachedEnd) return atEnd_;
            tau = chord.tau;
            g = chord.gap;
            continue;
        }
        tau += firstOrder;
        if (tau >= end_) return atEnd_;
        g = gap_.planeGap(n, tau);
        ++stats_.planeSteps;
    } while (g.gap > 0.5 * reference);
    return tau;
}

// Newton steps in time from an exact sample (each iterate exact, or above the contact gap a
// lower bound that proves the pair apart there; rootNear's certificate covers the whole step
// either way), until one touches (closing) or brackets a root (then refined); none when an
// iterate turns away, would pass `end`, goes beyond the reach where the root's certificate
// (M (t1 - t0)^2 / 2 < g(t0), in advance) keeps a margin of four, M (t1 - t0)^2 / 2 <= g(t0) / 4
// (the root normal's plane lies below s at t0), or the limit is reached. Where s is convex in
// time the iterates approach the root from outside, quadratically, and no step needs
// certifying on the way: the root found is certified as the first one from the start.
template <GapFunction Gap>
std::optional<Sample> FirstContactSearch<Gap>::newtonInTime(const Sample& from) {
    const double reach = from.tau + std::sqrt(0.5 * from.gap / gap_.planeCurvature(from.normal));
    Sample last = from;
    for (int k = 0; k < limits_.newtonStepsInTime; ++k) {
        const double tau = last.tau - last.gap / last.rate;
        if (!(tau > last.tau && tau <= std::min(end_, reach))) return std::nullopt;
        const Sample trial = gap_.at(tau);
        if (trial.gap <= 0.0) {
            ++stats_.newtonBrackets;
            return refine(last, trial);
        }
        if (trial.rate >= 0.0) return std::nullopt;
        if (trial.gap <= touching_) return trial;
        last = trial;
    }
    return std::nullopt;
}

// Near contact and closing, Newton steps in time; the root t1 they reach is the first one if
// the root normal's plane certifies [t0, t1): with g'' <= M and g(t1) ~ 0,
// g >= chord - M (t - t0)(t1 - t) / 2 > 0 there when g(t0) > M (t1 - t0)^2 / 2. Otherwise
// (s dips below zero and back within the step: rare, spin-driven) advancement goes on
// without Newton steps up to that root. The prediction when that decides it; else none.
template <GapFunction Gap>
std::optional<Found> FirstContactSearch<Gap>::rootNear(const Sample& now) {
    const double rate = gap_.planeRate(now.normal);
    if (!(atEnd_.time == kNoContact && now.exact && now.gap <= near_ && now.rate < 0.0 &&
          rate < 0.0))
        return std::nullopt;
    const double tau = now.tau - now.gap / now.rate;
    const std::optional<Sample> root =
        tau > now.tau + now.gap / -rate ? newtonInTime(now) : std::nullopt;
    if (!root) return std::nullopt;
    if (root->gap > touching_) return Found{root->tau, false}; // refinement stalled
    const double dt = root->tau - now.tau;
    if (gap_.planeGap(root->normal, now.tau).gap >
        0.5 * gap_.planeCurvature(root->normal) * dt * dt)
        return Found{root->tau, true, root->normal};
    ++stats_.uncertifiedRoots;
    end_ = root->tau;
    atEnd_ = {root->tau, true, root->normal};
    return std::nullopt;
}

template <GapFunction Gap>
Found FirstContactSearch<Gap>::advance(double start, const Vector3d& normal, PlaneGap cached,
                                       bool resolved,
                                       const std::optional<SignedDistanceResult>& contact) {
    if (cached.gap > touching_) {
        const auto reached = alongPlane(normal, 0.0, cached, cached.gap);
        if (const Found* done = std::get_if<Found>(&reached)) return *done;
        start = std::max(start, std::get<double>(reached));
    }
    Sample now = contact && start == 0.0 ? gap_.given(*contact) : gap_.at(start);
    if (start == 0.0 && now.gap < -touching_) ++stats_.startOverlaps;
    Found found = fromSample(now, resolved);
    found.sampled = true;
    return found;
}

// From a sample on: touching and closing is the contact; else Newton steps in time near
// contact, or advancement along the sample's plane to the next sample, and the refinement of
// the bracket where that one overlaps.
template <GapFunction Gap> Found FirstContactSearch<Gap>::fromSample(Sample now, bool resolved) {
    for (;;) {
        // A pair resolved at this very state touches now with no contact, by any path: Newton
        // steps in time from it would end on the same sample (refine returns a touching end).
        const bool justResolved = resolved && now.tau == 0.0;
        if (now.gap <= touching_ && now.rate < 0.0 && !justResolved)
            return {now.tau, true, now.normal};
        if (!justResolved)
            if (const std::optional<Found> decided = rootNear(now)) return *decided;
        const auto reached = alongPlane(now.normal, now.tau, {now.gap, now.planeRate}, now.gap);
        if (const Found* done = std::get_if<Found>(&reached)) return *done;
        const Sample previous = now;
        now = gap_.at(std::get<double>(reached));
        if (now.gap <= 0.0 && previous.gap > touching_) {
            const Sample root = refine(previous, now);
            return {root.tau, root.gap <= touching_, root.normal};
        }
    }
}

} // namespace sbpack
