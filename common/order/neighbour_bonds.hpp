#pragma once
// The neighbour bonds of a packing, the input of the bond-orientational order
// (docs/order-metrics.md §2): the contact network's pairs, the pairs within a distance cutoff, or
// the solid-angle based nearest neighbours (SANN).

#include "packing/packing.hpp"

#include <cstddef>
#include <utility>
#include <vector>

namespace sbpack {

/// One bond: particles i < j and the minimum-image bond vector r_j - r_i (length units).
struct Bond {
    int i = 0;
    int j = 0;
    Vector3d vector = Vector3d::Zero();
};

/// The bonds of a packing of particleCount particles; a pair listed twice counts twice. A pair
/// whose centres coincide (a valid, overlapping input: two identical particles) has no bond
/// direction: it is left out and counted in `coincident` (issue 65 item 5).
struct NeighbourBonds {
    std::size_t particleCount = 0;
    std::vector<Bond> bonds;
    std::size_t coincident = 0;

    /// Adds the bond i < j of minimum-image vector r_j - r_i, or counts it as coincident.
    void add(int i, int j, const Vector3d& vector);
};

/// The bonds of the given pairs, e.g. ContactResult::contacts (common/contacts/
/// contact_network.hpp): the contact network as neighbour definition. Rattlers are kept or left
/// out by the caller's choice of pairs. Throws std::invalid_argument for a pair whose index is
/// out of range or that joins a particle to itself.
NeighbourBonds contactBonds(const Packing& packing, const std::vector<std::pair<int, int>>& pairs);

/// The bonds of all pairs whose centres are closer than `cutoff` mean widths w (e.g. the first
/// minimum of g2: order/pair_correlation.hpp); of a mixture, than cutoff w sigma_ij, the pair's
/// own (Packing::pairSize), as g2 measures it. Throws std::invalid_argument unless
/// 0 < cutoff w <= L / 2.
NeighbourBonds distanceBonds(const Packing& packing, double cutoff);

/// The bonds of the solid-angle based nearest neighbours (SANN: van Meel, Filion, Valeriani &
/// Frenkel, J. Chem. Phys. 136, 234107 (2012), Eq. 3; docs/order-metrics.md §2): particle i's
/// N_b(i) nearest, N_b(i) the smallest m >= 3 with sum_{k=1..m} r_k / (m - 2) < r_{m+1} over its
/// centre distances r_1 <= r_2 <= ... A pair is a bond when either particle has the other in its
/// shell (the rule is not symmetric). It needs no cutoff and takes each lattice's full shells:
/// simple cubic 18 (6 + 12), bcc 14 (8 + 6), fcc and hcp 12. Throws std::runtime_error where a
/// particle's shell does not close within L / 2 (a box too small for the rule).
NeighbourBonds sannBonds(const Packing& packing);

} // namespace sbpack
