#include "hyperuniformity/spreadability_exponent.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbpack {

namespace {

/// One replica of `s` (its sums only): each individually listed wave vector counted a
/// Poisson(1) number of times.
DiscreteSpectrum resampled(const DiscreteSpectrum& s, std::mt19937_64& random) {
    std::poisson_distribution<int> poisson(1.0);
    DiscreteSpectrum r;
    r.boxLength = s.boxLength;
    r.meanWidth = s.meanWidth;
    r.phi = s.phi;
    r.cutoffQ = s.cutoffQ;
    r.missingWeight = s.missingWeight;
    r.sumByN2 = s.sumByN2;
    for (std::size_t i = 0; i < s.modes.size(); ++i) {
        const int count = poisson(random);
        r.sumByN2[s.modes.n2(i)] += 2.0 * s.modes.chi[i] * (count - 1); // +-n
    }
    for (double& v : r.sumByN2)
        v = std::max(v, 0.0); // rounding of the subtraction
    return r;
}

} // namespace

ExponentWindow findExponentWindow(const SpreadabilityCurve& curve, double peakQw) {
    if (!(peakQw > 0.0)) throw std::invalid_argument("alpha window: no peak of chi_V");
    const ExponentWindow w{kPeakDecay / (peakQw * peakQw), curve.cutoffTime() / kCutoffFraction};
    if (!(std::log10(w.tMax / w.tMin) >= kMinWindowDecades))
        throw std::domain_error(
            "alpha window: the long-time regime from t D / w^2 = " + std::to_string(w.tMin) +
            " (the chi_V peak has decayed) to " + std::to_string(w.tMax) +
            " (a quarter of the box's cutoff time) is shorter than " +
            std::to_string(kMinWindowDecades) +
            " decades: the box is too small for alpha (--alpha-window T1,T2 forces a window)");
    return w;
}

double windowExponent(const std::function<double(double)>& logExcess,
                      const ExponentWindow& window) {
    const double rise = logExcess(window.tMax) - logExcess(window.tMin);
    return -3.0 - 2.0 * rise / std::log(window.tMax / window.tMin);
}

double windowExponent(const SpreadabilityCurve& curve, const ExponentWindow& window) {
    return windowExponent([&](double t) { return curve.at(t).logExcess; }, window);
}

double sampledExponent(const std::vector<double>& t, const std::vector<double>& excess,
                       const ExponentWindow& window) {
    const auto logAt = [&](double time) {
        const auto upper = std::lower_bound(t.begin(), t.end(), time);
        if (upper == t.end() || (upper == t.begin() && *upper != time) || t.size() != excess.size())
            throw std::domain_error("alpha: the sampled times do not cover the window");
        const std::size_t j = static_cast<std::size_t>(upper - t.begin());
        if (*upper == time) return std::log(excess[j]);
        const double f = std::log(time / t[j - 1]) / std::log(t[j] / t[j - 1]);
        return (1.0 - f) * std::log(excess[j - 1]) + f * std::log(excess[j]);
    };
    return windowExponent(logAt, window);
}

ExponentEstimate estimateExponent(std::span<const DiscreteSpectrum> members,
                                  const ExponentWindow& window, int replicas,
                                  std::uint64_t seed) {
    ExponentEstimate e;
    const SpreadabilityCurve curve(members);
    e.alpha = windowExponent(curve, window);
    e.windowLow = e.windowHigh = e.alpha;
    for (const double f : {0.5, 2.0}) {
        const double alpha = windowExponent(curve, {window.tMin, std::max(f * window.tMax,
                                                                         1.5 * window.tMin)});
        e.windowLow = std::min(e.windowLow, alpha);
        e.windowHigh = std::max(e.windowHigh, alpha);
    }
    e.replicas = replicas;
    if (replicas < 2) return e;
    std::mt19937_64 random(seed);
    double mean = 0.0, m2 = 0.0;
    for (int r = 0; r < replicas; ++r) {
        std::vector<DiscreteSpectrum> replica;
        replica.reserve(members.size());
        for (const DiscreteSpectrum& s : members)
            replica.push_back(resampled(s, random));
        const double alpha = windowExponent(SpreadabilityCurve(replica), window);
        const double delta = alpha - mean;
        mean += delta / (r + 1);
        m2 += delta * (alpha - mean);
    }
    e.standardError = std::sqrt(m2 / (replicas - 1));
    return e;
}

} // namespace sbpack
