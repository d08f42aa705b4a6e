// The residuals and the virial of contact forces (common/packing/contact_forces; issue 62), on
// contacts whose answers are worked by hand.
#include "packing/contact_forces.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace sbpack {
namespace {

/// Two spheres of diameter 1 in a box of 4, touching across its x faces: r_1 - r_0 is
/// (-1, 0, 0) by the minimum image.
Packing twoAcrossTheBox() {
    Packing packing;
    packing.semiAxis = 0.5;
    packing.boxLength = 4.0;
    packing.positions = {Vector3d(0.25, 2, 2), Vector3d(3.25, 2, 2)};
    packing.orientations.assign(2, Quaterniond::Identity());
    return packing;
}

TEST(ContactForces, ABalancedPairHasOppositeNetForcesAndTheVirialOfItsSeparation) {
    const Packing packing = twoAcrossTheBox();
    // 0 pushes 1 along n = -x with f = 6 (kT / D), at the midpoint across the face.
    const ContactForces forces{
        {{0, 1, Vector3d(3.75, 2, 2), Vector3d(-1, 0, 0), 6.0}}, 1, 1.0, 0.0};
    const ForceBalance balance = forceBalance(packing, forces);
    EXPECT_EQ(balance.netForces[0], Vector3d(6, 0, 0)); // 1 pushes back on 0 along +x
    EXPECT_EQ(balance.netForces[1], Vector3d(-6, 0, 0));
    EXPECT_EQ(balance.netTorques[0], Vector3d::Zero()); // lever along the force: no torque
    EXPECT_EQ(balance.netTorques[1], Vector3d::Zero());
    // P = 1 + f (r_01 . n) / (3 N D) = 1 + 6 * 1 / 6.
    EXPECT_DOUBLE_EQ(virialPressure(packing, forces), 2.0);
}

TEST(ContactForces, AnOffCentreContactTurnsBothParticles) {
    const Packing packing = twoAcrossTheBox();
    // The same force at a point 0.25 above the centre line: lever of 0 (-0.5, 0.25, 0) by the
    // minimum image, of 1 (+0.5, 0.25, 0); torques (lever / D) x force.
    const ContactForces forces{
        {{0, 1, Vector3d(3.75, 2.25, 2), Vector3d(-1, 0, 0), 6.0}}, 1, 1.0, 0.0};
    const ForceBalance balance = forceBalance(packing, forces);
    EXPECT_TRUE(balance.netTorques[0].isApprox(Vector3d(-0.5, 0.25, 0).cross(Vector3d(6, 0, 0))));
    EXPECT_TRUE(balance.netTorques[1].isApprox(Vector3d(0.5, 0.25, 0).cross(Vector3d(-6, 0, 0))));
    EXPECT_DOUBLE_EQ(balance.netTorques[0].z(), -1.5);
}

TEST(ContactForces, AContactOutsideThePackingIsRefused) {
    const ContactForces forces{{{0, 2, Vector3d::Zero(), Vector3d(1, 0, 0), 1.0}}, 1, 1.0, 0.0};
    EXPECT_THROW(forceBalance(twoAcrossTheBox(), forces), std::invalid_argument);
    EXPECT_THROW(virialPressure(twoAcrossTheBox(), forces), std::invalid_argument);
}

} // namespace
} // namespace sbpack
