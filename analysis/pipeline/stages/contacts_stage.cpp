// contacts: the contact network of common/contacts (Z, rattlers).
#include "contacts/contact_network.hpp"
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"

#include <fmt/format.h>

namespace sbpack::stages {

bool runContacts(FileContext& context, schema::Record& record) {
    const Stopwatch clock;
    const ContactResult c = ContactNetwork(context.settings().contacts).compute(context.packing());
    const double seconds = clock.seconds();
    context.progress().stageDone("contacts", seconds,
                                 fmt::format("Z = {}, rattler fraction {}",
                                             describe(c.meanContactNumber),
                                             describe(c.rattlerFraction)));
    record.set("z_mean", c.meanContactNumber)
        .set("rattler_fraction", c.rattlerFraction)
        .set("tolerance", c.parameters.tolerance)
        .set("rattler_threshold", c.parameters.rattlerThreshold)
        .set("n_contacts", c.contacts.size())
        .set("overlapping_pairs", c.overlappingPairs)
        .set("runtime_s", seconds)
        .set("counts", std::vector<std::int64_t>(c.counts.begin(), c.counts.end()))
        .set("rattler", std::vector<std::int64_t>(c.rattler.begin(), c.rattler.end()));
    return true;
}

} // namespace sbpack::stages
