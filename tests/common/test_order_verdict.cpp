// The order verdict of common/order/order_metrics.hpp (docs/order-metrics.md §5) on stored
// packings: the N = 40 box of issue 44 that jammed ordered, the aligned near-cubes and the
// lattices are called ordered, for the reason each shows; the MRJ packings are not.
#include "io/text_io.hpp"
#include "order/order_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace sbpack {
namespace {

const std::string kData = SBPACK_DATA_DIR;

OrderMetrics metricsOf(const std::string& file) {
    return measureOrder(readPackingFile(kData + "/" + file));
}

TEST(OrderVerdict, TheOrderedSmallBoxIsCalledOrderedByItsLocalQ6) {
    const OrderMetrics m = metricsOf("ordered-p1.2-40.h5"); // sbgen --p 1.2 --n 40 --seed 1
    const OrderVerdict v = orderVerdict(m);
    EXPECT_TRUE(v.ordered);
    EXPECT_NE(v.reason.find("mean local q6"), std::string::npos) << v.reason;
    // T over the 2 fcc shells this box holds is high (0.67) but does not count: over fewer than
    // its 12 shells the contact shell dominates it, in disordered boxes as well.
    ASSERT_TRUE(m.translational);
    EXPECT_EQ(m.translational->parameters.shellCount, 2);
    EXPECT_GT(m.translational->order, 0.6);
    EXPECT_EQ(v.reason.find("T = "), std::string::npos) << v.reason;
}

TEST(OrderVerdict, AlignedNearCubesAreCalledOrderedByTheirAxes) {
    const OrderMetrics m = metricsOf("dense-p10-200.h5");
    ASSERT_TRUE(m.cubatic);
    EXPECT_GT(m.cubatic->order, 0.99);
    const OrderVerdict v = orderVerdict(m);
    EXPECT_TRUE(v.ordered);
    EXPECT_NE(v.reason.find("P4 = "), std::string::npos) << v.reason;
}

TEST(OrderVerdict, LatticesAreCalledOrdered) {
    // fcc: q6 = 0.575 (its closed form) and T = 1; the aligned simple-cubic superballs: P4 = 1.
    const OrderMetrics fcc = metricsOf("fcc-spheres.txt");
    ASSERT_TRUE(fcc.cutoffBonds);
    EXPECT_NEAR(fcc.cutoffBonds->q6.meanLocalOrder, 13.0 / std::sqrt(512.0), 1e-9);
    EXPECT_FALSE(fcc.cubatic); // spheres: no axes
    EXPECT_TRUE(orderVerdict(fcc).ordered);
    const OrderMetrics sc = metricsOf("sc-lattice-p1.5.txt");
    ASSERT_TRUE(sc.cubatic);
    EXPECT_NEAR(sc.cubatic->order, 1.0, 1e-12);
    EXPECT_TRUE(orderVerdict(sc).ordered);
}

TEST(OrderVerdict, MrjPackingsAreNotCalledOrdered) {
    for (const char* file : {"mrj-spheres-5000.h5", "mrj-p1.5-1000.h5"}) {
        const OrderMetrics m = metricsOf(file);
        const OrderVerdict v = orderVerdict(m);
        EXPECT_FALSE(v.ordered) << file << ": " << v.reason;
        EXPECT_EQ(v.reason, "");
        ASSERT_TRUE(m.cutoffBonds && m.translational) << file;
        EXPECT_EQ(m.translational->parameters.shellCount, 12) << file;
        EXPECT_LT(m.cutoffBonds->q6.meanLocalOrder, 0.45) << file;
    }
}

} // namespace
} // namespace sbpack
