#pragma once
// Gordan's alternative on the rigidity matrix (docs/jamming.md §3, "Gordan's shortcut"): either
// a self-stress f >= 0, f != 0, A f = 0 exists, or a motion dq opens every contact,
// A^T dq > 0. Where A (dof x contacts) has full column rank there is no self-stress of any
// sign, the contacts' gap changes can be prescribed, and the least-norm motion with
// A^T dq = 1 is found by one sparse factorisation of A^T A, as is the projection of a random
// motion onto the flexes (A^T dq = 0). Both are candidates: JammingTest accepts them only after
// checking A^T dq itself, so a near-singular A costs a factorisation, never a wrong verdict.

#include "jamming/rigidity_matrix.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstdint>
#include <optional>

namespace sbpack {

/// The candidates, per degree of freedom in the layout of A's rows, scaled to |x|_inf = 1;
/// empty where not finite.
struct GordanMotions {
    Eigen::VectorXd opening; ///< A^T x = const > 0 up to rounding: every contact opens
    Eigen::VectorXd flex;    ///< A^T x = 0 up to rounding (a random flex)
};

/// The candidates of A (Collective or Strict) on its translations and rotations (Strict's strain
/// is left 0: a motion of the fixed box is a strict motion too), with backbone particle
/// `fixed`'s translation subtracted from every particle's (a rigid translation moves no gap).
/// nullopt where A^T A is not positive definite to the factorisation (a self-stress, or more
/// contacts than degrees of freedom). `seed`: the flex's direction.
std::optional<GordanMotions> gordanMotions(const Eigen::SparseMatrix<double>& a,
                                           const DegreesOfFreedom& dof, int fixed,
                                           std::uint64_t seed);

} // namespace sbpack
