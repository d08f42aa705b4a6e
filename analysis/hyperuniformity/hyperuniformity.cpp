#include "hyperuniformity/hyperuniformity.hpp"

#include "hyperuniformity/debye_medium.hpp"
#include "hyperuniformity/spreadability_curve.hpp"
#include "parallel/parallel.hpp"
#include "progress/progress.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

std::vector<double> logSpaced(double from, double to, int perDecade) {
    const int intervals =
        std::max(1, static_cast<int>(std::ceil(perDecade * std::log10(to / from))));
    std::vector<double> t(intervals + 1);
    for (int i = 0; i <= intervals; ++i)
        t[i] = from * std::pow(to / from, static_cast<double>(i) / intervals);
    return t;
}

/// E(t), its local exponent, the truncation bound and the Debye curve on the time grid.
void fillCurves(HyperuniformityResult& r, const SpreadabilityCurve& curve, double phi) {
    r.t = logSpaced(r.parameters.tMin, r.parameters.tMax, r.parameters.pointsPerDecade);
    const std::size_t n = r.t.size();
    for (auto* v : {&r.excess, &r.localExponent, &r.localAlpha, &r.truncation, &r.debyeExcess})
        v->resize(n);
    parallelFor(0, static_cast<std::int64_t>(n), 8, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t i = begin; i < end; ++i) {
            const SpreadabilityCurve::Point p = curve.at(r.t[i]);
            r.excess[i] = std::exp(p.logExcess);
            r.localExponent[i] = p.exponent;
            r.localAlpha[i] = -3.0 - 2.0 * p.exponent;
            r.truncation[i] = curve.truncationBound(r.t[i]);
            r.debyeExcess[i] = debyeExcessSpreadability(r.t[i], phi);
        }
    });
    r.cutoffTime = curve.cutoffTime();
}

/// The fits of chi_V at small Q over the wave vectors of every member.
void fitSmallQ(HyperuniformityResult& r, std::span<const DiscreteSpectrum> members) {
    const double q = r.parameters.fitQmaxW;
    const double reach = q * kWindowFactors[std::size(kWindowFactors) - 1];
    SmallQPoints all;
    for (const DiscreteSpectrum& s : members)
        all.append(smallQPoints(s, reach));
    r.fitted = all.upTo(q);
    r.fit = fitFixedExponent(r.fitted, r.alpha.alpha);
    r.freeFit = fitFreeExponent(r.fitted);
    r.h = r.fit.a0 / r.peak.chi;
    r.hSpread = indexSpread(all, q, r.alpha.alpha, r.peak.chi);
}

} // namespace

Hyperuniformity::Hyperuniformity(HyperuniformityParameters parameters) : parameters_(parameters) {
    const HyperuniformityParameters& p = parameters_;
    if (!(p.tMin > 0.0 && p.tMax > p.tMin && std::isfinite(p.tMax)))
        throw std::invalid_argument("hyperuniformity: times must satisfy 0 < t_min < t_max");
    if (p.pointsPerDecade < 1) throw std::invalid_argument("hyperuniformity: no time points");
    if (!(p.fitQmaxW > 0.0 && std::isfinite(p.fitQmaxW)))
        throw std::invalid_argument("hyperuniformity: --fit-qmax must be positive");
    if (p.replicas < 0) throw std::invalid_argument("hyperuniformity: negative replicas");
    if (p.window && !(p.window->tMin > 0.0 && p.window->tMax > p.window->tMin))
        throw std::invalid_argument("hyperuniformity: --alpha-window needs 0 < T1 < T2");
}

HyperuniformityResult Hyperuniformity::compute(std::span<const DiscreteSpectrum> members,
                                               const SpectralPeak& peak) const {
    const Stopwatch clock;
    if (!(peak.chi > 0.0 && peak.qw > 0.0))
        throw std::invalid_argument("hyperuniformity: no peak of chi_V");
    HyperuniformityResult r;
    r.parameters = parameters_;
    r.peak = peak;
    const SpreadabilityCurve curve(members);
    double phi = 0.0;
    for (const DiscreteSpectrum& s : members)
        phi += s.phi / static_cast<double>(members.size());
    fillCurves(r, curve, phi);
    if (parameters_.window && parameters_.window->tMax > r.cutoffTime)
        throw std::domain_error(
            "alpha window: --alpha-window ends at t D_diff / w^2 = " +
            std::to_string(parameters_.window->tMax) + ", past the box's cutoff time " +
            std::to_string(r.cutoffTime) +
            " (beyond it E(t) is the smallest wave vectors' decay, not the packing's): end it "
            "there or analyse a larger box");
    r.window = parameters_.window ? *parameters_.window : findExponentWindow(curve, peak.qw);
    r.alpha = estimateExponent(curve, members, r.window, parameters_.replicas, parameters_.seed);
    fitSmallQ(r, members);
    r.runtimeSeconds = clock.seconds();
    return r;
}

std::vector<ChiBin> binnedChi(const SmallQPoints& points, double binWidthQw) {
    if (!(binWidthQw > 0.0)) throw std::invalid_argument("chi_V bins: width must be positive");
    std::map<long, ChiBin> bins;
    for (std::size_t i = 0; i < points.qw.size(); ++i) {
        ChiBin& b = bins[static_cast<long>(std::floor(points.qw[i] / binWidthQw))];
        b.qw += points.qw[i];
        b.chi += points.chi[i];
        ++b.modes;
    }
    std::vector<ChiBin> out;
    for (const auto& [index, b] : bins)
        out.push_back({b.qw / b.modes, b.chi / b.modes, b.modes});
    return out;
}

const ChiBin& largestBin(const std::vector<ChiBin>& bins) {
    return *std::max_element(bins.begin(), bins.end(),
                             [](const ChiBin& a, const ChiBin& b) { return a.chi < b.chi; });
}

SpectralPeak fittedPeak(const std::vector<ChiBin>& bins, double halfWidthQw) {
    if (bins.empty()) throw std::invalid_argument("chi_V peak: no bins");
    const ChiBin& top = largestBin(bins);
    // ln chi = c0 + c1 x + c2 x^2, x = Q w - top's (a Gaussian peak exactly), weighted by the
    // wave vectors of each bin (the relative scatter of its mean goes as 1 / sqrt(modes)).
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    int used = 0;
    for (const ChiBin& b : bins) {
        const double x = b.qw - top.qw;
        if (std::abs(x) > halfWidthQw || !(b.chi > 0.0)) continue;
        const Eigen::Vector3d basis(1.0, x, x * x);
        normal += b.modes * basis * basis.transpose();
        rhs += b.modes * std::log(b.chi) * basis;
        ++used;
    }
    const SpectralPeak largest{top.qw, top.chi};
    if (used < 4) return largest;
    const Eigen::Vector3d c = normal.ldlt().solve(rhs);
    if (!(c[2] < 0.0)) return largest;
    const double vertex = -c[1] / (2.0 * c[2]);
    if (!(std::abs(vertex) < halfWidthQw)) return largest;
    return {top.qw + vertex, std::exp(c[0] - c[1] * c[1] / (4.0 * c[2]))};
}

SpectralPeak principalPeak(const DiscreteSpectrum& s) {
    return fittedPeak(binnedChi(modePoints(s), kPeakBinQw), kPeakHalfWidthQw);
}

} // namespace sbpack
