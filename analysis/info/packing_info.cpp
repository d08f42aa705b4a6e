#include "info/packing_info.hpp"

#include "io/packing_formats.hpp"
#include "io/packing_io.hpp"

#include <iomanip>
#include <map>
#include <optional>
#include <ostream>
#include <stdexcept>

namespace sbpack {

PackingInfo packingInfo(const std::filesystem::path& file, const ContactParameters& parameters,
                        const JammingSettings* jamming) {
    Packing packing = readPackingFile(file);
    const double meanWidth = packing.shape().meanWidth();
    // In the analyses' length unit, as sbanalyze's stages (docs/reliability.md, "Units").
    const AnalysedPacking analysed(packing);
    const Packing& reduced = analysed.packing();
    ContactResult contacts = ContactNetwork(parameters).compute(reduced);
    ContactResolution resolution = resolveContacts(reduced, parameters.tolerance);
    std::optional<JamCheck> jam;
    if (reduced.reducedPressure && *reduced.reducedPressure > 0.0)
        jam = checkJam(reduced, *reduced.reducedPressure);
    OrderMetrics order = measureOrder(reduced, &contacts.contacts);
    OrderVerdict verdict = orderVerdict(order);
    std::optional<PackingJamming> categories;
    if (jamming) categories = testJammingCategories(reduced, *jamming, parameters);
    return {std::move(packing),    meanWidth,      analysed.lengthUnit(), std::move(contacts),
            std::move(resolution), std::move(jam), std::move(order),      std::move(verdict),
            std::move(categories)};
}

namespace {

/// "  order  mean local q6 = ..., solid-like ..., T = ..., P4 = ...: disordered" and the warning
/// when ordered.
void printOrder(const PackingInfo& info, std::ostream& out) {
    const OrderMetrics& m = info.order;
    out << "  order                ";
    if (m.cutoffBonds) out << "mean local q6 = " << m.cutoffBonds->q6.meanLocalOrder << ", ";
    if (m.solidLike) out << "solid-like " << m.solidLike->solidFraction << ", ";
    if (m.translational)
        out << "T = " << m.translational->order << " (" << m.translational->parameters.shellCount
            << " fcc shells), ";
    if (m.cubatic) out << "P4 = " << m.cubatic->order << ", ";
    out << (info.verdict.ordered ? "ORDERED" : "no sign of order")
        << "  (docs/order-metrics.md §5)\n";
    if (info.verdict.ordered)
        out << "  warning: this packing has ordered (" << info.verdict.reason
            << "): it is not MRJ, whatever the jam check says\n";
}

/// A mixture's sizes: each distinct semi-axis and how many particles have it (at most four
/// listed, then the range).
void printSizes(const Packing& packing, std::ostream& out) {
    std::map<double, int> counts;
    for (const double r : packing.semiAxes)
        ++counts[r];
    out << "  semi-axes        R_i = ";
    if (counts.size() > 4) {
        out << counts.begin()->first << " to " << counts.rbegin()->first << " (" << counts.size()
            << " sizes)\n";
        return;
    }
    const char* separator = "";
    for (const auto& [r, count] : counts) {
        out << separator << r << " (" << count << ")";
        separator = ", ";
    }
    out << "  (a mixture)\n";
}

/// "  made by  sbgen: C collisions, T CPU s" where the file keeps sbgen's provenance, with the
/// growth rate's raise at plateaus (docs/design.md §3, "Plateaus") where there was one.
void printRun(const Packing& packing, std::ostream& out) {
    const auto number = [&](const char* key) -> std::optional<double> {
        const auto found = packing.provenance.find(key);
        if (found == packing.provenance.end()) return std::nullopt;
        if (const auto* i = std::get_if<std::int64_t>(&found->second))
            return static_cast<double>(*i);
        if (const auto* d = std::get_if<double>(&found->second)) return *d;
        return std::nullopt;
    };
    const std::optional<double> collisions = number("collisions"), cpu = number("cpu_time_s");
    if (!collisions || !cpu) return;
    out << "  made by              sbgen: " << std::setprecision(4) << *collisions
        << " collisions, " << std::setprecision(5) << *cpu << " CPU s";
    if (const std::optional<double> raised = number("stall_speed"))
        out << "; growth raised x" << *raised << " at a plateau (docs/design.md §3, \"Plateaus\")";
    out << std::setprecision(10) << '\n';
}

/// The jamming categories: the network, a line per category tested, the category reached.
void printJamming(const PackingJamming& j, std::ostream& out) {
    if (j.relaxation)
        out << std::setprecision(3) << "  jamming relaxation   " << j.relaxationSummary() << '\n';
    out << std::setprecision(3) << "  jamming              contacts at gap < " << j.tolerance
        << " D (" << j.toleranceFrom << "): backbone " << j.backbone << " of " << j.particles
        << " particles, " << j.contacts << " contacts\n";
    for (const JammingResult& t : j.tests) {
        out << "    " << std::left << std::setw(17) << jammingCategoryName(t.category) << std::right
            << categoryDetail(t);
        if (t.category != JammingCategory::Local)
            out << " (Maxwell deficit " << t.isostaticDeficit << ")";
        out << "  [" << t.seconds << " s]\n";
    }
    out << "  jamming category     " << j.reachedName() << ": " << j.verdict() << '\n'
        << std::setprecision(6);
}

} // namespace

void printPackingInfo(const std::filesystem::path& file, const PackingInfo& info,
                      std::ostream& out) {
    const Packing& packing = info.packing;
    const ContactResult& c = info.contacts;
    const double diameter = 2.0 * packing.semiAxis / info.lengthUnit; // of the contacts' packing
    out << std::setprecision(10) << file.string() << '\n'
        << "  particles          N = " << packing.size() << '\n'
        << "  shape              " << packing.shapeSpec.info().name << ", "
        << packing.shapeSpec.describe() << '\n'
        << "  box edge           L = " << packing.boxLength << '\n'
        << "  semi-axis          R = " << packing.semiAxis
        << (packing.isMixture() ? "  (the largest)\n" : "\n");
    if (packing.isMixture()) printSizes(packing, out);
    out << "  packing fraction phi = " << packing.packingFraction() << '\n'
        << "  mean width         w = " << info.meanWidth
        << "  (w/D = " << info.meanWidth / (2.0 * packing.semiAxis) << ")\n";
    if (packing.reducedPressure)
        out << "  reduced pressure     = " << std::setprecision(4) << *packing.reducedPressure
            << std::setprecision(10) << '\n';
    printRun(packing, out);
    if (c.worstPairA >= 0)
        out << "  smallest gap         = " << std::setprecision(4) << c.worstGap / diameter
            << " D  (pair " << c.worstPairA << ", " << c.worstPairB << ")\n";
    else
        out << "  smallest gap         > " << c.parameters.tolerance
            << " D  (no pair within reach)\n";
    out << std::setprecision(6) << "  contacts (gap < " << c.parameters.tolerance
        << " D): " << c.contacts.size() << '\n';
    if (info.resolution.resolved.value_or(true))
        out << "  mean contacts    Z   = " << c.meanContactNumber << "  (non-rattlers)\n"
            << "  rattler fraction phi_R = " << c.rattlerFraction << "  (fewer than "
            << c.parameters.rattlerThreshold << " contacts, removed iteratively)\n";
    out << "  contact resolution   " << info.resolution.verdict << '\n';
    if (info.resolution.gaps) out << describe(*info.resolution.gaps);
    if (info.jam)
        out << "  jam check            " << info.jam->verdict << '\n';
    else
        out << "  jam check            none: the file has no reduced pressure\n";
    printOrder(info, out);
    if (info.jamming) printJamming(*info.jamming, out);
    if (c.overlappingPairs > 0)
        out << "  warning: " << describeOverlaps(c, diameter)
            << (overlapsWithinRounding(c, diameter, info.resolution.singlePrecision)
                    ? " (single-precision rounding: see the contact resolution above)"
                    : "")
            << '\n';
}

} // namespace sbpack
