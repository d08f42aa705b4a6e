#pragma once
// The three results groups of hyper, declared once (schema/field_table.hpp,
// docs/results-schema.md): the excess spreadability and alpha, the small-Q fit and H, and the
// Debye medium on the same time axis.

#include "hyperuniformity/hyperuniformity.hpp"
#include "schema/field_table.hpp"

#include <string>

namespace sbpack {

/// What the hyper groups record: the analysis and the spectrum it ran on.
struct HyperuniformityFigures {
    HyperuniformityResult h;
    std::string source;      ///< DiscreteSpectrum::source
    double phi = 0.0;        ///< DiscreteSpectrum::phi, which normalises E
    double chiExactQw = 0.0; ///< --chi-exact-qmax
    double fitSeconds = 0.0; ///< the exact chi_V, the fits and the bootstrap
};

namespace hyperuniformity_fields {
using namespace schema::columns;
using R = HyperuniformityFigures;
using H = HyperuniformityResult;

inline constexpr schema::FieldTable kSpreadability{std::array<schema::Column<R>, 21>{{
    {{"source", A, S, "",
      "chi_V used: \"voxel\" (the --voxels grid) or \"exact+voxel\" (exact at Q w <= "
      "chi_exact_qmax, voxels beyond)"},
     member<&R::source>},
    {{"chi_exact_qmax", A, F, "1", "exact chi_V up to Q w <= this (--chi-exact-qmax; 0: none)"},
     member<&R::chiExactQw>},
    {{"phi", A, F, "1", "the phi that normalises E: phi_voxel (voxel) or N v1 / V (exact+voxel)"},
     member<&R::phi>},
    {{"alpha", A, F, "1",
      "the local alpha -3 - 2 d ln E / d ln t in the window, extrapolated linearly in 1/t to "
      "t -> infinity (Eq. PLF; docs/hyperuniformity.md, \"alpha\")",
      Mean},
     member<&R::h, &H::alpha, &ExponentEstimate::alpha>},
    {{"alpha_slope", A, F, "w^2/D_diff",
      "c of the line alpha + c / t through the local alpha in the window (alpha its limit)", Mean},
     member<&R::h, &H::alpha, &ExponentEstimate::slope>},
    {{"alpha_stderr", A, F, "1",
      "standard deviation of alpha over the Poisson bootstrap replicas; alpha +- 2 alpha_stderr "
      "covered the truth in 20 of 20 fixtures of each known exponent"},
     member<&R::h, &H::alpha, &ExponentEstimate::standardError>},
    {{"bootstrap_replicas", A, I, "1", "bootstrap replicas over the wave vectors"},
     member<&R::h, &H::alpha, &ExponentEstimate::replicas>},
    {{"alpha_end_low", A, F, "1",
      "least alpha over the windows ending at t_fit_max / 2, t_fit_max, 2 t_fit_max"},
     member<&R::h, &H::alpha, &ExponentEstimate::endLow>},
    {{"alpha_end_high", A, F, "1", "largest alpha over those windows"},
     member<&R::h, &H::alpha, &ExponentEstimate::endHigh>},
    {{"alpha_window_mean", A, F, "1",
      "-3 - 2 ln(E(t_fit_max) / E(t_fit_min)) / ln(t_fit_max / t_fit_min): the window's mean "
      "local alpha (the paper's estimate; biased by the finite times; docs/hyperuniformity.md, "
      "\"alpha from the long-time decay\")",
      Mean},
     member<&R::h, &H::alpha, &ExponentEstimate::windowMean>},
    {{"alpha_window_mean_stderr", A, F, "1",
      "standard deviation of alpha_window_mean over the same replicas"},
     member<&R::h, &H::alpha, &ExponentEstimate::windowMeanError>},
    {{"alpha_pooled", A, F, "1",
      "ensembles only: alpha of the mean E(t) over the mean window (the local alpha of "
      "neighbouring time points, extrapolated in 1/t)",
      Pooled, true},
     schema::ensembleOnly<R>},
    {{"t_fit_min", A, F, "w^2/D_diff",
      "start of the alpha window: 10 / (Q_peak w)^2, the chi_V peak decayed (or --alpha-window)",
      Mean},
     member<&R::h, &H::window, &ExponentWindow::tMin>},
    {{"t_fit_max", A, F, "w^2/D_diff", "end of the alpha window: t_cutoff / 4 (or --alpha-window)",
      Mean},
     member<&R::h, &H::window, &ExponentWindow::tMax>},
    {{"t_cutoff", A, F, "w^2/D_diff", "t_c = 1 / (Q_min w)^2, the box's cutoff time"},
     member<&R::h, &H::cutoffTime>},
    {{"runtime_s", A, F, "s", kRuntime}, member<&R::h, &H::runtimeSeconds>},
    {{"t", D, F, "w^2/D_diff", "times t D_diff / w^2, log-spaced (--spread-times)", Same},
     member<&R::h, &H::t>},
    {{"excess", D, F, "1",
      "E(t) = S(inf) - S(t) = (1 / (phi V)) sum_{Q != 0} chi_V(Q) exp(-Q^2 D_diff t) (Eq. "
      "FT_spread)",
      Pointwise},
     member<&R::h, &H::excess>},
    {{"local_exponent", D, F, "1",
      "nu(t) = d ln E / d ln t = -t <(Q w)^2>, weights chi_V exp(-Q^2 D_diff t)"},
     member<&R::h, &H::localExponent>},
    {{"local_alpha", D, F, "1", "-3 - 2 nu(t): the alpha of a power law at each time"},
     member<&R::h, &H::localAlpha>},
    {{"truncation_bound", D, F, "1",
      "bound on what the wave vectors beyond the grid's Nyquist limit add to E(t)"},
     member<&R::h, &H::truncation>},
}}};

inline constexpr schema::FieldTable kHyperuniformity{std::array<schema::Column<R>, 27>{{
    {{"alpha", A, F, "1", "alpha of the fit, fixed from spreadability/alpha"},
     member<&R::h, &H::fit, &PowerLawFit::alpha>},
    {{"a0", A, F, "w^3", "chi_V(0) / w^3 of the fit chi_V = a0 + a1 Q^alpha (Eq. fit), not clamped",
      Mean},
     member<&R::h, &H::fit, &PowerLawFit::a0>},
    {{"a0_stderr", A, F, "w^3", "least-squares standard error of a0"},
     member<&R::h, &H::fit, &PowerLawFit::a0Error>},
    {{"a1", A, F, "w^(3+alpha)", "a1 of the fit, Q in units of 1 / w", Mean},
     member<&R::h, &H::fit, &PowerLawFit::a1>},
    {{"a1_stderr", A, F, "w^(3+alpha)", "least-squares standard error of a1"},
     member<&R::h, &H::fit, &PowerLawFit::a1Error>},
    {{"fit_points", A, I, "1", "wave vectors (one of each +-Q) in the fit window"},
     member<&R::h, &H::fit, &PowerLawFit::points>},
    {{"q_fit_max_w", A, F, "1", "the fit window 0 < Q w <= q_fit_max_w (--fit-qmax)"},
     member<&R::h, &H::parameters, &HyperuniformityParameters::fitQmaxW>},
    {{"fit_Q_w", D, F, "1", "Q w of each wave vector fitted (one of each +-Q, in the window)"},
     member<&R::h, &H::fitted, &SmallQPoints::qw>},
    {{"fit_chi", D, F, "w^3",
      "chi_V / w^3 fitted there: exact up to chi_exact_qmax (source), else the voxels'"},
     member<&R::h, &H::fitted, &SmallQPoints::chi>},
    {{"H", A, F, "1", "hyperuniformity index a0 / chi_peak (Eq. HX)", Mean}, member<&R::h, &H::h>},
    {{"H_stderr", A, F, "1", "a0_stderr / chi_peak"},
     +[](const R& r, const Scales&) -> Optional { return Value(r.h.fit.a0Error / r.h.peak.chi); }},
    {{"a0_pooled", A, F, "w^3",
      "ensembles only: a0 of one fit through every member's wave vectors at alpha_pooled (the "
      "fit of the ensemble-mean chi_V; docs/hyperuniformity.md, \"Ensembles\")",
      Pooled, true},
     schema::ensembleOnly<R>},
    {{"a0_pooled_stderr", A, F, "w^3",
      "ensembles only: least-squares standard error of a0_pooled at alpha_pooled fixed", Pooled,
      true},
     schema::ensembleOnly<R>},
    {{"a1_pooled", A, F, "w^(3+alpha)", "ensembles only: a1 of that fit", Pooled, true},
     schema::ensembleOnly<R>},
    {{"a1_pooled_stderr", A, F, "w^(3+alpha)", "ensembles only: its least-squares standard error",
      Pooled, true},
     schema::ensembleOnly<R>},
    {{"H_pooled", A, F, "1", "ensembles only: a0_pooled / chi_peak (the members' mean chi_peak)",
      Pooled, true},
     schema::ensembleOnly<R>},
    {{"H_pooled_stderr", A, F, "1", "ensembles only: a0_pooled_stderr / chi_peak", Pooled, true},
     schema::ensembleOnly<R>},
    {{"H_min", A, F, "1", "least H over fit windows 0.8 ... 1.5 q_fit_max_w"},
     member<&R::h, &H::hSpread, &IndexSpread::hMin>},
    {{"H_max", A, F, "1", "largest H over those windows"},
     member<&R::h, &H::hSpread, &IndexSpread::hMax>},
    {{"chi_peak", A, F, "w^3",
      "chi_V(Q_peak) / w^3: the top of a Gaussian through the voxels' chi_V in bins of Q w 0.05 "
      "within 0.4 of the largest (docs/hyperuniformity.md)",
      Mean},
     member<&R::h, &H::peak, &SpectralPeak::chi>},
    {{"q_peak_w", A, F, "1", "Q_peak w"}, member<&R::h, &H::peak, &SpectralPeak::qw>},
    {{"alpha_free", A, F, "1", "alpha of the free three-parameter fit (scan over [0, 4])"},
     member<&R::h, &H::freeFit, &FreeFit::best, &PowerLawFit::alpha>},
    {{"a0_free", A, F, "w^3", "a0 of the free fit"},
     member<&R::h, &H::freeFit, &FreeFit::best, &PowerLawFit::a0>},
    {{"alpha_free_low", A, F, "1", "least alpha within one standard deviation of the free fit"},
     member<&R::h, &H::freeFit, &FreeFit::alphaLow>},
    {{"alpha_free_high", A, F, "1", "largest such alpha"},
     member<&R::h, &H::freeFit, &FreeFit::alphaHigh>},
    {{"free_fit_degenerate", A, I, "1",
      "1 when the free fit does not fix alpha (range over 0.5 or at the scan's end)"},
     member<&R::h, &H::freeFit, &FreeFit::degenerate>},
    {{"runtime_s", A, F, "s", "wall-clock time of the exact chi_V, the fits and the bootstrap"},
     member<&R::fitSeconds>},
}}};

inline constexpr schema::FieldTable kSpreadabilityDebye{std::array<schema::Column<R>, 3>{{
    {{"phi", A, F, "1", "phi of the Debye medium (the packing's)"}, member<&R::phi>},
    {{"t", D, F, "a^2/D_diff", "times t D_diff / a^2, the same numbers as spreadability/t", Same},
     member<&R::h, &H::t>},
    {{"excess", D, F, "1",
      "E(t) of the Debye medium, chi_V = 8 pi phi (1 - phi) a^3 / (1 + (k a)^2)^2 (Eq. deb, "
      "normalised; docs/hyperuniformity.md)",
      Pointwise},
     member<&R::h, &H::debyeExcess>},
}}};
} // namespace hyperuniformity_fields

inline constexpr schema::Group kSpreadabilityGroup{
    "spreadability", "files/<i>/spreadability",
    "excess spreadability and alpha (hyper; docs/hyperuniformity.md)",
    hyperuniformity_fields::kSpreadability.fields()};
inline constexpr schema::Group kHyperuniformityGroup{
    "hyperuniformity", "files/<i>/hyperuniformity", "the small-Q fit of chi_V and H (hyper)",
    hyperuniformity_fields::kHyperuniformity.fields()};
inline constexpr schema::Group kSpreadabilityDebyeGroup{
    "spreadability_debye", "files/<i>/spreadability_debye",
    "the Debye random medium's excess spreadability on the same time axis (hyper)",
    hyperuniformity_fields::kSpreadabilityDebye.fields()};

} // namespace sbpack
