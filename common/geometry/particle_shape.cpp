#include "geometry/particle_shape.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace sbpack {

namespace {

/// The items' names, for messages: "superball, ball".
template <class Named> std::string namesOf(std::span<const Named> items) {
    std::string names;
    for (const Named& item : items)
        names += (names.empty() ? "" : ", ") + std::string(item.name);
    return names;
}

} // namespace

std::span<const ShapeFamily> shapeFamilies() {
    return ShapeFamilies::info;
}

const ShapeFamily* findShapeFamily(std::string_view name) {
    for (const ShapeFamily& family : ShapeFamilies::info)
        if (family.name == name) return &family;
    return nullptr;
}

const ShapeParameter* findShapeParameter(const ShapeFamily& family, std::string_view name) {
    for (const ShapeParameter& parameter : family.parameters)
        if (parameter.name == name) return &parameter;
    return nullptr;
}

const ShapeFamily* writtenShapeFamily(const std::optional<std::string>& written) {
    return findShapeFamily(written ? std::string_view(*written) : ShapeFamilies::info[0].name);
}

std::string shapeFamilyNames() {
    return namesOf(shapeFamilies());
}

ShapeSpec::ShapeSpec() : family_(0) {
    for (const ShapeParameter& parameter : ShapeFamilies::info[0].parameters)
        values_.push_back(parameter.fallback);
}

ShapeSpec ShapeSpec::fromValues(std::string_view name, std::span<const double> values) {
    const ShapeFamily* family = findShapeFamily(name);
    if (family == nullptr)
        throw std::invalid_argument(
            fmt::format("unknown shape family '{}' (known: {})", name, shapeFamilyNames()));
    if (values.size() != family->parameters.size())
        throw std::invalid_argument(fmt::format(
            "the {} takes {} parameter{} ({}), not {}", name, family->parameters.size(),
            family->parameters.size() == 1 ? "" : "s", namesOf(family->parameters), values.size()));
    return ShapeSpec(static_cast<std::size_t>(family - ShapeFamilies::info.data()),
                     std::vector<double>(values.begin(), values.end()));
}

bool ShapeSpec::isSphere() const {
    return withFamily([&]<class F>(std::type_identity<F>) { return F::isSphere(values_); });
}

std::vector<std::pair<std::string_view, double>> ShapeSpec::namedValues() const {
    std::vector<std::pair<std::string_view, double>> named;
    for (std::size_t k = 0; k < values_.size(); ++k)
        named.emplace_back(info().parameters[k].name, values_[k]);
    return named;
}

std::optional<std::string_view> ShapeSpec::writtenFamily() const {
    if (family_ == 0) return std::nullopt; // the first family is the unnamed one
    return ShapeFamilies::info.at(family_).name;
}

std::vector<ShapeField> shapeFields() {
    std::vector<ShapeField> fields{{.name = kShapeFamilyKey,
                                    .units = "",
                                    .description = "the shape family, whose parameters follow; "
                                                   "absent: superball (written only for another "
                                                   "family)",
                                    .text = true,
                                    .optional = true}};
    const bool several = ShapeFamilies::size > 1;
    const auto listed = [&](std::string_view name) {
        return std::ranges::any_of(fields, [&](const ShapeField& f) { return f.name == name; });
    };
    for (const ShapeFamily& family : ShapeFamilies::info)
        for (const ShapeParameter& parameter : family.parameters)
            if (!listed(parameter.name)) // a name two families share is one field
                fields.push_back({.name = parameter.name,
                                  .units = parameter.units,
                                  .description = parameter.description,
                                  .optional = several});
    return fields;
}

std::optional<std::string> ShapeSpec::problem() const {
    return withFamily([&]<class F>(std::type_identity<F>) { return F::problem(values_); });
}

Superquadric ShapeSpec::superquadric() const {
    return withFamily([&]<class F>(std::type_identity<F>) { return F::superquadric(values_); });
}

ShapeSpec ShapeSpec::fromSuperquadric(const Superquadric& q) {
    std::optional<ShapeSpec> found;
    std::string needs;
    for (std::size_t k = 0; k < ShapeFamilies::size && !found; ++k)
        ShapeFamilies::visit(k, [&]<class F>(std::type_identity<F>) {
            if (std::optional<std::vector<double>> values = F::fromSuperquadric(q))
                found = ShapeSpec(k, std::move(*values));
            needs += "; " + std::string(F::superquadricForm);
        });
    if (found) return *found;
    throw std::invalid_argument(fmt::format(
        "semi-axes in proportion {}:{}:{} with blockiness {} (x, y) and {} (z) are no shape "
        "sbpack knows ({}){}",
        q.axes.x(), q.axes.y(), q.axes.z(), q.eastWest, q.northSouth, shapeFamilyNames(), needs));
}

std::string ShapeSpec::describe() const {
    if (values_.empty()) return std::string(info().name);
    std::string text;
    for (const auto& [name, value] : namedValues())
        text += fmt::format("{}{} = {}", text.empty() ? "" : ", ", name, value);
    return text;
}

ParticleShape::ParticleShape(const ShapeSpec& spec, double semiAxis)
    : body_(ShapeFamilies::visit(spec.familyIndex(), [&]<class F>(std::type_identity<F>) {
          return AnyBody(std::in_place_index<ShapeFamilies::indexOf<F>>,
                         F::body(spec.values(), semiAxis));
      })) {}

const Superball& ParticleShape::superball() const {
    if (const Superball* body = std::get_if<Superball>(&body_)) return *body;
    throw std::invalid_argument(fmt::format(
        "the particles are {}s: this quantity is defined for superballs only", familyName()));
}

} // namespace sbpack
