#pragma once
// The particles' shape as Packing carries it (docs/architecture.md, "What a new shape needs"):
// a family and its parameters (ShapeSpec), and a body of that shape at a size (ParticleShape),
// whose geometry (volume, mean width, radii, the pair solvers' ConvexBody, the inside test and
// the nearest point) every analysis may use whatever the family. Both dispatch over the families
// of geometry/shape_families.hpp to each family's own files (geometry/shape_family.hpp says what
// a family provides), so that a new family changes nothing here. Code that holds for superballs
// only asks for the superball (ParticleShape::superball: the GPU's voxel geometry) or its
// exponent, nothing for another family (ShapeSpec::superballExponent: the transport fit in p,
// which then leaves k out; FileContext::gridsOnGpu, which keeps other families on the CPU).

#include "geometry/shape_families.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace sbpack {

/// The key under which the packing file, the results and the .vdb metadata name a shape's
/// family; absent: the superball (every file written before the family had a name).
inline constexpr const char* kShapeFamilyKey = "shape";

/// A shape family and its parameters, without a size. Files, results, ensembles and messages
/// know a shape only through its identity here (info(), values(), problem(), describe()).
class ShapeSpec {
  public:
    /// The first family (the superball) at its parameters' fallbacks (p = 1: spheres).
    ShapeSpec();
    static ShapeSpec superball(double exponent) {
        return ShapeSpec(ShapeFamilies::indexOf<SuperballFamily>, {exponent});
    }
    /// The shape of family `name` (shapeFamilies()) with `values` in its parameters' order;
    /// throws std::invalid_argument for an unknown family or the wrong number of values.
    static ShapeSpec fromValues(std::string_view name, std::span<const double> values);
    /// The family's place in ShapeFamilies (geometry/shape_families.hpp).
    std::size_t familyIndex() const { return family_; }
    /// Spheres (the superball of p = 1: sbgen's exact sphere engine; orientations carry nothing).
    bool isSphere() const;
    /// The superball's exponent, nothing for another family: what code that holds for superballs
    /// only asks (the transport fit in p, the GPU's grids), so that a new family leaves that code
    /// as it is.
    std::optional<double> superballExponent() const {
        if (family_ != ShapeFamilies::indexOf<SuperballFamily>) return std::nullopt;
        return values_[0];
    }
    /// The family's name and parameters.
    const ShapeFamily& info() const { return ShapeFamilies::info[family_]; }
    /// The parameters' values, in the order of info().parameters.
    const std::vector<double>& values() const { return values_; }
    /// Each parameter's name with its value, in the same order: what a file writes.
    std::vector<std::pair<std::string_view, double>> namedValues() const;
    /// The family's name as a file writes it under kShapeFamilyKey: nothing for the first family
    /// (the superball), so that every superball file is written as before.
    std::optional<std::string_view> writtenFamily() const;
    /// The shape a file or record holds: the family named `written` (nothing: the superball),
    /// each of its parameters read by name with value(name). Throws std::invalid_argument for an
    /// unknown family (fromValues).
    template <class Value>
    static ShapeSpec read(const std::optional<std::string>& written, Value&& value);
    /// read() where value(name) is a std::optional<double>: nothing where a parameter is
    /// missing (a format whose shape may come from elsewhere).
    template <class Value>
    static std::optional<ShapeSpec> readIfGiven(const std::optional<std::string>& written,
                                                Value&& value);
    /// read() where value(name) is a std::optional<double>: the parameter's fallback where it is
    /// missing (a program's options and keywords: sbgen's --p, Python's p=).
    template <class Value>
    static ShapeSpec readOrFallback(const std::optional<std::string>& written, Value&& value);
    /// What makes the parameters no shape of the family (e.g. "p = 0.4 (must be finite and
    /// >= 0.5)"), or nothing.
    std::optional<std::string> problem() const;
    /// The shape as a superquadric: what the exchange formats write.
    Superquadric superquadric() const;
    /// The shape whose superquadric `q` is (to 1e-12): what the exchange formats read. Throws
    /// std::invalid_argument, saying what each family needs, where no family has it.
    static ShapeSpec fromSuperquadric(const Superquadric& q);
    /// The parameters for messages and tables, each "name = value": "p = 1.5" (a family without
    /// parameters: its name).
    std::string describe() const;
    bool operator==(const ShapeSpec&) const = default;

