#include "cli/options.hpp"

#include "cli/option_values.hpp"
#include "io/atomic_file.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

namespace sbpack {

const char* const kGeneratorUsage = R"(usage: sbgen --out FILE.h5 [options]
       sbgen --resume CHECKPOINT.h5 --out FILE.h5 [--pressure-final P] [--checkpoint FILE.h5]

Generates a maximally random jammed packing with the Donev-Torquato-Stillinger event-driven
molecular dynamics: N particles start at random (phi-init), fly, collide elastically and grow
at rate gamma (dD/dt = gamma sqrt(kT/m)) until the reduced pressure P = PV/(NkT) diverges.

  --p P                   superball exponent in [0.5, 1000] (default 1: spheres, exact fast
                          path; otherwise rotating superballs)
  --n N                   number of particles (default 1000)
  --seed S                random seed (default 1); same seed and options: identical packing
  --phi-init PHI          initial packing fraction in (0, 0.5) (default 0.2, as the paper)
  --gamma-fast G          growth rate until --pressure-switch (default 0.01)
  --gamma-slow G          growth rate from there to --pressure-final (default 1e-4)
  --pressure-switch P     reduced pressure at which growth slows (default 1e6)
  --pressure-final P      reduced pressure at which the packing is jammed (default 1e12)
  --window W              collisions per particle between thermostat rescalings and
                          pressure estimates (default 10)
  --out FILE.h5           the packing (sbpack.packing format; see README), written atomically
  --checkpoint FILE.h5    write a checkpoint there every --checkpoint-interval seconds
  --checkpoint-interval S wall-clock seconds between checkpoints (default 600)
  --resume FILE.h5        continue from a checkpoint (or a finished sbgen output, e.g. with a
                          higher --pressure-final); the protocol options come from the file
  --quiet                 no progress lines on stderr
  --help, --version

No jam is declared from the pressure alone: at --pressure-final the contact network must hold
(at most 10 % rattlers at gaps below max(1e-10, 100 / P) D), and a pressure carried by a chain
of particles that wraps around the periodic box (columns of near-cubes in small boxes) ends the
run early. Such an output is still written, with provenance jammed = 0 and the reason.

Exit status: 0 jammed; 1 bad input or error; 3 written but not jammed; 128 + signal when
SIGINT or SIGTERM wrote a checkpoint (to --checkpoint, else OUT with .checkpoint.h5).
)";

GeneratorOptions parseGeneratorOptions(const std::vector<std::string>& args) {
    GeneratorOptions o;
    std::set<std::string> protocolOptions;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--help" || a == "-h") {
            o.help = true;
            continue;
        }
        if (a == "--version") {
            o.version = true;
            continue;
        }
        if (a == "--quiet") {
            o.quiet = true;
            continue;
        }
        if (a.rfind("--", 0) != 0) throw std::invalid_argument("unexpected argument '" + a + "'");
        if (i + 1 == args.size()) throw std::invalid_argument("option " + a + " needs a value");
        const std::string& v = args[++i];
        ProtocolParameters& p = o.protocol;
        if (a == "--out") {
            o.out = v;
        } else if (a == "--checkpoint") {
            o.checkpoint = v;
        } else if (a == "--checkpoint-interval") {
            o.checkpointInterval = parseNumber(a, v);
            if (!(o.checkpointInterval > 0.0))
                throw std::invalid_argument("option " + a + ": must be positive");
        } else if (a == "--resume") {
            o.resume = v;
        } else if (a == "--pressure-final") {
            o.pressureFinal = p.pressureFinal = parseNumber(a, v);
        } else {
            protocolOptions.insert(a);
            if (a == "--p") {
                p.p = parseNumber(a, v);
            } else if (a == "--n") {
                p.particles = static_cast<int>(parseInteger(a, v, 2, 100000000));
            } else if (a == "--seed") {
                p.seed = static_cast<std::uint64_t>(parseInteger(a, v, 0, std::int64_t(1) << 53));
            } else if (a == "--phi-init") {
                p.phiInit = parseNumber(a, v);
            } else if (a == "--gamma-fast") {
                p.gammaFast = parseNumber(a, v);
            } else if (a == "--gamma-slow") {
                p.gammaSlow = parseNumber(a, v);
            } else if (a == "--pressure-switch") {
                p.pressureSwitch = parseNumber(a, v);
            } else if (a == "--window") {
                p.collisionsPerWindow = parseNumber(a, v);
            } else {
                throw std::invalid_argument("unknown option " + a + " (see sbgen --help)");
            }
        }
    }
    if (o.help || o.version) return o;
    if (o.out.empty()) throw std::invalid_argument("option --out: an output file is required");
    if (o.resume) {
        if (!protocolOptions.empty())
            throw std::invalid_argument("option " + *protocolOptions.begin() +
                                        ": the protocol comes from the --resume file and cannot "
                                        "change (only --pressure-final can)");
    } else {
        o.protocol.validate();
    }
    checkWritable(o.out);
    if (o.checkpoint) checkWritable(*o.checkpoint);
    return o;
}

} // namespace sbpack
