// Honest contacts (docs/design.md §3, "Honest contacts"): a contact tolerance resolves a
// packing's contacts only if it reaches the load-bearing gaps at its reduced pressure, 100 / P D.
// An fcc lattice of spheres shrunk to a known gap g has exactly 6 N pairs at gap g (12
// neighbours each) and none below sqrt(2) - 1 D beyond them: the gap distribution must put
// all 6 N in g's decade.
#include "contacts/contact_resolution.hpp"
#include "io/packing_io.hpp"
#include "io/text_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

namespace sbpack {
namespace {

const std::string kData = SBPACK_DATA_DIR;

/// The fcc lattice (touching spheres, D = 1) with every nearest-neighbour gap equal to `gap` D.
Packing fccWithGap(double gap, std::optional<double> pressure) {
    Packing packing = readTextPacking(kData + "/fcc-spheres.txt");
    const double contact = 2.0 * packing.semiAxis; // nearest-neighbour distance
    packing.semiAxis = contact / (2.0 + 2.0 * gap);
    packing.reducedPressure = pressure;
    return packing;
}

TEST(ContactResolution, APressureTooLowForTheToleranceGivesTheGapDistribution) {
    const Packing packing = fccWithGap(3e-9, 1e10);
    const ContactResolution r = resolveContacts(packing, 1e-10);
    ASSERT_TRUE(r.resolved.has_value());
    EXPECT_FALSE(*r.resolved);
    EXPECT_DOUBLE_EQ(r.neededTolerance, 1e-8);
    EXPECT_NE(r.verdict.find("NOT resolved"), std::string::npos) << r.verdict;
    ASSERT_TRUE(r.gaps.has_value());
    const std::vector<long>& counts = r.gaps->counts;
    const long pairs = 6 * static_cast<long>(packing.size());
    EXPECT_EQ(std::accumulate(counts.begin(), counts.end(), 0L), pairs);
    // edges 1e-16 ... 1e-2: [1e-9, 1e-8) is bin 7
    EXPECT_EQ(counts[7], pairs);
    EXPECT_NE(describe(*r.gaps).find("[1e-09, 1e-08) D: " + std::to_string(pairs) + " pairs"),
              std::string::npos);
}

TEST(ContactResolution, AHighEnoughPressureResolvesThePapersTolerance) {
    const ContactResolution r = resolveContacts(fccWithGap(3e-13, 1e12), 1e-10);
    EXPECT_TRUE(r.resolved.value_or(false)) << r.verdict;
    EXPECT_FALSE(r.gaps.has_value());
    // The same packing read at a coarser tolerance is resolved at a lower pressure too.
    EXPECT_TRUE(resolveContacts(fccWithGap(3e-13, 1e8), 1e-6).resolved.value_or(false));
}

TEST(ContactResolution, WithoutAPressureTheResolutionIsUnknown) {
    const ContactResolution r = resolveContacts(fccWithGap(0.0, std::nullopt), 1e-10);
    EXPECT_FALSE(r.resolved.has_value());
    EXPECT_NE(r.verdict.find("no reduced pressure"), std::string::npos);
}

TEST(ContactResolution, TouchingPairsFallInTheFirstBin) {
    const GapDistribution d = gapDistribution(fccWithGap(0.0, std::nullopt));
    EXPECT_EQ(d.edges.size(), 15u);
    EXPECT_EQ(d.counts.front(), 6 * 108L) << "fcc-spheres.txt: 108 spheres";
}

std::string nineDigits(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", x);
    return text;
}

/// `packing` as a float32 file gives it back: positions and quaternion coefficients rounded to
/// single precision, the quaternions normalised again (as a reader does).
Packing roundedToSinglePrecision(Packing packing) {
    for (Vector3d& r : packing.positions)
        r = r.cast<float>().cast<double>();
    for (Quaterniond& q : packing.orientations)
        q = Quaterniond(q.coeffs().cast<float>().cast<double>()).normalized();
    return packing;
}

TEST(ContactResolution, SinglePrecisionCoordinatesAreFoundAndTheirRoundingBoundsTheOverlaps) {
    const Packing original = readPacking(kData + "/mrj-p1.5-1000.h5");
    EXPECT_FALSE(singlePrecisionRounding(original).has_value()); // double precision
    const Packing rounded = roundedToSinglePrecision(original);
    const std::optional<double> rounding = singlePrecisionRounding(rounded);
    ASSERT_TRUE(rounding.has_value());
    const double diameter = original.shape().diameter();
    EXPECT_NEAR(*rounding,
                (2.0 * std::sqrt(3.0) * std::ldexp(original.boxLength, -24) +
                 2.0 * original.shape().circumradius() * std::ldexp(1.0, -23)) /
                    diameter,
                1e-20);
    // The bound holds, and is not loose by more than a decade: the worst overlap of the rounded
    // packing (the double-precision one has none) lies between a tenth of it and it.
    const ContactResult contacts = ContactNetwork({1e-10, 4}).compute(rounded);
    const double worstOverlap = -contacts.worstGap / diameter;
    EXPECT_LE(worstOverlap, *rounding);
    EXPECT_GE(worstOverlap, 0.1 * *rounding);
    // Printed with 9 significant digits (a text or extended XYZ file), still single precision.
    Packing printed = rounded;
    for (Vector3d& r : printed.positions)
        for (int k = 0; k < 3; ++k)
            r[k] = std::stod(nineDigits(r[k]));
    EXPECT_TRUE(singlePrecisionRounding(printed).has_value());
    // Not resolved at the paper's tolerance, whatever the pressure; resolved at the advised one.
    const ContactResolution r = resolveContacts(rounded, 1e-10);
    EXPECT_FALSE(r.resolved.value_or(true));
    EXPECT_NE(r.verdict.find("single-precision (float32)"), std::string::npos) << r.verdict;
    EXPECT_DOUBLE_EQ(r.neededTolerance, 1e-5);
    EXPECT_TRUE(resolveContacts(rounded, r.neededTolerance).resolved.value_or(false));
}

TEST(ContactResolution, ALatticeOfShortBinaryFractionsIsNotSinglePrecision) {
    // Typed as quarters, a lattice's coordinates are float32 numbers too, but exact, not rounded.
    Packing lattice = fccWithGap(0.0, std::nullopt);
    for (Vector3d& r : lattice.positions)
        r = (r * 4.0).array().round() / 4.0; // quarters: 2 to 5 bits
    EXPECT_FALSE(singlePrecisionRounding(lattice).has_value());
}

} // namespace
} // namespace sbpack
