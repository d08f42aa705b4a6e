#include "packing/validation.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace sbpack {

namespace {

[[noreturn]] void reject(const std::string& source, const std::string& problem) {
    throw InvalidPacking("'" + source + "': invalid packing: " + problem);
}

/// Shortest text that reads back as the same double.
std::string formatDouble(double x) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
}

std::string formatVector(const auto& v) {
    std::string text = "(";
    for (int k = 0; k < v.size(); ++k)
        text += (k ? ", " : "") + formatDouble(v[k]);
    return text + ")";
}

void checkFiniteRows(const std::vector<Vector3d>& rows, const std::string& what,
                     const std::string& source) {
    for (std::size_t i = 0; i < rows.size(); ++i)
        if (!rows[i].allFinite())
            reject(source, "particle " + std::to_string(i) + " has a non-finite (NaN or inf) " +
                               what + " " + formatVector(rows[i]));
}

/// Positions wrapped into the box keep their absolute rounding, about eps |x|: beyond this many
/// box lengths from it that exceeds 1e-12 L, within a factor of the contact tolerance (1e-10 D;
/// issue 65 item 8: a shift of 1e6 L moved positions by 5e-10, x = 1e300 became 0).
constexpr double kFarthestBoxes = 1e3;

void checkNearTheBox(const Packing& packing, const std::string& source) {
    const double limit = kFarthestBoxes * packing.boxLength;
    for (std::size_t i = 0; i < packing.positions.size(); ++i)
        if (packing.positions[i].cwiseAbs().maxCoeff() > limit)
            reject(source, "particle " + std::to_string(i) + " lies at " +
                               formatVector(packing.positions[i]) + ", more than " +
                               formatDouble(kFarthestBoxes) +
                               " box lengths from the box: wrapping it would round its position "
                               "by more than 1e-12 L (wrap the positions where they were made)");
}

void checkOptionalRows(const std::vector<Vector3d>& rows, const std::string& what,
                       const std::string& source, std::size_t n) {
    if (!rows.empty() && rows.size() != n)
        reject(source, what + " array has " + std::to_string(rows.size()) + " rows for " +
                           std::to_string(n) + " particles (count mismatch)");
    checkFiniteRows(rows, what, source);
}

} // namespace

namespace {

/// The shape's parameters, the box, the semi-axis and the pressure: each finite and in range, the
/// particle narrower than the box.
void checkScalars(const Packing& packing, const std::string& source) {
    // Before any ParticleShape, which would throw.
    if (const std::optional<std::string> problem = packing.shapeSpec.problem())
        reject(source, *problem);
    if (!(packing.boxLength > 0.0 && std::isfinite(packing.boxLength)))
        reject(source,
               "box_length = " + formatDouble(packing.boxLength) + " (must be finite and > 0)");
    if (!(packing.semiAxis > 0.0 && std::isfinite(packing.semiAxis)))
        reject(source,
               "semi_axis = " + formatDouble(packing.semiAxis) + " (must be finite and > 0)");
    // A pressure of hard particles is positive: zero or negative is no pressure a generator
    // wrote, and reading it as "no pressure" would hide the damage.
    if (packing.reducedPressure &&
        !(std::isfinite(*packing.reducedPressure) && *packing.reducedPressure > 0.0))
        reject(source, "reduced_pressure = " + formatDouble(*packing.reducedPressure) +
                           " (must be finite and positive)");
    if (2.0 * packing.semiAxis > packing.boxLength)
        reject(source, "semi_axis = " + formatDouble(packing.semiAxis) +
                           ": a particle is wider than the box (L = " +
                           formatDouble(packing.boxLength) + ") and overlaps its own image");
}

/// Every orientation a finite unit quaternion (to kQuaternionNormTolerance).
void checkOrientations(const Packing& packing, const std::string& source) {
    for (std::size_t i = 0; i < packing.orientations.size(); ++i) {
        const Quaterniond& q = packing.orientations[i];
        if (!q.coeffs().allFinite())
            reject(source, "particle " + std::to_string(i) +
                               " has a non-finite (NaN or inf) orientation quaternion");
        const double norm = q.norm();
        if (std::abs(norm - 1.0) > kQuaternionNormTolerance)
            reject(source, "particle " + std::to_string(i) + " has an orientation quaternion " +
                               "of norm " + formatDouble(norm) + " (must be 1 within " +
                               formatDouble(kQuaternionNormTolerance) + ")");
    }
}

/// A mixture's semi-axes (docs/mixtures.md): one per particle, each finite and positive, the
/// largest semiAxis itself.
void checkSemiAxes(const Packing& packing, const std::string& source) {
    if (packing.semiAxes.empty()) return;
    if (packing.semiAxes.size() != packing.positions.size())
        reject(source, "semi_axes has " + std::to_string(packing.semiAxes.size()) + " rows for " +
                           std::to_string(packing.positions.size()) +
                           " particles (count mismatch)");
    double largest = 0.0;
    for (std::size_t i = 0; i < packing.semiAxes.size(); ++i) {
        const double r = packing.semiAxes[i];
        if (!(r > 0.0 && std::isfinite(r)))
            reject(source, "particle " + std::to_string(i) + " has semi-axis " + formatDouble(r) +
                               " in semi_axes (must be finite and > 0)");
        largest = std::max(largest, r);
    }
    if (largest != packing.semiAxis)
        reject(source, "semi_axis = " + formatDouble(packing.semiAxis) +
                           " is not the largest of semi_axes (" + formatDouble(largest) + ")");
}

} // namespace

