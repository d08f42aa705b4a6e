#include "shapes/superball_engines.hpp"

#include "shapes/superball_protocol.hpp"

namespace sbpack {

SuperballEngines::Shapes SuperballEngines::shapeFor(std::span<const double> values) {
    if (Family::isSphere(values)) return SphereShape{};
    return SuperballShape(values[0]);
}

MeasuredProtocol SuperballEngines::measured(std::span<const double> values) {
    return superballProtocol(values[0]);
}

std::string SuperballEngines::optionHelp(const ShapeParameter& /*parameter*/) {
    return "superball exponent in (0.5, 1000] (default 1: spheres, exact fast path;\n"
           "otherwise rotating superballs); practical up to 10, above it a warning";
}

} // namespace sbpack
