#pragma once
// Small packings with known geometry for the analysis tests (fixed seeds).

#include "packing/packing.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace sbpack::testing {

/// cells^3 superballs of semi-axis 0.5 on a simple-cubic lattice of the given spacing (box edge
/// cells * spacing), each displaced by up to `jitter` along each axis and, unless aligned,
/// rotated uniformly at random; the lattice starts at `offset` so that particles cross the box
/// faces. With spacing >= 2 circumradius + 2 sqrt(3) jitter nothing overlaps.
inline Packing latticePacking(double p, int cells, double spacing, double jitter,
                              std::uint64_t seed, bool aligned = false, double offset = 0.1) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::normal_distribution<double> normal;
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(p);
    packing.semiAxis = 0.5;
    packing.boxLength = cells * spacing;
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j)
            for (int k = 0; k < cells; ++k) {
                Vector3d r = Vector3d(i, j, k) * spacing + Vector3d::Constant(offset);
                if (jitter > 0.0) r += jitter * Vector3d(uniform(rng), uniform(rng), uniform(rng));
                packing.positions.push_back(wrapIntoBox(r, packing.boxLength));
                Quaterniond q = Quaterniond::Identity();
                if (!aligned)
                    q = Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng))
                            .normalized();
                packing.orientations.push_back(q);
            }
    return packing;
}

/// Random sequential addition of n unit-diameter spheres to packing fraction phi (a cubic box
/// of edge (n (pi / 6) / phi)^(1/3)): a fixture that is not hyperuniform (S(0) > 0, alpha = 0).
inline Packing randomSequentialAddition(int n, double phi, std::uint64_t seed) {
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(1.0);
    packing.semiAxis = 0.5;
    packing.boxLength = std::cbrt(n * (std::numbers::pi / 6.0) / phi);
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> uniform(0.0, packing.boxLength);
    while (static_cast<int>(packing.positions.size()) < n) {
        const Vector3d r(uniform(random), uniform(random), uniform(random));
        bool free = true;
        for (const Vector3d& s : packing.positions) {
            Vector3d d = r - s;
            for (int i = 0; i < 3; ++i)
                d[i] -= packing.boxLength * std::round(d[i] / packing.boxLength);
            if (d.squaredNorm() < 1.0) {
                free = false;
                break;
            }
        }
        if (free) {
            packing.positions.push_back(r);
            packing.orientations.push_back(Quaterniond::Identity());
        }
    }
    return packing;
}

/// One superball of semi-axis `radius` at `position` in a box of edge L.
inline Packing singleParticle(double p, double radius, double boxLength, const Vector3d& position,
                              const Quaterniond& orientation = Quaterniond::Identity()) {
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(p);
    packing.semiAxis = radius;
    packing.boxLength = boxLength;
    packing.positions = {position};
    packing.orientations = {orientation};
    return packing;
}

} // namespace sbpack::testing
