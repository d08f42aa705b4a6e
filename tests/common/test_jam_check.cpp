// The jam check (docs/design.md §3): lattices with every particle load-bearing are jammed; a
// column of face-to-face near-cubes that wraps around the box, with loose particles beside it,
// is not, and the chain found is the one built (its wrap is the sum of its contacts'
// minimum-image displacements).
#include "contacts/jam_check.hpp"
#include "io/text_io.hpp"

#include <gtest/gtest.h>

#include <set>

namespace sbpack {
namespace {

const std::string kData = SBPACK_DATA_DIR;

/// Six aligned p = 3 superballs stacked face to face along y, exactly touching (the contact
/// distance of aligned bodies along an axis is D), wrapping around a box of 6 D, and `loose`
/// particles well apart from the column and from each other.
Packing column(int loose) {
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(3.0);
    packing.semiAxis = 0.5;
    packing.boxLength = 6.0;
    for (int k = 0; k < 6; ++k)
        packing.positions.emplace_back(1.0, 0.5 + k, 1.0);
    for (int k = 0; k < loose; ++k)
        packing.positions.emplace_back(3.0 + 1.5 * (k % 2), 0.7 + 2.1 * (k / 2), 3.9);
    packing.orientations.assign(packing.size(), Quaterniond::Identity());
    return packing;
}

/// Square layers of touching spheres (4 x 4 in x and y, spacing D) two layers apart in z
/// (spacing 2 D): every sphere has exactly 4 contacts, all in its layer's plane.
Packing squareLayers() {
    Packing packing;
    packing.shapeSpec = sbpack::ShapeSpec::superball(1.0);
    packing.semiAxis = 0.5;
    packing.boxLength = 4.0;
    for (int layer = 0; layer < 2; ++layer)
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                packing.positions.emplace_back(0.5 + i, 0.5 + j, 0.5 + 2.0 * layer);
    packing.orientations.assign(packing.size(), Quaterniond::Identity());
    return packing;
}

TEST(LocalJamming, ContactsInOneClosedHemisphereLeaveAParticleFree) {
    const Vector3d x = Vector3d::UnitX(), y = Vector3d::UnitY(), z = Vector3d::UnitZ();
    EXPECT_TRUE(isLocallyTrapped({x, -x, y, -y, z, -z})); // simple cubic
    EXPECT_TRUE(isLocallyTrapped({Vector3d(1, 1, 1).normalized(), Vector3d(1, -1, -1).normalized(),
                                  Vector3d(-1, 1, -1).normalized(),
                                  Vector3d(-1, -1, 1).normalized()})); // tetrahedron
    EXPECT_FALSE(isLocallyTrapped({x, -x, y, -y}));                    // free along z
    EXPECT_FALSE(isLocallyTrapped({x, y, (x + y + z).normalized(), (x + z).normalized()}));
    EXPECT_FALSE(isLocallyTrapped({x, -x, x, -x})); // on one line
    EXPECT_FALSE(isLocallyTrapped({}));
    // Tilted out of the plane in opposite senses, the four span space around the origin.
    const double tilt = 1e-3;
    EXPECT_TRUE(isLocallyTrapped({(x + tilt * z).normalized(), (-x + tilt * z).normalized(),
                                  (y - tilt * z).normalized(), (-y - tilt * z).normalized()}));
}

TEST(JamCheck, LayersWithFourContactsInTheirPlaneAreNoJam) {
    // The count rule (d + 1 = 4 contacts) keeps every sphere, but each one is free across its
    // layer: before the local-jamming test such a packing was called jammed (bench/RESULTS.md,
    // "Near-cubes: the local search stops on its plane bound").
    const Packing layers = squareLayers();
    const JamCheck check = checkJam(layers, 1e12);
    EXPECT_EQ(check.contacts.rattlerFraction, 0.0);
    EXPECT_EQ(check.untrappedFraction, 1.0);
    EXPECT_FALSE(check.jammed) << check.verdict;
    ASSERT_TRUE(check.chain.has_value());
    EXPECT_NE(check.verdict.find("not locally jammed"), std::string::npos) << check.verdict;
}

TEST(JamCheck, TheSimpleCubicLatticeOfSuperballsIsJammed) {
    const Packing lattice = readTextPacking(kData + "/sc-lattice-p1.5.txt");
    const JamCheck check = checkJam(lattice, 1e12);
    EXPECT_TRUE(check.jammed) << check.verdict;
    EXPECT_EQ(check.tolerance, 1e-10);
    EXPECT_EQ(check.contacts.rattlerFraction, 0.0);
    EXPECT_EQ(check.untrappedFraction, 0.0); // six contacts along the axes trap every particle
    EXPECT_FALSE(check.chain.has_value());   // looked for only when not jammed
    EXPECT_EQ(check.verdict.rfind("jammed: rattler fraction 0.000", 0), 0u) << check.verdict;
}

TEST(JamCheck, TheToleranceFollowsThePressure) {
    const Packing lattice = readTextPacking(kData + "/fcc-spheres.txt");
    EXPECT_DOUBLE_EQ(checkJam(lattice, 1e6).tolerance, 1e-4);
    EXPECT_EQ(checkJam(lattice, 1e14).tolerance, 1e-10);
    EXPECT_TRUE(checkJam(lattice, 1e6).jammed);
    EXPECT_THROW(checkJam(lattice, 0.0), std::invalid_argument);
}

// At low pressure 100 / P would reach past half the box (sbgen --pressure-final 10 failed in its
// final check: the cell list refused the range); the tolerance stops at 1e-2 D.
TEST(JamCheck, AtLowPressureTheToleranceStopsAtOnePercentOfD) {
    const Packing lattice = readTextPacking(kData + "/fcc-spheres.txt");
    for (const double pressure : {10.0, 1.0, 1e-3}) {
        const JamCheck check = checkJam(lattice, pressure);
        EXPECT_EQ(check.tolerance, 1e-2);
        EXPECT_TRUE(check.jammed) << check.verdict; // fcc touches: every sphere has 12 contacts
    }
    EXPECT_DOUBLE_EQ(checkJam(lattice, 1e5).tolerance, 1e-3);
}

// Far below a jam (P = 10: gaps of about 10 D), a refusal names the pressure, not a chain of the
// near contacts that the largest contact gap, 1e-2 D, still catches.
TEST(JamCheck, FarBelowAJamARefusalSaysTheRunIsStillCompressing) {
    const JamCheck check = checkJam(column(4), 10.0);
    EXPECT_FALSE(check.jammed);
    EXPECT_FALSE(check.chain.has_value());
    EXPECT_NE(check.verdict.find("not jammed: still compressing (at reduced pressure 10 "),
              std::string::npos)
        << check.verdict;
    EXPECT_TRUE(checkJam(column(4), 1e4).chain.has_value()); // from 1e4 on, the chain is named
}

TEST(JamCheck, AColumnWrappingAroundTheBoxIsNoJam) {
    const Packing packing = column(4);
    const JamCheck check = checkJam(packing, 1e12);
    EXPECT_FALSE(check.jammed);
    EXPECT_EQ(check.contacts.contacts.size(), 6u); // the column's six faces, nothing else
    EXPECT_EQ(check.contacts.rattlerFraction, 1.0);
    ASSERT_TRUE(check.chain.has_value()) << check.verdict;
    EXPECT_EQ(check.chain->wrap.x(), 0.0);
    EXPECT_EQ(std::abs(check.chain->wrap.y()), 6.0);
    EXPECT_EQ(check.chain->wrap.z(), 0.0);
    // The cycle is the column, and its displacements add up to the wrap.
    const std::vector<int>& cycle = check.chain->cycle;
    EXPECT_EQ(std::set<int>(cycle.begin(), cycle.end()), (std::set<int>{0, 1, 2, 3, 4, 5}));
    Vector3d sum = Vector3d::Zero();
    for (std::size_t k = 0; k < cycle.size(); ++k) {
        const int a = cycle[k], b = cycle[(k + 1) % cycle.size()];
        sum += minimumImage(packing.positions[b] - packing.positions[a], packing.boxLength);
    }
    EXPECT_NEAR(std::abs(sum.y()), 6.0, 1e-12);
    EXPECT_NE(check.verdict.find("a chain of 6 particles in contact wraps around the periodic "
                                 "box along y (box 6.00 D)"),
              std::string::npos)
        << check.verdict;
}

TEST(JamCheck, AClusterThatDoesNotWrapIsNoChain) {
    Packing packing = column(0);
    packing.positions.pop_back(); // five in a row: an open chain in the box of 6 D
    packing.orientations.pop_back();
    const ContactResult contacts = ContactNetwork({}).compute(packing);
    EXPECT_EQ(contacts.contacts.size(), 4u);
    EXPECT_FALSE(findSpanningChain(packing, contacts.contacts).has_value());
    const JamCheck check = checkJam(packing, 1e12);
    EXPECT_FALSE(check.jammed);
    EXPECT_FALSE(check.chain.has_value());
    EXPECT_NE(check.verdict.find("not jammed: rattler fraction 1.000"), std::string::npos)
        << check.verdict;
}

} // namespace
} // namespace sbpack
