#pragma once
// Self-stresses of a backbone network (docs/jamming.md §6.2): contact forces f >= 0 with A f = 0,
// every particle's force and torque in balance (A the collective rigidity matrix,
// jamming/rigidity_matrix.hpp), found by a linear program or given (stored forces); at finite
// pressure, where the snapshot's network need not keep its jammed limit's self-stress, the
// forces that come closest to one (docs/jamming.md §6.6).

#include "jamming/linear_program.hpp"
#include "jamming/rigidity_network.hpp"

namespace sbpack {

/// What findSelfStress asks of the forces (docs/jamming.md §6.2, §6.6).
enum class SelfStressProgram {
    Exact,        ///< A f = 0, loading every contact that some self-stress loads
    LeastResidual ///< f >= 0 of mean 1 minimising |A f|_1: a snapshot's approximate self-stress
};

struct SelfStress {
    /// f_c per network contact, scaled to mean 1 over the contacts; empty when no self-stress
    /// but f = 0 exists.
    Eigen::VectorXd forces;
    /// rho = |A f|_inf with f of mean 1: the largest net force (or torque per D) on a particle in
    /// units of the mean contact force. Rounding for an exact self-stress, the distance from one
    /// for the least-residual forces (docs/jamming.md §6.6), the imbalance of given forces.
    double balanceResidual = 0.0;
    /// |A f|_2 with f of mean 1: the residual r of docs/jamming.md §6.6, Eq. (R), where a second-
    /// order flex must turn with a radius of curvature below |r|_2 / lambda.
    double residualNorm = 0.0;
    int loadedContacts = 0; ///< contacts with f_c above the load tolerance
};

/// Exact: the self-stress that loads as many contacts as any does, by the program
///   maximise sum_c y_c  subject to  A f = 0,  0 <= y_c <= min(f_c, 1),  f >= 0,
/// whose optimum has f_c >= 1 on every contact some self-stress loads and 0 on those none can
/// (docs/jamming.md §6.2); empty forces when only f = 0 balances.
/// LeastResidual: the forces of a finite-pressure snapshot (docs/jamming.md §6.6), by
///   minimise |A f|_1  subject to  sum_c f_c = contacts,  f >= 0,
/// never empty: their balanceResidual says how close to a self-stress they come.
/// `loadTolerance`: f_c / mean above it counts as loaded. Throws std::runtime_error if CLP fails.
SelfStress findSelfStress(const RigidityNetwork& network, double loadTolerance,
                          const LinearProgramTolerances& tolerances,
                          SelfStressProgram program = SelfStressProgram::Exact);

/// Given forces (one per network contact, >= 0, not all 0) scaled to mean 1, with their balance
/// residual. Throws std::invalid_argument for a wrong size, a negative or non-finite force, or
/// all forces 0.
SelfStress givenSelfStress(const RigidityNetwork& network, const Eigen::VectorXd& forces,
                           double loadTolerance);

} // namespace sbpack
