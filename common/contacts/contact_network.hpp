#pragma once
// Contact network, rattlers and mean contact number of a packing (paper Secs. III A, IV A, IV C;
// docs/design.md §2 and §3).

#include "packing/packing.hpp"

#include <string>
#include <utility>
#include <vector>

namespace sbpack {

struct ContactParameters {
    /// Two particles are in contact if their gap is below tolerance * D (paper Sec. III A); a
    /// mixture's pair below tolerance * (R_i + R_j), its own diameter (docs/mixtures.md).
    double tolerance = 1e-10;
    /// The largest tolerance accepted: a gap of a tenth of D is no contact (issue 65 item 7).
    static constexpr double kMaxTolerance = 0.1;
    /// Particles with fewer contacts than this among the non-rattlers are rattlers: d + 1 = 4.
    int rattlerThreshold = 4;
    /// True: allows a tolerance up to kMaxNeighbourTolerance, for a network of potential
    /// contacts (Donev et al. 2004's pairs within 0.25-0.5 D: the jamming finite-gap test,
    /// docs/jamming.md §4.1); its Z and rattlers then count all those pairs.
    bool neighbours = false;
    static constexpr double kMaxNeighbourTolerance = 0.5;
};

struct ContactResult {
    std::vector<std::pair<int, int>> contacts; ///< pairs (i, j), i < j, sorted
    std::vector<double> gaps;      ///< signed distance / D (a mixture's: / (R_i + R_j)), same order
    std::vector<Vector3d> normals; ///< unit contact normal, from i toward j, same order
    std::vector<Vector3d> points;  ///< contactPoint, relative to r_i, same order
    std::vector<int> counts;       ///< per particle, all contacts (rattlers included)
    std::vector<bool> rattler;     ///< per particle
    /// Z: mean over the non-rattlers of their contacts with non-rattlers; 0 if all are rattlers.
    double meanContactNumber = 0.0;
    /// phi_R: fraction of the particles removed as rattlers.
    double rattlerFraction = 0.0;
    /// Smallest signed distance (length units) over the pairs within the contact range: minus
    /// the worst penetration depth, or the smallest gap; +inf and pair (-1, -1) if there is none.
    double worstGap = 0.0;
    int worstPairA = -1;
    int worstPairB = -1;
    int overlappingPairs = 0; ///< pairs with signed distance < -tolerance * D (pair's D)
    long pairIterations = 0;  ///< Newton iterations of all pair solves, to monitor stiffness
    ContactParameters parameters;
};

/// The rattlers of `result`'s contacts and counts (fewer than `threshold` contacts among the
/// particles that remain, removed iteratively: docs/design.md §3), their fraction and Z: what
/// ContactNetwork::compute does last, for a network found otherwise (the nearest jammed
/// packing's, jamming/soft_relaxation.hpp).
void removeRattlers(ContactResult& result, int threshold);

/// "3 overlapping pair(s), the worst (4, 17) by 0.012 D" (depth in units of `diameter`), or ""
/// when none overlaps: the one wording of sbanalyze's warning, info's and sbgen's refusal.
std::string describeOverlaps(const ContactResult& contacts, double diameter);

/// Compute object: validates its parameters at construction, compute() returns a result.
class ContactNetwork {
  public:
    /// Throws std::invalid_argument unless tolerance is in [0, kMaxTolerance] (neighbours: [0,
    /// kMaxNeighbourTolerance]) and rattlerThreshold >= 1.
    explicit ContactNetwork(ContactParameters parameters);

    /// Signed distances of all pairs whose centres are closer than 2 circumradius + tolerance D,
    /// then iterative rattler removal (docs/design.md §3). Throws std::invalid_argument for a
    /// packing with mismatched positions and orientations or a box too small for one image of
    /// each neighbour (L below twice the contact range), and
    /// std::runtime_error if a pair solve returns a non-finite distance.
    ContactResult compute(const Packing& packing) const;

    const ContactParameters& parameters() const { return parameters_; }

  private:
    ContactParameters parameters_;
};

} // namespace sbpack
