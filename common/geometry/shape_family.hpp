#pragma once
// What a shape family is (docs/architecture.md, "What a new shape needs"): its name, its
// parameters, the body it makes at a size and the questions the analyses ask of that body, all in
// the family's own files (geometry/superball_family for the superball). The families are listed
// once, in geometry/shape_families.hpp; ShapeSpec and ParticleShape (geometry/particle_shape)
// dispatch over that list, so that a new family adds its files and one line there.

#include <Eigen/Core>

#include <array>
#include <concepts>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace sbpack {

/// One parameter of a shape family, under the name the packing file and the results carry.
struct ShapeParameter {
    std::string_view name;
    /// "1" dimensionless, "length" (the packing's, as the semi-axis).
    std::string_view units;
    std::string_view description;
    /// The value a program takes where none is given (sbgen's option, Python's keyword).
    double fallback = 0.0;
};

/// A shape family: its name and its parameters, in the order ShapeSpec::values gives them.
struct ShapeFamily {
    std::string_view name;
    std::span<const ShapeParameter> parameters;
};

/// A shape as the superquadric the exchange formats write (docs/cli.md, "Files"): OVITO's
/// (|x/a|^(2/phi) + |y/b|^(2/phi))^(phi/theta) + |z/c|^(2/theta) <= 1, held here by the
/// blockiness n = 2 / roundness that LAMMPS's superellipsoid takes, and the semi-axes over the
/// particle's size (the largest is 1). The superball (paper Eq. 1) is a = b = c = 1, n = 2p
/// both; an ellipsoid would be n = 2 both.
struct Superquadric {
    Eigen::Vector3d axes = Eigen::Vector3d::Ones();
    double eastWest = 2.0;   ///< n of x and y: 2 / OVITO's roundness phi
    double northSouth = 2.0; ///< n of z: 2 / OVITO's roundness theta
};

/// What the pair solvers need of a body (centrally symmetric and convex, in its own frame): its
/// support function h, support point and the Hessian of h (docs/design.md §2), its gauge, its
/// semi-axis, the body scaled by a factor (B of a mixture's pair), whether it is a sphere (solved
/// in closed form), and its surface's curvature at the support point (jamming/gap_hessian). A
/// body that may be the octahedron (the superball at p = 0.5) says so by isOctahedron(), and its
/// pairs are solved exactly over the polytope's face normals. Superball (sbgen's engine) and
/// ParticleShape (the analyses, any family) are two; pair/pair_geometry solves their pairs.
template <class Body>
concept ConvexBody = requires(const Body& body, const Eigen::Vector3d& v, double factor) {
    { body.support(v) } -> std::convertible_to<double>;
    { body.supportPoint(v) } -> std::convertible_to<Eigen::Vector3d>;
    { body.supportHessian(v) } -> std::convertible_to<Eigen::Matrix3d>;
    { body.gauge(v) } -> std::convertible_to<double>;
    { body.semiAxis() } -> std::convertible_to<double>;
    { body.scaled(factor) } -> std::same_as<Body>;
    { body.isSphere() } -> std::same_as<bool>;
    { body.surfaceCurvature(v) } -> std::convertible_to<Eigen::Matrix3d>;
};

/// What a family F provides (geometry/superball_family is the model). Its parameters' values come
/// as a span in the order of F::parameters, checked by F::problem before F::body sees them. Its
/// Body (body frame, semi-axis the largest half-width of its bounding box) is a ConvexBody (the
/// pair solvers, the curvature) with its volume, mean width (paper Sec. II D), circumradius and
/// inradius; the analyses ask further, as free functions found beside it:
/// hasCubicAxes (the cubatic order P4 is defined), hasCubicSymmetry (the contact regions <100>,
/// <110>, <111> name equivalent places), stacksInColumns (the jam check's advice on columns),
/// insideTest (a callable for many points: the voxels), gaugePower (an increasing function of the
/// gauge, 1 on the surface: the exact pore sizes) and closestPoint (the exact pore sizes).
template <class F>
concept ShapeFamilyTraits = requires(std::span<const double> values, double semiAxis,
                                     const Superquadric& q, const typename F::Body& body,
                                     const Eigen::Vector3d& x) {
    { F::name } -> std::convertible_to<std::string_view>;
    {std::span<const ShapeParameter>(F::parameters)};
    /// What the family's superquadric is, for the message of a superquadric no family has.
    { F::superquadricForm } -> std::convertible_to<std::string_view>;
    { F::problem(values) } -> std::same_as<std::optional<std::string>>;
    { F::isSphere(values) } -> std::same_as<bool>;
    { F::body(values, semiAxis) } -> std::same_as<typename F::Body>;
    { F::superquadric(values) } -> std::same_as<Superquadric>;
    /// The values whose superquadric is q (to 1e-12), or nothing.
    { F::fromSuperquadric(q) } -> std::same_as<std::optional<std::vector<double>>>;
    requires ConvexBody<typename F::Body>;
    { body.volume() } -> std::convertible_to<double>;
    { body.meanWidth() } -> std::convertible_to<double>;
    { body.circumradius() } -> std::convertible_to<double>;
    { body.inradius() } -> std::convertible_to<double>;
    { hasCubicAxes(body) } -> std::same_as<bool>;
    { hasCubicSymmetry(body) } -> std::same_as<bool>;
    { stacksInColumns(body) } -> std::same_as<bool>;
    { insideTest(body)(x) } -> std::same_as<bool>;
    { gaugePower(body, x) } -> std::convertible_to<double>;
    { closestPoint(body, x) } -> std::convertible_to<Eigen::Vector3d>;
};

/// The families, in order: an index into the list is how ShapeSpec names its family, and the
/// first is the family a file without a family name holds. Their bodies must differ (a body
/// says its family).
template <ShapeFamilyTraits... F> struct ShapeFamilyList {
    static constexpr std::size_t size = sizeof...(F);
    /// A body of any family, the alternatives in the families' order.
    using AnyBody = std::variant<typename F::Body...>;
    /// Each family's name and parameters, in order.
    static constexpr std::array<ShapeFamily, size> info = {ShapeFamily{F::name, F::parameters}...};

    /// The index of family G.
    template <class G>
    static constexpr std::size_t indexOf = [] {
        constexpr std::array<bool, size> same = {std::is_same_v<G, F>...};
        std::size_t i = 0;
        while (i < size && !same[i])
            ++i;
        return i;
    }();

    /// fn(std::type_identity<G>{}) for the family G at `index` (< size).
    template <class Fn> static decltype(auto) visit(std::size_t index, Fn&& fn) {
        using Result = std::common_type_t<decltype(fn(std::type_identity<F>{}))...>;
        using Call = Result (*)(Fn&);
        static constexpr std::array<Call, size> calls = {
            +[](Fn& f) -> Result { return f(std::type_identity<F>{}); }...};
        return calls[index](fn);
    }
};

} // namespace sbpack
