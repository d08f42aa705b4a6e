#pragma once
// The largest pore (paper Sec. V A, the saturation check max delta < w / 2): a local maximum of
// the distance to the nearest particle surface, found by Nelder-Mead from the largest points of
// a sample, so that it does not depend on where the sample happens to fall.

#include "pores/exact_pore_size.hpp"

#include <functional>
#include <span>
#include <vector>

namespace sbpack {

/// Keeps the `capacity` largest (pore size, point) pairs offered, largest first, at most one within
/// `separation` of another (the larger), so that the starts of largestPore lie in distinct pores.
class LargestPoints {
  public:
    LargestPoints(int capacity, double separation) : capacity_(capacity), separation_(separation) {}
    void offer(double size, const Vector3d& point);
    void offer(const LargestPoints& other);
    std::span<const std::pair<double, Vector3d>> points() const { return points_; }

  private:
    int capacity_;
    double separation_;
    std::vector<std::pair<double, Vector3d>> points_;
};

struct LargestPore {
    double size = 0.0; ///< pore size at `position` (ExactPoreSizes::poreSize), length units
    Vector3d position = Vector3d::Zero();
    int evaluations = 0; ///< pore sizes evaluated by the maximisation
};

/// The distance from a point (lab frame, any image) to the nearest particle surface:
/// ExactPoreSizes::poreSize, or an exact equivalent that finds the nearest particle faster.
using PoreSizeFunction = std::function<double(const Vector3d&)>;

/// Maximises poreSize from each start by Nelder-Mead (reflection 1, expansion 2,
/// contraction 1/2, shrink 1/2; first simplex the start and its offsets by `step` along each
/// axis), until the simplex is smaller than 1e-9 step and its values agree to 1e-14 of the pore
/// size, or 400 iterations, restarted from where it stopped (up to 10 times) while that gains.
/// The pore size is continuous and 1-Lipschitz but not smooth at its
/// maxima (points equidistant to several surfaces), where Nelder-Mead needs no derivative.
/// Returns the largest value found, never below the starts' own, its position wrapped into
/// [0, boxLength)^3. Throws std::invalid_argument for no start or a step that is not finite and
/// positive.
LargestPore largestPore(const PoreSizeFunction& poreSize, double boxLength,
                        std::span<const Vector3d> starts, double step);
/// The same from the points of two collections (the largest, and the largest of distinct pores).
LargestPore largestPore(const PoreSizeFunction& poreSize, double boxLength,
                        const LargestPoints& top, const LargestPoints& spread, double step);

} // namespace sbpack
