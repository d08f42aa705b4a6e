#pragma once
// The one front end of random numbers (docs/design.md §7): portable, so that the same seed gives
// the same packing (sbgen) and the same random samples and bootstrap replicas (sbanalyze) with
// any C++ library (std::*_distribution are implementation-defined, so only the engine is taken
// from <random>). Independent streams (chunks of a sample drawn on any number of threads, the
// replicas of a bootstrap) come from stream(seed, index).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace sbpack {

class Random {
  public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}

    /// Stream `index` of the streams of `seed`: the engine seeded with splitmix64 of both.
    static Random stream(std::uint64_t seed, std::int64_t index) {
        std::uint64_t z = seed + 0x9e3779b97f4a7c15ull * (static_cast<std::uint64_t>(index) + 1);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return Random(z ^ (z >> 31));
    }

    /// Uniform in [0, 1) with 53 random bits.
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

    /// Standard normal by the Box-Muller transform.
    double normal() {
        const double u = 1.0 - uniform(); // (0, 1]
        const double v = uniform();
        return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
    }

    Eigen::Vector3d normalVector() { return {normal(), normal(), normal()}; }

    /// Uniformly random rotation (Shoemake's method).
    Eigen::Quaterniond rotation() {
        const double u1 = uniform(), u2 = 2.0 * std::numbers::pi * uniform(),
                     u3 = 2.0 * std::numbers::pi * uniform();
        const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
        return Eigen::Quaterniond(a * std::sin(u2), a * std::cos(u2), b * std::sin(u3),
                                  b * std::cos(u3));
    }

  private:
    std::mt19937_64 engine_;
};

} // namespace sbpack
