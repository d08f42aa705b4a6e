// The pair solvers for the superball itself (pair/pair_solvers.hpp): sbgen's superball engine
// solves its pairs on Superball, without ParticleShape's dispatch over the families.
#include "pair/pair_solvers.hpp"

namespace sbpack {

SBPACK_PAIR_SOLVERS(Superball)

} // namespace sbpack
