#pragma once
// Mean and sample standard deviation of a set of values: the ensembles' statistics
// (pipeline/ensemble.hpp) and the bootstrap errors (hyperuniformity/spreadability_exponent.hpp).

#include <cmath>
#include <span>

namespace sbpack {

struct SampleStatistics {
    double mean = 0.0;
    double std = 0.0; ///< sample standard deviation (n - 1); 0 for fewer than two values
};

/// Two passes: the mean, then the squares about it.
inline SampleStatistics sampleStatistics(std::span<const double> values) {
    SampleStatistics s;
    if (values.empty()) return s;
    for (double v : values)
        s.mean += v;
    s.mean /= static_cast<double>(values.size());
    if (values.size() < 2) return s;
    double squares = 0.0;
    for (double v : values)
        squares += (v - s.mean) * (v - s.mean);
    s.std = std::sqrt(squares / static_cast<double>(values.size() - 1));
    return s;
}

} // namespace sbpack
