#include "pair/pair_solvers.hpp"

namespace sbpack {

Eigen::Matrix<double, 3, 2> tangentBasis(const Vector3d& n) {
    const Vector3d helper = std::abs(n.x()) < 0.6 ? Vector3d::UnitX() : Vector3d::UnitY();
    Eigen::Matrix<double, 3, 2> basis;
    basis.col(0) = n.cross(helper).normalized();
    basis.col(1) = n.cross(basis.col(0));
    return basis;
}

Vector3d contactPoint(const SignedDistanceResult& result) {
    return 0.5 * (result.contactA + result.contactB);
}

// The solvers for the particle shape of a packing (the analyses), which holds any family
// (geometry/particle_shape); a family's own body has its own file (pair/pair_solvers.hpp).
SBPACK_PAIR_SOLVERS(ParticleShape)

} // namespace sbpack
