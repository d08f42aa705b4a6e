#pragma once
// A results group declared once, beside the result it is read from (docs/architecture.md, "Add
// an analysis"): each column is a Field of the schema (schema/results_schema.hpp) and how its
// value is read from the analysis's result struct. The group's field list, the record its stage
// writes and so the HDF5 file, the JSON summary, the MPI gather, the generated docs and Python's
// dicts all come from the one table: a field added to the table is everywhere.
//
//     constexpr schema::FieldTable<FooResult, 2> kFooTable{{{
//         {{"bar", A, F, "length", "the bar"}, schema::member<&FooResult::bar>},
//         {{"bar_w", A, F, "1", "bar / w"}, schema::perWidth<1, &FooResult::bar>},
//     }}};
//     constexpr schema::Group kFooGroup{"foo", "files/<i>/foo", "the foo (foo)",
//     kFooTable.fields()};
//
// A column whose value is absent (a std::optional member that is empty) is not written; the
// record then refuses to be written if the field is not optional (schema/record.hpp).

#include "schema/record.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace sbpack::schema {

/// What a column may scale by: the file's lengths, in the units the analyses computed in.
struct Scales {
    double meanWidth = 1.0; ///< the mean width w of one particle
    /// The length unit of that computation in the packing's units (D: pipeline/stage.hpp):
    /// FieldTable::fill turns each column to the packing's units by unitFactor of its units.
    double lengthUnit = 1.0;
};

template <class R> using Read = std::optional<Value> (*)(const R&, const Scales&);

template <class R> struct Column {
    Field field;
    Read<R> read;
};

namespace detail {

template <class T> struct MemberOf;
template <class C, class T> struct MemberOf<T C::*> { using Class = C; };
template <class C, class T> struct MemberOf<T (C::*)() const> { using Class = C; };
template <class C, class T> struct MemberOf<T (C::*)() const noexcept> { using Class = C; };
template <auto... Path> struct Owner;
template <auto First, auto... Rest> struct Owner<First, Rest...> {
    using type = typename MemberOf<decltype(First)>::Class;
};
/// The struct a chain of member pointers starts from.
template <auto... Path> using OwnerOf = typename Owner<Path...>::type;

template <class T> struct IsOptional : std::false_type {};
template <class T> struct IsOptional<std::optional<T>> : std::true_type {};

/// A result's value, absent where it is an empty std::optional (record.hpp's toValue).
template <class T> std::optional<Value> optionalValue(const T& v) {
    if constexpr (IsOptional<T>::value)
        return v ? optionalValue(*v) : std::nullopt;
    else
        return toValue(v);
}

/// value / w^K for a number or an array (the dimensionless forms); K < 0 multiplies by w^-K.
template <int K> std::optional<Value> divideByWidth(std::optional<Value> v, double w) {
    if (!v) return v;
    double scale = 1.0;
    for (int k = 0; k < (K < 0 ? -K : K); ++k)
        scale *= w;
    const auto apply = [scale](double& x) { x = K < 0 ? x * scale : x / scale; };
    if (double* x = std::get_if<double>(&*v)) apply(*x);
    if (auto* xs = std::get_if<std::vector<double>>(&*v))
        for (double& x : *xs)
            apply(x);
    return v;
}

/// `v` times `factor`, a number or an array; std::logic_error for an integer with a factor
/// other than 1 (an integer column has no units to convert).
inline Value times(Value v, double factor) {
    if (factor == 1.0) return v;
    if (double* x = std::get_if<double>(&v)) {
        *x *= factor;
    } else if (auto* xs = std::get_if<std::vector<double>>(&v)) {
        for (double& x : *xs)
            x *= factor;
    } else {
        throw std::logic_error("results table: a non-float value has units to convert");
    }
    return v;
}

/// The value at the end of `path` from `object`: data members and const accessors alike.
template <class T, auto First, auto... Rest> decltype(auto) follow(const T& object) {
    if constexpr (sizeof...(Rest) == 0)
        return std::invoke(First, object);
    else
        return follow<std::remove_cvref_t<decltype(std::invoke(First, object))>, Rest...>(
            std::invoke(First, object));
}

} // namespace detail

