// Where contacts sit on a superball (docs/contact-types.md): the uniform-normal distribution of
// theta (Eqs. 2.1-2.3) and the regions' solid angles against a quadrature that does not use the
// classifier, the sphere packing with random orientations against them, aligned simple-cubic
// lattices (face to face only), and invariance under a rotation of the whole packing.

#include "contacts/contact_types.hpp"
#include "io/packing_formats.hpp"
#include "order_lattices.hpp"
#include "random/random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {
namespace {

const std::string kData = SBPACK_DATA_DIR;
constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kThetaMax = kMaxAxisAngleDegrees * kDegree;
constexpr std::size_t kAxisAxis = 0; // contactPairType(Axis, Axis)

/// The 26 symmetry directions: +-<100>, +-<110>, +-<111>, unit, with their region.
std::vector<std::pair<Vector3d, ContactRegion>> symmetryDirections() {
    std::vector<std::pair<Vector3d, ContactRegion>> out;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z) {
                const Vector3d d(x, y, z);
                const int nonzero = std::abs(x) + std::abs(y) + std::abs(z);
                if (nonzero > 0) out.emplace_back(d.normalized(), ContactRegion(nonzero - 1));
            }
    return out;
}

/// The region of `n` by brute force: the largest n . d over the 26 directions (independent of
/// classifyNormal).
ContactRegion nearestDirection(const Vector3d& n,
                               const std::vector<std::pair<Vector3d, ContactRegion>>& directions) {
    return std::max_element(
               directions.begin(), directions.end(),
               [&](const auto& a, const auto& b) { return n.dot(a.first) < n.dot(b.first); })
        ->second;
}

/// Solid angle over 4 pi of each region and P(theta <= t) at each `t`, by an equal-area
/// quadrature: the golden-spiral (Fibonacci) points z_k = 1 - (2k + 1) / N, phi_k = pi (1 +
/// sqrt 5) (k + 1/2), each of weight 4 pi / N (error ~ N^-3/4 for a region with a smooth
/// boundary; no boundary lines up with the points, as with a latitude-longitude grid's rows).
struct Quadrature {
    std::array<double, kContactRegions> regions{};
    std::vector<double> cdf;
};

Quadrature sphereQuadrature(int points, const std::vector<double>& t) {
    const auto directions = symmetryDirections();
    Quadrature q;
    q.cdf.assign(t.size(), 0.0);
    const double weight = 1.0 / points;
    for (int k = 0; k < points; ++k) {
        const double z = 1.0 - (2.0 * k + 1.0) / points, rho = std::sqrt(1.0 - z * z);
        const double phi = std::numbers::pi * (1.0 + std::sqrt(5.0)) * (k + 0.5);
        const Vector3d n(rho * std::cos(phi), rho * std::sin(phi), z);
        q.regions[static_cast<std::size_t>(nearestDirection(n, directions))] += weight;
        const double theta = std::acos(n.cwiseAbs().maxCoeff());
        for (std::size_t i = 0; i < t.size(); ++i)
            q.cdf[i] += theta <= t[i] ? weight : 0.0;
    }
    return q;
}

Vector3d randomNormal(Random& random) {
    return random.normalVector().normalized();
}

TEST(ContactTypes, SymmetryDirectionsAreTheirOwnRegionsAndAngles) {
    const ContactEnd axis = classifyNormal(Vector3d(0, -1, 0));
    EXPECT_EQ(axis.region, ContactRegion::Axis);
    EXPECT_EQ(axis.axisAngle, 0.0);
    const ContactEnd edge = classifyNormal(Vector3d(1, 0, -1).normalized());
    EXPECT_EQ(edge.region, ContactRegion::Edge);
    EXPECT_NEAR(edge.axisAngle, std::numbers::pi / 4.0, 1e-15);
    const ContactEnd diagonal = classifyNormal(Vector3d(-1, 1, -1).normalized());
    EXPECT_EQ(diagonal.region, ContactRegion::Diagonal);
    EXPECT_NEAR(diagonal.axisAngle, kThetaMax, 1e-7); // acos near 1 / sqrt 3 is well posed
    EXPECT_NEAR(kThetaMax, std::acos(1.0 / std::sqrt(3.0)), 1e-15);
    EXPECT_THROW(classifyNormal(Vector3d(1, 1, 0)), std::invalid_argument);
    EXPECT_THROW(classifyNormal(Vector3d::Zero()), std::invalid_argument);
}

