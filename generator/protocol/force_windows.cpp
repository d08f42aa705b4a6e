#include "protocol/force_windows.hpp"

namespace sbpack {

namespace {

/// sum += factor p.
void addInto(PairImpulse& sum, const PairImpulse& p, double factor = 1.0) {
    sum.i = p.i;
    sum.j = p.j;
    sum.impulse += factor * p.impulse;
    sum.moment += factor * p.moment;
    sum.magnitude += factor * p.magnitude;
}

} // namespace

void ForceWindows::push(const ContactImpulses& impulses, double duration, double kT,
                        double reducedPressure, std::uint64_t window) {
    if (blockWindows_ == 0) return;
    ++current_.windows;
    current_.duration += duration;
    current_.pressureDuration += reducedPressure * duration;
    impulses.forEach([&](const PairImpulse& p) {
        addInto(current_.pairs[{p.i, p.j}], p, 1.0 / kT);
    });
    if (window % static_cast<std::uint64_t>(blockWindows_) == 0)
        previous_ = std::exchange(current_, {});
}

ContactForces ForceWindows::forces(const Packing& packing) const {
    ContactForces forces;
    if (empty()) return forces;
    ForceBlock total = previous_;
    total.windows += current_.windows;
    total.duration += current_.duration;
    total.pressureDuration += current_.pressureDuration;
    for (const auto& [pair, sum] : current_.pairs)
        addInto(total.pairs[pair], sum);
    forces.windows = total.windows;
    forces.duration = total.duration;
    forces.reducedPressure = total.pressureDuration / total.duration;
    const double diameter = 2.0 * packing.semiAxis;
    for (const auto& [pair, sum] : total.pairs) {
        const double magnitude = sum.impulse.norm();
        if (!(magnitude > 0.0)) continue; // only grazing collisions, J = 0
        const Vector3d point = packing.positions[pair.first] + sum.moment / sum.magnitude;
        forces.contacts.push_back({pair.first, pair.second, wrapIntoBox(point, packing.boxLength),
                                   sum.impulse / magnitude, magnitude / total.duration * diameter});
    }
    return forces;
}

} // namespace sbpack
