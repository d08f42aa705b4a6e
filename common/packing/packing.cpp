#include "packing/packing.hpp"

namespace sbpack {

double Packing::packingFraction() const {
    return static_cast<double>(size()) * shape().volume() / (boxLength * boxLength * boxLength);
}

Packing inLengthUnit(const Packing& packing, double unit) {
    Packing reduced;
    reduced.p = packing.p;
    reduced.semiAxis = packing.semiAxis / unit;
    reduced.boxLength = packing.boxLength / unit;
    reduced.positions.reserve(packing.size());
    for (const Vector3d& r : packing.positions) // exact but where r / unit is subnormal
        reduced.positions.push_back(wrapIntoBox(r / unit, reduced.boxLength));
    reduced.orientations = packing.orientations;
    reduced.reducedPressure = packing.reducedPressure;
    reduced.seed = packing.seed;
    if (packing.contactForces) { // forces in kT / D keep their values; points and times scale
        reduced.contactForces = packing.contactForces;
        reduced.contactForces->duration /= unit;
        for (ContactForce& c : reduced.contactForces->contacts)
            c.point = wrapIntoBox(c.point / unit, reduced.boxLength);
    }
    return reduced;
}

} // namespace sbpack
