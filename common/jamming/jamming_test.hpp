#pragma once
// The first-order test of the jamming categories (Torquato & Stillinger, J. Phys. Chem. B 105,
// 11849 (2001)) by the linear programs of Donev, Torquato, Stillinger & Connelly, J. Comput.
// Phys. 197, 139 (2004); docs/jamming.md §3. On the rigidity matrix A of the backbone
// (jamming/rigidity_matrix.hpp), with dq bounded by Delta and trivial motions removed:
//   opening:  maximise sum_c ds_c  subject to ds = A^T dq >= -g   (a contact opens, none closes)
//   flex:     maximise c . dq      subject to A^T dq = 0,  c random (a motion that keeps every
//             contact at its gap to first order, found with probability 1 if one exists)
// Strict adds the strain eps with tr eps <= 0 to both. Where A has full column rank the motions
// come without the programs (Gordan's alternative, jamming/gordan_motion.hpp): an opening of
// every contact. Where the collective first order is Undecided (p != 1), the second-order stress
// test follows (jamming/second_order.hpp).

#include "jamming/linear_program.hpp"
#include "jamming/rigidity_matrix.hpp"
#include "jamming/second_order.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace sbpack {

struct JammingParameters {
    /// Delta (units of D): |dr_a| <= Delta, |dtheta_a| <= Delta (radians, lever arms ~ D / 2) and
    /// |eps_ab| <= Delta / L. The ideal-contact programs are homogeneous: Delta only scales them.
    double maxStep = 1.0;
    /// ds_c >= -g_c with the contacts' gaps; false: ideal contacts, g = 0 (Donev et al. 2004).
    bool useGaps = false;
    /// A contact opens, or a particle moves, when by more than this times Delta: far above CLP's
    /// feasibility tolerance, far below a real motion's O(Delta) (docs/jamming.md §4).
    double motionTolerance = 1e-6;
    /// Units of D; with useGaps, > 0 makes the finite-gap test of Donev et al. 2004 (their
    /// Delta R_unjam ~ D, with Delta ~ 10 D and the network of every pair within 0.25-0.5 D;
    /// docs/jamming.md §4.1), a test of sphere packings (rotations, in radians, are not
    /// measured by it; the analysis refuses p != 1): a motion unjams only where it moves a
    /// particle, or the box's images, by more than this; the flex program becomes their random
    /// load over the gaps' polytope (c and -c), and there is no Undecided. 0: any motion above
    /// the tolerance unjams.
    double unjammingDistance = 0.0;
    /// Whether these parameters make Donev et al.'s finite-gap test (unjammingDistance).
    bool finiteGaps() const { return useGaps && unjammingDistance > 0.0; }
    std::uint64_t seed = 1; ///< of the flex program's random objective
    /// Collective and Strict: the motions by Gordan's alternative where A has full column rank
    /// (jamming/gordan_motion.hpp); false: the programs always (bench/bench_jamming's baseline).
    bool gordanShortcut = true;
    LinearProgramTolerances solver;
    /// The second-order test where the collective first order is Undecided (enabled: true).
    SecondOrderParameters secondOrder;
};

/// The answer at first order.
enum class FirstOrderVerdict {
    Jammed,   ///< no nontrivial first-order motion: neither an opening nor a flex
    Unjammed, ///< a particle is certainly freed (JammingResult::freed); for spheres any opening
              ///< or flex (Connelly 1988: a sphere packing is jammed iff it is first-order rigid)
    Undecided ///< p != 1: an opening along which a closed contact slides or rolls, or a flex:
              ///< the curvatures decide at second order
};

/// A solution of one program, in units of D, per packing particle (rattlers do not move).
struct UnjammingMotion {
    std::vector<Vector3d> displacement; ///< dr; Strict: the whole, eps r included
    std::vector<Vector3d> rotation;     ///< dtheta, radians; empty for spheres
    Matrix3d strain = Matrix3d::Zero(); ///< eps (Strict)
    Eigen::VectorXd gapChange;          ///< ds = A^T dq, one per column of A
    /// Packing indices of the particles displaced or rotated by more than the motion tolerance.
    std::vector<int> moving;
};

