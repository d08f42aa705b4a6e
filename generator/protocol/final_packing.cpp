#include "protocol/final_packing.hpp"

#include "contacts/contact_network.hpp"

namespace sbpack {

Packing finalPacking(const JammingProtocol& protocol) {
    Packing packing = protocol.checkpoint();
    const JamCheck& jam = *protocol.status().jam;
    const ContactParameters paper{};
    const ContactResult contacts =
        jam.tolerance == paper.tolerance ? jam.contacts : ContactNetwork(paper).compute(packing);
    auto& log = packing.provenance;
    log["z_mean"] = contacts.meanContactNumber;
    log["rattler_fraction"] = contacts.rattlerFraction;
    log["contact_tolerance"] = contacts.parameters.tolerance;
    log["worst_gap_over_d"] = contacts.worstGap / (2.0 * packing.semiAxis);
    log["overlapping_pairs"] = static_cast<std::int64_t>(contacts.overlappingPairs);
    log["jammed"] = static_cast<std::int64_t>(jam.jammed);
    log["jam_check"] = jam.verdict;
    log["jam_check_tolerance"] = jam.tolerance;
    return packing;
}

} // namespace sbpack
