#include "packing/contact_forces.hpp"

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

} // namespace sbpack
