#include "pores/exact_pore_size.hpp"

#include "parallel/parallel.hpp"
#include "pores/largest_pore.hpp"
#include "pores/random_points.hpp"
#include "random/random.hpp"

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
/// Closed forms for m = 2 (p = 1.5), a quadratic in u, and m = 1/2 (p = 0.75), a quadratic in
/// sqrt(u), each in its cancellation-free form.
double axisRoot(double xi, double kappa, double m) {
    if (m == 2.0) return 2.0 * xi / (1.0 + std::sqrt(1.0 + 4.0 * kappa * xi));
    if (m == 0.5) {
        const double t = 2.0 * xi / (kappa + std::sqrt(kappa * kappa + 4.0 * xi));
        return t * t;
    }
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

/// u^{m-1} for u > 0, by a root at m = 2 and m = 1/2 (as axisRoot).
double powerMinusOne(double u, double m) {
    if (m == 2.0) return u;
    if (m == 0.5) return 1.0 / std::sqrt(u);
    return std::pow(u, m - 1.0);
}

/// y^e for y >= 0: products and roots at e = 2, 3 and 3/2 (p = 1, 1.5, 0.75), else std::pow.
double powerOf(double y, double e) {
    if (e == 2.0) return y * y;
    if (e == 3.0) return y * y * y;
    if (e == 1.5) return y * std::sqrt(y);
    return std::pow(y, e);
}

/// Newton's start for kappa from the radial point u_r = xi / g(xi) on the surface, with
/// s = sum xi_i^e = g^e: the least-squares kappa of u + kappa u^m = xi, i.e. the step from u_r
/// along the surface normal there, which is exact at the axes, on the diagonals and as the
/// point approaches the surface.
double kappaStart(const Vector3d& xi, double e, double s) {
    const double m = e - 1.0;
    const double inverseGauge = e == 3.0 ? 1.0 / std::cbrt(s) : std::pow(s, -1.0 / e);
    double along = 0.0, norm = 0.0;
    for (int i = 0; i < 3; ++i) {
        if (!(xi[i] > 0.0)) continue;
        const double u = xi[i] * inverseGauge;
        const double normal = powerMinusOne(u, m) * u; // u^m
        along += (xi[i] - u) * normal;
        norm += normal * normal;
    }
    return along / norm;
}

/// Projection of xi (>= 0, outside: s = sum xi_i^{2p} > 1) onto { u >= 0, sum u_i^{2p} <= 1 },
/// 0.5 < p: KKT u_i + kappa u_i^{2p-1} = xi_i with sum u_i^{2p} = 1; the sum falls monotonically
/// with kappa, whose root lies in [max(0, max xi - 1), 3 max xi] (the largest u_i is
/// >= 3^{-1/(2p)}). Safeguarded Newton in kappa until the sum is 1 to rounding (then u is the
/// projection onto that surface) or kappa stops moving.
Vector3d projectOntoSuperball(const Vector3d& xi, double p, double s) {
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
            const double power = powerMinusOne(u[i], m);
            const double um = power * u[i];
            c += um * u[i];
            derivative -= e * um * um / (1.0 + kappa * m * power);
        }
        return c;
    };
    double kappa = std::clamp(kappaStart(xi, e, s), lo, hi);
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        double derivative = 0.0;
        const double c = evaluate(kappa, derivative);
        if (std::abs(c) <= 4e-16) break; // on the surface to rounding
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

double gaugePower(const Superball& shape, const Vector3d& xBody) {
    double s = 0.0;
    for (int i = 0; i < 3; ++i)
        s += powerOf(std::abs(xBody[i]) / shape.semiAxis(), 2.0 * shape.p());
    return s;
}

Vector3d closestPoint(const Superball& shape, const Vector3d& xBody) {
    const double r = shape.semiAxis();
    if (shape.isSphere() || shape.isOctahedron()) {
        if (!(shape.gauge(xBody) > 1.0)) return xBody;
        if (shape.isSphere()) return xBody * (r / xBody.norm());
    }
    const Vector3d xi = xBody.cwiseAbs() / r;
    const double s = gaugePower(shape, xBody); // g(x)^{2p}: inside iff <= 1
    if (!shape.isOctahedron() && !(s > 1.0)) return xBody;
    const Vector3d u =
        shape.isOctahedron() ? projectOntoOctahedron(xi) : projectOntoSuperball(xi, shape.p(), s);
    Vector3d y;
    for (int i = 0; i < 3; ++i)
        y[i] = std::copysign(u[i] * r, xBody[i]);
    return y;
}

namespace {

/// The packing's positions after the checks of ExactPoreSizes' constructor.
const std::vector<Vector3d>& checkedPositions(const Packing& packing) {
    if (packing.positions.empty())
        throw std::invalid_argument("exact pore sizes: the packing has no particles");
    if (packing.orientations.size() != packing.positions.size())
        throw std::invalid_argument(
            "exact pore sizes: " + std::to_string(packing.positions.size()) + " positions but " +
            std::to_string(packing.orientations.size()) + " orientations");
    if (!(std::isfinite(packing.boxLength) && packing.boxLength > 0.0))
        throw std::invalid_argument("exact pore sizes: box length is not finite and positive");
    return packing.positions;
}

} // namespace

