#include "geometry/superball_family.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sbpack {

std::optional<std::string> SuperballFamily::problem(std::span<const double> values) {
    const double p = values[0];
    if (p >= 0.5 && std::isfinite(p)) return std::nullopt;
    return fmt::format("p = {} (must be finite and >= 0.5)", p);
}

std::optional<std::vector<double>> SuperballFamily::fromSuperquadric(const Superquadric& q) {
    const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::abs(b); };
    if (near(q.axes.x(), 1.0) && near(q.axes.y(), 1.0) && near(q.axes.z(), 1.0) &&
        near(q.northSouth, q.eastWest))
        return std::vector<double>{0.5 * q.eastWest};
    return std::nullopt;
}

} // namespace sbpack
