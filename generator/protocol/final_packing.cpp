#include "protocol/final_packing.hpp"

namespace sbpack {

// The contacts are the jam check's: at the paper's tolerance 1e-10 D when the final pressure
// resolves it (P >= 1e12), else at 100 / P D, where the load-bearing gaps are (docs/design.md
// §3, "Honest contacts"; at 1e-10 D a packing at P = 1e10 has Z = 0).
Packing finalPacking(const JammingProtocol& protocol) {
    Packing packing = protocol.checkpoint();
    const JamCheck& jam = *protocol.status().jam;
    const ContactResult& contacts = jam.contacts;
    auto& log = packing.provenance;
    log["z_mean"] = contacts.meanContactNumber;
    log["rattler_fraction"] = contacts.rattlerFraction;
    log["contact_tolerance"] = contacts.parameters.tolerance;
    log["worst_gap_over_d"] = contacts.worstGap / (2.0 * packing.semiAxis);
    log["overlapping_pairs"] = static_cast<std::int64_t>(contacts.overlappingPairs);
    log["jammed"] = static_cast<std::int64_t>(jam.jammed);
    log["jam_check"] = jam.verdict;
    if (!protocol.forceWindows().empty())
        packing.contactForces = protocol.forceWindows().forces(packing);
    return packing;
}

} // namespace sbpack
