#pragma once
// The engine's per-pair records, keyed by the pair's index min(i, j) N + max(i, j): an
// open-addressing hash table (linear probing, Fibonacci hashing, at most half full) with the keys
// apart from the values, so that a lookup reads one short run of keys and then its value.
// std::unordered_map takes a node chase and a modulo by a prime per lookup (bench/RESULTS.md,
// "Roots instead of exp2/log2 at p = 1.5, and a flat pair table"; "Measurement history moved
// out of code comments").

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <vector>

namespace sbpack {

/// The key of the unordered pair {i, j} of N particles: min(i, j) N + max(i, j).
inline std::uint64_t pairKey(int i, int j, std::uint64_t particles) {
    return static_cast<std::uint64_t>(std::min(i, j)) * particles +
           static_cast<std::uint64_t>(std::max(i, j));
}

template <class Value> class PairTable {
  public:
    /// The value of `key` (any but kEmpty), inserted as Value{} when absent. The reference
    /// holds until the next call (an insertion may move every value), unlike std::unordered_map's.
    Value& operator[](std::uint64_t key) {
        assert(key != kEmpty);
        if (2 * (size_ + 1) > keys_.size()) grow();
        std::size_t slot = home(key);
        while (keys_[slot] != key) {
            if (keys_[slot] == kEmpty) {
                keys_[slot] = key;
                values_[slot] = Value{};
                ++size_;
                break;
            }
            slot = (slot + 1) & (keys_.size() - 1);
        }
        return values_[slot];
    }

    /// The value of `key`, or nullptr when absent (nothing inserted). Valid until the next
    /// insertion.
    Value* find(std::uint64_t key) {
        if (keys_.empty()) return nullptr;
        for (std::size_t slot = home(key);; slot = (slot + 1) & (keys_.size() - 1)) {
            if (keys_[slot] == key) return &values_[slot];
            if (keys_[slot] == kEmpty) return nullptr;
        }
    }

    /// f(key, value) for every record, in slot order.
    template <class F> void forEach(F&& f) {
        for (std::size_t slot = 0; slot < keys_.size(); ++slot)
            if (keys_[slot] != kEmpty) f(keys_[slot], values_[slot]);
    }
    template <class F> void forEach(F&& f) const {
        for (std::size_t slot = 0; slot < keys_.size(); ++slot)
            if (keys_[slot] != kEmpty) f(keys_[slot], values_[slot]);
    }

    /// Forgets every record, keeping the capacity.
    void clear() {
        std::fill(keys_.begin(), keys_.end(), kEmpty);
        size_ = 0;
    }

    std::size_t size() const { return size_; }

    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

  private:
    std::size_t home(std::uint64_t key) const {
        return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
    }

    void grow() {
        std::vector<std::uint64_t> keys(std::max<std::size_t>(64, 2 * keys_.size()), kEmpty);
        std::vector<Value> values(keys.size());
        shift_ = 64;
        for (std::size_t n = keys.size(); n > 1; n >>= 1)
            --shift_;
        keys.swap(keys_);
        values.swap(values_);
        size_ = 0;
        for (std::size_t slot = 0; slot < keys.size(); ++slot)
            if (keys[slot] != kEmpty) (*this)[keys[slot]] = values[slot];
    }

    std::vector<std::uint64_t> keys_;
    std::vector<Value> values_;
    std::size_t size_ = 0;
    int shift_ = 64;
};

} // namespace sbpack
