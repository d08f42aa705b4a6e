#pragma once
// The superball family (paper Eq. 1) as geometry/shape_family's ShapeFamilyTraits: its one
// parameter p, the body (geometry/superball) and the questions the analyses ask of it. Listed
// first in geometry/shape_families.hpp: a file without a family name holds superballs.

#include "geometry/shape_family.hpp"
#include "geometry/superball.hpp"
#include "geometry/superball_inside.hpp"
#include "geometry/superball_projection.hpp"

namespace sbpack {

struct SuperballFamily {
    using Body = Superball;
    static constexpr std::string_view name = "superball";
    static constexpr std::array<ShapeParameter, 1> parameters = {
        ShapeParameter{"p", "1",
                       "superball exponent (paper Eq. 1), >= 0.5: 1 the sphere, 0.5 the "
                       "octahedron, infinity the cube",
                       1.0}};
    static constexpr std::string_view superquadricForm =
        "a superball has three equal semi-axes and one blockiness 2p";

    /// "p = 0.4 (must be finite and >= 0.5)", or nothing.
    static std::optional<std::string> problem(std::span<const double> values);
    static bool isSphere(std::span<const double> values) { return values[0] == 1.0; }
    static Superball body(std::span<const double> values, double semiAxis) {
        return {values[0], semiAxis};
    }
    /// |x|^2p + |y|^2p + |z|^2p <= 1: three equal semi-axes, blockiness 2p.
    static Superquadric superquadric(std::span<const double> values) {
        return {Vector3d::Ones(), 2.0 * values[0], 2.0 * values[0]};
    }
    static std::optional<std::vector<double>> fromSuperquadric(const Superquadric& q);
};

/// The cube's three axes are equivalent, so that the cubatic order P4 (common/order) is defined:
/// every superball but the sphere.
inline bool hasCubicAxes(const Superball& body) {
    return !body.isSphere();
}
/// Every superball (the sphere too) is symmetric under the cube's group: its contacts' regions
/// <100>, <110>, <111> name equivalent places (docs/contact-types.md).
inline bool hasCubicSymmetry(const Superball& /*body*/) {
    return true;
}
/// Near-cubes stack face to face into columns that can span a small periodic box
/// (bench/RESULTS.md, "Near-cubes after the jam check"): superballs from kNearCubeExponent.
inline bool stacksInColumns(const Superball& body) {
    return body.p() >= kNearCubeExponent;
}
/// The voxels' inside test (geometry/superball_inside).
inline SuperballInsideTest insideTest(const Superball& body) {
    return SuperballInsideTest(body);
}

} // namespace sbpack
