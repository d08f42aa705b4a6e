#pragma once
// Self-stresses of a backbone network (docs/jamming.md §6.2): contact forces f >= 0 with A f = 0,
// every particle's force and torque in balance (A the collective rigidity matrix,
// jamming/rigidity_matrix.hpp), found by a linear program or given (stored forces).

#include "jamming/linear_program.hpp"
#include "jamming/rigidity_network.hpp"

namespace sbpack {

struct SelfStress {
    /// f_c per network contact, scaled to mean 1 over the contacts; empty when no self-stress
    /// but f = 0 exists.
    Eigen::VectorXd forces;
    /// |A f|_inf (units of the mean force; torques per D): rounding for the program's, the
    /// stored forces' imbalance for given ones.
    double balanceResidual = 0.0;
    int loadedContacts = 0; ///< contacts with f_c above the load tolerance
};

/// The self-stress that loads as many contacts as any does: the program
///   maximise sum_c y_c  subject to  A f = 0,  0 <= y_c <= min(f_c, 1),  f >= 0,
/// whose optimum has f_c >= 1 on every contact some self-stress loads and 0 on those none can
/// (docs/jamming.md §6.2). `loadTolerance`: f_c / mean above it counts as loaded. Throws
/// std::runtime_error if CLP fails.
SelfStress findSelfStress(const RigidityNetwork& network, double loadTolerance,
                          const LinearProgramTolerances& tolerances);

/// Given forces (one per network contact, >= 0, not all 0) scaled to mean 1, with their balance
/// residual. Throws std::invalid_argument for a wrong size, a negative or non-finite force, or
/// all forces 0.
SelfStress givenSelfStress(const RigidityNetwork& network, const Eigen::VectorXd& forces,
                           double loadTolerance);

} // namespace sbpack
