#pragma once
// The superball predictor's tolerances and limits (generator/shapes/superball_shape.hpp and its
// layers in this folder), in one place: the first-contact search's
// (shapes/first_contact_limits.hpp) and those of the superball's exact signed distance.

#include "shapes/first_contact_limits.hpp"

namespace sbpack {

/// Tolerances and limits of the superball predictor, in one place.
struct SuperballPredictorLimits : FirstContactLimits {
    /// Warm Newton steps of an exact signed distance before its plane serves as a lower bound or
    /// the local search and the robust pair solver take over (fewer steps send p = 1.5 to the
    /// robust solver more often; since lower bounds serve down to the contact gap, 16 is enough
    /// for p = 1.5 and spares near-cubes the steps of a Newton that will not converge:
    /// bench/RESULTS.md, "Near-cubes: lower bounds down to the contact gap"; "Measurement
    /// history moved out of code comments").
    int newtonSteps = 16;
    /// Where a lower bound on s will do (it must clear the contact gap), warm Newton stops, from
    /// its second iterate on, once its plane gap clears that need by 1 / this times the ascent
    /// its next step predicts: the plane serves (bench/RESULTS.md, "Warm Newton stops where its
    /// plane will do").
    double boundAscentRatio = 0.25;
    /// Along a trajectory each exact evaluation starts from the last optimal normal carried at
    /// its rate dn/dtau, while that turns it by less than this (radians).
    double maxNormalCarry = 0.1;
    /// Near contact, an unconverged Newton's normal is polished by the cutting-plane search over
    /// the normals within this (radians, about) of it before the robust pair solver is called.
    double localSearchRadius = 1e-3;
    /// The polish stops when its normal is known to this (radians, about): f is stationary or
    /// has a kink |u|^q, q > 1, at its maximum, so its value is then exact to rounding.
    double localSearchResolution = 1e-16;
};

} // namespace sbpack
