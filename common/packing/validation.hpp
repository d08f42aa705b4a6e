#pragma once
// Checks that a packing read from a file can be trusted (docs/design.md §4). Overlaps are not
// checked here: the contact module reports them.

#include "packing/packing.hpp"

#include <stdexcept>
#include <string>

namespace sbpack {

/// A packing whose contents are invalid; the message names the source and the problem.
class InvalidPacking : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Largest accepted | |q| - 1 | of an orientation quaternion.
inline constexpr double kQuaternionNormTolerance = 1e-6;

/// The range of lengths in a packing, in its own units: D = 2 semi_axis >= kShortestLength and
/// box_length <= kLongestLength, so that every result in those units, up to length^3 (chi_V),
/// is a normal double (docs/design.md §5, "Units": the analyses compute in a unit near D).
inline constexpr double kShortestLength = 1e-100, kLongestLength = 1e100;

/// Throws InvalidPacking, naming `source` (usually the file), unless: 0.5 <= p < inf;
/// box_length and semi_axis are positive and finite, D >= kShortestLength, L <= kLongestLength; N >
/// 0 with N positions and N orientations; velocity arrays are empty or have N entries; every
/// coordinate, quaternion component and velocity is finite; every quaternion has norm 1 within
/// kQuaternionNormTolerance; a reduced pressure, if present, is finite. Positions outside [0, L)
/// are accepted (readers wrap them).
void validatePacking(const Packing& packing, const std::string& source);

/// What readers do after validation: normalise the quaternions (those already unit to rounding
/// are left bit-exact) and wrap positions into [0, L).
void canonicalizePacking(Packing& packing);

} // namespace sbpack
