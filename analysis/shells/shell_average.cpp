#include "shells/shell_average.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sbpack {

ShellAccumulator::ShellAccumulator(double boxLength, int maxShell) : boxLength_(boxLength) {
    if (!(boxLength > 0.0) || !std::isfinite(boxLength))
        throw std::invalid_argument("shell average: box length must be positive and finite");
    if (maxShell < 1) throw std::invalid_argument("shell average: no shell (maxShell < 1)");
    sumQ_.assign(maxShell, 0.0);
    sumValue_.assign(maxShell, 0.0);
    count_.assign(maxShell, 0);
}

void ShellAccumulator::add(std::int64_t n2, double value, std::int64_t weight) {
    const double n = std::sqrt(static_cast<double>(n2));
    // |n| = s + 1/2 never happens for integer n2, so rounding has no ties.
    const auto shell = static_cast<std::size_t>(std::llround(n));
    if (n2 < 1 || shell > count_.size())
        throw std::out_of_range("shell average: |n|^2 = " + std::to_string(n2) +
                                " is outside shells 1.." + std::to_string(count_.size()));
    const double q = 2.0 * std::numbers::pi * n / boxLength_;
    const auto w = static_cast<double>(weight);
    sumQ_[shell - 1] += w * q;
    sumValue_[shell - 1] += w * value;
    count_[shell - 1] += weight;
}

void ShellAccumulator::merge(const ShellAccumulator& other) {
    if (other.count_.size() != count_.size() || other.boxLength_ != boxLength_)
        throw std::invalid_argument("shell average: merging accumulators of different shells");
    for (std::size_t s = 0; s < count_.size(); ++s) {
        sumQ_[s] += other.sumQ_[s];
        sumValue_[s] += other.sumValue_[s];
        count_[s] += other.count_[s];
    }
}

std::vector<double> ShellAccumulator::sums() const {
    std::vector<double> out(sumQ_);
    out.insert(out.end(), sumValue_.begin(), sumValue_.end());
    for (std::int64_t c : count_)
        out.push_back(static_cast<double>(c));
    return out;
}

void ShellAccumulator::mergeSums(const std::vector<double>& sums) {
    const std::size_t n = count_.size();
    if (sums.size() != 3 * n)
        throw std::invalid_argument("shell average: merging sums of different shells");
    for (std::size_t s = 0; s < n; ++s) {
        sumQ_[s] += sums[s];
        sumValue_[s] += sums[n + s];
        count_[s] += static_cast<std::int64_t>(sums[2 * n + s]);
    }
}

ShellAverage ShellAccumulator::average() const {
    ShellAverage out;
    for (std::size_t s = 0; s < count_.size(); ++s) {
        if (count_[s] == 0)
            throw std::logic_error("shell average: shell " + std::to_string(s + 1) + " is empty");
        const auto c = static_cast<double>(count_[s]);
        out.q.push_back(sumQ_[s] / c);
        out.value.push_back(sumValue_[s] / c);
        out.count.push_back(count_[s]);
    }
    return out;
}

} // namespace sbpack
