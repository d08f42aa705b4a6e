#pragma once
// The superball's nearest point and the power of its gauge (paper Eq. 1): the exact pore sizes'
// geometry (analysis/pores, docs/design.md), read through ParticleShape.

#include "geometry/superball.hpp"

namespace sbpack {

/// g(x)^{2p} = sum |x_i / R|^{2p} (g the gauge, Superball::gauge): x is inside iff it is < 1;
/// products and roots instead of powers at p = 1 and 1.5, the pore sizes' inner loop.
double gaugePower(const Superball& shape, const Vector3d& xBody);

/// The point of the superball (body frame, centred at the origin) nearest to xBody; xBody itself
/// when it is inside. Euclidean projection onto { sum |y_i / R|^{2p} <= 1 }: by symmetry in the
/// octant of |x|, from the KKT conditions u_i + kappa u_i^{2p-1} = |x_i| / R (u = |y| / R), a
/// monotone scalar equation per axis inside a monotone equation sum u_i^{2p} = 1 for kappa, both
/// solved by bracketed Newton steps to rounding. Closed forms for the sphere and, as the l1-ball
/// projection, for the octahedron p = 0.5. The distance |x - y| is certified by the support
/// function: with n = (x - y) / |x - y|, n.x - h(n) <= dist(x, body) <= |x - y|.
Vector3d closestPoint(const Superball& shape, const Vector3d& xBody);

} // namespace sbpack
