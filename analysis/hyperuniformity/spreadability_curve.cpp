#include "hyperuniformity/spreadability_curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

/// exp(-x) underflows to zero beyond this.
constexpr double kUnderflow = 745.0;

void check(const DiscreteSpectrum& s) {
    if (!(s.phi > 0.0 && s.phi < 1.0))
        throw std::invalid_argument("spreadability: phi = " + std::to_string(s.phi) +
                                    " is not in (0, 1)");
    if (!(s.boxLength > 0.0) || !(s.meanWidth > 0.0))
        throw std::invalid_argument("spreadability: the box length and the mean width must be "
                                    "positive");
}

} // namespace

SpreadabilityCurve::SpreadabilityCurve(std::span<const DiscreteSpectrum> members) {
    if (members.empty()) throw std::invalid_argument("spreadability: no spectrum");
    cutoffTime_ = std::numeric_limits<double>::infinity();
    for (const DiscreteSpectrum& s : members) {
        check(s);
        const double unit = 2.0 * std::numbers::pi * s.meanWidth / s.boxLength; // Q w of |n| = 1
        const double normalisation = 1.0 / (s.phi * std::pow(s.boxLength, 3));
        Member m{{}, {}, s.missingWeight, std::pow(s.cutoffQ * s.meanWidth, 2)};
        for (std::size_t n2 = 1; n2 < s.sumByN2.size(); ++n2)
            if (s.sumByN2[n2] > 0.0) {
                m.q2.push_back(unit * unit * static_cast<double>(n2));
                m.weight.push_back(s.sumByN2[n2] * normalisation);
            }
        if (m.q2.empty()) throw std::invalid_argument("spreadability: the spectrum is empty");
        members_.push_back(std::move(m));
        cutoffTime_ = std::min(cutoffTime_, 1.0 / (unit * unit));
    }
}

SpreadabilityCurve::Moments SpreadabilityCurve::moments(const Member& m, double t) {
    // Relative to the smallest q2, so that nothing underflows before the sum does; weighted
    // mean and variance in one pass (West's update).
    double sum = 0.0, mean = 0.0, m2 = 0.0;
    for (std::size_t i = 0; i < m.q2.size(); ++i) {
        const double x = (m.q2[i] - m.q2[0]) * t;
        if (x > kUnderflow) break; // ascending: the rest underflow too
        const double e = m.weight[i] * std::exp(-x);
        sum += e;
        const double delta = m.q2[i] - mean;
        mean += e / sum * delta;
        m2 += e * delta * (m.q2[i] - mean);
    }
    return {std::log(sum) - m.q2[0] * t, mean, m2 / sum};
}

SpreadabilityCurve::Point SpreadabilityCurve::at(double t) const {
    // Pooled: E = mean of E_k; nu = sum E_k nu_k / sum E_k; d nu / d ln t =
    // sum E_k (nu_k^2 + nu_k') / sum E_k - nu^2, with nu_k' = nu_k + t^2 Var_k.
    std::vector<Moments> m;
    m.reserve(members_.size());
    double top = -std::numeric_limits<double>::infinity();
    for (const Member& member : members_) {
        m.push_back(moments(member, t));
        top = std::max(top, m.back().logSum);
    }
    double weights = 0.0, nu = 0.0, second = 0.0;
    for (const Moments& k : m) {
        const double e = std::exp(k.logSum - top);
        const double nuK = -t * k.mean;
        weights += e;
        nu += e * nuK;
        second += e * (nuK * nuK + nuK + t * t * k.variance);
    }
    nu /= weights;
    return {top + std::log(weights / static_cast<double>(members_.size())), nu,
            second / weights - nu * nu};
}

double SpreadabilityCurve::excess(double t) const {
    return std::exp(at(t).logExcess);
}

double SpreadabilityCurve::truncationBound(double t) const {
    double sum = 0.0;
    for (const Member& m : members_)
        if (m.missingWeight > 0.0) sum += m.missingWeight * std::exp(-m.cutoffQ2 * t);
    return sum / static_cast<double>(members_.size());
}

} // namespace sbpack
