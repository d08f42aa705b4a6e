#include "shapes/superball/first_contact.hpp"

#include "shapes/sphere.hpp"

#include <cmath>

namespace sbpack::superball {

std::optional<SphereWindow> circumscribedWindow(const PairMotion& m, double c, double horizon) {
    const double D = m.diameter, gamma = m.growthRate;
    const PairMotion spheres{m.displacement, m.relativeVelocity, {}, {}, {}, {}, c * D, c * gamma};
    const double enter =
        m.displacement.squaredNorm() <= c * c * D * D ? 0.0 : SphereShape{}.collisionTime(spheres);
    if (enter >= horizon) return std::nullopt;
    double end = horizon;
    const double a = m.relativeVelocity.squaredNorm() - c * c * gamma * gamma;
    if (a > 0.0) { // after the spheres part for good, nothing touches
        const double b = m.displacement.dot(m.relativeVelocity) - c * c * D * gamma;
        const double c0 = m.displacement.squaredNorm() - c * c * D * D;
        end = std::min(end, (-b + std::sqrt(std::max(0.0, b * b - a * c0))) / a);
    }
    return SphereWindow{enter, end};
}

// Safeguarded Newton on s over a bracket gap(left) > 0 >= gap(right): the Newton step from
// the end nearer to zero (s has an exact rate), regula falsi when it leaves the bracket and
// bisection when that stalls. Returns the safe (left) end once it touches, so an overlap is
// never accepted (or the right end at a rounding-level overlap). If it stalls (s jumps where
// the pair solver's kinks make it inconsistent), the left end, not touching, becomes a safe
// recheck time.
Sample PairPrediction::refine(Sample left, Sample right) {
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
        const Sample mid = trajectory_.at(tau);
        ++stats_.refinementSteps;
        (mid.gap > 0.0 ? left : right) = mid;
    }
    ++stats_.limitHits;
    return left;
}

// The chord step where it certifies (up to `end`, or 0.9 of its reach sqrt(8 gap / M), then
// eighths of that while longer than the first-order step). The first chord tried: where the
// plane's tangent g + r t is still k = 32 times the chord's margin M t^2 / 8, the root of
// (k M / 8) t^2 - r t - g (a guess from the exact rate, since g'' has no lower bound; only the
// chord certifies). At p = 1.5 it halves the plane gaps per collision against trying 0.9 of the
// chord's reach first.
PairPrediction::Chord PairPrediction::chordStep(const Vector3d& n, double tau, const PlaneGap& g,
                                                double firstOrder, double curvature) {
    const double chord = curvature > 0.0 ? std::sqrt(8.0 * g.gap / curvature) : kNever;
    const double margin = std::sqrt(g.rate * g.rate + 16.0 * curvature * g.gap);
    const double likely =
        g.rate > 0.0 ? (g.rate + margin) / (8.0 * curvature) : 2.0 * g.gap / (margin - g.rate);
    for (double tryStep = std::min({end_ - tau, limits_.chordReach * chord, likely});
         g.gap > 0.0 && tryStep > firstOrder; tryStep *= limits_.chordShrink) {
        const PlaneGap far = planeGap(n, tau + tryStep);
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
std::variant<double, Found> PairPrediction::alongPlane(const Vector3d& n, double tau, PlaneGap g,
                                                       double reference) {
    const double rate = planeRate(n), curvature = planeCurvature(n);
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
        g = planeGap(n, tau);
        ++stats_.planeSteps;
    } while (g.gap > 0.5 * reference);
    return tau;
}

// Newton steps in time from an exact sample (each iterate exact, or above the contact gap a
// lower bound that proves the pair apart there; rootNear's certificate covers the whole step
// either way), until one touches (closing)
// or brackets a root (then refined); none when an iterate turns away, would pass `end`, goes
// beyond the reach where the root's certificate (M (t1 - t0)^2 / 2 < g(t0), in advance) keeps a
// margin of four, M (t1 - t0)^2 / 2 <= g(t0) / 4 (the root normal's plane lies below s at
// t0), or the limit is reached. Where s is convex in time the iterates approach the root from
// outside, quadratically, and no step needs certifying on the way: the root found is
// certified as the first one from the start.
std::optional<Sample> PairPrediction::newtonInTime(const Sample& from) {
    const double reach = from.tau + std::sqrt(0.5 * from.gap / planeCurvature(from.normal));
    Sample last = from;
    for (int k = 0; k < limits_.newtonStepsInTime; ++k) {
        const double tau = last.tau - last.gap / last.rate;
        if (!(tau > last.tau && tau <= std::min(end_, reach))) return std::nullopt;
        const Sample trial = trajectory_.at(tau);
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
// without Newton steps up to that root.
std::optional<Found> PairPrediction::rootNear(const Sample& now) {
    const double rate = planeRate(now.normal);
    if (!(atEnd_.time == kNever && now.exact && now.gap <= near_ && now.rate < 0.0 && rate < 0.0))
        return std::nullopt;
    const double tau = now.tau - now.gap / now.rate;
    const std::optional<Sample> root =
        tau > now.tau + now.gap / -rate ? newtonInTime(now) : std::nullopt;
    if (!root) return std::nullopt;
    if (root->gap > touching_) return Found{root->tau, false}; // refinement stalled
    const double dt = root->tau - now.tau;
    if (planeGap(root->normal, now.tau).gap > 0.5 * planeCurvature(root->normal) * dt * dt)
        return Found{root->tau, true, root->normal};
    ++stats_.uncertifiedRoots;
    end_ = root->tau;
    atEnd_ = {root->tau, true, root->normal};
    return std::nullopt;
}

Found PairPrediction::advance(double start, const Vector3d& normal, PlaneGap cached, bool resolved,
                              const std::optional<SignedDistanceResult>& contact,
                              PairMemory& memory) {
    if (cached.gap > touching_) {
        const auto reached = alongPlane(normal, 0.0, cached, cached.gap);
        if (const Found* done = std::get_if<Found>(&reached)) return *done;
        start = std::max(start, std::get<double>(reached));
    }
    memory.gap = -kNever; // the exact evaluations move the normal on
    Sample now = contact && start == 0.0 ? trajectory_.given(*contact) : trajectory_.at(start);
    if (start == 0.0 && now.gap < -touching_) ++stats_.startOverlaps;
    return fromSample(now, resolved);
}

// From an exact sample on: touching and closing is the contact; else Newton steps in time near
// contact, or advancement along the sample's plane to the next exact sample, and the refinement
// of the bracket where that one overlaps.
Found PairPrediction::fromSample(Sample now, bool resolved) {
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
        now = trajectory_.at(std::get<double>(reached));
        if (now.gap <= 0.0 && previous.gap > touching_) {
            const Sample root = refine(previous, now);
            return {root.tau, root.gap <= touching_, root.normal};
        }
    }
}

} // namespace sbpack::superball
