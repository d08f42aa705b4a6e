#include "geometry/particle_shape.hpp"

namespace sbpack {

ParticleShape::ParticleShape(const ShapeSpec& spec, double semiAxis)
    : superball_(spec.p, semiAxis) {}

} // namespace sbpack
