#include "variance/volume_fraction_variance.hpp"

#include "numerics/sample_statistics.hpp"
#include "parallel/parallel.hpp"
#include "random/random.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sbpack {

double sphereWindowFactor(double x) {
    // Below 0.1 the closed form loses digits to cancellation; its Taylor series to x^8 is exact
    // there to rounding (the next term, x^10 / 1.9e8, is below 1e-18).
    if (std::abs(x) < 0.1) {
        const double y = x * x;
        return 1.0 - y / 10.0 + y * y / 280.0 - y * y * y / 15120.0 + y * y * y * y / 1330560.0;
    }
    return 3.0 * (std::sin(x) - x * std::cos(x)) / (x * x * x);
}

double spectralVariance(const DiscreteSpectrum& spectrum, double radius) {
    const double l = spectrum.boxLength;
    double sum = 0.0;
    for (std::size_t n2 = 1; n2 < spectrum.sumByN2.size(); ++n2) {
        if (spectrum.sumByN2[n2] == 0.0) continue;
        const double q = 2.0 * std::numbers::pi * std::sqrt(static_cast<double>(n2)) / l;
        const double f = sphereWindowFactor(q * radius);
        sum += spectrum.sumByN2[n2] * f * f;
    }
    return sum / (l * l * l);
}

std::vector<double> windowRadii(double boxLength, double meanWidth,
                                const VarianceParameters& parameters) {
    std::vector<double> radii;
    for (int k = 0;; ++k) {
        const double r = meanWidth * parameters.minRadiusW *
                         std::pow(10.0, static_cast<double>(k) / parameters.radiiPerDecade);
        if (r > 0.5 * boxLength) break;
        radii.push_back(r);
    }
    return radii;
}

namespace {

/// The tail fit's grid of alpha (docs/local-structure.md §2): at alpha = 1 its two terms are one,
/// and beyond it the volume term is one of the surface term's corrections.
constexpr double kAlphaLow = -1.0, kAlphaHigh = 0.98, kAlphaStep = 1e-3;

/// Bound on what the wave vectors left out (|Q| >= cutoffQ) add to sigma_V^2(R): their weight
/// phi missingWeight times the largest F^2 beyond cutoffQ R, F^2 <= (3 / x^2 + 3 / x^3)^2.
double truncationBound(const DiscreteSpectrum& s, double radius) {
    const double x = s.cutoffQ * radius;
    const double envelope =
        x < 3.0 ? 1.0 : std::min(1.0, std::pow(3.0 / (x * x) + 3.0 / (x * x * x), 2));
    return s.phi * std::max(0.0, s.missingWeight) * (std::isfinite(x) ? envelope : 0.0);
}

/// Per row (x, y) of the grid the solid voxels among z < k: prefix[(x M + y) (M + 1) + k].
std::vector<std::uint32_t> rowPrefixSums(const Voxelization& voxels, const Progress& progress) {
    const std::int64_t m = voxels.voxels();
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(m * m * m));
    voxels.copySolidMask(mask, progress);
    std::vector<std::uint32_t> prefix(static_cast<std::size_t>(m * m * (m + 1)));
    parallelFor(
        0, m * m, 256,
        [&](std::int64_t begin, std::int64_t end) {
            for (std::int64_t row = begin; row < end; ++row) {
                std::uint32_t* p = &prefix[static_cast<std::size_t>(row * (m + 1))];
                const std::uint8_t* solid = &mask[static_cast<std::size_t>(row * m)];
                p[0] = 0;
                for (std::int64_t k = 0; k < m; ++k)
                    p[k + 1] = p[k] + solid[k];
            }
        },
        progress);
    return prefix;
}

/// The solid voxels among z0, ..., z0 + n - 1 (modulo M) of one row's prefix sums.
std::int64_t rowSolid(const std::uint32_t* row, std::int64_t m, std::int64_t z0, std::int64_t n) {
    const std::int64_t start = ((z0 % m) + m) % m, end = start + n % m;
    std::int64_t count = (n / m) * row[m];
    count += end <= m ? row[end] - row[start] : (row[m] - row[start]) + row[end - m];
    return count;
}

struct WindowCount {
    std::int64_t solid = 0, total = 0;
};

