#pragma once
// Event queues that know nothing of physics (docs/design.md §7): each of n items (particles) holds
// one pending event time; the queue returns the item with the earliest one. Ties go to the lower
// index, so runs are deterministic.

#include <cstdint>
#include <limits>
#include <vector>

namespace sbpack {

/// Indexed binary min-heap: set() and top() in O(log n) and O(1).
class EventQueue {
  public:
    explicit EventQueue(int items = 0);

    int size() const { return static_cast<int>(time_.size()); }
    /// Sets item's event time (+inf: nothing pending).
    void set(int item, double time);
    double time(int item) const { return time_[item]; }
    int top() const { return heap_[0]; }
    double topTime() const { return time_[heap_[0]]; }

  private:
    bool earlier(int a, int b) const {
        return time_[a] < time_[b] || (time_[a] == time_[b] && a < b);
    }
    void place(int slot, int item) {
        heap_[slot] = item;
        slot_[item] = slot;
    }
    void siftUp(int slot);
    void siftDown(int slot);

    std::vector<double> time_;
    std::vector<int> heap_; ///< heap order of items
    std::vector<int> slot_; ///< position of each item in heap_
};

/// Reference queue: a plain vector scanned for the minimum, to test faster queues against.
class ReferenceEventQueue {
  public:
    explicit ReferenceEventQueue(int items = 0)
        : time_(items, std::numeric_limits<double>::infinity()) {}

    int size() const { return static_cast<int>(time_.size()); }
    void set(int item, double time) { time_[item] = time; }
    double time(int item) const { return time_[item]; }
    int top() const {
        int best = 0;
        for (int i = 1; i < size(); ++i)
            if (time_[i] < time_[best]) best = i;
        return best;
    }
    double topTime() const { return time_[top()]; }

  private:
    std::vector<double> time_;
};

} // namespace sbpack
