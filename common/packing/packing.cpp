#include "packing/packing.hpp"

#include <cmath>

namespace sbpack {

double Packing::packingFraction() const {
    const double cube = boxLength * boxLength * boxLength;
    if (semiAxes.empty()) return static_cast<double>(size()) * shape().volume() / cube;
    // v_i = v1 (R_i / R)^3: one volume integral, scaled per particle.
    double sum = 0.0;
    for (const double r : semiAxes)
        sum += std::pow(r / semiAxis, 3);
    return sum * shape().volume() / cube;
}

Packing inLengthUnit(const Packing& packing, double unit) {
    Packing reduced;
    reduced.p = packing.p;
    reduced.semiAxis = packing.semiAxis / unit;
    reduced.semiAxes.reserve(packing.semiAxes.size());
    for (const double r : packing.semiAxes)
        reduced.semiAxes.push_back(r / unit);
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
