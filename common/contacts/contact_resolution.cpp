#include "contacts/contact_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

/// Significant bits of x's binary mantissa (0 for 0): at most 24 for a float32.
int significantBits(double x) {
    if (x == 0.0) return 0;
    int exponent = 0;
    const double mantissa = std::frexp(std::abs(x), &exponent); // in [0.5, 1)
    auto bits = static_cast<std::uint64_t>(std::ldexp(mantissa, 53));
    int width = 53;
    for (; width > 0 && (bits & 1U) == 0; bits >>= 1U)
        --width;
    return width;
}

} // namespace

std::optional<double> singlePrecisionRounding(const Packing& packing) {
    int widest = 0;
    // A float32 as read back: exactly (binary files), or from the 9 significant digits that
    // print it (text, extended XYZ), within half a unit of the 9th digit.
    const auto widen = [&](double x) {
        const auto single = static_cast<double>(static_cast<float>(x));
        widest = std::abs(x - single) <= 1e-8 * std::abs(x)
                     ? std::max(widest, significantBits(single))
                     : 64;
    };
    // The positions only: a reader normalises the quaternions, which leaves float32's grid.
    for (std::size_t i = 0; i < packing.size() && widest <= 24; ++i)
        for (int k = 0; k < 3; ++k)
            widen(packing.positions[i][k]);
    if (widest > 24 || widest <= 12) return std::nullopt;
    const double centres = 2.0 * std::sqrt(3.0) * std::ldexp(packing.boxLength, -24);
    const double turns = 2.0 * packing.shape().circumradius() * std::ldexp(1.0, -23);
    return (centres + turns) / packing.shape().diameter();
}

bool overlapsWithinRounding(const ContactResult& contacts, double diameter,
                            const std::optional<double>& rounding) {
    return rounding && -contacts.worstGap <= *rounding * diameter;
}

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
    r.singlePrecision = singlePrecisionRounding(packing);
    if (r.singlePrecision && tolerance < *r.singlePrecision) {
        r.resolved = false;
        r.neededTolerance = std::pow(10.0, std::ceil(std::log10(*r.singlePrecision)));
        r.gaps = gapDistribution(packing);
        r.verdict = "NOT resolved: every coordinate is a single-precision (float32) number, whose "
                    "rounding moves surfaces by up to " +
                    scientific(*r.singlePrecision) + " D, above the tolerance " +
                    scientific(tolerance) +
                    " D: gaps and overlaps of that size are rounding, so Z and phi_R are "
                    "undetermined (count the contacts through it with --tolerance " +
                    scientific(r.neededTolerance) +
                    ", or analyse the double-precision file); the gap distribution instead:";
        return r;
    }
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
