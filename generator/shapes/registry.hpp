#pragma once
// The shapes sbgen runs, registered once (docs/architecture.md, "What a new shape needs"): the
// shape variant and its engines, the factory that picks a shape for a packing's exponent, and
// the shapes' pair records in a checkpoint, and what sbgen has measured of each. A new shape is
// one alternative of AnyShape, one branch of shapeFor, one of measuredProtocol and one of
// shapeOptionHelp; the protocol, the random start, the checkpoint table and sbgen's options name
// no shape.

#include "engine/event_driven_md.hpp"
#include "shapes/measured_protocol.hpp"
#include "shapes/sphere.hpp"
#include "shapes/superball_shape.hpp"

#include <string>
#include <variant>
#include <vector>

namespace sbpack {

/// Every shape sbgen can run.
using AnyShape = std::variant<SphereShape, SuperballShape>;

template <class Shapes> struct EnginesOf;
template <class... Shapes> struct EnginesOf<std::variant<Shapes...>> {
    using type = std::variant<EventDrivenMd<Shapes>...>;
};
/// Every engine sbgen can run, one per shape.
using AnyEngine = EnginesOf<AnyShape>::type;

/// Whether the bodies rotate: all but spheres, which run on the exact sphere shape.
bool rotating(const ShapeSpec& shape);

/// What sbgen has measured of `shape`: its default rates, cost and range.
MeasuredProtocol measuredProtocol(const ShapeSpec& shape);

/// sbgen's help for the option of `parameter` of the shape family `family` (--p): its range,
/// default and what the engine makes of it.
std::string shapeOptionHelp(std::string_view family, const ShapeParameter& parameter);

/// The engine's shape for `shape`: the exact sphere for superballs of p = 1, the rotating
/// superball of its p otherwise.
AnyShape shapeFor(const ShapeSpec& shape);

/// The engine of shapeFor(shape); `sizes` a mixture's (EventDrivenMd).
AnyEngine makeEngine(const ShapeSpec& shape, double boxLength, std::vector<ParticleState> state,
                     GrowthClock clock, std::vector<double> sizes);

/// The engine's synchronised pair records as the rows of a checkpoint's dataset
/// resume_state/pair_records (kPairRecordColumns values a row, ascending pairs): i, j, then the
/// columns the shape's memory writes (PairMemory::appendColumns); none for a shape whose
/// predictor remembers nothing (the sphere).
std::vector<double> pairRecordRows(const AnyEngine& engine);

/// The records of pairRecordRows back into `engine`, refused (naming `source` and the row)
/// unless i < j are particles and the shape's memory reads its columns, or where the shape
/// keeps no records.
void restorePairRecords(AnyEngine& engine, const std::vector<double>& rows,
                        const std::string& source);

} // namespace sbpack
