// Mixtures (docs/mixtures.md): the packing model's volume sum, the file's semi_axes, the pair of
// two sizes against closed forms, the contact network's per-pair tolerance, and the order
// metrics at the pair's own size.

#include "contacts/contact_network.hpp"
#include "contacts/jam_check.hpp"
#include "io/packing_formats.hpp"
#include "io/packing_io.hpp"
#include "order/order_metrics.hpp"
#include "order/pair_correlation.hpp"
#include "order_lattices.hpp"
#include "packing/validation.hpp"
#include "pair/pair_geometry.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <unistd.h>

namespace sbpack {
namespace {

namespace fs = std::filesystem;

/// Four spheres of two sizes on a line along x, in a box of edge 10: pairs (0, 1) and (2, 3)
/// at the gaps given (in units of their own R_i + R_j), the rest far apart.
Packing fourSpheres(double gap01, double gap23) {
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(1.0);
    packing.boxLength = 10.0;
    packing.semiAxes = {0.5, 0.35, 0.35, 0.35};
    packing.semiAxis = 0.5;
    const double d01 = (0.5 + 0.35) * (1.0 + gap01), d23 = 0.7 * (1.0 + gap23);
    packing.positions = {Vector3d(1, 1, 1), Vector3d(1 + d01, 1, 1), Vector3d(5, 5, 5),
                         Vector3d(5 + d23, 5, 5)};
    packing.orientations.assign(4, Quaterniond::Identity());
    return packing;
}

fs::path scratchFile(const std::string& name) {
    return fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()) + ".h5");
}

TEST(Mixtures, ThePackingFractionSumsTheParticlesVolumes) {
    const Packing packing = fourSpheres(0.1, 0.1);
    const double sum = 0.5 * 0.5 * 0.5 + 3 * 0.35 * 0.35 * 0.35;
    EXPECT_NEAR(packing.packingFraction(), 4.0 / 3.0 * std::numbers::pi * sum / 1000.0, 1e-15);
    Packing identical = packing;
    identical.semiAxes.clear();
    EXPECT_EQ(identical.packingFraction(), 4 * identical.shape().volume() / 1000.0);
}

TEST(Mixtures, TheFileKeepsEachParticlesSemiAxis) {
    const Packing packing = fourSpheres(0.1, 0.2);
    const fs::path file = scratchFile("mixture");
    writePacking(packing, file);
    const Packing read = readPacking(file);
    EXPECT_EQ(read.semiAxes, packing.semiAxes);
    EXPECT_EQ(read.semiAxis, 0.5);
    EXPECT_DOUBLE_EQ(read.packingFraction(), packing.packingFraction());
    // Text (an eighth column), extended XYZ (OVITO's aspherical_shape), GSD (a type per size,
    // the exact sizes in sbpack's log) and LAMMPS (each atom's shape) hold each particle's own:
    // they come back.
    for (const char* extension : {".txt", ".xyz", ".gsd", ".dump", ".data"}) {
        const fs::path other = fs::path(file).replace_extension(extension);
        writePackingFile(packing, other);
        const Packing back = readPackingFile(other);
        EXPECT_EQ(back.semiAxes, packing.semiAxes) << extension;
        EXPECT_EQ(back.semiAxis, 0.5) << extension;
        fs::remove(other);
    }
    fs::remove(file);
}

