#include "events/event_queue.hpp"

namespace sbpack {

EventQueue::EventQueue(int items)
    : time_(items, std::numeric_limits<double>::infinity()), heap_(items), slot_(items) {
    for (int i = 0; i < items; ++i)
        place(i, i);
}

void EventQueue::set(int item, double time) {
    const double old = time_[item];
    time_[item] = time;
    if (time < old)
        siftUp(slot_[item]);
    else
        siftDown(slot_[item]);
}

void EventQueue::siftUp(int slot) {
    const int item = heap_[slot];
    while (slot > 0) {
        const int parent = (slot - 1) / 2;
        if (!earlier(item, heap_[parent])) break;
        place(slot, heap_[parent]);
        slot = parent;
    }
    place(slot, item);
}

void EventQueue::siftDown(int slot) {
    const int item = heap_[slot];
    const int n = size();
    while (true) {
        int child = 2 * slot + 1;
        if (child >= n) break;
        if (child + 1 < n && earlier(heap_[child + 1], heap_[child])) ++child;
        if (!earlier(heap_[child], item)) break;
        place(slot, heap_[child]);
        slot = child;
    }
    place(slot, item);
}

} // namespace sbpack
