#pragma once
// The shape families sbgen runs, listed once (docs/architecture.md, "What a new shape needs"):
// each an engine family in its own files (shapes/superball_engines is the model: the family of
// geometry/shape_families.hpp, its engine shapes, its measurements and its options' help), one
// entry of EngineFamilies here. From the list: the shape variant and its engines, the factory
// that picks a shape, the shapes' pair records in a checkpoint and what sbgen has measured of
// each. The protocol, the random start, the checkpoint table and sbgen's options name no shape.

#include "engine/event_driven_md.hpp"
#include "geometry/particle_shape.hpp"
#include "shapes/measured_protocol.hpp"
#include "shapes/superball_engines.hpp"

#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace sbpack {

/// The engine families, each with its Family (a ShapeFamilyTraits), its engine Shapes (a
/// std::variant), shapeFor(values), measured(values) and optionHelp(parameter).
template <class... E> struct EngineFamilyList {
    static_assert(((ShapeFamilies::indexOf<typename E::Family> < ShapeFamilies::size) && ...),
                  "an engine family's Family is one of ShapeFamilies");
    /// fn(std::type_identity<E>{}) for the engine family of ShapeFamilies' family `index`;
    /// false where sbgen runs no such family.
    template <class Fn> static bool find(std::size_t index, Fn&& fn) {
        bool found = false;
        const auto tryOne = [&]<class One>(std::type_identity<One> one) {
            if (found || ShapeFamilies::indexOf<typename One::Family> != index) return;
            found = true;
            fn(one);
        };
        (tryOne(std::type_identity<E>{}), ...);
        return found;
    }
};

/// Every family sbgen runs.
using EngineFamilies = EngineFamilyList<SuperballEngines>;

template <class... Variants> struct JoinedVariants;
template <class... A> struct JoinedVariants<std::variant<A...>> {
    using type = std::variant<A...>;
};
template <class... A, class... B, class... Rest>
struct JoinedVariants<std::variant<A...>, std::variant<B...>, Rest...>
    : JoinedVariants<std::variant<A..., B...>, Rest...> {};
template <class List> struct ShapesOf;
template <class... E> struct ShapesOf<EngineFamilyList<E...>> {
    using type = typename JoinedVariants<typename E::Shapes...>::type;
};
/// Every shape sbgen can run: the engine families' shapes, in order.
using AnyShape = ShapesOf<EngineFamilies>::type;

template <class Shapes> struct EnginesOf;
template <class... Shapes> struct EnginesOf<std::variant<Shapes...>> {
    using type = std::variant<EventDrivenMd<Shapes>...>;
};
/// Every engine sbgen can run, one per shape.
using AnyEngine = EnginesOf<AnyShape>::type;

/// Whether the bodies rotate: the engine shape's kRotates (all but spheres, which run on the
/// exact sphere shape); throws as shapeFor.
bool rotating(const ShapeSpec& shape);

/// What sbgen has measured of `shape`: its default rates, cost and range; for a family sbgen
/// does not run, a problem that says so.
MeasuredProtocol measuredProtocol(const ShapeSpec& shape);

/// sbgen's help for the option of `parameter` of the shape family `family` (--p): its range,
/// default and what the engine makes of it.
std::string shapeOptionHelp(std::string_view family, const ShapeParameter& parameter);

/// The engine's shape for `shape` (its engine family's shapeFor); throws std::invalid_argument
/// for a family sbgen does not run (measuredProtocol's problem).
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
