// Cost of the pair functions (common/pair/pair_geometry.hpp) on near-contact pairs:
// ns per call, Newton iterations per call and cutting-plane fallbacks per call (for
// signedDistance, those of mu and of s together, so up to 2), from a cold start and from a
// generator-like warm start (the normal of mu before d moved by a relative 1e-9).
// Results and the command that produced them: bench/RESULTS.md.

#include "pair/pair_geometry.hpp"

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using sbpack::Matrix3d;
using sbpack::Superball;
using sbpack::SuperballPair;
using sbpack::Vector3d;

/// Parameters of the pair pool, in one place.
struct PoolParameters {
    std::size_t size = 1024;
    double semiAxis = 0.5;
    /// |d| = contact distance along d times U(minGap, maxGap): near contact, both sides.
    double minGap = 0.98;
    double maxGap = 1.05;
    /// Relative displacement change between the warm-start call and the timed one.
    double perturbation = 1e-9;
    std::uint64_t seed = 20240611;
};

/// One pool entry: the timed pair (d already perturbed) and the normal a previous call
/// on the unperturbed pair returned.
struct PoolEntry {
    SuperballPair pair;
    Vector3d warmNormal;
};

Vector3d gaussianDirection(std::mt19937_64& rng) {
    std::normal_distribution<double> gauss;
    return Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
}

/// Uniform random rotation from a normalised Gaussian quaternion.
Matrix3d randomRotation(std::mt19937_64& rng) {
    std::normal_distribution<double> gauss;
    Eigen::Quaterniond q(gauss(rng), gauss(rng), gauss(rng), gauss(rng));
    return q.normalized().toRotationMatrix();
}

std::vector<PoolEntry> makePool(double p, const PoolParameters& parameters) {
    std::mt19937_64 rng(parameters.seed);
    std::uniform_real_distribution<double> gap(parameters.minGap, parameters.maxGap);
    const Superball shape(p, parameters.semiAxis);
    std::vector<PoolEntry> pool;
    pool.reserve(parameters.size);
    for (std::size_t i = 0; i < parameters.size; ++i) {
        const Matrix3d rotationA = randomRotation(rng);
        const Matrix3d rotationB = randomRotation(rng);
        const Vector3d u = gaussianDirection(rng);
        // mu is homogeneous of degree one in d, so the contact distance along u is 1/mu(u).
        const double contact =
            1.0 / sbpack::scaleFactor(SuperballPair{shape, rotationA, rotationB, u}).scaleFactor;
        SuperballPair pair{shape, rotationA, rotationB, contact * gap(rng) * u};
        const Vector3d warmNormal = sbpack::scaleFactor(pair).normal;
        pair.displacement +=
            parameters.perturbation * pair.displacement.norm() * gaussianDirection(rng);
        pool.push_back({pair, warmNormal});
    }
    return pool;
}

/// Pools are built once per p, outside the timed loops.
const std::vector<PoolEntry>& poolFor(double p) {
    static std::map<double, std::vector<PoolEntry>> pools;
    auto it = pools.find(p);
    if (it == pools.end()) it = pools.emplace(p, makePool(p, PoolParameters{})).first;
    return it->second;
}

enum class Start { cold, warm };

/// Times `solve(pair, warmNormal)` over whole passes of the pool, so that every figure is an
/// exact pool average: seconds per call (s_per_call, shown with an SI prefix),
/// Newton iterations per call and cutting-plane fallbacks per call.
template <class Solve> void benchPair(benchmark::State& state, double p, Start start, Solve solve) {
    const std::vector<PoolEntry>& pool = poolFor(p);
    const Vector3d zero = Vector3d::Zero();
    std::int64_t iterations = 0, fallbacks = 0;
    for (auto _ : state) {
        for (const PoolEntry& entry : pool) {
            const auto result = solve(entry.pair, start == Start::warm ? entry.warmNormal : zero);
            benchmark::DoNotOptimize(result);
            iterations += result.iterations;
            fallbacks += result.fallbacks;
        }
    }
    const double calls = static_cast<double>(state.iterations()) * static_cast<double>(pool.size());
    state.counters["s_per_call"] = benchmark::Counter(
        static_cast<double>(pool.size()),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["newton_per_call"] = static_cast<double>(iterations) / calls;
    state.counters["fallbacks_per_call"] = static_cast<double>(fallbacks) / calls;
}

std::string label(const char* function, double p, Start start) {
    std::ostringstream name;
    name << function << "/p=" << p << (start == Start::cold ? "/cold" : "/warm");
    return name.str();
}

void registerAll() {
    const double exponents[] = {0.6, 1.0, 1.5, 3.0, 10.0};
    for (double p : exponents) {
        for (Start start : {Start::cold, Start::warm}) {
            benchmark::RegisterBenchmark(
                label("scaleFactor", p, start).c_str(), [p, start](benchmark::State& state) {
                    benchPair(state, p, start, [](const SuperballPair& pair, const Vector3d& n) {
                        return sbpack::scaleFactor(pair, n);
                    });
                });
            benchmark::RegisterBenchmark(
                label("signedDistance", p, start).c_str(), [p, start](benchmark::State& state) {
                    benchPair(state, p, start, [](const SuperballPair& pair, const Vector3d& n) {
                        return sbpack::signedDistance(pair, n);
                    });
                });
        }
    }
}

} // namespace

int main(int argc, char** argv) {
    registerAll();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
