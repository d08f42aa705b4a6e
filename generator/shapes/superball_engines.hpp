#pragma once
// What sbgen runs of the superball family (shapes/registry lists it; docs/architecture.md, "What
// a new shape needs"): the engine's shapes (the exact sphere at p = 1, the rotating superball
// otherwise), what sbgen has measured of them (shapes/superball_protocol) and the help of the
// family's option --p.

#include "geometry/superball_family.hpp"
#include "shapes/measured_protocol.hpp"
#include "shapes/sphere.hpp"
#include "shapes/superball_shape.hpp"

#include <span>
#include <string>
#include <variant>

namespace sbpack {

struct SuperballEngines {
    using Family = SuperballFamily;
    /// The engine's shapes of the family.
    using Shapes = std::variant<SphereShape, SuperballShape>;
    /// The exact sphere for p = 1, the rotating superball of its p otherwise.
    static Shapes shapeFor(std::span<const double> values);
    /// The default rates, cost and range at p.
    static MeasuredProtocol measured(std::span<const double> values);
    /// sbgen's help for the option of `parameter` (--p).
    static std::string optionHelp(const ShapeParameter& parameter);
};

} // namespace sbpack