TEST(ContactTypes, PairTypesAreTheSixUnorderedPairs) {
    const std::array regions{ContactRegion::Axis, ContactRegion::Edge, ContactRegion::Diagonal};
    std::vector<int> seen(kContactPairTypes, 0);
    for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t b = a; b < 3; ++b) {
            const std::size_t type = contactPairType(regions[a], regions[b]);
            EXPECT_EQ(type, contactPairType(regions[b], regions[a]));
            EXPECT_EQ(pairTypeName(type), std::string(regionName(regions[a])) + "_" +
                                              std::string(regionName(regions[b])));
            ++seen[type];
        }
    EXPECT_EQ(seen, std::vector<int>(kContactPairTypes, 1));
}

TEST(ContactTypes, UniformNormalsClassifyAsTheBruteForceNearestDirection) {
    const auto directions = symmetryDirections();
    Random random(20240601);
    for (int k = 0; k < 200000; ++k) {
        const Vector3d n = randomNormal(random);
        const ContactEnd end = classifyNormal(n);
        ASSERT_EQ(end.region, nearestDirection(n, directions)) << n.transpose();
        ASSERT_NEAR(end.axisAngle, std::acos(n.cwiseAbs().maxCoeff()), 1e-15);
    }
}

// Eq. 2.1: up to 45 deg the six caps |n_k| >= cos t about +-e_k do not overlap (two axes are
// 90 deg apart), each has solid angle 2 pi (1 - cos t): P(theta <= t) = 3 (1 - cos t). Beyond,
// Eq. 2.2 takes off the 12 overlaps of adjacent caps; the quadrature checks both.
TEST(ContactTypes, UniformAxisAngleIsThreeCapsUpTo45DegreesAndTheQuadratureBeyond) {
    std::vector<double> t;
    for (double degrees = 2.5; degrees < kMaxAxisAngleDegrees; degrees += 2.5)
        t.push_back(degrees * kDegree);
    t.push_back(54.7 * kDegree);
    const Quadrature q = sphereQuadrature(2000000, t);
    for (std::size_t k = 0; k < t.size(); ++k) {
        if (t[k] <= std::numbers::pi / 4.0) {
            EXPECT_NEAR(uniformAxisAngleCdf(t[k]), 3.0 * (1.0 - std::cos(t[k])), 1e-15);
        }
        EXPECT_NEAR(uniformAxisAngleCdf(t[k]), q.cdf[k], 5e-5) << t[k] / kDegree << " deg";
    }
    EXPECT_NEAR(uniformAxisAngleCdf(std::numbers::pi / 4.0 + 1e-9),
                uniformAxisAngleCdf(std::numbers::pi / 4.0), 1e-8); // continuous at 45 deg
    EXPECT_LT(uniformAxisAngleCdf(50.0 * kDegree), 3.0 * (1.0 - std::cos(50.0 * kDegree)) - 0.05);
    EXPECT_NEAR(uniformAxisAngleCdf(kThetaMax - 1e-9), 1.0, 1e-12);
    EXPECT_EQ(uniformAxisAngleCdf(kThetaMax), 1.0);
}

TEST(ContactTypes, RegionFractionsOfUniformNormalsAreTheirSolidAngles) {
    const Quadrature q = sphereQuadrature(2000000, {});
    EXPECT_NEAR(q.regions[0] + q.regions[1] + q.regions[2], 1.0, 1e-9);
    // The classifier on a random sample of normals, within 4 binomial standard deviations.
    constexpr int kSample = 400000;
    Random random(77);
    std::array<int, kContactRegions> counts{};
    for (int k = 0; k < kSample; ++k)
        ++counts[static_cast<std::size_t>(classifyNormal(randomNormal(random)).region)];
    for (std::size_t r = 0; r < kContactRegions; ++r) {
        const double sd = std::sqrt(q.regions[r] * (1.0 - q.regions[r]) / kSample);
        EXPECT_NEAR(counts[r] / double(kSample), q.regions[r], 4.0 * sd)
            << regionName(ContactRegion(r));
    }
    // Eq. 2.4, the spherical polygons' areas by Girard's theorem.
    for (std::size_t r = 0; r < kContactRegions; ++r)
        EXPECT_NEAR(q.regions[r], kUniformRegionFractions[r], 3e-5);
}

