#include "pores/exact_pore_size.hpp"

#include "parallel/parallel.hpp"
#include "pores/random_points.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sbpack {

namespace {

constexpr int kMaxIterations = 200;

/// Projection of xi (>= 0, sum > 1) onto { u >= 0, sum u <= 1 }: u = max(xi - kappa, 0) with
/// kappa from the sorted coordinates (the l1 ball, i.e. the octahedron p = 0.5).
Vector3d projectOntoOctahedron(const Vector3d& xi) {
    std::array<double, 3> sorted = {xi[0], xi[1], xi[2]};
    std::sort(sorted.begin(), sorted.end(), std::greater<>());
    double kappa = 0.0, partial = 0.0;
    for (int k = 0; k < 3; ++k) {
        partial += sorted[k];
        const double candidate = (partial - 1.0) / (k + 1);
        if (sorted[k] > candidate) kappa = candidate;
    }
    return (xi.array() - kappa).max(0.0).matrix();
}

/// Root u in (0, min(xi, 1)] of u + kappa u^m = xi, for xi > 0 and 1 + kappa >= xi (so that
/// the root is <= 1 and u^m cannot overflow): increasing in u, bracketed Newton from the right.
double axisRoot(double xi, double kappa, double m) {
    double lo = 0.0, hi = std::min(xi, 1.0), u = hi;
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        const double power = std::pow(u, m - 1.0); // u^{m-1}, u > 0
        const double residual = u + kappa * power * u - xi;
        if (residual == 0.0) return u;
        (residual > 0.0 ? hi : lo) = u;
        double next = u - residual / (1.0 + kappa * m * power);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - u) <= 4e-16 * u) return next;
        u = next;
    }
    return u;
}

/// Projection of xi (>= 0, outside) onto { u >= 0, sum u_i^{2p} <= 1 }, 0.5 < p: KKT
/// u_i + kappa u_i^{2p-1} = xi_i with sum u_i^{2p} = 1; the sum falls monotonically with kappa,
/// whose root lies in [max(0, max xi - 1), 3 max xi] (the largest u_i is >= 3^{-1/(2p)}).
Vector3d projectOntoSuperball(const Vector3d& xi, double p) {
    const double e = 2.0 * p, m = e - 1.0;
    const double largest = xi.maxCoeff();
    double lo = std::max(0.0, largest - 1.0), hi = 3.0 * largest;
    Vector3d u;
    // c(kappa) = sum u_i^e - 1 and its derivative, du_i/dkappa = -u_i^m / (1 + kappa m u_i^{m-1}).
    auto evaluate = [&](double kappa, double& derivative) {
        double c = -1.0;
        derivative = 0.0;
        for (int i = 0; i < 3; ++i) {
            u[i] = xi[i] > 0.0 ? axisRoot(xi[i], kappa, m) : 0.0;
            if (u[i] == 0.0) continue;
            const double power = std::pow(u[i], m - 1.0);
            const double um = power * u[i];
            c += um * u[i];
            derivative -= e * um * um / (1.0 + kappa * m * power);
        }
        return c;
    };
    // Start from the radial scaling u = xi / g(xi), exact for the sphere.
    const double gauge = std::pow(xi.array().pow(e).sum(), 1.0 / e);
    const int axis = static_cast<int>(std::max_element(xi.data(), xi.data() + 3) - xi.data());
    const double uAxis = xi[axis] / gauge;
    double kappa = std::clamp((xi[axis] - uAxis) / std::pow(uAxis, m), lo, hi);
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        double derivative = 0.0;
        const double c = evaluate(kappa, derivative);
        if (c == 0.0) break;
        (c > 0.0 ? lo : hi) = kappa;
        double next = derivative < 0.0 ? kappa - c / derivative : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const bool converged = std::abs(next - kappa) <= 4e-16 * std::max(kappa, 1e-300);
        kappa = next;
        if (converged || !(hi > lo)) {
            evaluate(kappa, derivative);
            break;
        }
    }
    return u;
}

} // namespace

