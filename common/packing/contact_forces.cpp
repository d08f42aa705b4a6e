#include "packing/contact_forces.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

/// The contact's particles, refused unless both are in the packing.
void checkParticles(const ContactForce& c, std::size_t particles) {
    const auto n = static_cast<int>(particles);
    if (c.i < 0 || c.j < 0 || c.i >= n || c.j >= n)
        throw std::invalid_argument("contact force between particles " + std::to_string(c.i) +
                                    " and " + std::to_string(c.j) + " of a packing of " +
                                    std::to_string(particles));
}

} // namespace

ForceBalance forceBalance(const Packing& packing, const ContactForces& forces) {
    const double diameter = 2.0 * packing.semiAxis;
    ForceBalance balance{std::vector<Vector3d>(packing.size(), Vector3d::Zero()),
                         std::vector<Vector3d>(packing.size(), Vector3d::Zero())};
    for (const ContactForce& c : forces.contacts) {
        checkParticles(c, packing.size());
        const Vector3d onJ = c.force * c.normal; // i pushes j along n
        for (const auto& [k, f] : {std::pair{c.i, Vector3d(-onJ)}, std::pair{c.j, onJ}}) {
            const Vector3d lever = minimumImage(c.point - packing.positions[k], packing.boxLength);
            balance.netForces[k] += f;
            balance.netTorques[k] += (lever / diameter).cross(f);
        }
    }
    return balance;
}

double virialPressure(const Packing& packing, const ContactForces& forces) {
    const double diameter = 2.0 * packing.semiAxis;
    double virial = 0.0;
    for (const ContactForce& c : forces.contacts) {
        checkParticles(c, packing.size());
        const Vector3d separation =
            minimumImage(packing.positions[c.j] - packing.positions[c.i], packing.boxLength);
        virial += c.force * c.normal.dot(separation) / diameter;
    }
    return 1.0 + virial / (3.0 * static_cast<double>(packing.size()));
}

ForceDistribution forceDistribution(const ContactForces& forces) {
    using D = ForceDistribution;
    D d;
    d.count = static_cast<std::int64_t>(forces.contacts.size());
    const double width = D::kLargest / D::kBins;
    for (int k = 0; k <= D::kBins; ++k)
        d.edges.push_back(k * width);
    d.density.assign(D::kBins, 0.0);
    double sum = 0.0;
    for (const ContactForce& c : forces.contacts)
        sum += c.force;
    d.mean = sum / static_cast<double>(d.count); // NaN without contacts
    if (d.count == 0 || !(d.mean > 0.0)) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        d.secondMoment = d.tailFraction = nan;
        d.density.assign(D::kBins, nan);
        return d;
    }
    const double weight = 1.0 / static_cast<double>(d.count);
    for (const ContactForce& c : forces.contacts) {
        const double x = c.force / d.mean;
        d.secondMoment += x * x * weight;
        const auto bin = static_cast<std::size_t>(x / width);
        if (bin < d.density.size())
            d.density[bin] += weight / width;
        else
            d.tailFraction += weight;
    }
    return d;
}

} // namespace sbpack
