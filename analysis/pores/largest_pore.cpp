#include "pores/largest_pore.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace sbpack {

void LargestPoints::offer(double size, const Vector3d& point) {
    if (static_cast<int>(points_.size()) == capacity_ && !(size > points_.back().first)) return;
    const double near = separation_ * separation_;
    const auto close = std::find_if(points_.begin(), points_.end(), [&](const auto& p) {
        return (p.second - point).squaredNorm() < near;
    });
    if (close != points_.end()) {
        if (!(size > close->first)) return; // a larger point of the same pore is kept
        points_.erase(close);
    }
    const auto at = std::find_if(points_.begin(), points_.end(),
                                 [size](const auto& p) { return size > p.first; });
    points_.insert(at, {size, point});
    if (static_cast<int>(points_.size()) > capacity_) points_.pop_back();
}

void LargestPoints::offer(const LargestPoints& other) {
    for (const auto& [size, point] : other.points_)
        offer(size, point);
}

namespace {

constexpr int kMaxIterations = 400;
constexpr int kRestarts = 10;

/// One Nelder-Mead run maximising f from `start`.
template <class Function>
LargestPore nelderMead(const Function& f, const Vector3d& start, double step) {
    std::array<Vector3d, 4> x{start, start, start, start};
    std::array<double, 4> v{};
    for (int k = 0; k < 3; ++k)
        x[k + 1][k] += step;
    LargestPore best;
    auto evaluate = [&](const Vector3d& point) {
        ++best.evaluations;
        return f(point);
    };
    for (int k = 0; k < 4; ++k)
        v[k] = evaluate(x[k]);
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        std::array<int, 4> order{0, 1, 2, 3}; // largest value first
        std::sort(order.begin(), order.end(), [&](int a, int b) { return v[a] > v[b]; });
        const int hi = order[0], worst = order[3];
        double size = 0.0;
        for (int k = 1; k < 4; ++k)
            size = std::max(size, (x[k] - x[0]).cwiseAbs().maxCoeff());
        if (size < 1e-9 * step && v[hi] - v[worst] <= 1e-14 * std::max(v[hi], 1e-300)) break;
        Vector3d centroid = Vector3d::Zero();
        for (int k = 0; k < 3; ++k)
            centroid += x[order[k]] / 3.0;
        const Vector3d reflected = centroid + (centroid - x[worst]);
        const double vr = evaluate(reflected);
        if (vr > v[hi]) {
            const Vector3d expanded = centroid + 2.0 * (centroid - x[worst]);
            const double ve = evaluate(expanded);
            x[worst] = ve > vr ? expanded : reflected;
            v[worst] = std::max(ve, vr);
        } else if (vr > v[order[2]]) {
            x[worst] = reflected, v[worst] = vr;
        } else {
            const Vector3d contracted = centroid + 0.5 * (x[worst] - centroid);
            const double vc = evaluate(contracted);
            if (vc > v[worst]) {
                x[worst] = contracted, v[worst] = vc;
            } else { // shrink towards the best vertex
                for (int k = 0; k < 4; ++k)
                    if (k != hi) x[k] = x[hi] + 0.5 * (x[k] - x[hi]), v[k] = evaluate(x[k]);
            }
        }
    }
    const int top = static_cast<int>(std::max_element(v.begin(), v.end()) - v.begin());
    best.size = v[top];
    best.position = x[top];
    return best;
}

} // namespace

LargestPore largestPore(const PoreSizeFunction& poreSize, double boxLength,
                        std::span<const Vector3d> starts, double step) {
    if (starts.empty()) throw std::invalid_argument("largest pore: no start point");
    if (!(std::isfinite(step) && step > 0.0))
        throw std::invalid_argument("largest pore: the step is not finite and positive");
    LargestPore best;
    int evaluations = 0;
    for (const Vector3d& start : starts) {
        // Nelder-Mead can stall on a ridge of a non-smooth function: restart it from where it
        // stopped, with a fresh simplex, while that still gains.
        LargestPore local = nelderMead(poreSize, start, step);
        evaluations += local.evaluations;
        for (int restart = 0; restart < kRestarts; ++restart) {
            const LargestPore again = nelderMead(poreSize, local.position, step);
            evaluations += again.evaluations;
            const bool gained = again.size > local.size * (1.0 + 1e-13);
            if (again.size > local.size) local = again;
            if (!gained) break;
        }
        if (local.size > best.size) best = local;
    }
    best.evaluations = evaluations;
    best.position = wrapIntoBox(best.position, boxLength);
    return best;
}

LargestPore largestPore(const PoreSizeFunction& poreSize, double boxLength,
                        const LargestPoints& top, const LargestPoints& spread, double step) {
    std::vector<Vector3d> starts;
    for (const LargestPoints* points : {&top, &spread})
        for (const auto& [size, point] : points->points())
            starts.push_back(point);
    return largestPore(poreSize, boxLength, starts, step);
}

} // namespace sbpack