// A text file's sizes: every particle line has the eighth number or none does, and the
// header's semi_axis is the largest; each refusal names the line.
TEST(Mixtures, TextSizesAreOnEveryLineAndTheHeaderHoldsTheLargest) {
    const fs::path file = fs::path(scratchFile("mixture")).replace_extension(".txt");
    writePackingFile(fourSpheres(0.1, 0.1), file);
    std::vector<std::string> lines;
    {
        std::ifstream in(file);
        for (std::string line; std::getline(in, line);)
            lines.push_back(line);
    }
    const auto refusal = [&](std::vector<std::string> changed) {
        std::ofstream out(file);
        for (const std::string& line : changed)
            out << line << '\n';
        out.close();
        try {
            readPackingFile(file);
        } catch (const PackingFileError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    ASSERT_EQ(std::count(lines.back().begin(), lines.back().end(), ' '), 7) << lines.back();
    std::vector<std::string> short7 = lines; // the last particle's semi-axis dropped
    short7.back().erase(short7.back().rfind(' '));
    EXPECT_NE(refusal(short7).find("expected 8 numbers (x y z qw qx qy qz semi_axis) as on the "
                                   "first particle line, found 7"),
              std::string::npos);
    std::vector<std::string> header = lines;
    const auto semiAxis = std::find_if(header.begin(), header.end(), [](const std::string& l) {
        return l.starts_with("# semi_axis ");
    });
    ASSERT_NE(semiAxis, header.end());
    *semiAxis = "# semi_axis 0.6";
    const std::string line = std::to_string(semiAxis - header.begin() + 1);
    EXPECT_NE(refusal(header).find("line " + line +
                                   ": the header's semi_axis is not the largest of the "
                                   "semi_axis column"),
              std::string::npos);
    fs::remove(file);
}

TEST(Mixtures, BadSemiAxesAreRefusedNamingTheProblem) {
    const auto refusal = [](const Packing& packing) {
        try {
            validatePacking(packing, "mix.h5");
        } catch (const InvalidPacking& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    Packing count = fourSpheres(0.1, 0.1);
    count.semiAxes.pop_back();
    EXPECT_NE(refusal(count).find("semi_axes has 3 rows for 4 particles"), std::string::npos);
    Packing negative = fourSpheres(0.1, 0.1);
    negative.semiAxes[2] = -0.35;
    EXPECT_NE(refusal(negative).find("particle 2 has semi-axis -0.35"), std::string::npos);
    Packing notLargest = fourSpheres(0.1, 0.1);
    notLargest.semiAxis = 0.6;
    EXPECT_NE(refusal(notLargest).find("is not the largest of semi_axes (0.5)"), std::string::npos);
    EXPECT_EQ(refusal(fourSpheres(0.1, 0.1)), "");
}

TEST(Mixtures, TwoSpheresOfTwoSizesAreApartByTheSumOfTheirRadii) {
    const Vector3d d(0.3, -0.8, 0.4);
    const SuperballPair pair{Superball(1.0, 0.25), Matrix3d::Identity(), Matrix3d::Identity(), d,
                             1.6};
    EXPECT_DOUBLE_EQ(signedDistance(pair).signedDistance, d.norm() - 0.25 * 2.6);
    EXPECT_DOUBLE_EQ(scaleFactor(pair).scaleFactor, d.norm() / (0.25 * 2.6));
}

/// With equal orientations B = sizeB A, so K = A + B = (1 + sizeB) A: mu = g_A(d) / (1 + sizeB).
TEST(Mixtures, EqualOrientationsScaleTheSumOfTwoSizes) {
    const Matrix3d rotation =
        Eigen::AngleAxisd(0.7, Vector3d(1, 2, -0.5).normalized()).toRotationMatrix();
    for (const double p : {0.7, 1.5, 3.0})
        for (const double sizeB : {0.5, 1.0, 1.4}) {
            const Superball shape(p, 0.5);
            const Vector3d d(0.9, 0.35, -0.2);
            const SuperballPair pair{shape, rotation, rotation, d, sizeB};
            const double expected = shape.gauge(rotation.transpose() * d) / (1.0 + sizeB);
            EXPECT_NEAR(scaleFactor(pair).scaleFactor, expected, 1e-12 * expected)
                << "p " << p << " sizeB " << sizeB;
        }
}

/// The pair of sizes (R_A, R_B) seen from B: the same signed distance (an independent solve).
TEST(Mixtures, APairOfTwoSizesIsTheSameFromEitherBody) {
    const Matrix3d ra = Eigen::AngleAxisd(0.4, Vector3d(0, 1, 1).normalized()).toRotationMatrix();
    const Matrix3d rb = Eigen::AngleAxisd(1.1, Vector3d(1, 0, 2).normalized()).toRotationMatrix();
    const Vector3d d(0.95, 0.4, 0.3);
    for (const double p : {0.8, 1.5, 4.0}) {
        const SuperballPair fromA{Superball(p, 0.5), ra, rb, d, 0.7};
        const SuperballPair fromB{Superball(p, 0.35), rb, ra, -d, 0.5 / 0.35};
        const SignedDistanceResult a = signedDistance(fromA), b = signedDistance(fromB);
        EXPECT_NEAR(a.signedDistance, b.signedDistance, 1e-12) << "p " << p;
        EXPECT_NEAR((a.normal + b.normal).norm(), 0.0, 1e-7) << "p " << p;
    }
}

TEST(Mixtures, AContactIsWithinTheToleranceOfItsOwnPair) {
    // Pair (0, 1) (R 0.5 and 0.35) apart by 0.5e-10 of its R_i + R_j: within 1e-10 of it. Pair
    // (2, 3) (both 0.35) by 1.2e-10 of its own 0.7: no contact, though its gap, 0.84e-10, is
    // within 1e-10 of the largest D = 1.
    const ContactResult c = ContactNetwork({}).compute(fourSpheres(0.5e-10, 1.2e-10));
    ASSERT_EQ(c.contacts.size(), 1U);
    EXPECT_EQ(c.contacts[0], std::make_pair(0, 1));
    EXPECT_NEAR(c.gaps[0], 0.5e-10, 1e-15);
    const ContactResult overlap = ContactNetwork({}).compute(fourSpheres(0.5e-10, -2e-10));
    EXPECT_EQ(overlap.overlappingPairs, 1);
    EXPECT_NEAR(overlap.worstGap, -2e-10 * 0.7, 1e-15);
}

// Three spheres of two sizes in a row that wraps the box along x: every one a rattler, and a
// wrapping chain. A mixture's jam check judges its backbone's count, not its rattlers
// (docs/mixtures.md, "The jam check of a mixture"): the verdict names the empty backbone.
TEST(Mixtures, TheJamChecksVerdictOnAMixtureNamesItsBackbonesCount) {
    Packing row;
    row.shapeSpec = sbpack::ShapeSpec::superball(1.0);
    row.boxLength = 2.4;
    row.semiAxis = 0.5;
    row.semiAxes = {0.5, 0.35, 0.35};
    row.positions = {Vector3d(0.0, 1.2, 1.2), Vector3d(0.85, 1.2, 1.2), Vector3d(1.55, 1.2, 1.2)};
    row.orientations.assign(3, Quaterniond::Identity());
    const JamCheck check = checkJam(row, 1e12);
    EXPECT_FALSE(check.jammed);
    EXPECT_EQ(check.backbone, 0);
    EXPECT_NE(check.verdict.find("the backbone of 0 particles has 0 contacts"), std::string::npos)
        << check.verdict;
    EXPECT_EQ(check.verdict.find("use more particles"), std::string::npos) << check.verdict;
}

/// `packing` as a 50:50 mixture: particle i of size 0.5 (even i) or 0.5 / ratio (odd i).
Packing asBinary(Packing packing, double ratio) {
    packing.semiAxis = 0.5;
    packing.semiAxes.clear();
    for (std::size_t i = 0; i < packing.size(); ++i)
        packing.semiAxes.push_back(i % 2 == 0 ? 0.5 : 0.5 / ratio);
    return packing;
}

// docs/order-metrics.md §1, mixtures: an ideal gas's pairs at reduced distance r number
// N rho V_shell(r) <sigma^3> / 2, so g2 of uncorrelated centres is 1 at every r. Without the
// factor <sigma^3> (0.66 at ratio 1.4) the counts would be 1.5 times the normalisation.
TEST(Mixtures, AnIdealGasOfTwoSizesHasAReducedG2OfOne) {
    Random random(17);
    std::vector<Vector3d> centres(4000);
    for (Vector3d& r : centres)
        r = 20.0 * Vector3d(random.uniform(), random.uniform(), random.uniform());
    const Packing gas = asBinary(lattices::pointPacking(centres, 20.0), 1.4);
    const PairCorrelationResult g = PairCorrelation({}).compute(gas);
    double counted = 0.0, expected = 0.0; // the ideal count: 1 / (its relative error)^2
    for (std::size_t b = 0; b < g.g2.size(); ++b) {
        counted += static_cast<double>(g.pairCount[b]);
        expected += 1.0 / (g.idealGasError[b] * g.idealGasError[b]);
    }
    EXPECT_NEAR(counted / expected, 1.0, 4.0 / std::sqrt(expected)); // Poisson: 0.3 %
}

// A substitutionally random fcc of two sizes (ratio 1.1): ordered by every metric, and its
// cutoff bonds, at the reduced distance of the pair's own size, are the 12 nearest neighbours.
TEST(Mixtures, ARandomAlloyOfTwoSizesOnAnFccLatticeIsOrdered) {
    const Packing alloy = asBinary(
        lattices::displaced(lattices::cubicCrystal(6, 1.3, lattices::kFaceCentred), 0.01, 5), 1.1);
    const OrderMetrics m = measureOrder(alloy);
    ASSERT_TRUE(m.cutoffBonds);
    EXPECT_NEAR(m.cutoffBonds->q6.meanLocalOrder, 0.575, 0.02);
    EXPECT_TRUE(orderVerdict(m).ordered);
}

} // namespace
} // namespace sbpack