Vector3d closestPoint(const Superball& shape, const Vector3d& xBody) {
    if (!(shape.gauge(xBody) > 1.0)) return xBody;
    const double r = shape.semiAxis();
    if (shape.isSphere()) return xBody * (r / xBody.norm());
    const Vector3d xi = xBody.cwiseAbs() / r;
    const Vector3d u =
        shape.isOctahedron() ? projectOntoOctahedron(xi) : projectOntoSuperball(xi, shape.p());
    Vector3d y;
    for (int i = 0; i < 3; ++i)
        y[i] = std::copysign(u[i] * r, xBody[i]);
    return y;
}

ExactPoreSizes::ExactPoreSizes(const Packing& packing)
    : shape_(packing.shape()), boxLength_(packing.boxLength), circumradius_(shape_.circumradius()),
      inradius_(shape_.inradius()) {
    if (packing.positions.empty())
        throw std::invalid_argument("exact pore sizes: the packing has no particles");
    if (packing.orientations.size() != packing.positions.size())
        throw std::invalid_argument(
            "exact pore sizes: " + std::to_string(packing.positions.size()) + " positions but " +
            std::to_string(packing.orientations.size()) + " orientations");
    if (!(std::isfinite(boxLength_) && boxLength_ > 0.0))
        throw std::invalid_argument("exact pore sizes: box length is not finite and positive");
    cellsPerSide_ = std::max(1, static_cast<int>(std::floor(boxLength_ / circumradius_)));
    cellSize_ = boxLength_ / cellsPerSide_;
    const int n = cellsPerSide_;
    const std::size_t count = packing.positions.size();
    positions_.reserve(count);
    rotations_.reserve(count);
    std::vector<int> cellOf(count);
    cellStart_.assign(static_cast<std::size_t>(n) * n * n + 1, 0);
    for (std::size_t j = 0; j < count; ++j) {
        positions_.push_back(wrapIntoBox(packing.positions[j], boxLength_));
        rotations_.push_back(packing.orientations[j].normalized().toRotationMatrix());
        std::array<int, 3> c{};
        for (int k = 0; k < 3; ++k)
            c[k] = std::min(n - 1, static_cast<int>(positions_[j][k] / cellSize_));
        cellOf[j] = (c[0] * n + c[1]) * n + c[2];
        ++cellStart_[cellOf[j] + 1];
    }
    for (std::size_t c = 1; c < cellStart_.size(); ++c)
        cellStart_[c] += cellStart_[c - 1];
    cellParticles_.resize(count);
    std::vector<int> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::size_t j = 0; j < count; ++j)
        cellParticles_[fill[cellOf[j]]++] = static_cast<int>(j);
}

double ExactPoreSizes::distanceToParticle(int particle, const Vector3d& d) const {
    if (shape_.isSphere()) return std::max(0.0, d.norm() - shape_.semiAxis());
    const Vector3d xBody = rotations_[particle].transpose() * d;
    return (xBody - closestPoint(shape_, xBody)).norm();
}

