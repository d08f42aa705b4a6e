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
// packing at delta > delta_J has gaps in [0, delta) where f_c < delta. With deformBox the box's
// shape relaxes too, at its volume (docs/jamming.md §6.8): the minimum's stress is then
// isotropic, and the strict test (a volume-nonincreasing strain of the box) has a packing that
// can pass it.

#include "contacts/contact_network.hpp"
#include "packing/packing.hpp"

#include <functional>
#include <optional>
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
    /// The box's shape is an unknown too: five traceless strains, the cell F L with det F = 1
    /// (docs/jamming.md §6.8). At the minimum the contact stress is then isotropic.
    bool deformBox = false;
};

/// The five traceless strains of a deformable box, dq's last entries: eps = s0 (e_x e_x - e_z
/// e_z) + s1 (e_y e_y - e_z e_z) + s2 (e_y e_z + e_z e_y) + s3 (e_x e_z + e_z e_x) + s4 (e_x e_y +
/// e_y e_x).
using BoxStrain = Eigen::Matrix<double, 5, 1>;
inline constexpr int kBoxStrains = 5;

/// The cell after the strain step `strain` (docs/jamming.md §6.8): (I + eps) F, rescaled to det
/// 1, so that the volume stays exact whatever the steps (eps is traceless only to first order of
/// the volume).
Matrix3d strainedCell(const Matrix3d& cell, const BoxStrain& strain);

enum class SoftVerdict {
    Jammed,   ///< a minimum with E > 0: the forces balance (balanceResidual)
    Unjammed, ///< the overlaps relax away (mean force below unjammedForce delta)
    Unconverged
};

/// One minimisation at shell `shell`.
struct SoftMinimum {
    double shell = 0.0;
    SoftVerdict verdict = SoftVerdict::Unconverged;
    Packing packing; ///< the relaxed particles, the size and box of the input
    /// The periodic cell's edges over L as columns (images at r + F L m, det F = 1): the
    /// identity unless the box deforms (RelaxationParameters::deformBox).
    Matrix3d cell = Matrix3d::Identity();
    int contacts = 0;             ///< pairs with s_c < delta (forces > 0)
    double meanForce = 0.0;       ///< mean f_c over them, units of D
    double balanceResidual = 0.0; ///< |grad E|_inf / meanForce (0 without contacts)
    int iterations = 0;
    double seconds = 0.0; ///< wall-clock time of the minimisation
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
    /// relaxed - given, minimum image, units of D; in a deformed cell the displacement less the
    /// cell's affine part (F^-1 r_relaxed - r_given), which boxStrain reports.
    std::vector<Vector3d> displacement;
    double largestDisplacement = 0.0;
    double boxStrain = 0.0; ///< the largest |F - I| entry of the relaxed cell (0: box kept)
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
/// rotations for p != 1, then the five strains where `cell` is given: the box deforms from that
/// cell): what every step uses, for tests.
struct OverlapEnergyTerms {
    double energy = 0.0;
    Eigen::VectorXd gradient;
    Eigen::MatrixXd hessian;
};
OverlapEnergyTerms overlapEnergy(const Packing& packing, double shell,
                                 const std::optional<Matrix3d>& cell = std::nullopt);

/// The network of a relaxed packing in its cell: every pair with a signed distance below
/// `tolerance` D (its gap / D, normal, contact point), the rattlers by `rattlerThreshold`
/// (removeRattlers). For a cubic cell the pairs ContactNetwork finds at that tolerance.
ContactResult relaxedContacts(const SoftMinimum& minimum, double tolerance, int rattlerThreshold);

/// Throws std::invalid_argument for parameters out of range (shells in (0, 0.1], smallest <=
/// largest, bracket in (0, 1), tolerances in (0, 1), iterations >= 1).
void validate(const RelaxationParameters& parameters);

/// Called before every step (it may throw to stop the relaxation: an interrupt).
using RelaxationPoll = std::function<void()>;
/// Called after each minimisation of the bracketing, with it (a progress line).
using RelaxationReport = std::function<void(const SoftMinimum&)>;

/// E minimised at `shell` from `packing` in `cell` (its edges over L as columns; deformBox:
/// the cell's start).
SoftMinimum minimiseOverlapEnergy(const Packing& packing, double shell,
                                  const RelaxationParameters& parameters,
                                  const RelaxationPoll& poll = {},
                                  const Matrix3d& cell = Matrix3d::Identity());

/// delta_J bracketed from `packing`: shells 10^k smallestShell until jammed, then bisection;
/// each minimisation starts from the last unjammed minimum (the given packing at first), so that
/// the shells compress it step by step. Jammed only where a minimisation converges to E > 0.
JammingPoint findJammingPoint(const Packing& packing, const RelaxationParameters& parameters,
                              const RelaxationPoll& poll = {}, const RelaxationReport& report = {});

} // namespace sbpack
