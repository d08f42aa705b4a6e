#pragma once
// The form factors of the exact spectral density's series path, one per shape family
// (docs/architecture.md, "What a new shape needs"). Each has kTile and kSeriesLimit (in
// |k| R_c), order(|k|) and seriesTile(order, u_x, u_y, u_z, out) over u_i = -(k_i R)^2 in the
// body frame: a body symmetric under reflections of its axes, whose m(k) is a series in the
// squared components (exact_spectral_density.cpp's hot loop). A new family adds its form
// factor, one alternative of AnyFormFactor and its branch of formFactorOf.

#include "geometry/particle_shape.hpp"
#include "spectral/superball_form_factor.hpp"

#include <variant>

namespace sbpack {

/// Every form factor the series path can sum.
using AnyFormFactor = std::variant<SuperballFormFactor>;

/// The form factor of `shape`'s body, at its size.
inline AnyFormFactor formFactorOf(const ParticleShape& shape) {
    return SuperballFormFactor(shape.superball());
}

} // namespace sbpack
