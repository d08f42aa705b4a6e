#pragma once
// Is a packing jammed, or does its reduced pressure come from a subset? (docs/design.md §3,
// "Jam check"). At reduced pressure P the load-bearing gaps are of order D / P, so the contact
// network is taken at gap < max(1e-10, gapsPerPressure / P) D; a jammed packing has few
// rattlers there. A pressure carried by a chain of particles that wraps around the periodic box
// (a column of face-to-face near-cubes in a box a few D long) is no jam: the chain is rigid
// along one axis while the rest of the packing is loose, and growth cannot proceed.

#include "contacts/contact_network.hpp"

#include <optional>
#include <string>

namespace sbpack {

struct JamCheckParameters {
    /// The contact tolerance at reduced pressure P is max(minTolerance, gapsPerPressure / P) ...
    double minTolerance = 1e-10;
    double gapsPerPressure = 100.0;
    /// ... and at most maxTolerance: a gap of 1 % of D is no contact at any pressure (below
    /// P = 1e4 the check cannot call anything jammed that is not in contact to within that).
    double maxTolerance = 1e-2;
    /// Jammed only if at most this fraction of the particles are rattlers or not locally jammed
    /// (a mixture past it: if its backbone holds 3 N' - 2 contacts and at most this fraction is
    /// free among the non-rattlers; docs/mixtures.md, "The jam check of a mixture").
    double maxRattlerFraction = 0.1;
    int rattlerThreshold = 4;
};

/// A connected set of contacts that wraps around the periodic box: following the contacts'
/// minimum-image displacements around one of its cycles gains a nonzero lattice vector.
struct SpanningChain {
    Vector3d wrap;          ///< the lattice vector gained (multiples of L per axis)
    std::vector<int> cycle; ///< the particles of one wrapping cycle, in order
};

struct JamCheck {
    bool jammed = false;
    double tolerance = 0.0; ///< contact gap tolerance used, in units of D
    ContactResult contacts; ///< at that tolerance
    /// The fraction of particles that are rattlers or not locally jammed (their contacts with
    /// the non-rattlers leave a free translation; see isLocallyTrapped).
    double untrappedFraction = 0.0;
    /// The backbone (the non-rattlers) and its contacts: a jammed backbone of N' particles has
    /// at least 3 N' - 2 (its translations, less the box's 3, and one self-stress).
    int backbone = 0;
    int backboneContacts = 0;
    /// Looked for only when not jammed: contacts that wrap around the box, carrying the pressure.
    std::optional<SpanningChain> chain;
    std::string verdict; ///< one line: why jammed or why not
};

/// Local jamming (Torquato and Stillinger): a particle whose unit contact normals n_k (toward
/// its neighbours) admit no translation v != 0 with v . n_k <= 0 for every k, i.e. they do not
/// all lie in one closed hemisphere. Four contacts in one plane satisfy the count rule of d + 1
/// but leave the particle free across that plane (docs/design.md §3, "Jam check").
bool isLocallyTrapped(const std::vector<Vector3d>& normals);

/// The contact-network criterion of a jam at reduced pressure `reducedPressure` (> 0).
JamCheck checkJam(const Packing& packing, double reducedPressure,
                  const JamCheckParameters& parameters = {});

/// The first wrapping cycle among `contacts` of the packing, if any.
std::optional<SpanningChain> findSpanningChain(const Packing& packing,
                                               const std::vector<std::pair<int, int>>& contacts);

} // namespace sbpack
