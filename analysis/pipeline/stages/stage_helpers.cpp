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

double collectiveDensityBytes(const Packing& packing, int maxShell) {
    const double modes = 2.0 / 3.0 * std::numbers::pi * std::pow(maxShell + 0.5, 3);
    return 6.0 * 8.0 * static_cast<double>(packing.size()) * (maxShell + 1) + modes * 2.0 * 20.0;
}

} // namespace sbpack::stages
