// contacts: the contact network of common/contacts (Z, rattlers).
#include "contacts/contact_network.hpp"
#include "contacts/contact_resolution.hpp"
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"

#include <fmt/format.h>

#include <limits>

namespace sbpack::stages {

bool runContacts(FileContext& context, schema::Record& record) {
    const Stopwatch clock;
    const ContactResult c = ContactNetwork(context.settings().contacts).compute(context.packing());
    const ContactResolution resolution =
        resolveContacts(context.packing(), context.settings().contacts.tolerance);
    const double seconds = clock.seconds();
    // Z and phi_R are undetermined when the tolerance cuts through the load-bearing gaps
    // (docs/design.md §3, "Honest contacts"): NaN, and the gap distribution instead.
    const bool undetermined = !resolution.resolved.value_or(true);
    if (undetermined)
        context.progress().warn("contacts: " + resolution.verdict + "\n" +
                                describe(*resolution.gaps));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    context.progress().stageDone("contacts", seconds,
                                 undetermined ? std::string("Z undetermined (not resolved)")
                                              : fmt::format("Z = {}, rattler fraction {}",
                                                            describe(c.meanContactNumber),
                                                            describe(c.rattlerFraction)));
    record.set("z_mean", undetermined ? nan : c.meanContactNumber)
        .set("rattler_fraction", undetermined ? nan : c.rattlerFraction)
        .set("resolved", resolution.resolved ? std::int64_t{*resolution.resolved} : -1)
        .set("tolerance_needed", resolution.neededTolerance)
        .set("tolerance", c.parameters.tolerance)
        .set("rattler_threshold", c.parameters.rattlerThreshold)
        .set("n_contacts", c.contacts.size())
        .set("overlapping_pairs", c.overlappingPairs)
        .set("runtime_s", seconds)
        .set("counts", std::vector<std::int64_t>(c.counts.begin(), c.counts.end()))
        .set("rattler", std::vector<std::int64_t>(c.rattler.begin(), c.rattler.end()));
    if (resolution.gaps)
        record.set("gap_edges", resolution.gaps->edges)
            .set("gap_counts", std::vector<std::int64_t>(resolution.gaps->counts.begin(),
                                                         resolution.gaps->counts.end()));
    return true;
}

} // namespace sbpack::stages
