// contacts: the contact network of common/contacts (Z, rattlers) and where on the particles its
// contacts sit (docs/contact-types.md).
#include "contacts/contacts_fields.hpp"
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"

#include <fmt/format.h>

namespace sbpack::stages {

bool runContacts(FileContext& context, schema::Record& record) {
    const Stopwatch clock;
    ContactFigures c{ContactNetwork(context.settings().contacts).compute(context.packing()),
                     resolveContacts(context.packing(), context.settings().contacts.tolerance)};
    // The regions are the cube's symmetry directions (docs/contact-types.md): NaN for a shape
    // without that symmetry, as where no contact joins two non-rattlers.
    c.types = contactTypeDistribution(context.packing().shape().hasCubicSymmetry()
                                          ? typedContacts(context.packing(), c.network)
                                          : std::vector<TypedContact>());
    if (context.packing().contactForces)
        c.forces = forceDistribution(*context.packing().contactForces);
    c.seconds = clock.seconds();
    if (c.undetermined())
        context.progress().warn("contacts: " + c.resolution.verdict + "\n" +
                                describe(*c.resolution.gaps));
    context.progress().stageDone("contacts", c.seconds,
                                 c.undetermined()
                                     ? std::string("Z undetermined (not resolved)")
                                     : fmt::format("Z = {}, rattler fraction {}",
                                                   describe(c.network.meanContactNumber),
                                                   describe(c.network.rattlerFraction)));
    contacts_fields::kTable.fill(record, c, context.scales());
    if (context.settings().runs(Analysis::Order) || context.settings().runs(Analysis::Voronoi))
        context.keep(Analysis::Contacts,
                     KeptContacts{std::move(c.network.contacts),
                                  c.undetermined() ? std::vector<bool>() : c.network.rattler});
    return true;
}

} // namespace sbpack::stages