/// The voxel centres within r of c (voxel units, voxel i's centre at i; periodic).
WindowCount countWindow(const std::vector<std::uint32_t>& prefix, std::int64_t m, const Vector3d& c,
                        double r) {
    WindowCount w;
    for (auto x = static_cast<std::int64_t>(std::ceil(c.x() - r)); x <= c.x() + r; ++x) {
        const double restX = r * r - (x - c.x()) * (x - c.x());
        if (restX < 0.0) continue;
        const double hy = std::sqrt(restX);
        const std::int64_t xi = ((x % m) + m) % m;
        for (auto y = static_cast<std::int64_t>(std::ceil(c.y() - hy)); y <= c.y() + hy; ++y) {
            const double restY = restX - (y - c.y()) * (y - c.y());
            if (restY < 0.0) continue;
            const double hz = std::sqrt(restY);
            const auto z0 = static_cast<std::int64_t>(std::ceil(c.z() - hz));
            const auto z1 = static_cast<std::int64_t>(std::floor(c.z() + hz));
            if (z1 < z0) continue;
            const std::int64_t yi = ((y % m) + m) % m;
            w.solid += rowSolid(&prefix[static_cast<std::size_t>((xi * m + yi) * (m + 1))], m, z0,
                                z1 - z0 + 1);
            w.total += z1 - z0 + 1;
        }
    }
    return w;
}

/// The sampled route: `windows` random windows per radius, each the stream (seed, its index).
void sampleWindows(const Voxelization& voxels, const VarianceParameters& p,
                   const Progress& progress, VarianceResult& r) {
    const std::vector<std::uint32_t> prefix = rowPrefixSums(voxels, progress);
    const std::int64_t m = voxels.voxels(), k = p.windows;
    const double a = voxels.voxelSize(), phi = voxels.phiVoxel();
    std::vector<double> squares(r.radius.size() * static_cast<std::size_t>(k));
    parallelFor(
        0, static_cast<std::int64_t>(squares.size()), 16,
        [&](std::int64_t begin, std::int64_t end) {
            progress.checkInterrupt();
            for (std::int64_t i = begin; i < end; ++i) {
                Random random = Random::stream(p.seed, i);
                const Vector3d u(random.uniform(), random.uniform(), random.uniform());
                const Vector3d centre = u * static_cast<double>(m) - Vector3d::Constant(0.5);
                const WindowCount w = countWindow(prefix, m, centre, r.radius[i / k] / a);
                const double f = static_cast<double>(w.solid) / static_cast<double>(w.total);
                squares[i] = (f - phi) * (f - phi);
            }
        },
        progress);
    for (std::size_t j = 0; j < r.radius.size(); ++j) {
        std::vector<double> batch(static_cast<std::size_t>(p.batches), 0.0);
        for (std::int64_t i = 0; i < k; ++i)
            batch[i % p.batches] += squares[j * k + i];
        for (std::int64_t b = 0; b < p.batches; ++b) {
            const std::int64_t windows = (k - b + p.batches - 1) / p.batches; // k / B or one more
            batch[b] /= static_cast<double>(windows);
        }
        const SampleStatistics s = sampleStatistics(batch);
        double all = 0.0;
        for (std::int64_t i = 0; i < k; ++i)
            all += squares[j * k + i];
        r.sampled.push_back(all / static_cast<double>(k));
        r.sampledError.push_back(s.std / std::sqrt(static_cast<double>(p.batches)));
    }
}

/// The residual sum of the tail model sigma^2 = A R^-(3 + alpha) + B R^-4 (the volume term of
/// an exponent-alpha medium and the windows' surface term) at one alpha, relative to sigma^2,
/// with A and B by linear least squares; +inf where the two terms cannot be told apart.
double tailResiduals(std::span<const double> r, std::span<const double> y, std::size_t first,
                     std::size_t last, double alpha) {
    double s11 = 0.0, s12 = 0.0, s22 = 0.0, t1 = 0.0, t2 = 0.0;
    for (std::size_t i = first; i < last; ++i) {
        const double c1 = std::pow(r[i], -3.0 - alpha) / y[i], c2 = std::pow(r[i], -4.0) / y[i];
        s11 += c1 * c1, s12 += c1 * c2, s22 += c2 * c2, t1 += c1, t2 += c2;
    }
    const double det = s11 * s22 - s12 * s12;
    if (!(det > 1e-10 * s11 * s22)) return std::numeric_limits<double>::infinity();
    const double a = (t1 * s22 - t2 * s12) / det, b = (t2 * s11 - t1 * s12) / det;
    double sum = 0.0;
    for (std::size_t i = first; i < last; ++i) {
        const double e =
            1.0 - a * std::pow(r[i], -3.0 - alpha) / y[i] - b * std::pow(r[i], -4.0) / y[i];
        sum += e * e;
    }
    return sum;
}

} // namespace

