#pragma once
// The Debye random medium, the paper's nonhyperuniform reference (Sec. V B, Eq. deb;
// docs/hyperuniformity.md, "Debye random medium"). Its spectral density, correctly normalised in
// three dimensions (its inverse transform at r = 0 is phi (1 - phi); the paper prints the prefactor
// pi instead of 8 pi, which would make E(0) = (1 - phi) / 8):
//   chi_V(k) = 8 pi phi (1 - phi) a^3 / (1 + (k a)^2)^2,
// and its excess spreadability (Eq. FT_spread) in closed form, with s = t D_diff / a^2,
//   E(s) = 2 (1 - phi) [(1/2 + s) e^s erfc(sqrt s) - sqrt(s / pi)]  ~ (1 - phi) / sqrt(pi)
//   s^{-3/2}.

namespace sbpack {

/// chi_V(k) of the Debye medium of length scale a (length^3).
double debyeSpectralDensity(double k, double phi, double a);

/// E(s) at s = t D_diff / a^2 >= 0 by the closed form (its asymptotic series for s >= 50, where the
/// closed form cancels): relative error below 1e-12.
double debyeExcessSpreadability(double s, double phi);

} // namespace sbpack