/// The member reached through `Path`: a member pointer or const accessor (e.g.
/// &PoreSizeDistributionResult::meanOverWidth), or a chain of them into nested structs.
template <auto... Path>
std::optional<Value> member(const detail::OwnerOf<Path...>& result, const Scales&) {
    return detail::optionalValue(detail::follow<detail::OwnerOf<Path...>, Path...>(result));
}

/// A number written only where it is finite (NaN: the case that does not fill it).
template <auto... Path>
std::optional<Value> finite(const detail::OwnerOf<Path...>& result, const Scales&) {
    const double v = detail::follow<detail::OwnerOf<Path...>, Path...>(result);
    return std::isfinite(v) ? std::optional<Value>(v) : std::nullopt;
}

/// The value at `Path` inside the std::optional member `Optional`; absent where it is empty.
template <auto Optional, auto... Path>
std::optional<Value> inside(const detail::OwnerOf<Optional>& result, const Scales&) {
    const auto& held = std::invoke(Optional, result);
    if (!held) return std::nullopt;
    using Held = std::remove_cvref_t<decltype(*held)>;
    return detail::optionalValue(detail::follow<Held, Path...>(*held));
}

/// The member at `Path` divided by w^K; K = -1 multiplies by w (Q w).
template <int K, auto... Path>
std::optional<Value> perWidth(const detail::OwnerOf<Path...>& result, const Scales& scales) {
    return detail::divideByWidth<K>(member<Path...>(result, scales), scales.meanWidth);
}

/// A Reduce::Pooled column: never read from one file's result (the analysis's EnsembleFinish
/// sets it on the ensemble, pipeline/analysis_registry.hpp).
template <class R> std::optional<Value> ensembleOnly(const R&, const Scales&) {
    return std::nullopt;
}

/// The columns of one group and the Field list its schema Group spans, built at compile time.
template <class R, std::size_t N> class FieldTable {
  public:
    constexpr explicit FieldTable(const std::array<Column<R>, N>& columns) : columns_(columns) {
        for (std::size_t i = 0; i < N; ++i)
            fields_[i] = columns[i].field;
    }
    /// What the group's schema::Group spans.
    constexpr std::span<const Field> fields() const { return fields_; }

    /// Fills `record` (whose group spans fields()) with every column present in `result`, in
    /// the packing's units: a column's value times unitFactor(its units, scales.lengthUnit).
    void fill(Record& record, const R& result, const Scales& scales) const {
        for (std::size_t i = 0; i < N; ++i)
            if (std::optional<Value> v = columns_[i].read(result, scales)) {
                const double factor = unitFactor(fields_[i].units, scales.lengthUnit);
                record.set(fields_[i], detail::times(std::move(*v), factor));
            }
    }

  private:
    std::array<Column<R>, N> columns_;
    std::array<Field, N> fields_{};
};

/// Tables made of parts (columns several groups share, e.g. shellColumns): the parts in order.
template <class R, std::size_t... N>
constexpr std::array<Column<R>, (N + ...)> joinColumns(const std::array<Column<R>, N>&... parts) {
    std::array<Column<R>, (N + ...)> out{};
    std::size_t i = 0;
    ((std::copy(parts.begin(), parts.end(), out.begin() + static_cast<std::ptrdiff_t>(i)), i += N),
     ...);
    return out;
}

/// What a table's rows use besides the Kind, Type and Reduce names of results_schema.hpp.
namespace columns {
inline constexpr std::string_view kRuntime = "wall-clock time of this analysis";
using schema::finite;
using schema::inside;
using schema::member;
using schema::perWidth;
using schema::Scales;
using schema::Value;
using Optional = std::optional<Value>;
} // namespace columns

} // namespace sbpack::schema
