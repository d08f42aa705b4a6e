#include "geometry/particle_shape.hpp"
#include "transport/transport.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace sbpack {
namespace {

TEST(Transport, FormationFactorLimits) {
    for (const double phi : {0.0, 0.3, 0.64}) {
        // zeta_2 = 0: the Hashin-Shtrikman bound (2 + phi) / (2 (1 - phi)).
        EXPECT_DOUBLE_EQ(formationFactor(phi, 0.0), (2.0 + phi) / (2.0 * (1.0 - phi)));
        // zeta_2 = 1: (1 + 2 phi) / (1 - phi).
        EXPECT_DOUBLE_EQ(formationFactor(phi, 1.0), (1.0 + 2.0 * phi) / (1.0 - phi));
        if (phi > 0.0) {
            EXPECT_LT(formationFactor(phi, 0.2), formationFactor(phi, 0.6));
        }
    }
    EXPECT_DOUBLE_EQ(formationFactor(0.0, 0.5), 1.0); // no solid: F = 1
    EXPECT_THROW(formationFactor(1.0, 0.5), std::invalid_argument);
    EXPECT_THROW(formationFactor(0.5, 1.5), std::invalid_argument);
}

TEST(Transport, Zeta2InterpolationOfSectionVA) {
    EXPECT_DOUBLE_EQ(zeta2Interpolation(1.0, 0.64), 0.21068 * 0.64);
    EXPECT_DOUBLE_EQ(zeta2Interpolation(1.5, 0.7),
                     0.21068 * 0.7 + 0.5 * (0.11882 + 0.772236 * 0.7));
    EXPECT_DOUBLE_EQ(zeta2Interpolation(0.85, 0.66), zeta2Interpolation(1.15, 0.66));
}

TEST(Transport, PermeabilityAndBoundsFromTheMoments) {
    // Pore sizes 0.1 (x3) and 0.3 (x1): <delta> = 0.15, <delta^2> = 0.03.
    const std::vector<double> sizes = {0.1, 0.3};
    const std::vector<std::int64_t> counts = {3, 1};
    const double w = 1.2;
    const PoreSizeDistributionResult pores = poreSizeStatistics(sizes, counts, w, 8);
    TransportParameters parameters;
    parameters.diffusionCoefficient = 2.0;
    const double p = 1.25, phi = 0.65;
    const TransportResult t = Transport(parameters).compute(pores, p, phi);
    const double zeta2 = 0.21068 * phi + 0.25 * (0.11882 + 0.772236 * phi);
    const double f = (2.0 + phi - (1.0 - phi) * zeta2) / ((1.0 - phi) * (2.0 - zeta2));
    EXPECT_DOUBLE_EQ(t.zeta2.value(), zeta2);
    EXPECT_DOUBLE_EQ(t.formationFactor.value(), f);
    EXPECT_NEAR(t.permeability.value(), 0.03 / f, 1e-15);      // Eq. 17
    EXPECT_NEAR(t.meanSurvivalTime, 0.15 * 0.15 / 2.0, 1e-15); // Eq. 19
    EXPECT_NEAR(t.principalRelaxationTime, 0.03 / 2.0, 1e-15); // Eq. 20
    EXPECT_NEAR(t.permeabilityOverWidth2().value(), 0.03 / f / (w * w), 1e-15);
    EXPECT_NEAR(t.meanSurvivalTimeOverWidth2(), 0.15 * 0.15 / (w * w), 1e-15);
    EXPECT_NEAR(t.principalRelaxationTimeOverWidth2(), 0.03 / (w * w), 1e-15);
    EXPECT_EQ(t.p, p);
    EXPECT_EQ(t.phi, phi);
    EXPECT_EQ(t.parameters.diffusionCoefficient, 2.0);
}

TEST(Transport, RejectsBadInputAndLeavesOutKWhereTheInterpolationEnds) {
    const std::vector<double> sizes = {0.1};
    const std::vector<std::int64_t> counts = {1};
    const PoreSizeDistributionResult pores = poreSizeStatistics(sizes, counts, 1.0, 8);
    EXPECT_THROW(Transport({0.0}), std::invalid_argument);
    const Transport transport({});
    EXPECT_THROW(transport.compute(pores, 1.0, 0.0), std::invalid_argument);
    EXPECT_THROW(transport.compute(pores, 1.0, 1.0), std::invalid_argument);
    EXPECT_THROW(transport.compute(pores, 0.4, 0.6), std::invalid_argument);
    // zeta_2 = 1.38 at p = 3: no F, no k; the pore-size bounds tau and T1 as at any p.
    const TransportResult cubes = transport.compute(pores, 3.0, 0.7);
    EXPECT_FALSE(cubes.zeta2 || cubes.formationFactor || cubes.permeability ||
                 cubes.permeabilityOverWidth2());
    EXPECT_NE(cubes.permeabilityOmitted.find("outside (0, 1]"), std::string::npos);
    EXPECT_NEAR(cubes.meanSurvivalTime, 0.01, 1e-15);
    EXPECT_NEAR(cubes.principalRelaxationTime, 0.01, 1e-15);
    const TransportResult fitted = transport.compute(pores, 1.5, 0.7);
    EXPECT_TRUE(fitted.permeability.has_value());
    EXPECT_TRUE(fitted.permeabilityOmitted.empty());
    // Another shape (ShapeSpec::superballExponent nothing): the fit in p does not apply.
    const TransportResult other = transport.compute(pores, std::nullopt, 0.7);
    EXPECT_FALSE(other.zeta2 || other.formationFactor || other.permeability);
    EXPECT_NE(other.permeabilityOmitted.find("not superballs"), std::string::npos);
    EXPECT_NEAR(other.principalRelaxationTime, 0.01, 1e-15);
    EXPECT_EQ(ShapeSpec::superball(1.5).superballExponent(), 1.5);
}

} // namespace
} // namespace sbpack
