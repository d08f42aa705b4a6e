#pragma once
// The second-order test of jamming for hypostatic packings (Donev, Connelly, Stillinger &
// Torquato, PRE 75, 051304 (2007); Connelly & Whiteley, SIAM J. Discrete Math. 9, 453 (1996),
// prestress stability; docs/jamming.md §6): a self-stress f >= 0, A f = 0 (jamming/self_stress),
// and the stiffness matrix S_f = -sum_c f_c Hess(s_c) (jamming/gap_hessian) positive definite on
// the first-order flexes of the loaded contacts, trivial translations removed by fixing the
// first backbone particle's translation: then every nontrivial motion closes some loaded
// contact at second order, sum_c f_c ds_c = (1/2) dq^T (-S_f) dq < 0. Decided by Finsler's lemma
// (S_f + mu A A^T positive definite for some mu >= 0, a sparse Cholesky), the smallest
// eigenvalue of S_f + mu A A^T (a lower bound on S_f's on the flexes, rising to it as mu grows)
// by Spectra's shift-invert Lanczos. Collective category: the box fixed.

#include "jamming/self_stress.hpp"

#include <optional>

namespace sbpack {

struct SecondOrderParameters {
    bool enabled = true; ///< JammingTest runs it where the collective first order is Undecided
    /// f_c / mean f above this: a loaded contact, whose first-order change must vanish on the
    /// tested flexes (an unloaded one may open at first order).
    double loadTolerance = 1e-6;
    /// The smallest stiffness counts as positive above this times |S_f| (its largest row sum).
    double stiffnessTolerance = 1e-9;
    /// The penalty mu grows by 100 until the smallest eigenvalue of S_f + mu A A^T moves by less
    /// than this times |S_f| (or turns positive), at most to 1e8 |S_f| / |A A^T|.
    double penaltyConvergence = 1e-6;
    /// A pivot of the rank-revealing QR of A counts as zero below this times its largest.
    double rankTolerance = 1e-9;
    /// The program's self-stress: Exact, or LeastResidual for a finite-pressure snapshot
    /// (docs/jamming.md §6.6); forces given to compute are used as they are.
    SelfStressProgram selfStress = SelfStressProgram::Exact;
    /// LeastResidual: forces whose balanceResidual rho exceeds this are no self-stress
    /// (NoSelfStress). The default, from the MRJ packings' rho against pressure, is justified in
    /// docs/jamming.md §6.6.
    double residualAcceptance = 1e-6;
    LinearProgramTolerances solver; ///< of the self-stress program
};

enum class SecondOrderVerdict {
    Jammed,    ///< S_f positive definite on the flexes: jammed at second order (a proof)
    NotJammed, ///< S_f has a direction <= 0 on the flexes: this self-stress does not jam it (with
               ///< a unique self-stress, selfStresses == 1, a second-order flex exists)
    NoSelfStress,     ///< f = 0 only: a first-order motion opens every contact (Gordan); or
                      ///< the least-residual forces' rho is above residualAcceptance
    SingularCurvature ///< a loaded contact where Hess s diverges: on an edge of a p < 1
                      ///< superball, or two flat faces (face centres of aligned p > 1)
};

struct SecondOrderResult {
    SecondOrderVerdict verdict = SecondOrderVerdict::NoSelfStress;
    SelfStress stress;        ///< the self-stress tested (mean 1)
    bool forcesGiven = false; ///< stored forces, not the program's
    int floppyModes = 0;      ///< dim ker A^T - 3 over all contacts (rank-revealing QR of A)
    int testedModes = 0;      ///< the same over the loaded contacts: the flexes S_f is tested on
    int selfStresses = 0;     ///< dim ker A (all contacts): 1 means the self-stress is unique
    /// lambda_min of S_f + mu A A^T (fixed particle's translation removed), units of the mean
    /// force per D (lengths in D, rotations in radians): a lower bound on S_f's on the flexes.
    double smallestStiffness = 0.0;
    double penalty = 0.0;      ///< the mu of smallestStiffness
    double flexResidual = 0.0; ///< |A_loaded^T v|_2 of its unit eigenvector v (0: an exact flex)
    /// |A f|_2 / smallestStiffness (units of D, rotations in radians), where positive: a motion
    /// that keeps the loaded contacts closed to second order turns with a radius of curvature
    /// below it (docs/jamming.md §6.6, Eq. (R)); 0 for an exact self-stress.
    double curvatureRadius = 0.0;
    Eigen::VectorXd softestMode; ///< v in the dof layout (rigidity_matrix.hpp), fixed dr = 0
    double seconds = 0.0;
};

class SecondOrderTest {
  public:
    /// Throws std::invalid_argument unless the tolerances lie in (0, 1).
    explicit SecondOrderTest(SecondOrderParameters parameters);

    /// The test on `network` with the program's self-stress, or with `forces` (one per network
    /// contact; givenSelfStress). Throws std::invalid_argument for an empty backbone.
    SecondOrderResult compute(const RigidityNetwork& network,
                              const std::optional<Eigen::VectorXd>& forces = std::nullopt) const;

    const SecondOrderParameters& parameters() const { return parameters_; }

  private:
    SecondOrderParameters parameters_;
};

} // namespace sbpack