TEST(ContactTypes, BinsOfThetaCarryTheUniformDensity) {
    const ContactTypeDistribution d = contactTypeDistribution({});
    ASSERT_EQ(d.axisAngleEdges.size(), std::size_t(kAxisAngleBins) + 1);
    EXPECT_EQ(d.axisAngleEdges.front(), 0.0);
    EXPECT_EQ(d.axisAngleEdges.back(), kMaxAxisAngleDegrees);
    double total = 0.0;
    for (int b = 0; b < kAxisAngleBins; ++b) {
        const double width = d.axisAngleEdges[b + 1] - d.axisAngleEdges[b];
        total += d.uniformAngleDensity[b] * width;
        const double middle = 0.5 * (d.axisAngleEdges[b] + d.axisAngleEdges[b + 1]) * kDegree;
        if (d.axisAngleEdges[b + 1] <= 45.0) { // 3 sin t per radian, to the bin's curvature
            EXPECT_NEAR(d.uniformAngleDensity[b], 3.0 * std::sin(middle) * kDegree, 1e-5);
        }
    }
    EXPECT_NEAR(total, 1.0, 1e-12);
    EXPECT_EQ(d.contactCount, 0u); // no contact: NaN, not 0
    EXPECT_TRUE(std::isnan(d.regionFractions[0]) && std::isnan(d.meanAxisAngleDegrees));
    EXPECT_TRUE(std::isnan(d.axisAngleDensity[0]));
}

/// The packing with each orientation uniformly random (fixed seed).
Packing randomlyOriented(Packing packing, std::uint64_t seed) {
    Random random(seed);
    for (Quaterniond& q : packing.orientations)
        q = random.rotation();
    return packing;
}

// The orientations of spheres mean nothing, so with random ones the body-frame normals are
// uniform. The ends of one particle turn together (and its opposite contacts share theta), so
// the variance of a bin's count is taken over the particles as units: var C_b = sum_i var c_ib,
// estimated by sum_i (c_ib - m_i P_b)^2 with m_i the particle's ends and P_b the uniform bin
// probability. Every bin within 4 of its standard deviations (30 bins: a false alarm in 0.2 %
// of seeds for Gaussian counts), the mean theta within 4 too.
TEST(ContactTypes, SpherePackingWithRandomOrientationsIsUniform) {
    const Packing packing = randomlyOriented(readPackingFile(kData + "/mrj-spheres-5000.h5"), 2024);
    const ContactResult network = ContactNetwork({}).compute(packing);
    const std::vector<TypedContact> typed = typedContacts(packing, network);
    const ContactTypeDistribution d = contactTypeDistribution(typed);
    ASSERT_GT(d.contactCount, 14000u);
    const double width = kMaxAxisAngleDegrees / kAxisAngleBins;
    std::vector<std::vector<int>> perParticle(packing.size(), std::vector<int>(kAxisAngleBins));
    std::vector<double> angleSum(packing.size(), 0.0);
    std::vector<int> ends(packing.size(), 0);
    for (const TypedContact& c : typed)
        for (const auto& [particle, end] : {std::pair{c.i, c.atI}, std::pair{c.j, c.atJ}}) {
            const double theta = end.axisAngle / kDegree;
            ++perParticle[particle][std::min(kAxisAngleBins - 1, int(theta / width))];
            angleSum[particle] += theta;
            ++ends[particle];
        }
    const double allEnds = 2.0 * static_cast<double>(d.contactCount);
    for (int b = 0; b < kAxisAngleBins; ++b) {
        const double pb = d.uniformAngleDensity[b] * width;
        double variance = 0.0;
        for (std::size_t i = 0; i < packing.size(); ++i)
            variance += std::pow(perParticle[i][b] - ends[i] * pb, 2);
        const double z = (d.axisAngleDensity[b] * width - pb) * allEnds / std::sqrt(variance);
        EXPECT_LT(std::abs(z), 4.0) << "bin " << b;
    }
    double meanTheta = 0.0; // the uniform normals' mean theta, by Eq. 2.1-2.2 in 1e-4 steps
    for (double t = 0.5e-4; t < kThetaMax; t += 1e-4)
        meanTheta += (1.0 - uniformAxisAngleCdf(t)) * 1e-4 / kDegree;
    double variance = 0.0;
    for (std::size_t i = 0; i < packing.size(); ++i)
        variance += std::pow(angleSum[i] - ends[i] * meanTheta, 2);
    EXPECT_LT(std::abs(d.meanAxisAngleDegrees - meanTheta) * allEnds / std::sqrt(variance), 4.0);
    EXPECT_NEAR(meanTheta, 31.90, 0.01);
}

/// An aligned simple-cubic lattice of superballs of exponent p touching face to face (5^3).
Packing alignedSimpleCubic(double p) {
    Packing packing = lattices::cubicCrystal(5, 1.0, lattices::kSimpleCubic);
    packing.shapeSpec = sbpack::ShapeSpec::superball(p);
    return packing;
}

