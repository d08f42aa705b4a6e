// Links sbpack::common from the installed package and checks two closed forms: the volume of the
// sphere (p = 1) and of the cube limit's lower neighbour p = 1000 (within 1 % of (2R)^3).
#include "geometry/superball.hpp"
#include "version.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

int main() {
    const double sphere = sbpack::Superball(1.0, 0.5).volume();
    const double cube = sbpack::Superball(1000.0, 0.5).volume();
    const bool ok = std::abs(sphere - std::numbers::pi / 6.0) < 1e-14 && cube < 1.0 && cube > 0.99;
    std::printf("sbpack %s: sphere volume %.15f, p = 1000 volume %.6f: %s\n", sbpack::kVersion,
                sphere, cube, ok ? "ok" : "WRONG");
    return ok ? 0 : 1;
}
