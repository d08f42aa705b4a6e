// sq: the structure factor S(Q) of the centroids.
#include "pipeline/stage.hpp"
#include "pipeline/stages/stages.hpp"
#include "structure/structure_factor_fields.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace sbpack::stages {

StageMemory structureFactorMemory(const Packing& packing, const RunSettings& settings) {
    const int shell = StructureFactor::maxShellFor(settings.structureFactor.maxQw,
                                                   packing.boxLength, packing.shape().meanWidth());
    return {collectiveDensityBytes(packing, std::max(shell, 1)), "S(Q) tables", "--qmax"};
}

bool runStructureFactor(FileContext& context, schema::Record& record) {
    const StructureFactorParameters& parameters = context.settings().structureFactor;
    const StructureFactorResult s =
        StructureFactor(parameters).compute(context.packing(), context.progress());
    context.progress().stageDone(
        "structure factor", s.runtimeSeconds,
        fmt::format("{} shells up to Q w = {}", s.maxShell, describe(parameters.maxQw)));
    structure_factor_fields::kTable.fill(record, s, context.scales());
    return true;
}

} // namespace sbpack::stages