void expectFaceToFaceOnly(const Packing& packing, const std::string& what) {
    const ContactResult network = ContactNetwork({}).compute(packing);
    const ContactTypeDistribution d = contactTypeDistribution(typedContacts(packing, network));
    EXPECT_EQ(d.contactCount, 3 * packing.size()) << what;
    EXPECT_EQ(d.regionFractions[0], 1.0) << what;
    EXPECT_EQ(d.pairTypeFractions[kAxisAxis], 1.0) << what;
    EXPECT_LT(d.meanAxisAngleDegrees, 1e-5) << what;
    EXPECT_EQ(d.axisAngleDensity[0], 1.0 / d.axisAngleEdges[1]) << what;
}

TEST(ContactTypes, AlignedSimpleCubicLatticesTouchFaceToFaceOnly) {
    expectFaceToFaceOnly(readPackingFile(kData + "/sc-lattice-p1.5.txt"), "sc-lattice-p1.5.txt");
    expectFaceToFaceOnly(alignedSimpleCubic(4.0), "p = 4");
    expectFaceToFaceOnly(alignedSimpleCubic(10.0), "p = 10");
}

TEST(ContactTypes, RattlersContactsAreLeftOut) {
    const Packing packing = alignedSimpleCubic(4.0);
    ContactResult network = ContactNetwork({}).compute(packing);
    network.rattler[7] = true;
    const std::vector<TypedContact> typed = typedContacts(packing, network);
    EXPECT_EQ(typed.size(), 3 * packing.size() - 6);
    for (const TypedContact& c : typed)
        EXPECT_TRUE(c.i != 7 && c.j != 7);
    network.rattler.pop_back();
    EXPECT_THROW(typedContacts(packing, network), std::invalid_argument);
}

/// A cluster of 3^3 touching particles in the middle of a box of 12, turned by `rotation`
/// about the box's centre, positions and orientations alike.
Packing turnedCluster(double p, std::uint64_t orientationSeed, const Quaterniond& rotation) {
    Packing packing = lattices::cubicCrystal(3, 1.0, lattices::kSimpleCubic, Vector3d::Zero());
    packing.shapeSpec = sbpack::ShapeSpec::superball(p);
    if (orientationSeed) packing = randomlyOriented(packing, orientationSeed);
    packing.boxLength = 12.0;
    const Vector3d centre = Vector3d::Constant(6.0);
    for (std::size_t i = 0; i < packing.size(); ++i) {
        packing.positions[i] = centre + rotation * (packing.positions[i] - Vector3d::Ones());
        packing.orientations[i] = rotation * packing.orientations[i];
    }
    return packing;
}

// Turning the whole packing turns each lab normal and each orientation alike: the body-frame
// normals, and so every end's region and theta, stay. Spheres with random orientations give
// ends in every region; aligned near-cubes give faces. No rattlers: the cluster's corners have
// three contacts.
TEST(ContactTypes, TurningThePackingKeepsEveryContactsType) {
    const ContactNetwork network({.rattlerThreshold = 1});
    Random random(99);
    for (const auto& [p, seed] :
         {std::pair{1.0, std::uint64_t{5}}, std::pair{4.0, std::uint64_t{0}}}) {
        const Packing still = turnedCluster(p, seed, Quaterniond::Identity());
        const Packing turned = turnedCluster(p, seed, random.rotation());
        const auto before = typedContacts(still, network.compute(still));
        const auto after = typedContacts(turned, network.compute(turned));
        ASSERT_EQ(before.size(), 54u) << "p = " << p;
        ASSERT_EQ(after.size(), before.size()) << "p = " << p;
        for (std::size_t k = 0; k < before.size(); ++k) {
            EXPECT_EQ(after[k].i, before[k].i);
            EXPECT_EQ(after[k].j, before[k].j);
            EXPECT_EQ(after[k].atI.region, before[k].atI.region);
            EXPECT_EQ(after[k].atJ.region, before[k].atJ.region);
            EXPECT_NEAR(after[k].atI.axisAngle, before[k].atI.axisAngle, 1e-6);
            EXPECT_NEAR(after[k].atJ.axisAngle, before[k].atJ.axisAngle, 1e-6);
        }
        const ContactTypeDistribution d = contactTypeDistribution(after);
        if (p == 1.0) {
            EXPECT_GT(*std::min_element(d.regionFractions.begin(), d.regionFractions.end()), 0.0);
        } else {
            EXPECT_EQ(d.pairTypeFractions[kAxisAxis], 1.0);
        }
    }
}

} // namespace
} // namespace sbpack
