#pragma once
// The nearest jammed packing (docs/jamming.md §6.7): the particles inflated by a shell of
// thickness delta (D units), the overlap energy
//   E(q) = (1/2) sum_c (delta - s_c(q))_+^2,   s_c the exact signed distance (common/pair),
// minimised over translations and, for p != 1, rotations by Levenberg-Marquardt steps on its
// exact Hessian, sum_c a_c a_c^T - sum_c f_c Hess(s_c) (a_c the rigidity column,
// jamming/rigidity_matrix.hpp; Hess(s_c) jamming/gap_hessian.hpp), f_c = delta - s_c. At a minimum
// with E > 0 the forces f balance every particle's force and torque exactly (grad E = -A f = 0):
// the inflated packing is jammed, and f is a self-stress of its network. The jamming point
// delta_J, the smallest shell at which the minimum keeps E > 0, is bracketed by bisection, each
// minimisation from the last unjammed minimum; the particles keep their size, so the relaxed
// packing at delta > delta_J has gaps in [0, delta) where f_c < delta.

#include "packing/packing.hpp"

#include <functional>
#include <vector>

namespace sbpack {

struct RelaxationParameters {
    /// The smallest shell tried (units of D): a packing jammed there is jammed within its gaps.
    double smallestShell = 1e-10;
    /// The largest (units of D, at most 0.05 so that it and the candidate margin stay within
    /// the contact analyses' 0.1 D): a packing not jammed there is reported unjammed.
    double largestShell = 1e-2;
    /// The bracket [unjammed, jammed] is narrowed to this fraction of its upper end.
    double bracketWidth = 0.05;
    /// Levenberg-Marquardt steps of one minimisation.
    int maxIterations = 2000;
    /// Converged when |grad E|_inf <= this times the mean force.
    double balanceTolerance = 1e-10;
    /// The minimum counts as unjammed when its mean force is below this times delta, jammed when
    /// above `stalledForce` delta where the steps stall at rounding: |grad E|_inf below
    /// `stalledGradient` D (the gaps' rounding, 1e-15 D, times the dozen contacts of a particle)
    /// or `stalledBalance` times the mean force (the normals' rounding, about 1e-8, and the
    /// stress test's acceptance of a self-stress, docs/jamming.md §6.6), and in any case below
    /// 1e-3 of the mean force.
    double unjammedForce = 1e-6;
    double stalledForce = 1e-3;
    double stalledGradient = 1e-14;
    double stalledBalance = 1e-6;
    /// The pairs within delta + this (units of D) are the candidates, found again after a particle
    /// has moved by a quarter of it.
    double candidateMargin = 1e-2;
};

enum class SoftVerdict {
    Jammed,   ///< a minimum with E > 0: the forces balance (balanceResidual)
    Unjammed, ///< the overlaps relax away (mean force below unjammedForce delta)
    Unconverged
};

/// One minimisation at shell `shell`.
struct SoftMinimum {
    double shell = 0.0;
    SoftVerdict verdict = SoftVerdict::Unconverged;
    Packing packing;              ///< the relaxed particles, the size and box of the input
    int contacts = 0;             ///< pairs with s_c < delta (forces > 0)
    double meanForce = 0.0;       ///< mean f_c over them, units of D
    double balanceResidual = 0.0; ///< |grad E|_inf / meanForce (0 without contacts)
    int iterations = 0;
    /// The deepest overlap of the particles themselves (s_c < 0, units of D) on the way, the
    /// start included; 0 where every step kept them apart: then the path is a motion of the hard
    /// particles (in steps of at most 1e-2 D).
    double deepestOverlap = 0.0;
};

/// The jamming point of a packing and the relaxed packing just above it.
struct JammingPoint {
    bool found = false;         ///< jammed at some shell <= largestShell
    double unjammedShell = 0.0; ///< the largest shell found unjammed (0: jammed at the smallest)
    double jammedShell = 0.0;   ///< the smallest found jammed (delta_J lies between); 0: none
    SoftMinimum relaxed; ///< the minimum at jammedShell (where not found: the last one tried)
    std::vector<Vector3d> displacement; ///< relaxed - given, minimum image, units of D
    double largestDisplacement = 0.0;
    double largestRotation = 0.0;
    double deepestOverlap = 0.0; ///< the largest SoftMinimum::deepestOverlap on the way
    int minimisations = 0;
    /// Minimisations that ended neither jammed nor unjammed (the iteration limit, or a stall
    /// above rounding), counted unjammed.
    int unconverged = 0;
    double seconds = 0.0;
};

/// E at `shell` (units of D) with its gradient and Hessian, in the packing's length units and
/// the unknowns' layout of jamming/rigidity_matrix.hpp (3 translations per particle, then 3
/// rotations for p != 1): what every step uses, for tests.
struct OverlapEnergyTerms {
    double energy = 0.0;
    Eigen::VectorXd gradient;
    Eigen::MatrixXd hessian;
};
OverlapEnergyTerms overlapEnergy(const Packing& packing, double shell);

/// Throws std::invalid_argument for parameters out of range (shells in (0, 0.1], smallest <=
/// largest, bracket in (0, 1), tolerances in (0, 1), iterations >= 1).
void validate(const RelaxationParameters& parameters);

/// Called before every step (it may throw to stop the relaxation: an interrupt).
using RelaxationPoll = std::function<void()>;

/// E minimised at `shell` from `packing`.
SoftMinimum minimiseOverlapEnergy(const Packing& packing, double shell,
                                  const RelaxationParameters& parameters,
                                  const RelaxationPoll& poll = {});

/// delta_J bracketed from `packing`: shells 10^k smallestShell until jammed, then bisection;
/// each minimisation starts from the last unjammed minimum (the given packing at first), so that
/// the shells compress it step by step. Jammed only where a minimisation converges to E > 0.
JammingPoint findJammingPoint(const Packing& packing, const RelaxationParameters& parameters,
                              const RelaxationPoll& poll = {});

} // namespace sbpack
