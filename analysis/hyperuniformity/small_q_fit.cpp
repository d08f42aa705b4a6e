#include "hyperuniformity/small_q_fit.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sbpack {

namespace {

/// Q w of the box's first wave number, 2 pi w / L.
double qwUnit(const DiscreteSpectrum& spectrum) {
    return 2.0 * std::numbers::pi * spectrum.meanWidth / spectrum.boxLength;
}

} // namespace

SmallQPoints modePoints(const DiscreteSpectrum& spectrum, double qMaxW) {
    const double unit = qwUnit(spectrum);
    SmallQPoints p;
    const double w3 = std::pow(spectrum.meanWidth, 3);
    for (std::size_t i = 0; i < spectrum.modes.size(); ++i) {
        const double qw = unit * std::sqrt(static_cast<double>(spectrum.modes.n2(i)));
        if (qw > qMaxW) break; // ordered by |n|^2
        p.qw.push_back(qw);
        p.chi.push_back(spectrum.modes.chi[i] / w3);
    }
    return p;
}

SmallQPoints smallQPoints(const DiscreteSpectrum& spectrum, double qMaxW) {
    const double reach =
        std::sqrt(static_cast<double>(spectrum.individualMaxN2)) * qwUnit(spectrum);
    if (qMaxW > reach * (1.0 + 1e-12))
        throw std::domain_error(
            "small-Q fit: the windows up to Q w = " + std::to_string(qMaxW) +
            " reach beyond the wave vectors resolved (Q w <= " + std::to_string(reach) +
            "): lower --fit-qmax, or raise --voxels or --chi-exact-qmax");
    return modePoints(spectrum, qMaxW);
}

namespace {

/// The distinct |Q| among the points: values within 1e-3 of each other are one (the same shell
/// |n|^2 of the members of an ensemble, whose boxes differ by their phi; shells of |n|^2 <= 500
/// lie further apart).
int distinctMagnitudes(std::vector<double> qw) {
    std::sort(qw.begin(), qw.end());
    int distinct = 0;
    for (std::size_t i = 0; i < qw.size(); ++i)
        if (i == 0 || qw[i] > qw[i - 1] * (1.0 + 1e-3)) ++distinct;
    return distinct;
}

} // namespace

PowerLawFit fitFixedExponent(const SmallQPoints& points, double alpha) {
    const int n = static_cast<int>(points.qw.size());
    const int magnitudes = distinctMagnitudes(points.qw);
    if (magnitudes < 2 || n < 3) // a0 and a1 through one |Q| are not determined
        throw std::domain_error(
            "small-Q fit: the " + std::to_string(n) + " wave vectors in the fit window lie at " +
            std::to_string(magnitudes) +
            " distinct |Q| (a0 + a1 Q^alpha at the spreadability's alpha needs 2, and 3 wave "
            "vectors); raise --fit-qmax or analyse a larger box");
    Eigen::MatrixXd x(n, 2);
    Eigen::VectorXd y(n);
    for (int i = 0; i < n; ++i) {
        x(i, 0) = 1.0;
        x(i, 1) = std::pow(points.qw[i], alpha);
        y(i) = points.chi[i];
    }
    const Eigen::Matrix2d normal = x.transpose() * x;
    const Eigen::Vector2d a = normal.ldlt().solve(x.transpose() * y);
    PowerLawFit f;
    f.alpha = alpha;
    f.a0 = a(0);
    f.a1 = a(1);
    f.residual = (x * a - y).squaredNorm();
    f.points = n;
    const Eigen::Matrix2d covariance = normal.inverse() * (f.residual / (n - 2));
    f.a0Error = std::sqrt(covariance(0, 0));
    f.a1Error = std::sqrt(covariance(1, 1));
    return f;
}

FreeFit fitFreeExponent(const SmallQPoints& points) {
    constexpr double kStep = 0.005, kMax = 4.0;
    std::vector<PowerLawFit> scan;
    for (int i = 0; i * kStep <= kMax + 1e-12; ++i)
        scan.push_back(fitFixedExponent(points, i * kStep));
    const auto best = std::min_element(scan.begin(), scan.end(), [](const auto& a, const auto& b) {
        return a.residual < b.residual;
    });
    FreeFit f{*best, kMax, 0.0, false};
    const int n = best->points;
    const double limit = best->residual * (1.0 + 1.0 / std::max(1, n - 3));
    for (const PowerLawFit& s : scan)
        if (s.residual <= limit) {
            f.alphaLow = std::min(f.alphaLow, s.alpha);
            f.alphaHigh = std::max(f.alphaHigh, s.alpha);
        }
    f.degenerate = f.alphaHigh - f.alphaLow > 0.5 || best == scan.begin() || best + 1 == scan.end();
    return f;
}

SmallQPoints SmallQPoints::upTo(double qMaxW) const {
    SmallQPoints p;
    for (std::size_t i = 0; i < qw.size(); ++i)
        if (qw[i] <= qMaxW) {
            p.qw.push_back(qw[i]);
            p.chi.push_back(chi[i]);
        }
    return p;
}

void SmallQPoints::append(const SmallQPoints& other) {
    qw.insert(qw.end(), other.qw.begin(), other.qw.end());
    chi.insert(chi.end(), other.chi.begin(), other.chi.end());
}

IndexSpread indexSpread(const SmallQPoints& points, double qMaxW, double alpha, double chiPeak) {
    IndexSpread s{INFINITY, -INFINITY};
    for (const double factor : kWindowFactors) {
        const SmallQPoints window = points.upTo(factor * qMaxW);
        // A window through one shell determines no a0 (fitFixedExponent refuses it): the
        // narrowest windows of a small box (Q_min w near qMaxW) hold only the first shell.
        if (window.qw.size() < 3 || distinctMagnitudes(window.qw) < 2) continue;
        const double h = fitFixedExponent(window, alpha).a0 / chiPeak;
        s.hMin = std::min(s.hMin, h);
        s.hMax = std::max(s.hMax, h);
    }
    return s;
}

} // namespace sbpack