std::optional<VarianceExponent> fitVarianceTail(std::span<const double> radius,
                                                std::span<const double> sigma2, double minRadius,
                                                double maxRadius) {
    // alpha on a grid of kAlphaStep over [kAlphaLow, kAlphaHigh] minimising tailResiduals; its
    // error the half width of the profile interval where the residuals exceed the least by at
    // most their variance per degree of freedom (s^2 = RSS / (n - 3)).
    std::size_t first = 0, last = 0;
    for (std::size_t i = 0; i < radius.size(); ++i) {
        if (radius[i] < minRadius) first = i + 1;
        if (radius[i] <= maxRadius) last = i + 1;
    }
    if (last < first + 4) return std::nullopt;
    std::vector<double> alphas, residuals;
    for (double alpha = kAlphaLow; alpha <= kAlphaHigh + 1e-9; alpha += kAlphaStep) {
        alphas.push_back(alpha);
        residuals.push_back(tailResiduals(radius, sigma2, first, last, alpha));
    }
    const auto best = static_cast<std::size_t>(
        std::min_element(residuals.begin(), residuals.end()) - residuals.begin());
    const double bound = residuals[best] * (1.0 + 1.0 / static_cast<double>(last - first - 3));
    std::size_t lo = best, hi = best;
    while (lo > 0 && residuals[lo - 1] <= bound)
        --lo;
    while (hi + 1 < residuals.size() && residuals[hi + 1] <= bound)
        ++hi;
    VarianceExponent e;
    e.alpha = alphas[best];
    e.saturated = best + 1 == alphas.size();
    e.standardError = std::max(0.5 * (alphas[hi] - alphas[lo]), 0.5 * kAlphaStep);
    e.minRadius = radius[first];
    e.maxRadius = radius[last - 1];
    e.points = static_cast<int>(last - first);
    return e;
}

VolumeFractionVariance::VolumeFractionVariance(VarianceParameters parameters)
    : parameters_(parameters) {
    const VarianceParameters& p = parameters_;
    if (!(p.minRadiusW > 0.0) || p.radiiPerDecade < 1 || p.windows < 0 ||
        (p.windows > 0 && (p.batches < 2 || p.windows < p.batches)))
        throw std::invalid_argument(
            "volume-fraction variance: needs minRadiusW > 0, radiiPerDecade >= 1, and windows 0 "
            "or at least " +
            std::to_string(std::max(2, p.batches)) + " (got " + std::to_string(p.windows) + ")");
}

double VolumeFractionVariance::memoryBytes(int voxels) {
    const double m = voxels;
    return m * m * (4.0 * (m + 1.0) + m);
}

VarianceResult VolumeFractionVariance::compute(const DiscreteSpectrum& spectrum,
                                               const Voxelization* voxels,
                                               const Progress& progress) const {
    const Stopwatch clock;
    if (!(spectrum.boxLength > 0.0) || !(spectrum.meanWidth > 0.0))
        throw std::invalid_argument("volume-fraction variance: a spectrum without a box or width");
    if (voxels != nullptr &&
        std::abs(voxels->boxLength() - spectrum.boxLength) > 1e-12 * spectrum.boxLength)
        throw std::invalid_argument("volume-fraction variance: the voxels' box is not the "
                                    "spectrum's");
    VarianceResult r;
    r.radius = windowRadii(spectrum.boxLength, spectrum.meanWidth, parameters_);
    for (double radius : r.radius) {
        r.spectral.push_back(spectralVariance(spectrum, radius));
        r.truncation.push_back(truncationBound(spectrum, radius));
    }
    r.exponent =
        fitVarianceTail(r.radius, r.spectral, parameters_.fitMinRadiusW * spectrum.meanWidth,
                        0.25 * spectrum.boxLength);
    r.spectrumSource = spectrum.source;
    r.phi = spectrum.phi;
    if (voxels != nullptr && parameters_.windows > 0) {
        r.windows = parameters_.windows;
        sampleWindows(*voxels, parameters_, progress, r);
    }
    r.runtimeSeconds = clock.seconds();
    return r;
}

} // namespace sbpack
