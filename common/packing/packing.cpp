#include "packing/packing.hpp"

#include <algorithm>

namespace sbpack {

double meanCubedSize(const std::vector<double>& sizes, double unit) {
    if (sizes.empty()) return 1.0;
    double sum = 0.0;
    for (const double size : sizes) {
        const double s = size / unit;
        sum += s * s * s;
    }
    return sum / static_cast<double>(sizes.size());
}

std::vector<double> Packing::relativeSizes() const {
    std::vector<double> sizes;
    sizes.reserve(semiAxes.size());
    for (std::size_t i = 0; i < semiAxes.size(); ++i)
        sizes.push_back(relativeSize(i));
    return sizes;
}

double Packing::smallestSemiAxis() const {
    return semiAxes.empty() ? semiAxis : *std::min_element(semiAxes.begin(), semiAxes.end());
}

double Packing::packingFraction() const {
    // v_i = v1 (R_i / R)^3: one volume integral, scaled per particle.
    return static_cast<double>(size()) * meanCubedSize(semiAxes, semiAxis) * shape().volume() /
           (boxLength * boxLength * boxLength);
}

Packing inLengthUnit(const Packing& packing, double unit) {
    Packing reduced;
    reduced.shapeSpec = packing.shapeSpec;
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
