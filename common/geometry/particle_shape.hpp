#pragma once
// The particles' shape as Packing carries it (docs/architecture.md, "What a new shape needs"):
// a family and its parameters (ShapeSpec), and a body of that shape at a size (ParticleShape),
// whose geometry (volume, mean width, radii) every analysis may use whatever the family. Code
// that holds for superballs only (their exponent, inside test, form factor, contact types) asks
// for the superball (ParticleShape::superball). The superball is the one family so far; a
// second one adds its body here, its branch to each method, and a refusal to superball().

#include "geometry/superball.hpp"

namespace sbpack {

/// A shape family and its parameters, without a size.
struct ShapeSpec {
    enum class Family { superball };
    Family family = Family::superball;
    /// The superball's exponent (paper Eq. 1); read it through ParticleShape::superball.
    double p = 1.0;

    static ShapeSpec superball(double exponent) { return {Family::superball, exponent}; }
    /// Spheres: superballs of p = 1 (sbgen's exact sphere engine; orientations carry nothing).
    bool isSphere() const { return family == Family::superball && p == 1.0; }
    bool operator==(const ShapeSpec&) const = default;
};

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
    /// The superball, for code that holds for superballs only.
    const Superball& superball() const { return superball_; }

  private:
    Superball superball_;
};

} // namespace sbpack
