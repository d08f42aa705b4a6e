#include "spectral/exact_spectral_density.hpp"

#include "parallel/parallel.hpp"
#include "spectral/form_factors.hpp"
#include "spectral/spectral_density.hpp"
#include "structure/collective_density.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

namespace sbpack {

namespace {

/// WaveVectorSpectrum's order: by |n|^2, then lexicographically.
bool before(const std::array<int, 3>& a, const std::array<int, 3>& b) {
    const std::int64_t a2 = squaredIndex(a), b2 = squaredIndex(b);
    return a2 != b2 ? a2 < b2 : a < b;
}

/// exp(-2 pi i n x / L) from the phase table of one axis (n of either sign).
std::complex<double> phase(const PhaseTable& t, std::size_t row, int n) {
    const std::size_t k = row + static_cast<std::size_t>(std::abs(n));
    return {t.c[k], n >= 0 ? -t.s[k] : t.s[k]};
}

/// Everything the series path needs per particle: the body-frame map u = B n (u = k R, k
/// the body-frame wave vector of n: B = (2 pi R / L) R_j^T) and the three phase tables. A
/// mixture's particle j of size s_j = R_j / R has m(k; s_j R) = s_j^3 m(s_j k; R): B carries
/// s_j and `cubedSize` s_j^3 (empty for identical particles).
struct ParticleTables {
    std::vector<Eigen::Matrix3d> toBody;
    PhaseTable x, y, z;
    std::size_t stride;
    std::vector<double> cubedSize;
};

ParticleTables particleTables(const Packing& packing, int kmax) {
    ParticleTables t{{},
                     phaseTable(packing.positions, 0, packing.boxLength, kmax),
                     phaseTable(packing.positions, 1, packing.boxLength, kmax),
                     phaseTable(packing.positions, 2, packing.boxLength, kmax),
                     static_cast<std::size_t>(kmax) + 1,
                     {}};
    const double scale = 2.0 * std::numbers::pi * packing.semiAxis / packing.boxLength;
    t.toBody.reserve(packing.size());
    for (const Quaterniond& q : packing.orientations)
        t.toBody.push_back(scale * q.normalized().toRotationMatrix().transpose());
    for (std::size_t j = 0; j < packing.semiAxes.size(); ++j) {
        const double size = packing.relativeSize(j);
        t.toBody[j] *= size;
        t.cubedSize.push_back(size * size * size);
    }
    return t;
}

/// sum_j m(R_j^T Q) exp(-i Q.r_j) for the kTile wave vectors modes[first..first + kTile)
/// (padded by repeating the last), written to sums[first..].
template <class Form>
void tileSums(const Form& form, const ParticleTables& t,
              const std::vector<std::array<int, 3>>& modes, std::size_t first, int order,
              std::vector<std::complex<double>>& sums) {
    constexpr int T = Form::kTile;
    std::array<Eigen::Vector3d, T> n;
    for (int lane = 0; lane < T; ++lane) {
        const auto& m = modes[std::min(first + lane, modes.size() - 1)];
        n[lane] = Eigen::Vector3d(m[0], m[1], m[2]);
    }
    std::array<std::complex<double>, T> acc{};
    double ux[T], uy[T], uz[T], value[T];
    for (std::size_t j = 0; j < t.toBody.size(); ++j) {
        for (int lane = 0; lane < T; ++lane) {
            const Eigen::Vector3d u = t.toBody[j] * n[lane];
            ux[lane] = -u.x() * u.x();
            uy[lane] = -u.y() * u.y();
            uz[lane] = -u.z() * u.z();
        }
        form.seriesTile(order, ux, uy, uz, value);
        if (!t.cubedSize.empty())
            for (double& v : value)
                v *= t.cubedSize[j];
        const std::size_t row = j * t.stride;
        for (int lane = 0; lane < T && first + lane < modes.size(); ++lane) {
            const auto& m = modes[first + lane];
            acc[lane] += value[lane] *
                         (phase(t.x, row, m[0]) * phase(t.y, row, m[1]) * phase(t.z, row, m[2]));
        }
    }
    for (int lane = 0; lane < T && first + lane < modes.size(); ++lane)
        sums[first + lane] = acc[lane];
}

} // namespace

std::vector<std::array<int, 3>> halfSpaceWaveVectors(std::int64_t maxN2) {
    std::vector<std::array<int, 3>> modes;
    const int k = maxN2 >= 1 ? isqrt(maxN2) : 0;
    for (int nx = 0; nx <= k; ++nx)
        for (int ny = -k; ny <= k; ++ny)
            for (int nz = -k; nz <= k; ++nz) {
                const bool half = nx > 0 || (nx == 0 && (ny > 0 || (ny == 0 && nz > 0)));
                const std::array<int, 3> n{nx, ny, nz};
                if (half && squaredIndex(n) <= maxN2) modes.push_back(n);
            }
    std::sort(modes.begin(), modes.end(), before);
    return modes;
}

ShellAverage shellAverage(const WaveVectorSpectrum& spectrum, int maxShell) {
    const std::int64_t maxN2 = maxSquaredIndex(maxShell);
    if (spectrum.size() == 0 || spectrum.maxN2 < maxN2)
        throw std::invalid_argument("shell average: the spectrum does not reach shell " +
                                    std::to_string(maxShell));
    ShellAccumulator shells(spectrum.boxLength, maxShell);
    for (std::size_t i = 0; i < spectrum.size() && spectrum.n2(i) <= maxN2; ++i)
        shells.add(spectrum.n2(i), spectrum.chi[i], 2); // chi(Q) = chi(-Q)
    return shells.average();
}

bool sumsFormFactors(const Packing& packing) {
    return !packing.shape().isSphere() || packing.isMixture();
}

WaveVectorSpectrum sphereWaveVectors(const Packing& packing, std::int64_t maxN2,
                                     const Progress& progress) {
    if (sumsFormFactors(packing))
        throw std::invalid_argument("exact spectral density: the particles are not identical "
                                    "spheres (" +
                                    packing.shapeSpec.describe() + ")");
    if (maxN2 < 1) throw std::invalid_argument("exact spectral density: no wave vector");
    const DensityModes modes =
        collectiveDensity(packing.positions, packing.boxLength, maxN2, progress);
    std::vector<std::size_t> order(modes.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return before(modes.n[a], modes.n[b]); });
    const double volume = std::pow(packing.boxLength, 3);
    WaveVectorSpectrum out{packing.boxLength, maxN2, {}, {}};
    out.n.reserve(order.size());
    out.chi.reserve(order.size());
    for (const std::size_t i : order) {
        const double q = 2.0 * std::numbers::pi *
                         std::sqrt(static_cast<double>(squaredIndex(modes.n[i]))) /
                         packing.boxLength;
        const double m = sphereFormFactor(q, packing.semiAxis);
        out.n.push_back(modes.n[i]);
        out.chi.push_back(modes.intensity[i] * m * m / volume); // Eq. 12
    }
    return out;
}

