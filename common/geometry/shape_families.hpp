#pragma once
// The shape families, listed once (docs/architecture.md, "What a new shape needs"): a new family
// is its own files (a ShapeFamilyTraits, geometry/shape_family) and one entry here. The superball
// stays first: a file without a family name holds superballs.

#include "geometry/superball_family.hpp"

namespace sbpack {

using ShapeFamilies = ShapeFamilyList<SuperballFamily>;

} // namespace sbpack