ExactPoreSizes::ExactPoreSizes(const Packing& packing)
    : shape_(packing.superball()), boxLength_(packing.boxLength),
      circumradius_(shape_.circumradius()), inradius_(shape_.inradius()),
      cells_(checkedPositions(packing), packing.boxLength, shape_.circumradius()) {
    positions_.reserve(packing.size());
    rotations_.reserve(packing.size());
    for (std::size_t j = 0; j < packing.size(); ++j) {
        positions_.push_back(wrapIntoBox(packing.positions[j], boxLength_));
        rotations_.push_back(packing.orientations[j].normalized().toRotationMatrix());
    }
    sizes_ = packing.relativeSizes();
}

SurfaceDistance ExactPoreSizes::particleDistance(int particle, const Vector3d& d) const {
    const double s = relativeSize(particle);
    if (s == 1.0) return unitDistance(particle, d);
    const SurfaceDistance unit = unitDistance(particle, d / s); // distances scale with the size
    return {s * unit.lower, s * unit.upper};
}

SurfaceDistance ExactPoreSizes::unitDistance(int particle, const Vector3d& d) const {
    if (shape_.isSphere()) {
        const double distance = std::max(0.0, d.norm() - shape_.semiAxis());
        return {distance, distance};
    }
    const Vector3d xBody = rotations_[particle].transpose() * d;
    const Vector3d y = closestPoint(shape_, xBody);
    const Vector3d gap = xBody - y;
    const double upper = gap.norm();
    if (upper == 0.0) return {};
    // The certificate of closestPoint: n.x - h(n) <= dist(x, body) <= |x - y|.
    const Vector3d n = gap / upper;
    return {std::clamp(n.dot(xBody) - shape_.support(n), 0.0, upper), upper};
}

std::array<int, 3> ExactPoreSizes::homeCell(const Vector3d& xWrapped) const {
    return cells_.cells().coordinates(cells_.cells().cellContaining(xWrapped));
}

int ExactPoreSizes::particleContaining(const Vector3d& x) const {
    const Vector3d xw = wrapIntoBox(x, boxLength_);
    const std::array<int, 3> home = homeCell(xw);
    const int reach = std::min(1, cells_.cellsPerSide() / 2); // cells >= circumradius
    const double rc2 = circumradius_ * circumradius_;
    int found = -1;
    for (int ox = -reach; ox <= reach && found < 0; ++ox)
        for (int oy = -reach; oy <= reach && found < 0; ++oy)
            for (int oz = -reach; oz <= reach && found < 0; ++oz)
                forEachInCell({home[0] + ox, home[1] + oy, home[2] + oz},
                              [&](int j, const Vector3d&) {
                                  if (found >= 0) return;
                                  const Vector3d d = minimumImage(xw - positions_[j], boxLength_);
                                  if (d.squaredNorm() <= rc2 && inside(j, d)) found = j;
                              });
    return found;
}

