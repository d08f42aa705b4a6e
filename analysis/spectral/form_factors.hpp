#pragma once
// The form factors of the exact spectral density's series path, one per shape family
// (docs/architecture.md, "What a new shape needs"). Each has kTile and kSeriesLimit (in
// |k| R_c), order(|k|) and seriesTile(order, u_x, u_y, u_z, out) over u_i = -(k_i R)^2 in the
// body frame: a body symmetric under reflections of its axes, whose m(k) is a series in the
// squared components (exact_spectral_density.cpp's hot loop), and is found as formFactorFor(body)
// beside it. A new family with a form factor adds its header and its alternative here.

#include "geometry/particle_shape.hpp"
#include "spectral/superball_form_factor.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <variant>

namespace sbpack {

/// Every form factor the series path can sum.
using AnyFormFactor = std::variant<SuperballFormFactor>;

/// Whether `shape`'s family has a form factor here (else the exact chi_V leaves it out).
inline bool hasFormFactor(const ParticleShape& shape) {
    return shape.visitBody([](const auto& body) {
        return requires {
            AnyFormFactor(formFactorFor(body));
        };
    });
}

/// The form factor of `shape`'s body, at its size; throws std::invalid_argument for a family
/// without one (hasFormFactor).
inline AnyFormFactor formFactorOf(const ParticleShape& shape) {
    return shape.visitBody([&](const auto& body) -> AnyFormFactor {
        if constexpr (requires { AnyFormFactor(formFactorFor(body)); })
            return formFactorFor(body);
        else
            throw std::invalid_argument(fmt::format(
                "exact spectral density: no form factor of {}s (spectral/form_factors.hpp)",
                shape.familyName()));
    });
}

} // namespace sbpack