  private:
    ShapeSpec(std::size_t family, std::vector<double> values)
        : family_(family), values_(std::move(values)) {}
    /// fn(std::type_identity<F>{}) for this shape's family F.
    template <class Fn> decltype(auto) withFamily(Fn&& fn) const {
        return ShapeFamilies::visit(family_, std::forward<Fn>(fn));
    }
    std::size_t family_;
    std::vector<double> values_;
};

/// Every shape family, the superball first (a file without a family name holds superballs).
std::span<const ShapeFamily> shapeFamilies();
/// The family called `name`, or nullptr.
const ShapeFamily* findShapeFamily(std::string_view name);
/// The family a file names (kShapeFamilyKey; nothing: the superball), or nullptr.
const ShapeFamily* writtenShapeFamily(const std::optional<std::string>& written);
/// The parameter of `family` called `name`, or nullptr.
const ShapeParameter* findShapeParameter(const ShapeFamily& family, std::string_view name);
/// The families' names, for messages: "superball".
std::string shapeFamilyNames();

/// One entry a schema declares for the shape (the packing file's, the results'): the family's
/// name under kShapeFamilyKey, then every family's parameters.
struct ShapeField {
    std::string_view name;
    std::string_view units;
    std::string_view description;
    bool text = false;     ///< the family's name, a string; else a parameter, a float
    bool optional = false; ///< a file may lack it (the family's name; a parameter of one family
                           ///< where there are several)
};
/// The shape's entries, in the order files write them.
std::vector<ShapeField> shapeFields();

template <class Value>
ShapeSpec ShapeSpec::read(const std::optional<std::string>& written, Value&& value) {
    std::vector<double> values;
    const ShapeFamily* family = writtenShapeFamily(written);
    if (family)
        for (const ShapeParameter& parameter : family->parameters)
            values.push_back(value(parameter.name));
    return fromValues(family ? family->name : std::string_view(*written), values);
}

template <class Value>
std::optional<ShapeSpec> ShapeSpec::readIfGiven(const std::optional<std::string>& written,
                                                Value&& value) {
    if (const ShapeFamily* family = writtenShapeFamily(written))
        for (const ShapeParameter& parameter : family->parameters)
            if (!value(parameter.name)) return std::nullopt;
    return read(written, [&](std::string_view name) { return *value(name); });
}

template <class Value>
ShapeSpec ShapeSpec::readOrFallback(const std::optional<std::string>& written, Value&& value) {
    const ShapeFamily* family = writtenShapeFamily(written); // read() asks only a known one's
    return read(written, [&](std::string_view name) {
        return value(name).value_or(findShapeParameter(*family, name)->fallback);
    });
}

/// A body of a ShapeSpec at semi-axis R (the largest half-width of its bounding box): the
/// family's Body, each question dispatched to it (geometry/shape_family, ShapeFamilyTraits).
class ParticleShape {
    using AnyBody = ShapeFamilies::AnyBody;
    AnyBody body_;
    explicit ParticleShape(AnyBody body) : body_(body) {}
    template <class Fn> decltype(auto) visit(Fn&& fn) const {
        return std::visit(std::forward<Fn>(fn), body_);
    }

  public:
    /// Throws std::invalid_argument where the parameters are not the family's.
    ParticleShape(const ShapeSpec& spec, double semiAxis);