struct JammingResult {
    JammingCategory category = JammingCategory::Collective;
    FirstOrderVerdict verdict = FirstOrderVerdict::Jammed;
    double largestOpening = 0.0;            ///< max_c ds_c of the opening, units of D
    std::optional<UnjammingMotion> opening; ///< when a contact opens by > tolerance Delta
    /// The opening opens every contact (Collective, Strict): A has full column rank, no
    /// self-stress exists, and the network is not jammed by Gordan's alternative; the opening
    /// and, where it checks, the flex come from one factorisation of A^T A
    /// (jamming/gordan_motion.hpp), not the programs, and the flexes number isostaticDeficit.
    bool opensEveryContact = false;
    std::optional<UnjammingMotion> flex; ///< when a flex moves by > tolerance Delta
    /// Packing indices of the particles an opening contact frees (its two ends; Local: the end
    /// whose test it is), for p != 1 only where no closed contact slides or rolls (in the local
    /// test per particle, else for the whole motion), and, for spheres, those the flex moves.
    std::vector<int> freed;
    /// The particle held fixed against the trivial translations (Collective, Strict), or -1.
    int fixedParticle = -1;
    /// Degrees of freedom - 3 trivial - contacts (Collective, Strict; 0 for Local): above 0,
    /// flexes must exist (the Maxwell count; isostatic: 0).
    int isostaticDeficit = 0;
    int contacts = 0;
    /// The largest displacement of a particle (or of the box's images, eps L) by any solution
    /// of the programs or the shortcut, kept as a motion or not, units of D: how near the
    /// finite-gap test came to its unjamming distance (docs/jamming.md §4.1).
    double largestDisplacement = 0.0;
    double seconds = 0.0; ///< wall time of the matrix and both programs (the second order apart)
    JammingParameters parameters;
    /// Collective, first order Undecided, parameters.secondOrder.enabled: the stress test.
    std::optional<SecondOrderResult> secondOrder;
    /// Jammed, at first order, or at second order where the first order is Undecided.
    bool jammed() const {
        return verdict == FirstOrderVerdict::Jammed ||
               (secondOrder && secondOrder->verdict == SecondOrderVerdict::Jammed);
    }
};

/// Compute object: parameters validated at construction, compute() returns the result.
class JammingTest {
  public:
    /// Throws std::invalid_argument unless maxStep > 0 is finite, motionTolerance lies in
    /// (0, 1), unjammingDistance lies in [0, maxStep] and is 0 without useGaps, the solver's
    /// tolerances are positive and at most 1e-2 motionTolerance and the second order's are
    /// valid (SecondOrderTest).
    explicit JammingTest(JammingParameters parameters);

    /// The category's first-order verdict on `network` (backboneNetwork), and for Collective
    /// where it is Undecided the second order's, with `forces` (one per network contact, e.g.
    /// stored by sbgen) or the program's self-stress. Throws std::invalid_argument for an empty
    /// backbone or bad forces, std::runtime_error if CLP fails.
    JammingResult compute(const RigidityNetwork& network, JammingCategory category,
                          const std::optional<Eigen::VectorXd>& forces = std::nullopt) const;

    /// Strict from a Collective result that opens every contact, without a second
    /// factorisation: its motions, of the fixed box, are strict motions too (tr eps = 0), so
    /// strict is unjammed by the same opening. Throws std::invalid_argument unless `collective`
    /// is a Collective result with opensEveryContact on `network`.
    static JammingResult strictFromCollective(const JammingResult& collective,
                                              const RigidityNetwork& network);

    const JammingParameters& parameters() const { return parameters_; }

  private:
    JammingParameters parameters_;
};

} // namespace sbpack
