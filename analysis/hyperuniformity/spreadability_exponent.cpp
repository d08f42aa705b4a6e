#include "hyperuniformity/spreadability_exponent.hpp"

#include "numerics/sample_statistics.hpp"
#include "parallel/parallel.hpp"
#include "random/random.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace sbpack {

namespace {

/// Poisson(1) by inversion of one uniform draw: the cumulative probabilities of 0 ... 17
/// (the rest, below 1e-16, is folded into 17).
class PoissonOne {
  public:
    PoissonOne() {
        double p = std::exp(-1.0), sum = 0.0;
        for (int k = 0; k < kSize; ++k) {
            sum += p;
            cumulative_[k] = sum;
            p /= k + 1;
        }
    }
    int operator()(Random& random) const {
        const double u = random.uniform();
        int k = 0;
        while (k + 1 < kSize && u >= cumulative_[k])
            ++k;
        return k;
    }

  private:
    static constexpr int kSize = 18;
    double cumulative_[kSize];
};

/// One replica of `s` (its sums only): each individually listed wave vector counted a
/// Poisson(1) number of times.
DiscreteSpectrum resampled(const DiscreteSpectrum& s, Random& random) {
    static const PoissonOne poisson;
    DiscreteSpectrum r;
    r.boxLength = s.boxLength;
    r.meanWidth = s.meanWidth;
    r.phi = s.phi;
    r.cutoffQ = s.cutoffQ;
    r.missingWeight = s.missingWeight;
    r.sumByN2 = s.sumByN2;
    for (std::size_t i = 0; i < s.modes.size(); ++i) {
        const int count = poisson(random);
        if (count != 1) r.sumByN2[s.modes.n2(i)] += 2.0 * s.modes.chi[i] * (count - 1); // +-n
    }
    for (double& v : r.sumByN2)
        v = std::max(v, 0.0); // rounding of the subtraction
    return r;
}

/// The extrapolated alpha and the window's mean of replica r (its own stream: the same for any
/// number of threads).
std::pair<double, double> replicaExponents(std::span<const DiscreteSpectrum> members,
                                           const ExponentWindow& window, std::uint64_t seed,
                                           int r) {
    Random random = Random::stream(seed, r);
    std::vector<DiscreteSpectrum> replica;
    replica.reserve(members.size());
    for (const DiscreteSpectrum& s : members)
        replica.push_back(resampled(s, random));
    const SpreadabilityCurve curve(replica);
    return {extrapolatedExponent(curve, window).alpha, windowExponent(curve, window)};
}

/// The least-squares line y = alpha + slope x through (x_k, y_k).
ExponentLine lineThrough(const std::vector<double>& x, const std::vector<double>& y) {
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k)
        sx += x[k], sy += y[k], sxx += x[k] * x[k], sxy += x[k] * y[k];
    const auto n = static_cast<double>(x.size());
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    return {(sy - slope * sx) / n, slope};
}

} // namespace

ExponentWindow findExponentWindow(const SpreadabilityCurve& curve, double peakQw) {
    if (!(peakQw > 0.0)) throw std::invalid_argument("alpha window: no peak of chi_V");
    const ExponentWindow w{kPeakDecay / (peakQw * peakQw), curve.cutoffTime() / kCutoffFraction};
    if (!(std::log10(w.tMax / w.tMin) >= kMinWindowDecades))
        throw std::domain_error(
            "alpha window: the long-time regime from t D_diff / w^2 = " + std::to_string(w.tMin) +
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

ExponentLine extrapolatedExponent(const SpreadabilityCurve& curve, const ExponentWindow& window) {
    std::vector<double> inverseTime, local;
    const double step = std::log(window.tMax / window.tMin) / (kExtrapolationPoints - 1);
    for (int k = 0; k < kExtrapolationPoints; ++k) {
        const double t = window.tMin * std::exp(k * step);
        inverseTime.push_back(1.0 / t);
        local.push_back(-3.0 - 2.0 * curve.at(t).exponent);
    }
    return lineThrough(inverseTime, local);
}

ExponentLine sampledExponent(const std::vector<double>& t, const std::vector<double>& excess,
                             const ExponentWindow& window) {
    if (t.size() != excess.size()) throw std::invalid_argument("alpha: times and E differ in size");
    std::vector<double> inverseTime, local;
    for (std::size_t j = 0; j + 1 < t.size(); ++j) {
        if (t[j] < window.tMin || t[j + 1] > window.tMax) continue;
        inverseTime.push_back(1.0 / std::sqrt(t[j] * t[j + 1]));
        local.push_back(-3.0 -
                        2.0 * std::log(excess[j + 1] / excess[j]) / std::log(t[j + 1] / t[j]));
    }
    if (local.size() < 2)
        throw std::domain_error("alpha: fewer than three sampled times lie in the window");
    return lineThrough(inverseTime, local);
}

ExponentEstimate estimateExponent(const SpreadabilityCurve& curve,
                                  std::span<const DiscreteSpectrum> members,
                                  const ExponentWindow& window, int replicas, std::uint64_t seed) {
    ExponentEstimate e;
    const ExponentLine line = extrapolatedExponent(curve, window);
    e.alpha = line.alpha;
    e.slope = line.slope;
    e.windowMean = windowExponent(curve, window);
    e.endLow = e.endHigh = e.alpha;
    for (const double f : {0.5, 2.0}) {
        const double alpha =
            extrapolatedExponent(curve, {window.tMin, std::max(f * window.tMax, 1.5 * window.tMin)})
                .alpha;
        e.endLow = std::min(e.endLow, alpha);
        e.endHigh = std::max(e.endHigh, alpha);
    }
    e.replicas = replicas;
    if (replicas < 2) return e;
    std::vector<double> alphas(static_cast<std::size_t>(replicas)), means(alphas.size());
    parallelFor(0, replicas, 1, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t r = begin; r < end; ++r)
            std::tie(alphas[r], means[r]) =
                replicaExponents(members, window, seed, static_cast<int>(r));
    });
    e.standardError = sampleStatistics(alphas).std;
    e.windowMeanError = sampleStatistics(means).std;
    return e;
}

} // namespace sbpack