double ExactPoreSizes::poreSize(const Vector3d& x) const {
    struct Candidate {
        double lower; ///< |d| - circumradius <= distance to this particle image
        int particle;
        Vector3d d; ///< x minus the image's centre
    };
    const int n = cellsPerSide_;
    const Vector3d xw = wrapIntoBox(x, boxLength_);
    std::array<int, 3> home{};
    for (int k = 0; k < 3; ++k)
        home[k] = std::min(n - 1, static_cast<int>(xw[k] / cellSize_));
    std::vector<Candidate> candidates;
    double bestUpper = std::numeric_limits<double>::infinity(); // min of |d| - inradius
    for (int s = 0;; ++s) {
        // Shell s: the cells (and their periodic images) at Chebyshev offset s from home.
        for (int ox = -s; ox <= s; ++ox)
            for (int oy = -s; oy <= s; ++oy)
                for (int oz = -s; oz <= s; ++oz) {
                    if (std::max({std::abs(ox), std::abs(oy), std::abs(oz)}) != s) continue;
                    const std::array<int, 3> unwrapped = {home[0] + ox, home[1] + oy, home[2] + oz};
                    std::array<int, 3> cell{};
                    Vector3d shift;
                    for (int k = 0; k < 3; ++k) {
                        const int image =
                            static_cast<int>(std::floor(static_cast<double>(unwrapped[k]) / n));
                        cell[k] = unwrapped[k] - image * n;
                        shift[k] = image * boxLength_;
                    }
                    const int c = (cell[0] * n + cell[1]) * n + cell[2];
                    for (int a = cellStart_[c]; a < cellStart_[c + 1]; ++a) {
                        const int j = cellParticles_[a];
                        const Vector3d d = xw - (positions_[j] + shift);
                        const double centre = d.norm();
                        if (centre - circumradius_ >= bestUpper) continue;
                        candidates.push_back({centre - circumradius_, j, d});
                        bestUpper = std::min(bestUpper, centre - inradius_);
                    }
                }
        // Every image not yet visited has its centre at least s cells away.
        if (s * cellSize_ - circumradius_ >= bestUpper) break;
    }
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& a, const Candidate& b) { return a.lower < b.lower; });
    double best = std::numeric_limits<double>::infinity();
    for (const Candidate& candidate : candidates) {
        if (candidate.lower >= best) break;
        best = std::min(best, distanceToParticle(candidate.particle, candidate.d));
        if (best == 0.0) break;
    }
    return best;
}

ExactPoreSizeDistribution::ExactPoreSizeDistribution(ExactPoreSizeParameters parameters)
    : parameters_(parameters) {
    if (parameters_.randomPoints < 1)
        throw std::invalid_argument("exact pore sizes: the number of random points K = " +
                                    std::to_string(parameters_.randomPoints) + " (need >= 1)");
    if (parameters_.densityBins < 1)
        throw std::invalid_argument("exact pore sizes: densityBins = " +
                                    std::to_string(parameters_.densityBins) + " (need >= 1)");
}

PoreSizeDistributionResult ExactPoreSizeDistribution::compute(const Packing& packing) const {
    const auto started = std::chrono::steady_clock::now();
    const ExactPoreSizes pores(packing);
    const double length = pores.boxLength();
    const std::int64_t k = parameters_.randomPoints;
    const std::int64_t chunks = (k + kRandomPointChunk - 1) / kRandomPointChunk;
    std::vector<std::vector<double>> local(chunks);
    parallelFor(
        0, chunks, 1,
        [&](std::int64_t begin, std::int64_t end) {
            for (std::int64_t c = begin; c < end; ++c) {
                std::mt19937_64 generator = chunkGenerator(parameters_.seed, c);
                const std::int64_t points = std::min(kRandomPointChunk, k - c * kRandomPointChunk);
                std::vector<double>& sizes = local[c];
                sizes.reserve(points);
                std::int64_t draws = 0;
                while (static_cast<std::int64_t>(sizes.size()) < points) {
                    if (++draws > 1000 * points)
                        throw std::domain_error("exact pore sizes: no void found in " +
                                                std::to_string(draws - 1) +
                                                " random points (the particles fill the box)");
                    Vector3d x;
                    for (int a = 0; a < 3; ++a)
                        x[a] = length * uniform01(generator);
                    const double delta = pores.poreSize(x);
                    if (delta > 0.0) sizes.push_back(delta); // 0: inside a particle, draw again
                }
            }
        },
        parameters_.serial);
    std::vector<double> all;
    all.reserve(k);
    for (const auto& sizes : local)
        all.insert(all.end(), sizes.begin(), sizes.end());
    std::sort(all.begin(), all.end());
    std::vector<double> sizes;
    std::vector<std::int64_t> counts;
    for (const double delta : all) {
        if (!sizes.empty() && sizes.back() == delta) {
            ++counts.back();
        } else {
            sizes.push_back(delta);
            counts.push_back(1);
        }
    }
    PoreSizeDistributionResult r =
        poreSizeStatistics(sizes, counts, packing.shape().meanWidth(), parameters_.densityBins);
    r.method = "exact";
    r.parameters.randomPoints = k;
    r.parameters.seed = parameters_.seed;
    r.parameters.serial = parameters_.serial;
    r.runtimeSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return r;
}

} // namespace sbpack
