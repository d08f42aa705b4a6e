// transport: k, tau and T1 from the kept pore sizes (diffusion-controlled limit).
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "pores/pore_size_distribution.hpp"
#include "transport/transport_fields.hpp"

namespace sbpack::stages {

bool runTransport(FileContext& context, schema::Record& record) {
    const Packing& packing = context.packing();
    const TransportResult t =
        Transport({}).compute(context.kept<PoreSizeDistributionResult>(Analysis::PoreSizes),
                              packing.shapeSpec.superballExponent(), packing.packingFraction());
    // Outside the fitted range of the zeta_2 interpolation: tau and T1 alone, and a warning.
    if (!t.permeability)
        context.progress().warn("transport: k left out (tau and T1 written): " +
                                t.permeabilityOmitted);
    context.progress().stageDone(
        "transport", t.runtimeSeconds,
        t.permeability ? "k/w^2 = " + describe(*t.permeabilityOverWidth2())
                       : "T1 D_diff/w^2 = " + describe(t.principalRelaxationTimeOverWidth2()));
    transport_fields::kTable.fill(record, t, context.scales());
    return true;
}

} // namespace sbpack::stages
