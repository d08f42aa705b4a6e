#pragma once
// The shape families, listed once (docs/architecture.md, "What a new shape needs"): a new family
// is its own files (a ShapeFamilyTraits, geometry/shape_family) and one entry here. The superball
// stays first: a file without a family name holds superballs.

#ifdef SBPACK_SHAPE_FAMILIES_HEADER
// A test's own list (tests/families: ShapeSpec and ParticleShape with a second family), never a
// program's.
#include SBPACK_SHAPE_FAMILIES_HEADER
#else
#include "geometry/superball_family.hpp"

namespace sbpack {

using ShapeFamilies = ShapeFamilyList<SuperballFamily>;

} // namespace sbpack
#endif