namespace {

/// formFactorWaveVectors with the body's form factor `form`.
template <class Form>
WaveVectorSpectrum seriesWaveVectors(const Form& form, const Packing& packing, std::int64_t maxN2,
                                     const Progress& progress) {
    WaveVectorSpectrum out{packing.boxLength, maxN2, halfSpaceWaveVectors(maxN2), {}};
    const ParticleTables tables = particleTables(packing, isqrt(maxN2));
    constexpr int T = Form::kTile;
    const auto tiles = static_cast<std::int64_t>((out.size() + T - 1) / T);
    std::vector<int> orders(tiles);
    for (std::int64_t i = 0; i < tiles; ++i) { // the tile's largest |Q| sets its series order
        const std::size_t last = std::min(out.size(), static_cast<std::size_t>(i + 1) * T) - 1;
        orders[i] = form.order(2.0 * std::numbers::pi *
                               std::sqrt(static_cast<double>(out.n2(last))) / packing.boxLength);
    }
    std::vector<std::complex<double>> sums(out.size());
    parallelFor(
        0, tiles, 1,
        [&](std::int64_t begin, std::int64_t end) {
            for (std::int64_t i = begin; i < end; ++i) {
                progress.checkInterrupt();
                tileSums(form, tables, out.n, static_cast<std::size_t>(i) * T, orders[i], sums);
            }
        },
        progress);
    const double volume = std::pow(packing.boxLength, 3);
    out.chi.reserve(out.size());
    for (const std::complex<double>& s : sums)
        out.chi.push_back(std::norm(s) / volume); // Eq. 12
    return out;
}

} // namespace

WaveVectorSpectrum formFactorWaveVectors(const Packing& packing, std::int64_t maxN2,
                                         const Progress& progress) {
    if (maxN2 < 1) throw std::invalid_argument("exact spectral density: no wave vector");
    return std::visit(
        [&](const auto& form) { return seriesWaveVectors(form, packing, maxN2, progress); },
        formFactorOf(packing.shape()));
}

ExactSpectralDensity::ExactSpectralDensity(ExactSpectralDensityParameters parameters)
    : parameters_(parameters) {
    if (!(parameters.maxQw > 0.0) || !std::isfinite(parameters.maxQw))
        throw std::invalid_argument("exact spectral density: qmax must be positive and finite, "
                                    "not " +
                                    fmt::format("{:g}", parameters.maxQw));
}

std::int64_t ExactSpectralDensity::maxN2For(double maxQw, double boxLength, double meanWidth) {
    const double n = maxQw * boxLength / (2.0 * std::numbers::pi * meanWidth);
    return static_cast<std::int64_t>(std::floor(n * n));
}

ExactSpectralDensityResult ExactSpectralDensity::compute(const Packing& packing,
                                                         const Progress& progress) const {
    const Stopwatch clock;
    ExactSpectralDensityResult result;
    result.parameters = parameters_;
    result.boxLength = packing.boxLength;
    const ParticleShape shape = packing.shape();
    result.meanWidth = shape.meanWidth();
    result.phi = packing.packingFraction();
    result.maxN2 = maxN2For(parameters_.maxQw, packing.boxLength, result.meanWidth);
    const double qMinW = 2.0 * std::numbers::pi * result.meanWidth / packing.boxLength;
    if (result.maxN2 < 1)
        throw std::invalid_argument("exact spectral density: no wave vector with Q w <= qmax = " +
                                    fmt::format("{:g}", parameters_.maxQw) +
                                    "; the box's smallest is Q w = " + std::to_string(qMinW));
    const bool series = sumsFormFactors(packing);
    // The series path's form factor, built once: its range checked, then summed.
    const auto withinRange = [&](const auto& form) {
        const double limit = std::decay_t<decltype(form)>::kSeriesLimit;
        if (parameters_.maxQw / result.meanWidth * shape.circumradius() > limit)
            throw std::invalid_argument(
                "exact spectral density: qmax = " + fmt::format("{:g}", parameters_.maxQw) +
                " is beyond the form factor series' range for " + packing.shapeSpec.describe() +
                " (Q w <= " + std::to_string(limit * result.meanWidth / shape.circumradius()) +
                ")");
        return seriesWaveVectors(form, packing, result.maxN2, progress);
    };
    result.modes = series ? std::visit(withinRange, formFactorOf(shape))
                          : sphereWaveVectors(packing, result.maxN2, progress);
    result.runtimeSeconds = clock.seconds();
    return result;
}

} // namespace sbpack
