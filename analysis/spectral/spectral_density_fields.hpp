#pragma once
// The results group of chi, declared once (schema/field_table.hpp, docs/results-schema.md): the
// spectral density, where its FFT plan came from and how its grid was shared out.

#include "parallel/distribution_figures.hpp"
#include "schema/field_table.hpp"
#include "shells/shell_columns.hpp"
#include "spectral/spectral_density.hpp"

#include <optional>
#include <string>

namespace sbpack {

/// What the chi group records: the spectral density, the transform's precision and the figures
/// of a distributed grid.
struct SpectralDensityFigures {
    SpectralDensityResult chi;
    std::string precision; ///< "double" or "single" (--fft-precision)
    std::optional<DistributionFigures> distribution;
};

namespace spectral_density_fields {
using namespace schema::columns;
using R = SpectralDensityFigures;
using C = SpectralDensityResult;

/// The fields of the exact sphere path (present for spheres).
inline constexpr std::array<schema::Column<R>, 2> kExactSphere{{
    {{"exact_s", A, F, "s", "spheres only: the exact path", No, true},
     +[](const R& r, const Scales&) -> Optional {
         return r.chi.exactSphere ? Optional(r.chi.exactSeconds) : std::nullopt;
     }},
    {{"exact_error", A, F, "1",
      "spheres only: max over shells of |chi - chi_exact| over the peak of chi_exact", Mean, true},
     +[](const R& r, const Scales&) -> Optional {
         return r.chi.exactSphere ? Optional(r.chi.exactSphere->maxErrorOverPeak) : std::nullopt;
     }},
}};

inline constexpr schema::FieldTable kTable{schema::joinColumns(
    std::array<schema::Column<R>, 12>{{
        {{"voxels", A, I, "1", "M of the M^3 grid (--voxels)"}, member<&R::chi, &C::voxels>},
        {{"phi_voxel", A, F, "1", "fraction of solid voxels", Mean}, member<&R::chi, &C::phiVoxel>},
        {{"voxel_size", A, F, "length", "a = L / M"}, member<&R::chi, &C::voxelSize>},
        {{"qmax", A, F, "1", "shells up to Q w <= qmax (--qmax) and |n| < M / 2"},
         member<&R::chi, &C::parameters, &SpectralDensityParameters::maxQw>},
        {{"max_shell", A, I, "1", "number of shells"}, member<&R::chi, &C::maxShell>},
        {{"fft_planning", A, S, "", "FFTW planning effort (--fft-plan)"},
         +[](const R& r, const Scales&) -> Optional {
             return Value(std::string(fftPlanningName(r.chi.parameters.fft.planning)));
         }},
        {{"fft_plan_s", A, F, "s", "FFTW planning time (also on the \"FFT plan\" progress line)"},
         member<&R::chi, &C::planSeconds>},
        {{"fft_plan_source", A, S, "",
          "where the plan came from: \"estimate\", \"wisdom\", \"estimate (measuring predicted "
          "over the budget)\", \"measured\" or \"measured within the budget\""},
         +[](const R& r, const Scales&) -> Optional {
             return Value(std::string(fftPlanSourceName(r.chi.planSource)));
         }},
        {{"fft_planning_budget_s", A, F, "s",
          "--fft-planning-budget: without wisdom, measuring predicted to take longer falls back "
          "on estimate (inf: no limit)"},
         member<&R::chi, &C::parameters, &SpectralDensityParameters::fft,
                &FftSettings::planningBudget>},
        {{"fft_s", A, F, "s", "filling the grid and the FFT"},
         +[](const R& r, const Scales&) -> Optional {
             return Value(r.chi.fillSeconds + r.chi.transformSeconds);
         }},
        {{"fft_precision", A, S, "",
          "\"double\" (FFTW, or cuFFT), or \"single\" (cuFFT, --fft-precision single)"},
         member<&R::precision>},
        {{"shell_average_s", A, F, "s", "shell averaging"}, member<&R::chi, &C::shellSeconds>},
    }},
    distributionColumns<&R::distribution>(), kExactSphere,
    std::array<schema::Column<R>, 1>{{
        {{"runtime_s", A, F, "s", kRuntime}, member<&R::chi, &C::runtimeSeconds>},
    }},
    shellColumns<&R::chi, &C::shells>(
        {"chi", D, F, "length^3",
         "chi_V(Q) = |F(Q)|^2 [prod_i a sinc(Q_i a / 2)]^2 / V from the voxels (Eq. 12)", Curve}),
    std::array<schema::Column<R>, 1>{{
        {{"chi_exact", D, F, "length^3", "spheres only: chi_V(Q) without voxels", No, true},
         +[](const R& r, const Scales&) -> Optional {
             return r.chi.exactSphere ? Optional(r.chi.exactSphere->exact.value) : std::nullopt;
         }},
    }})};
} // namespace spectral_density_fields

inline constexpr schema::Group kSpectralDensityGroup{
    "spectral_density", "files/<i>/spectral_density", "chi_V(Q) from the voxels (chi)",
    spectral_density_fields::kTable.fields()};

} // namespace sbpack
