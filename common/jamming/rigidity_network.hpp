#pragma once
// The backbone's contact network as the first-order jamming tests see it (docs/jamming.md §2):
// the particles that are not rattlers and, per contact between two of them, what the rigidity
// matrix needs: the unit normal, the lever arms from both centres to the contact point, the
// lattice vector of the minimum image and the gap. Lengths in units of D.

#include "contacts/contact_network.hpp"
#include "packing/packing.hpp"

#include <vector>

namespace sbpack {

/// Contact c between backbone particles i and j.
struct RigidContact {
    int i = 0;                          ///< backbone index of the first particle
    int j = 0;                          ///< backbone index of the second
    Vector3d normal = Vector3d::Zero(); ///< n, unit, from i to j
    Vector3d leverI = Vector3d::Zero(); ///< rho_i = x - r_i
    Vector3d leverJ = Vector3d::Zero(); ///< rho_j = x - r_j
    /// The lattice vector the minimum image adds, r_ij - (r_j - r_i) with r in the box (F L m
    /// in a deformed cell): 0 for a contact inside the box.
    Vector3d boxShift = Vector3d::Zero();
    double gap = 0.0; ///< g_c >= 0: overlaps count as touching
    /// The surfaces' curvature tensors at the contact point (jamming/gap_hessian.hpp), i's along
    /// n and j's along -n, 1 / D: what the second-order test needs (docs/jamming.md §6).
    Matrix3d curvatureI = Matrix3d::Zero();
    Matrix3d curvatureJ = Matrix3d::Zero();
};

struct RigidityNetwork {
    std::vector<int> backbone; ///< packing index of each backbone particle, ascending
    int packingSize = 0;       ///< N, rattlers included
    bool rotations = false;    ///< rotations are degrees of freedom (p != 1)
    double boxLength = 1.0;    ///< L (the largest edge of a non-cubic cell), bounds the strain
    std::vector<RigidContact> contacts;
};

/// The contacts of `network` (ContactNetwork or checkJam on `packing`) among its non-rattlers, in
/// units of D, with the lever arms to the closest points of contactCurvature (jamming/gap_hessian:
/// each support point trusted where its surface is the more curved) and the curvatures. Negative
/// gaps (overlaps within the contact tolerance) become 0: a first-order motion cannot undo an
/// overlap. `cell`: the periodic cell's edges over L as columns, the identity for the packing's
/// cubic box; a volume-preserving F where the box deformed (the nearest jammed packing,
/// jamming/soft_relaxation.hpp), its images at r + F L m and the box shifts F L m. Throws
/// std::invalid_argument if the network's sizes do not match the packing's.
RigidityNetwork backboneNetwork(const Packing& packing, const ContactResult& network,
                                const Matrix3d& cell = Matrix3d::Identity());

} // namespace sbpack
