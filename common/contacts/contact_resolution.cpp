#include "contacts/contact_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace sbpack {

namespace {

constexpr int kFirstDecade = -16, kLastDecade = -2; // the bins' edges, powers of ten of D

std::string scientific(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0e", x);
    return text;
}

} // namespace

GapDistribution gapDistribution(const Packing& packing) {
    GapDistribution d;
    for (int k = kFirstDecade; k <= kLastDecade; ++k)
        d.edges.push_back(std::pow(10.0, k));
    d.counts.assign(d.edges.size() - 1, 0);
    const ContactResult near = ContactNetwork({d.edges.back(), 1}).compute(packing);
    for (const double gap : near.gaps) {
        const auto above = std::upper_bound(d.edges.begin(), d.edges.end(), gap);
        const long bin = std::max(0L, static_cast<long>(std::distance(d.edges.begin(), above)) - 1);
        if (bin < static_cast<long>(d.counts.size())) ++d.counts[bin];
    }
    return d;
}

ContactResolution resolveContacts(const Packing& packing, double tolerance,
                                  const JamCheckParameters& scale) {
    ContactResolution r;
    if (!packing.reducedPressure || !(*packing.reducedPressure > 0.0)) {
        r.verdict = "unknown: the file has no reduced pressure to set the scale of its gaps";
        return r;
    }
    const double pressure = *packing.reducedPressure;
    r.neededTolerance = scale.gapsPerPressure / pressure;
    r.resolved = tolerance >= r.neededTolerance;
    if (*r.resolved) {
        r.verdict = "resolved: load-bearing gaps at reduced pressure " + scientific(pressure) +
                    " stay below " + scientific(r.neededTolerance) + " D";
        return r;
    }
    r.gaps = gapDistribution(packing);
    r.verdict = "NOT resolved: at reduced pressure " + scientific(pressure) +
                " load-bearing gaps reach about " + scientific(r.neededTolerance) +
                " D, above the tolerance " + scientific(tolerance) +
                " D, so Z and phi_R are undetermined (compress further, e.g. sbgen --resume "
                "FILE --pressure-final 1e12); the gap distribution instead:";
    return r;
}

std::string describe(const GapDistribution& gaps) {
    std::string lines;
    for (std::size_t k = 0; k < gaps.counts.size(); ++k) {
        if (gaps.counts[k] == 0) continue;
        char range[64];
        if (k == 0)
            std::snprintf(range, sizeof range, "below %.0e", gaps.edges[1]);
        else
            std::snprintf(range, sizeof range, "[%.0e, %.0e)", gaps.edges[k], gaps.edges[k + 1]);
        lines.append("    ").append(range).append(" D: ");
        lines.append(std::to_string(gaps.counts[k])).append(" pairs\n");
    }
    return lines;
}

} // namespace sbpack
