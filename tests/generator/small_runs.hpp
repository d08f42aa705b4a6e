#pragma once
// Short protocol runs the generator's tests share: fast rates and low pressures, so that a run
// takes a second, and the checkpoint such a run writes.

#include "protocol/jamming_protocol.hpp"

#include <cstdint>

namespace sbpack::testing {

/// 64 spheres from phi 0.2 to P = 1e7, switching at 1e3.
inline ProtocolParameters smallRun(std::uint64_t seed) {
    ProtocolParameters p;
    p.particles = 64;
    p.seed = seed;
    p.gammaFast = 0.05;
    p.gammaSlow = 0.01;
    p.pressureSwitch = 1e3;
    p.pressureFinal = 1e7;
    return p;
}

/// The checkpoint at the end of the run of `p`.
inline Packing finishedCheckpoint(const ProtocolParameters& p) {
    JammingProtocol run(p);
    run.run([](const ProtocolStatus&) {});
    return run.checkpoint();
}

} // namespace sbpack::testing
