#pragma once
// The rigidity matrix A of a backbone network (Donev, Torquato, Stillinger & Connelly,
// J. Comput. Phys. 197, 139 (2004), Sec. 3; docs/jamming.md §2): the first-order changes of the
// gaps are ds = A^T dq, per contact c between i and j with unit normal n (i to j) and lever arms
// rho = x - r to the contact point x,
//   ds_c = n . [(dr_j + dtheta_j x rho_j) - (dr_i + dtheta_i x rho_i)] + n . (eps r_ij),
// with the rotations only for p != 1 (a sphere's rotation moves no gap: its columns are left out)
// and the symmetric strain eps of the box only for strict jamming. There the unknowns are the
// particles' whole displacements, dr'_i = dr_i + eps r_i with r_i in the box, so that the strain
// enters only the contacts that cross the box's faces, by n . (eps (r_ij - (r_j - r_i))): a
// strain column touches those few rows, not all (docs/jamming.md §3, "Method").

#include "jamming/rigidity_network.hpp"

#include <Eigen/SparseCore>

namespace sbpack {

/// The jamming categories of Torquato & Stillinger, J. Phys. Chem. B 105, 11849 (2001).
enum class JammingCategory {
    Local,      ///< each particle alone, its neighbours fixed
    Collective, ///< all particles together, the periodic box fixed
    Strict,     ///< all particles together with a volume-nonincreasing strain of the box
};

/// The layout of dq (the rows of A): 3 translations per backbone particle (Strict: dr'), then 3
/// rotations per particle (p != 1), then the strain eps_xx, eps_yy, eps_zz, eps_yz, eps_xz,
/// eps_xy (Strict).
struct DegreesOfFreedom {
    int particles = 0;
    bool rotations = false;
    bool strain = false;
    /// The first of the three components of dr of `particle`, or of its dtheta.
    int translation(int particle) const { return 3 * particle; }
    int rotation(int particle) const { return 3 * (particles + particle); }
    int strainComponent(int k) const { return 3 * particles * (rotations ? 2 : 1) + k; }
    int count() const { return strainComponent(strain ? 6 : 0); }
};

DegreesOfFreedom degreesOfFreedom(const RigidityNetwork& network, JammingCategory category);

/// The first-order change of one contact's gap in (dr_i, dtheta_i, dr_j, dtheta_j), the order of
/// jamming/gap_hessian.hpp: (-n, -rho_i x n, n, rho_j x n), since n . (dtheta x rho) =
/// dtheta . (rho x n). The rigidity matrix's column, and the relaxation's gradient.
Eigen::Matrix<double, 12, 1> gapGradient(const Vector3d& normal, const Vector3d& leverI,
                                         const Vector3d& leverJ);

/// A (degrees of freedom x gaps). Collective and Strict: one column per contact. Local: two per
/// contact, 2c the change of gap c with j held fixed (in particle i's test), 2c + 1 with i held
/// fixed (in j's), so that the particles' tests are independent blocks of one program.
Eigen::SparseMatrix<double> rigidityMatrix(const RigidityNetwork& network,
                                           JammingCategory category);

} // namespace sbpack
