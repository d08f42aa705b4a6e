// What several stages share.
#include "pipeline/stages/stages.hpp"
#include "schema/record.hpp"

#include "packing/packing.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace sbpack::stages {

std::string describe(double value, int digits) {
    return fmt::format("{:.{}g}", value, digits);
}

void setShells(schema::Record& record, const ShellAverage& shells, std::string_view valueName,
               double meanWidth) {
    std::vector<double> qw(shells.q);
    for (double& x : qw)
        x *= meanWidth;
    record.set("Q", shells.q)
        .set(valueName, shells.value)
        .set("count", shells.count)
        .set("Q_w", qw);
}

void setDistribution(schema::Record& record, const DistributionFigures& figures) {
    record.set("ranks", figures.ranks)
        .set("slab", figures.slab)
        .set("memory_per_rank_bytes", figures.memoryPerRankBytes)
        .set("communication_bytes", figures.communicationBytes);
}

double collectiveDensityBytes(const Packing& packing, int maxShell) {
    const double modes = 2.0 / 3.0 * std::numbers::pi * std::pow(maxShell + 0.5, 3);
    return 6.0 * 8.0 * static_cast<double>(packing.size()) * (maxShell + 1) + modes * 2.0 * 20.0;
}

} // namespace sbpack::stages