/// The lengths in [kShortestLength, kLongestLength] (sbgen --phi-init 1e-300 wrote L = 2.2e100).
void checkLengthRange(const Packing& packing, const std::string& source) {
    const auto range = formatDouble(kShortestLength) + ", " + formatDouble(kLongestLength);
    if (2.0 * packing.semiAxis < kShortestLength)
        reject(source, "semi_axis = " + formatDouble(packing.semiAxis) +
                           ": D = 2 semi_axis below " + formatDouble(kShortestLength) +
                           " (lengths must lie in [" + range +
                           "], where results up to length^3 are normal doubles; rescale)");
    if (packing.boxLength > kLongestLength)
        reject(source, "box_length = " + formatDouble(packing.boxLength) + " above " +
                           formatDouble(kLongestLength) + " (lengths must lie in [" + range +
                           "], where results up to length^3 are normal doubles; rescale)");
}

void validatePacking(const Packing& packing, const std::string& source) {
    checkScalars(packing, source);
    checkLengthRange(packing, source);
    const std::size_t n = packing.positions.size();
    if (n == 0) reject(source, "no particles");
    checkSemiAxes(packing, source);
    // Finite sizes can still overflow or underflow the volume (semi_axis 1e300 or 1e-300).
    const double phi = packing.packingFraction();
    if (!(std::isfinite(phi) && phi > 0.0))
        reject(source, "packing fraction N v1 / L^3 = " + formatDouble(phi) +
                           " (semi_axis and box_length out of range)");
    if (packing.orientations.size() != n)
        reject(source, std::to_string(n) + " positions but " +
                           std::to_string(packing.orientations.size()) +
                           " orientations (count mismatch)");
    checkFiniteRows(packing.positions, "position", source);
    checkNearTheBox(packing, source);
    checkOrientations(packing, source);
    checkOptionalRows(packing.velocities, "velocity", source, n);
    checkOptionalRows(packing.angularVelocities, "angular velocity", source, n);
}

void canonicalizePacking(Packing& packing) {
    // Quaternions already unit to rounding stay bit-exact, so write/read round trips are exact.
    constexpr double kUnitToRounding = 8.0 * std::numeric_limits<double>::epsilon();
    for (Quaterniond& q : packing.orientations)
        if (std::abs(q.squaredNorm() - 1.0) > kUnitToRounding) q.normalize();
    for (Vector3d& r : packing.positions)
        r = wrapIntoBox(r, packing.boxLength);
}

} // namespace sbpack
