#pragma once
// Angular averages over spherical shells of wave vectors, shared by S(Q) and chi(Q)
// (paper Sec. II A: "angular-averaged"). The wave vectors of a cubic periodic box of edge L are
// Q = 2 pi n / L with integer n; shell s >= 1 holds those with round(|n|) = s, so every shell is
// 2 pi / L wide and the shells up to s_max hold exactly the n with |n| < s_max + 1/2.

#include <array>
#include <cstdint>
#include <vector>

namespace sbpack {

/// One angular-averaged curve: for each shell, the mean |Q| of its wave vectors, the mean value
/// over them and their number (Q and -Q counted separately). Shells 1..maxShell, in order.
struct ShellAverage {
    std::vector<double> q;
    std::vector<double> value;
    std::vector<std::int64_t> count;

    std::size_t size() const { return q.size(); }
};

/// |n|^2 of the wave vector Q = 2 pi n / L, exact in 64 bits.
inline std::int64_t squaredIndex(const std::array<int, 3>& n) {
    return std::int64_t{n[0]} * n[0] + std::int64_t{n[1]} * n[1] + std::int64_t{n[2]} * n[2];
}

/// Largest |n|^2 of the wave vectors of shells 1..maxShell: round(|n|) <= s iff |n|^2 <= s(s+1).
inline std::int64_t maxSquaredIndex(int maxShell) {
    return static_cast<std::int64_t>(maxShell) * (maxShell + 1);
}

/// Sums values into shells. Accumulators of disjoint parts of wave-vector space are merged in
/// a fixed order, so that the result does not depend on the number of threads.
class ShellAccumulator {
  public:
    /// Throws std::invalid_argument unless boxLength > 0 and maxShell >= 1.
    ShellAccumulator(double boxLength, int maxShell);

    int maxShell() const { return static_cast<int>(count_.size()); }
    /// Adds `value` at wave vector n with |n|^2 = n2 (1 <= n2 <= maxSquaredIndex(maxShell()))
    /// standing for `weight` wave vectors (2 for n when -n is left out by symmetry).
    void add(std::int64_t n2, double value, std::int64_t weight);
    void merge(const ShellAccumulator& other);
    /// The sums as numbers (sum Q, sum value, count per shell; counts exact below 2^53), and
    /// merging such numbers in: how ranks of a distributed grid combine their shells in rank
    /// order (docs/scale-out.md).
    std::vector<double> sums() const;
    void mergeSums(const std::vector<double>& sums);
    /// Throws std::logic_error if a shell is empty (it never is when every n was added).
    ShellAverage average() const;

  private:
    double boxLength_;
    std::vector<double> sumQ_;
    std::vector<double> sumValue_;
    std::vector<std::int64_t> count_;
};

} // namespace sbpack