SurfaceDistance ExactPoreSizes::poreSizeBounds(const Vector3d& x) const {
    struct Candidate {
        double lower; ///< |d| - s_j circumradius <= distance to this particle image
        int particle;
        Vector3d d; ///< x minus the image's centre
    };
    const Vector3d xw = wrapIntoBox(x, boxLength_);
    const std::array<int, 3> home = homeCell(xw);
    std::vector<Candidate> candidates;
    double bestUpper = std::numeric_limits<double>::infinity(); // min of |d| - inradius
    for (int s = 0;; ++s) {
        // Shell s: the cells (and their periodic images) at Chebyshev offset s from home.
        for (int ox = -s; ox <= s; ++ox)
            for (int oy = -s; oy <= s; ++oy)
                for (int oz = -s; oz <= s; ++oz) {
                    if (std::max({std::abs(ox), std::abs(oy), std::abs(oz)}) != s) continue;
                    forEachInCell({home[0] + ox, home[1] + oy, home[2] + oz},
                                  [&](int j, const Vector3d& shift) {
                                      const Vector3d d = xw - (positions_[j] + shift);
                                      const double centre = d.norm(), s = relativeSize(j);
                                      const double lower = centre - circumradius_ * s;
                                      if (lower >= bestUpper) return;
                                      candidates.push_back({lower, j, d});
                                      bestUpper = std::min(bestUpper, centre - inradius_ * s);
                                  });
                }
        // Every image not yet visited has its centre at least s cells away.
        if (s * cells_.cells().width() - circumradius_ >= bestUpper) break;
    }
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& a, const Candidate& b) { return a.lower < b.lower; });
    SurfaceDistance best{std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::infinity()};
    for (const Candidate& candidate : candidates) {
        if (candidate.lower >= best.upper) break;
        const SurfaceDistance next = particleDistance(candidate.particle, candidate.d);
        best = {std::min(best.lower, next.lower), std::min(best.upper, next.upper)};
        if (best.upper == 0.0) return {};
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

namespace {

/// A chunk of the exact sampler, or chunks joined: the pore sizes, their largest certificate gap,
/// the largest.
struct SampleChunk {
    explicit SampleChunk(double separation) : top(16, 0.0), spread(16, separation) {}
    /// Appends a later chunk: its sizes after these, its largest points offered after these.
    void add(const SampleChunk& later) {
        sizes.insert(sizes.end(), later.sizes.begin(), later.sizes.end());
        errorBound = std::max(errorBound, later.errorBound);
        top.offer(later.top);
        spread.offer(later.spread);
    }
    std::vector<double> sizes;
    double errorBound = 0.0;
    LargestPoints top;    ///< the largest points
    LargestPoints spread; ///< the largest of distinct pores
};

/// The distinct sizes of a sample, ascending, with their counts, and the sums of the sample.
void distinctSizes(std::vector<double> all, std::vector<double>& sizes,
                   std::vector<std::int64_t>& counts, PoreSizeSums& sums) {
    std::sort(all.begin(), all.end());
    for (const double delta : all) {
        sums.add(delta);
        if (!sizes.empty() && sizes.back() == delta) {
            ++counts.back();
        } else {
            sizes.push_back(delta);
            counts.push_back(1);
        }
    }
}

/// The exact pore sizes of chunk c's random points of the void (its own stream of the seed;
/// points inside a particle are drawn again).
SampleChunk sampleChunk(const ExactPoreSizes& pores, const ExactPoreSizeParameters& parameters,
                        double separation, std::int64_t c) {
    const double length = pores.boxLength();
    Random generator = Random::stream(parameters.seed, c);
    const std::int64_t points =
        std::min(kRandomPointChunk, parameters.randomPoints - c * kRandomPointChunk);
    SampleChunk chunk(separation);
    chunk.sizes.reserve(points);
    std::int64_t draws = 0;
    while (static_cast<std::int64_t>(chunk.sizes.size()) < points) {
        if (++draws > 1000 * points)
            throw std::domain_error("exact pore sizes: no void found in " +
                                    std::to_string(draws - 1) +
                                    " random points (the particles fill the box)");
        Vector3d x;
        for (int a = 0; a < 3; ++a)
            x[a] = length * generator.uniform();
        const SurfaceDistance delta = pores.poreSizeBounds(x);
        if (!(delta.upper > 0.0)) continue; // inside a particle: draw again
        chunk.sizes.push_back(delta.upper);
        chunk.errorBound = std::max(chunk.errorBound, delta.upper - delta.lower);
        chunk.top.offer(delta.upper, x);
        chunk.spread.offer(delta.upper, x);
    }
    return chunk;
}

/// The exact pore sizes of K uniformly random points of the void, in fixed chunks joined in
/// order (the result does not depend on the threads).
SampleChunk sampleVoid(const ExactPoreSizes& pores, const ExactPoreSizeParameters& parameters,
                       double separation, const Progress& progress) {
    const std::int64_t chunks =
        (parameters.randomPoints + kRandomPointChunk - 1) / kRandomPointChunk;
    return orderedReduce(
        chunks, SampleChunk(separation),
        [&](std::int64_t c) {
            progress.checkInterrupt();
            return sampleChunk(pores, parameters, separation, c);
        },
        [](SampleChunk& sample, const SampleChunk& later) { sample.add(later); }, progress);
}

} // namespace

PoreSizeDistributionResult ExactPoreSizeDistribution::compute(const Packing& packing,
                                                              const Progress& progress) const {
    const auto started = std::chrono::steady_clock::now();
    const ExactPoreSizes pores(packing);
    const double length = pores.boxLength();
    const std::int64_t k = parameters_.randomPoints;
    // Starts of the largest pore at least 4 point spacings apart (distinct pores).
    const double spacing = length / std::cbrt(static_cast<double>(k));
    SampleChunk sample = sampleVoid(pores, parameters_, 4.0 * spacing, progress);
    std::vector<double> sizes;
    std::vector<std::int64_t> counts;
    PoreSizeSums sums;
    distinctSizes(std::move(sample.sizes), sizes, counts, sums);
    PoreSizeDistributionResult r =
        poreSizeStatistics(sizes, counts, packing.shape().meanWidth(), parameters_.densityBins);
    r.method = "exact";
    r.parameters.randomPoints = k;
    r.parameters.seed = parameters_.seed;
    setStandardErrors(r, sums);
    r.errorBound = sample.errorBound;
    r.maxSampled = r.max;
    // First simplex: half the spacing of K points in the box, a scale the sample cannot resolve.
    r.max = std::max(r.max, largestPore([&pores](const Vector3d& x) { return pores.poreSize(x); },
                                        pores.boxLength(), sample.top, sample.spread, 0.5 * spacing)
                                .size);
    r.saturated = r.max < 0.5 * r.meanWidth; // paper Sec. V A
    r.runtimeSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return r;
}

} // namespace sbpack
