#pragma once
// Random superball pairs near contact, as the predictor meets them (the warm-distance and
// pair-gap tests share them).

#include "pair/pair_geometry.hpp"
#include "random/random.hpp"

namespace sbpack::testing {

/// Two superballs of exponent p and diameter 1 in random orientations, displaced along a random
/// direction by 1 + stretch times the displacement at which they touch (the scale factor mu, the
/// gauge of the displacement, is 1 there): apart by about stretch D for stretch > 0, overlapping
/// for stretch < 0.
inline SuperballPair pairNearContact(double p, double stretch, Random& random) {
    SuperballPair pair{Superball(p, 0.5), random.rotation().toRotationMatrix(),
                       random.rotation().toRotationMatrix(), random.normalVector().normalized()};
    pair.displacement *= (1.0 + stretch) / scaleFactor(pair).scaleFactor;
    return pair;
}

} // namespace sbpack::testing