    double semiAxis() const {
        return visit([](const auto& b) { return b.semiAxis(); });
    }
    double diameter() const { return 2.0 * semiAxis(); }
    double volume() const {
        return visit([](const auto& b) { return b.volume(); });
    }
    /// The mean width w (paper Sec. II D): the length unit of the paper's reduced distances.
    double meanWidth() const {
        return visit([](const auto& b) { return b.meanWidth(); });
    }
    double circumradius() const {
        return visit([](const auto& b) { return b.circumradius(); });
    }
    double inradius() const {
        return visit([](const auto& b) { return b.inradius(); });
    }
    bool isSphere() const {
        return visit([](const auto& b) { return b.isSphere(); });
    }
    /// Whether the body is the octahedron, whose pairs the solvers take over its face normals.
    bool isOctahedron() const {
        return visit([](const auto& b) {
            if constexpr (requires { b.isOctahedron(); }) return b.isOctahedron();
            return false;
        });
    }
    /// Whether the body's three axes are equivalent under its symmetry (the cube's group), so that
    /// their cubatic order P4 (common/order) is defined.
    bool hasCubicAxes() const {
        return visit([](const auto& b) { return sbpack::hasCubicAxes(b); });
    }
    /// Whether the body is symmetric under the cube's group, so that its contacts' regions <100>,
    /// <110>, <111> name equivalent places (docs/contact-types.md).
    bool hasCubicSymmetry() const {
        return visit([](const auto& b) { return sbpack::hasCubicSymmetry(b); });
    }
    /// Whether the bodies stack face to face into columns that can span a small periodic box
    /// (bench/RESULTS.md, "Near-cubes after the jam check").
    bool stacksInColumns() const {
        return visit([](const auto& b) { return sbpack::stacksInColumns(b); });
    }
    /// The same shape at `factor` times the size.
    ParticleShape scaled(double factor) const {
        return visit([&](const auto& b) { return ParticleShape(AnyBody(b.scaled(factor))); });
    }

    /// The body as the pair solvers and the curvature see it (pair/pair_geometry's ConvexBody,
    /// body frame): gauge, support function, support point, its Hessian, the surface curvature.
    double gauge(const Vector3d& xBody) const {
        return visit([&](const auto& b) { return b.gauge(xBody); });
    }
    double support(const Vector3d& nBody) const {
        return visit([&](const auto& b) { return b.support(nBody); });
    }
    Vector3d supportPoint(const Vector3d& nBody) const {
        return visit([&](const auto& b) -> Vector3d { return b.supportPoint(nBody); });
    }
    Matrix3d supportHessian(const Vector3d& nBody) const {
        return visit([&](const auto& b) -> Matrix3d { return b.supportHessian(nBody); });
    }
    Matrix3d surfaceCurvature(const Vector3d& nBody) const {
        return visit([&](const auto& b) -> Matrix3d { return b.surfaceCurvature(nBody); });
    }

    /// The inside test for many body-frame points (the voxels): the answer of gauge(x) < 1, by
    /// the family's own test.
    class InsideTest {
      public:
        template <class Body>
        explicit InsideTest(const Body& body) : test_(sbpack::insideTest(body)) {}
        bool operator()(const Vector3d& xBody) const {
            return std::visit([&](const auto& test) { return test(xBody); }, test_);
        }

      private:
        template <class Bodies> struct TestsOf;
        template <class... Bodies> struct TestsOf<std::variant<Bodies...>> {
            using type =
                std::variant<decltype(sbpack::insideTest(std::declval<const Bodies&>()))...>;
        };
        typename TestsOf<ShapeFamilies::AnyBody>::type test_;
    };
    InsideTest insideTest() const {
        return visit([](const auto& b) { return InsideTest(b); });
    }
    /// An increasing function of the gauge that is 1 on the surface (the superball's g^{2p},
    /// without a root): xBody is inside iff it is < 1 (the exact pore sizes' inner loop).
    double gaugePower(const Vector3d& xBody) const {
        return visit([&](const auto& b) { return sbpack::gaugePower(b, xBody); });
    }
    /// The point of the body nearest to xBody, xBody itself inside (the exact pore sizes).
    Vector3d closestPoint(const Vector3d& xBody) const {
        return visit([&](const auto& b) -> Vector3d { return sbpack::closestPoint(b, xBody); });
    }

    /// The superball, for code that holds for superballs only; throws std::invalid_argument for
    /// another family.
    const Superball& superball() const;
    /// fn(body) with the family's own body: for code that each family provides in its own files
    /// (the form factor of analysis/spectral/form_factors.hpp).
    template <class Fn> decltype(auto) visitBody(Fn&& fn) const {
        return visit(std::forward<Fn>(fn));
    }
    /// The family's name, for messages.
    std::string_view familyName() const { return ShapeFamilies::info[body_.index()].name; }
};

} // namespace sbpack
