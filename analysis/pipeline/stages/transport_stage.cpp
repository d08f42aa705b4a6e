// transport: k, tau and T1 from the kept pore sizes (diffusion-controlled limit).
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "pores/pore_size_distribution.hpp"
#include "transport/transport.hpp"

#include <stdexcept>

namespace sbpack::stages {

bool runTransport(FileContext& context, schema::Record& record) {
    const Packing& packing = context.packing();
    TransportResult t;
    try {
        t = Transport({}).compute(context.kept<PoreSizeDistributionResult>(Analysis::PoreSizes),
                                  packing.p, packing.packingFraction());
    } catch (const std::domain_error& e) {
        // Outside the fitted range of the zeta_2 interpolation: no group, a warning.
        context.progress().warn(std::string("transport skipped: ") + e.what());
        return false;
    }
    context.progress().stageDone("transport", t.runtimeSeconds,
                                 "k/w^2 = " + describe(t.permeabilityOverWidth2()));
    record.set("zeta2", t.zeta2)
        .set("formation_factor", t.formationFactor)
        .set("permeability", t.permeability)
        .set("permeability_w2", t.permeabilityOverWidth2())
        .set("mean_survival_time", t.meanSurvivalTime)
        .set("mean_survival_time_scaled", t.meanSurvivalTimeScaled())
        .set("principal_relaxation_time", t.principalRelaxationTime)
        .set("principal_relaxation_time_scaled", t.principalRelaxationTimeScaled())
        .set("diffusion_coefficient", t.parameters.diffusionCoefficient)
        .set("runtime_s", t.runtimeSeconds);
    return true;
}

} // namespace sbpack::stages
