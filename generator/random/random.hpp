#pragma once
// Portable random numbers for sbgen: the same seed gives the same packing with any C++ library
// (std::*_distribution are implementation-defined, so only the engine is taken from <random>).

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
