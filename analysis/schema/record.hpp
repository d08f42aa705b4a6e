#pragma once
// One group's values, filled by name against the results schema (schema/results_schema.hpp):
// a name the schema does not declare for the group, or a value of the wrong kind or type, is a
// std::logic_error, and so is reading the entries of a record that lacks a required field
// (Field::optional false), so the writers can trust every record they are given.

#include "schema/results_schema.hpp"

#include <concepts>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace sbpack::schema {

using Value =
    std::variant<double, std::int64_t, std::string, std::vector<double>, std::vector<std::int64_t>>;

namespace detail {

/// A number, text or array as a Value: integers (bool included) as Int, whatever their width;
/// Record::set converts an Int to a Float field's double.
template <class T> Value toValue(const T& v) {
    if constexpr (std::is_same_v<T, bool> || std::is_integral_v<T>) {
        return Value(static_cast<std::int64_t>(v));
    } else if constexpr (std::is_floating_point_v<T>) {
        return Value(static_cast<double>(v));
    } else if constexpr (std::is_convertible_v<T, std::string_view>) {
        return Value(std::string(std::string_view(v)));
    } else if constexpr (std::is_same_v<T, std::vector<double>>) {
        return Value(v);
    } else { // a std::vector of integers
        static_assert(std::is_integral_v<typename T::value_type>, "no Value holds this type");
        return Value(std::vector<std::int64_t>(v.begin(), v.end()));
    }
}

} // namespace detail

struct Entry {
    const Field* field;
    Value value;
};

class Record {
  public:
    explicit Record(const Group& group) : group_(&group) {}

    const Group& group() const { return *group_; }
    /// Entries in the schema's order: what every writer (the HDF5 file, the JSON summary, the
    /// MPI gather, Python) reads. std::logic_error naming the group and each required field
    /// (Field::optional false) that was not set: a stage must fill what the schema requires.
    const std::vector<Entry>& entries() const;

    /// Sets field `name` (replacing an earlier value); numbers are stored as the schema's type
    /// (an Int field takes integers and bools only).
    template <class T> Record& set(std::string_view name, const T& value) {
        return set(field(name), detail::toValue(value));
    }

    /// Sets `field`, one of the group's own Fields (a FieldTable's column: schema/field_table.hpp);
    /// an Int value for a Float field is converted.
    Record& set(const Field& field, Value value);

    bool has(std::string_view name) const { return find(name) != nullptr; }
    /// The value of `name`; nullptr if it was not set.
    const Value* find(std::string_view name) const;
    /// Typed reads; std::logic_error if `name` is unset or of another type.
    double number(std::string_view name) const;
    std::int64_t integer(std::string_view name) const;
    const std::string& text(std::string_view name) const;
    const std::vector<double>& floats(std::string_view name) const;
    const std::vector<std::int64_t>& integers(std::string_view name) const;

  private:
    const Field& field(std::string_view name) const;
    Record& store(const Field& field, Value value);
    template <class T> const T& get(std::string_view name) const;

    const Group* group_;
    std::vector<Entry> entries_;
};

} // namespace sbpack::schema
