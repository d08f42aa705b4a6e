#include "events/event_queue.hpp"
#include "random/random.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace sbpack {
namespace {

TEST(EventQueue, AgreesWithReferenceQueueUnderRandomUpdates) {
    for (const int n : {1, 2, 3, 17, 1000}) {
        EventQueue heap(n);
        ReferenceEventQueue reference(n);
        Random random(7 + n);
        for (int step = 0; step < 20000; ++step) {
            const int item = static_cast<int>(random.uniform() * n);
            const double u = random.uniform();
            // Ties (coarse times), infinities and decreases as well as increases.
            const double time = u < 0.1   ? std::numeric_limits<double>::infinity()
                                : u < 0.5 ? std::floor(random.uniform() * 8.0)
                                          : random.uniform() * 100.0;
            heap.set(item, time);
            reference.set(item, time);
            ASSERT_EQ(heap.top(), reference.top()) << "n " << n << " step " << step;
            ASSERT_EQ(heap.topTime(), reference.topTime());
        }
    }
}

TEST(EventQueue, TiesGoToTheLowerIndex) {
    EventQueue heap(4);
    for (int i = 3; i >= 0; --i)
        heap.set(i, 1.0);
    EXPECT_EQ(heap.top(), 0);
    heap.set(0, 2.0);
    EXPECT_EQ(heap.top(), 1);
}

} // namespace
} // namespace sbpack
