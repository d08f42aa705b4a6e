#include "geometry/particle_shape.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace sbpack {

namespace {

constexpr ShapeParameter kSuperballParameters[] = {
    {"p", "1",
     "superball exponent (paper Eq. 1), >= 0.5: 1 the sphere, 0.5 the octahedron, "
     "infinity the cube",
     1.0}};
constexpr ShapeFamily kFamilies[] = {{"superball", kSuperballParameters}};

} // namespace

std::span<const ShapeFamily> shapeFamilies() {
    return kFamilies;
}

const ShapeFamily* findShapeFamily(std::string_view name) {
    for (const ShapeFamily& family : kFamilies)
        if (family.name == name) return &family;
    return nullptr;
}

const ShapeParameter* findShapeParameter(const ShapeFamily& family, std::string_view name) {
    for (const ShapeParameter& parameter : family.parameters)
        if (parameter.name == name) return &parameter;
    return nullptr;
}

const ShapeFamily* writtenShapeFamily(const std::optional<std::string>& written) {
    return findShapeFamily(written ? std::string_view(*written) : kFamilies[0].name);
}

std::string shapeFamilyNames() {
    std::string names;
    for (const ShapeFamily& family : kFamilies)
        names += (names.empty() ? "" : ", ") + std::string(family.name);
    return names;
}

ShapeSpec ShapeSpec::fromValues(std::string_view name, std::span<const double> values) {
    if (findShapeFamily(name) == nullptr)
        throw std::invalid_argument(
            fmt::format("unknown shape family '{}' (known: {})", name, shapeFamilyNames()));
    if (values.size() != std::size(kSuperballParameters))
        throw std::invalid_argument(
            fmt::format("the superball takes 1 parameter (p), not {}", values.size()));
    return superball(values[0]);
}

const ShapeFamily& ShapeSpec::info() const {
    return kFamilies[static_cast<int>(family)];
}

std::vector<double> ShapeSpec::values() const {
    return {p};
}

std::vector<std::pair<std::string_view, double>> ShapeSpec::namedValues() const {
    std::vector<std::pair<std::string_view, double>> named;
    const std::vector<double> all = values();
    for (std::size_t k = 0; k < all.size(); ++k)
        named.emplace_back(info().parameters[k].name, all[k]);
    return named;
}

std::optional<std::string_view> ShapeSpec::writtenFamily() const {
    if (family == Family::superball) return std::nullopt;
    return info().name;
}

std::vector<ShapeField> shapeFields() {
    std::vector<ShapeField> fields{{.name = kShapeFamilyKey,
                                    .units = "",
                                    .description = "the shape family, whose parameters follow; "
                                                   "absent: superball (written only for another "
                                                   "family)",
                                    .text = true,
                                    .optional = true}};
    const bool several = std::size(kFamilies) > 1;
    for (const ShapeFamily& family : kFamilies)
        for (const ShapeParameter& parameter : family.parameters)
            fields.push_back({.name = parameter.name,
                              .units = parameter.units,
                              .description = parameter.description,
                              .optional = several});
    return fields;
}

std::optional<std::string> ShapeSpec::problem() const {
    if (p >= 0.5 && std::isfinite(p)) return std::nullopt;
    return fmt::format("p = {} (must be finite and >= 0.5)", p);
}

Superquadric ShapeSpec::superquadric() const {
    return {Vector3d::Ones(), 2.0 * p, 2.0 * p}; // paper Eq. 1: |x|^2p + |y|^2p + |z|^2p <= 1
}

ShapeSpec ShapeSpec::fromSuperquadric(const Superquadric& q) {
    const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::abs(b); };
    if (near(q.axes.x(), 1.0) && near(q.axes.y(), 1.0) && near(q.axes.z(), 1.0) &&
        near(q.northSouth, q.eastWest))
        return superball(0.5 * q.eastWest);
    throw std::invalid_argument(fmt::format(
        "semi-axes in proportion {}:{}:{} with blockiness {} (x, y) and {} (z) are no shape "
        "sbpack knows ({}); a superball has three equal semi-axes and one blockiness 2p",
        q.axes.x(), q.axes.y(), q.axes.z(), q.eastWest, q.northSouth, shapeFamilyNames()));
}

std::string ShapeSpec::describe() const {
    return fmt::format("p = {}", p);
}

ParticleShape::ParticleShape(const ShapeSpec& spec, double semiAxis)
    : superball_(spec.p, semiAxis) {}

} // namespace sbpack
