#pragma once
// The one interface of the event-driven engine's shapes (docs/design.md §3, "One shape
// concept"): value types with the same operations, so the engine has no shape branches. A sphere
// is a shape whose bodies keep their orientation and whose exact predictor remembers nothing.
//
//   geometry:    circumscribedRatio() (over the semi-axis: the neighbour lists), inertiaPerMass(D)
//                (isotropic, docs/design.md §1), kRotates (whether bodies turn: spheres do not),
//                overlapping(m) (the pair now: the random start's test)
//   motion:      turned(q, omega, tau), the orientation after free flight; orient(m, ...), the
//                pair's orientations and spins in its PairMotion
//   prediction:  Memory, what the predictor keeps of a pair between predictions;
//                inPredictionOrder(count, motionOf, consider), the order neighbours are asked in;
//                collisionTime(m, horizon, memory, resolved) (resolved: Memory::Resolved, where
//                the pair's collision at this very state was the engine's last, else null)
//   collision:   contact(m, memory, resolved) (leaves the contact in resolved),
//                resolve(m, contact, i, j) (the elastic impulse, returned)
//   statistics:  takeStats(), the predictor's counters since the last call

#include "shapes/pair_motion.hpp"
#include "shapes/predictor_stats.hpp"

#include <concepts>

namespace sbpack {

template <class S>
concept EngineShape = requires(S shape, const S& constShape, const PairMotion& m, PairMotion& out,
                               typename S::Memory& memory, typename S::Memory::Resolved& resolved,
                               const PairContact& contact, ParticleState& body,
                               const Quaterniond& q, const Vector3d& omega, double x) {
    { constShape.circumscribedRatio() } -> std::convertible_to<double>;
    { S::kRotates } -> std::convertible_to<bool>;
    { constShape.overlapping(m) } -> std::convertible_to<bool>;
    { constShape.inertiaPerMass(x) } -> std::convertible_to<double>;
    { constShape.turned(q, omega, x) } -> std::convertible_to<Quaterniond>;
    constShape.orient(out, body, x, body, x);
    { shape.collisionTime(m, x, memory, &resolved) } -> std::same_as<Prediction>;
    { shape.contact(m, memory, resolved) } -> std::same_as<PairContact>;
    { constShape.resolve(m, contact, body, body) } -> std::convertible_to<double>;
    { shape.takeStats() } -> std::same_as<PredictorStats>;
};

} // namespace sbpack
