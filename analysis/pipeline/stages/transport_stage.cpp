// transport: k, tau and T1 from the kept pore sizes (diffusion-controlled limit).
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "pores/pore_size_distribution.hpp"
#include "transport/transport_fields.hpp"

#include <stdexcept>

namespace sbpack::stages {

bool runTransport(FileContext& context, schema::Record& record) {
    const Packing& packing = context.packing();
    TransportResult t;
    try {
        t = Transport({}).compute(context.kept<PoreSizeDistributionResult>(Analysis::PoreSizes),
                                  packing.superball().p(), packing.packingFraction());
    } catch (const std::domain_error& e) {
        // Outside the fitted range of the zeta_2 interpolation: no group, a warning.
        context.progress().warn(std::string("transport skipped: ") + e.what());
        return false;
    }
    context.progress().stageDone("transport", t.runtimeSeconds,
                                 "k/w^2 = " + describe(t.permeabilityOverWidth2()));
    transport_fields::kTable.fill(record, t, context.scales());
    return true;
}

} // namespace sbpack::stages
