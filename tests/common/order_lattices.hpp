#pragma once
// Lattice packings whose order is known, shared by the order tests (tests/common/test_order*.cpp).

#include "packing/packing.hpp"
#include "random/random.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

namespace sbpack::lattices {

/// Spheres of diameter 1 (mean width w = 1) at the given centres, aligned.
inline Packing pointPacking(const std::vector<Vector3d>& positions, double boxLength) {
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(1.0);
    packing.semiAxis = 0.5;
    packing.boxLength = boxLength;
    for (const Vector3d& r : positions)
        packing.positions.push_back(wrapIntoBox(r, boxLength));
    packing.orientations.assign(positions.size(), Quaterniond::Identity());
    return packing;
}

/// cells^3 cubic unit cells of edge a with the given basis (in units of a), shifted by `offset`
/// so that points lie on no box face.
inline Packing cubicCrystal(int cells, double a, const std::vector<Vector3d>& basis,
                            const Vector3d& offset = Vector3d(0.13, 0.29, 0.41)) {
    std::vector<Vector3d> positions;
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j)
            for (int k = 0; k < cells; ++k)
                for (const Vector3d& b : basis)
                    positions.push_back(a * (Vector3d(i, j, k) + b + offset));
    return pointPacking(positions, cells * a);
}

inline const std::vector<Vector3d> kSimpleCubic = {Vector3d(0, 0, 0)};
inline const std::vector<Vector3d> kBodyCentred = {Vector3d(0, 0, 0), Vector3d(0.5, 0.5, 0.5)};
inline const std::vector<Vector3d> kFaceCentred = {Vector3d(0, 0, 0), Vector3d(0.5, 0.5, 0),
                                                   Vector3d(0.5, 0, 0.5), Vector3d(0, 0.5, 0.5)};

/// hcp of 448 sites in a cube: 7 x 4 x 4 orthohexagonal cells (a, sqrt 3 a, c) of 4 sites, with
/// c / a = 1.75 (the ideal 1.633 fits no cube; Zn has 1.86) and the sqrt 3 a side stretched by
/// 1 % to 7 a. Nearest neighbours: 6 in the layer at `a`, 6 in the next layers at 1.048 a.
inline Packing hcpCrystal(double a) {
    const Vector3d cell(a, 7.0 * a / 4.0, 7.0 * a / 4.0);
    const std::vector<Vector3d> basis = {Vector3d(0, 0, 0), Vector3d(0.5, 0.5, 0),
                                         Vector3d(0.5, 1.0 / 6.0, 0.5),
                                         Vector3d(0, 2.0 / 3.0, 0.5)};
    std::vector<Vector3d> positions;
    for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k)
                for (const Vector3d& b : basis)
                    positions.push_back(
                        (Vector3d(i, j, k) + b + Vector3d(0.13, 0.29, 0.41)).cwiseProduct(cell));
    return pointPacking(positions, 7.0 * a);
}

/// The packing with each centre moved uniformly in [-h, h]^3: rms displacement h; two centres
/// approach by at most 2 sqrt(3) h.
inline Packing displaced(Packing packing, double h, std::uint64_t seed) {
    Random random(seed);
    for (Vector3d& r : packing.positions) {
        const Vector3d u(random.uniform(), random.uniform(), random.uniform());
        r = wrapIntoBox(r + h * (2.0 * u - Vector3d::Ones()), packing.boxLength);
    }
    return packing;
}

/// Carves an fcc crystallite into a packing of spheres: the fcc sites of nearest-neighbour distance
/// d in the ball of `radius` about `centre` (radius < L / 2) are added, and every particle closer
/// than `clearance` to a site removed (2 semiAxis for spheres: no overlap). Returns the sites'
/// count; they are the packing's last particles.
inline std::size_t carveFccNucleus(Packing& packing, const Vector3d& centre, double radius,
                                   double d, double clearance) {
    const double a = std::sqrt(2.0) * d; // the cubic cell's edge
    const int cells = static_cast<int>(std::ceil(radius / a)) + 1;
    std::vector<Vector3d> sites;
    for (int i = -cells; i <= cells; ++i)
        for (int j = -cells; j <= cells; ++j)
            for (int k = -cells; k <= cells; ++k)
                for (const Vector3d& b : kFaceCentred)
                    if (const Vector3d r = a * (Vector3d(i, j, k) + b); r.norm() < radius)
                        sites.push_back(wrapIntoBox(centre + r, packing.boxLength));
    std::vector<Vector3d> kept;
    for (const Vector3d& r : packing.positions) {
        bool clear = true;
        for (const Vector3d& s : sites)
            clear = clear && minimumImage(r - s, packing.boxLength).norm() >= clearance;
        if (clear) kept.push_back(r);
    }
    kept.insert(kept.end(), sites.begin(), sites.end());
    packing.positions = kept;
    packing.orientations.assign(kept.size(), Quaterniond::Identity());
    packing.velocities.clear();
    packing.angularVelocities.clear();
    return sites.size();
}

} // namespace sbpack::lattices
