#include "info/packing_info.hpp"

#include "io/packing_io.hpp"
#include "io/text_io.hpp"

#include <iomanip>
#include <ostream>

namespace sbpack {

PackingInfo packingInfo(const std::filesystem::path& file, const ContactParameters& parameters) {
    Packing packing = readPackingFile(file);
    const double meanWidth = packing.shape().meanWidth();
    ContactResult contacts = ContactNetwork(parameters).compute(packing);
    ContactResolution resolution = resolveContacts(packing, parameters.tolerance);
    std::optional<JamCheck> jam;
    if (packing.reducedPressure && *packing.reducedPressure > 0.0)
        jam = checkJam(packing, *packing.reducedPressure);
    return {std::move(packing), meanWidth, std::move(contacts), std::move(resolution),
            std::move(jam)};
}

void printPackingInfo(const std::filesystem::path& file, const PackingInfo& info,
                      std::ostream& out) {
    const Packing& packing = info.packing;
    const ContactResult& c = info.contacts;
    const double diameter = 2.0 * packing.semiAxis;
    out << std::setprecision(10) << file.string() << '\n'
        << "  particles          N = " << packing.size() << '\n'
        << "  exponent           p = " << packing.p << '\n'
        << "  box edge           L = " << packing.boxLength << '\n'
        << "  semi-axis          R = " << packing.semiAxis << '\n'
        << "  packing fraction phi = " << packing.packingFraction() << '\n'
        << "  mean width         w = " << info.meanWidth << "  (w/D = " << info.meanWidth / diameter
        << ")\n";
    if (packing.reducedPressure)
        out << "  reduced pressure     = " << std::setprecision(4) << *packing.reducedPressure
            << std::setprecision(10) << '\n';
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
    if (c.overlappingPairs > 0) out << "  warning: " << describeOverlaps(c, diameter) << '\n';
}

} // namespace sbpack
