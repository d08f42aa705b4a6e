#pragma once
// What sbgen has measured of a shape (docs/design.md §3): its default growth rates, the cost
// model's constants, the parameters its engine runs and what sbgen says before a run. The
// protocol, its advice and the cost model know a shape only through this (shapes/registry:
// measuredProtocol), so that a new shape brings its measurements in its own files
// (docs/architecture.md, "What a new shape needs").

#include <optional>
#include <string>
#include <vector>

namespace sbpack {

struct MeasuredProtocol {
    /// The default fast rate (the paper's protocol: its phi).
    double fastRate = 0.0;
    /// The default slow rate at speed 1 (the paper's protocol: its Z).
    double slowRate = 0.0;
    /// Collisions per CPU second on this machine class.
    double collisionRate = 0.0;
    /// The slow phase's collisions per particle per decade of pressure, times its rate.
    double slowCollisionsTimesRate = 0.0;
    /// A shape parameter the engine cannot run (its name in the provenance) and why.
    struct Problem {
        std::string parameter;
        std::string message;
    };
    std::optional<Problem> problem;
    /// What sbgen says, each one line, before a run of this shape (beyond the measured range).
    std::vector<std::string> warnings;
};

} // namespace sbpack
