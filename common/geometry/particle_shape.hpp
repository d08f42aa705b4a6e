#pragma once
// The particles' shape as Packing carries it (docs/architecture.md, "What a new shape needs"):
// a family and its parameters (ShapeSpec), and a body of that shape at a size (ParticleShape),
// whose geometry (volume, mean width, radii, the pair solvers' ConvexBody, the inside test and
// the nearest point) every analysis may use whatever the family. Code that holds for superballs
// only asks for the superball (ParticleShape::superball: the form factor, the GPU's inside test)
// or its exponent, nothing for another family (ShapeSpec::superballExponent: the transport fit
// in p, which then leaves k out); sbgen's superball-only code (its rates,
// generator/shapes/superball) reads ShapeSpec::p. The superball is the one family so far; a second
// one adds its body here, its branch to each method, and a refusal to superball().

#include "geometry/superball.hpp"
#include "geometry/superball_inside.hpp"
#include "geometry/superball_projection.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sbpack {

/// The key under which the packing file, the results and the .vdb metadata name a shape's
/// family; absent: the superball (every file written before the family had a name).
inline constexpr const char* kShapeFamilyKey = "shape";

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
    Vector3d axes = Vector3d::Ones();
    double eastWest = 2.0;   ///< n of x and y: 2 / OVITO's roundness phi
    double northSouth = 2.0; ///< n of z: 2 / OVITO's roundness theta
};

/// A shape family and its parameters, without a size. Files, results, ensembles and messages
/// know a shape only through its identity here (family(), values(), problem(), describe()).
struct ShapeSpec {
    enum class Family { superball };
    Family family = Family::superball;
    /// The superball's exponent (paper Eq. 1); analyses read it through ParticleShape::superball.
    double p = 1.0;

    static ShapeSpec superball(double exponent) { return {Family::superball, exponent}; }
    /// The shape of family `name` (shapeFamilies()) with `values` in its parameters' order;
    /// throws std::invalid_argument for an unknown family or the wrong number of values.
    static ShapeSpec fromValues(std::string_view name, std::span<const double> values);
    /// Spheres: superballs of p = 1 (sbgen's exact sphere engine; orientations carry nothing).
    bool isSphere() const { return family == Family::superball && p == 1.0; }
    /// The superball's exponent, nothing for another family: what code that holds for superballs
    /// only asks (the transport fit in p), so that a new family leaves that code as it is.
    std::optional<double> superballExponent() const {
        if (family != Family::superball) return std::nullopt;
        return p;
    }
    /// The family's name and parameters.
    const ShapeFamily& info() const;
    /// The parameters' values, in the order of info().parameters.
    std::vector<double> values() const;
    /// Each parameter's name with its value, in the same order: what a file writes.
    std::vector<std::pair<std::string_view, double>> namedValues() const;
    /// The family's name as a file writes it under kShapeFamilyKey: nothing for the superball,
    /// so that every superball file is written as before.
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
    /// The parameters for messages and tables: "p = 1.5".
    std::string describe() const;
    bool operator==(const ShapeSpec&) const = default;
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

/// A body of a ShapeSpec at semi-axis R (the largest half-width of its bounding box).
class ParticleShape {
  public:
    /// Throws std::invalid_argument where the parameters are not the family's (Superball).
    ParticleShape(const ShapeSpec& spec, double semiAxis);

    double semiAxis() const { return superball_.semiAxis(); }
    double diameter() const { return superball_.diameter(); }
    double volume() const { return superball_.volume(); }
    /// The mean width w (paper Sec. II D): the length unit of the paper's reduced distances.
    double meanWidth() const { return superball_.meanWidth(); }
    double circumradius() const { return superball_.circumradius(); }
    double inradius() const { return superball_.inradius(); }
    bool isSphere() const { return superball_.isSphere(); }
    bool isOctahedron() const { return superball_.isOctahedron(); }
    /// Whether the body's three axes are equivalent under its symmetry (the cube's group), so that
    /// their cubatic order P4 (common/order) is defined: every superball but the sphere.
    bool hasCubicAxes() const { return !superball_.isSphere(); }
    /// Whether the body is symmetric under the cube's group (the sphere too), so that its
    /// contacts' regions <100>, <110>, <111> name equivalent places (docs/contact-types.md): every
    /// superball.
    bool hasCubicSymmetry() const { return true; }
    /// Whether the bodies stack face to face into columns that can span a small periodic box
    /// (bench/RESULTS.md, "Near-cubes after the jam check"): superballs from kNearCubeExponent.
    bool stacksInColumns() const { return superball_.p() >= kNearCubeExponent; }
    /// The same shape at `factor` times the size.
    ParticleShape scaled(double factor) const { return ParticleShape(superball_.scaled(factor)); }

    /// The body as the pair solvers and the curvature see it (pair/pair_geometry's ConvexBody,
    /// body frame): gauge, support function, support point, its Hessian, the surface curvature.
    double gauge(const Vector3d& xBody) const { return superball_.gauge(xBody); }
    double support(const Vector3d& nBody) const { return superball_.support(nBody); }
    Vector3d supportPoint(const Vector3d& nBody) const { return superball_.supportPoint(nBody); }
    Matrix3d supportHessian(const Vector3d& nBody) const {
        return superball_.supportHessian(nBody);
    }
    Matrix3d surfaceCurvature(const Vector3d& nBody) const {
        return superball_.surfaceCurvature(nBody);
    }

    /// The inside test for many body-frame points (the voxels): the answer of gauge(x) < 1.
    using InsideTest = SuperballInsideTest;
    InsideTest insideTest() const { return InsideTest(superball_); }
    /// An increasing function of the gauge that is 1 on the surface (the superball's g^{2p},
    /// without a root): xBody is inside iff it is < 1 (the exact pore sizes' inner loop).
    double gaugePower(const Vector3d& xBody) const { return sbpack::gaugePower(superball_, xBody); }
    /// The point of the body nearest to xBody, xBody itself inside (the exact pore sizes).
    Vector3d closestPoint(const Vector3d& xBody) const {
        return sbpack::closestPoint(superball_, xBody);
    }

    /// The superball, for code that holds for superballs only.
    const Superball& superball() const { return superball_; }

  private:
    explicit ParticleShape(const Superball& superball) : superball_(superball) {}
    Superball superball_;
};

} // namespace sbpack
