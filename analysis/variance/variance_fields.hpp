#pragma once
// The results group of variance, declared once (schema/field_table.hpp, docs/results-schema.md):
// the local volume-fraction variance of variance/volume_fraction_variance.hpp by both routes
// (docs/local-structure.md §2).

#include "schema/field_table.hpp"
#include "variance/volume_fraction_variance.hpp"

#include <algorithm>
#include <cmath>

namespace sbpack {

namespace variance_fields {
using namespace schema::columns;
using R = VarianceResult;
using E = VarianceExponent;

/// A radius of the tail fit over w; absent without a fit.
template <auto Member> Optional perWidthInside(const R& r, const Scales& s) {
    return r.exponent ? Optional(Value((*r.exponent).*Member / s.meanWidth)) : std::nullopt;
}

/// A dataset of the sampled route; absent without windows.
template <auto Member> Optional sampledOrNone(const R& r, const Scales&) {
    return r.sampled.empty() ? std::nullopt : Optional(Value(r.*Member));
}

/// The largest |sampled - spectral| over sqrt(error^2 + truncation^2) across the radii.
inline Optional routeDeviation(const R& r, const Scales&) {
    if (r.sampled.empty()) return std::nullopt;
    double worst = 0.0;
    for (std::size_t i = 0; i < r.radius.size(); ++i)
        worst = std::max(worst, std::abs(r.sampled[i] - r.spectral[i]) /
                                    std::hypot(r.sampledError[i], r.truncation[i]));
    return Value(worst);
}

inline constexpr schema::FieldTable kTable{std::array<schema::Column<R>, 19>{{
    {{"alpha", A, F, "1",
      "alpha from the tail sigma_V^2 = A R^-(3 + alpha) + B R^-4 of the spectral route over "
      "fit_min_w <= R / w <= fit_max_w; absent with fewer than 4 radii there",
      Mean, true},
     schema::inside<&R::exponent, &E::alpha>},
    {{"alpha_error", A, F, "1", "half the fit's profile interval of alpha", Mean, true},
     schema::inside<&R::exponent, &E::standardError>},
    {{"alpha_saturated", A, I, "1",
      "1 if the fit sits at the top of its range (alpha >= 1: the windows' surface term leads)", No,
      true},
     schema::inside<&R::exponent, &E::saturated>},
    {{"alpha_pooled",
      A,
      F,
      "1",
      "ensembles only: alpha of the tail fit to the members' mean sigma2_spectral over the "
      "radii they share (R / w from 2 to the smallest L / 4 w); absent below 4 such radii",
      Pooled,
      true,
      {},
      0,
      true},
     schema::ensembleOnly<R>},
    {{"alpha_pooled_error",
      A,
      F,
      "1",
      "ensembles only: its alpha_error",
      Pooled,
      true,
      {},
      0,
      true},
     schema::ensembleOnly<R>},
    {{"alpha_pooled_saturated",
      A,
      I,
      "1",
      "ensembles only: its alpha_saturated",
      Pooled,
      true,
      {},
      0,
      true},
     schema::ensembleOnly<R>},
    {{"fit_min_w", A, F, "1", "smallest R / w of the tail fit", No, true},
     perWidthInside<&E::minRadius>},
    {{"fit_max_w", A, F, "1", "largest R / w of the tail fit (<= L / 4)", No, true},
     perWidthInside<&E::maxRadius>},
    {{"route_deviation_max", A, F, "1",
      "largest |sampled - spectral| / sqrt(sampled error^2 + truncation^2) over the radii", Mean,
      true},
     routeDeviation},
    {{"windows", A, I, "1", "random windows per radius of the sampled route (--variance-windows)"},
     member<&R::windows>},
    {{"spectrum", A, S, "", "the spectral route's chi_V: \"voxel\" or \"exact+voxel\" (as hyper)"},
     member<&R::spectrumSource>},
    {{"runtime_s", A, F, "s", kRuntime}, member<&R::runtimeSeconds>},
    {{"radius", D, F, "length", "window radii R"}, member<&R::radius>},
    {{"radius_w", D, F, "1", "R / w"}, schema::perWidth<1, &R::radius>},
    {{"sigma2_spectral", D, F, "1",
      "sigma_V^2(R) = (1 / V) sum_{Q != 0} chi_V(Q) F(Q R)^2 (docs/local-structure.md §2)"},
     member<&R::spectral>},
    {{"sigma2_truncation", D, F, "1",
      "bound on what the wave vectors beyond the grid add to sigma2_spectral"},
     member<&R::truncation>},
    {{"sigma2_sampled", D, F, "1",
      "sigma_V^2(R) of random windows on the voxel grid, about phi_voxel", No, true},
     sampledOrNone<&R::sampled>},
    {{"sigma2_sampled_error", D, F, "1", "its standard error by batch means", No, true},
     sampledOrNone<&R::sampledError>},
    {{"phi", A, F, "1", "the phi the spectral route's chi_V is normalised by"}, member<&R::phi>},
}}};
} // namespace variance_fields

inline constexpr schema::Group kVarianceGroup{
    "variance", "files/<i>/variance",
    "local volume-fraction variance sigma_V^2(R) by sampled windows and by chi_V, and alpha "
    "from its tail (variance; docs/local-structure.md)",
    variance_fields::kTable.fields()};

} // namespace sbpack
