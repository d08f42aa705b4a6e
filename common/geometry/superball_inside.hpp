#pragma once
// The superball's inside test for many points (the voxelization's inner loop, analysis/voxels):
// the answer of Superball::contains, mostly without std::pow. Read through
// ParticleShape::insideTest.

#include "geometry/superball.hpp"

#include <cmath>

namespace sbpack {

/// Superball::contains for body-frame points, mostly without std::pow. With y = |x| / R and the
/// integers lo = floor(2p) <= 2p <= hi = ceil(2p), sum y_i^hi <= sum y_i^2p <= sum y_i^lo while
/// every y_i < 1 (norms decrease with the exponent), so integer powers decide most points; then
/// single-precision powers, accurate to ~1e-6; only points closer than that to the surface
/// take the exact test. Margins keep every shortcut's answer that of Superball::contains.
class SuperballInsideTest {
  public:
    explicit SuperballInsideTest(const Superball& shape)
        : shape_(shape), inverseRadius_(1.0 / shape.semiAxis()),
          lo_(static_cast<int>(std::floor(2.0 * shape.p()))),
          hi_(static_cast<int>(std::ceil(2.0 * shape.p()))),
          exponent_(static_cast<float>(2.0 * shape.p())) {}

    bool operator()(const Vector3d& x) const {
        const Vector3d y = x.cwiseAbs() * inverseRadius_;
        const double largest = y.maxCoeff();
        if (largest > 1.0 + kExactMargin) return false; // one term alone exceeds 1
        if (largest < 1.0 - kExactMargin) {
            if (powerSum(y, lo_) < 1.0 - kExactMargin) return true;
            if (powerSum(y, hi_) > 1.0 + kExactMargin) return false;
            if (lo_ != hi_) {
                float sum = 0.0f;
                for (int i = 0; i < 3; ++i)
                    sum += std::exp(exponent_ * std::log(static_cast<float>(y[i])));
                if (sum < 1.0f - kFloatMargin) return true;
                if (sum > 1.0f + kFloatMargin) return false;
            }
        }
        return shape_.contains(x);
    }

  private:
    static constexpr double kExactMargin = 1e-12;
    static constexpr float kFloatMargin = 1e-5f;

    /// sum of y_i^n by repeated squaring (n >= 1).
    static double powerSum(const Vector3d& y, int n) {
        double sum = 0.0;
        for (int i = 0; i < 3; ++i) {
            double power = 1.0, base = y[i];
            for (int e = n; e > 0; e >>= 1, base *= base)
                if (e & 1) power *= base;
            sum += power;
        }
        return sum;
    }

    Superball shape_;
    double inverseRadius_;
    int lo_, hi_;
    float exponent_;
};

} // namespace sbpack
