// sbanalyze: thread-parallel analysis engine for stored packings (command line in cli/). Built
// with SBPACK_WITH_MPI, the same program runs on the ranks of mpirun (docs/scale-out.md).
#include "cli/command_line.hpp"
#include "io/read_guard.hpp"

#include <cstdlib>
#include <iostream>
#include <stdexcept>

namespace sbpack {
namespace {

/// io/read_guard.hpp with its 60 s; false, with the message, for a bad SBPACK_READ_DEADLINE_S.
bool armSbanalyzeReadGuard() {
    try {
        armReadGuard("sbanalyze", 60.0);
        return true;
    } catch (const std::invalid_argument& e) {
        std::cerr << "sbanalyze: error: " << e.what() << '\n';
        return false;
    }
}

} // namespace
} // namespace sbpack

#ifdef SBPACK_WITH_MPI
#include "mpi/mpi_communicator.hpp"

#include <sstream>

int main(int argc, char** argv) {
    if (!sbpack::armSbanalyzeReadGuard()) return EXIT_FAILURE;
    const sbpack::MpiSession session(argc, argv);
    const sbpack::MpiCommunicator world;
    if (world.rank() == 0) return sbpack::runCommandLine(argc, argv, std::cout, std::cerr, world);
    // Rank 0 prints the agreed errors and the outputs; the others' stage lines still go to stderr.
    std::ostringstream quiet;
    return sbpack::runCommandLine(argc, argv, quiet, quiet, world);
}
#else
int main(int argc, char** argv) {
    if (!sbpack::armSbanalyzeReadGuard()) return EXIT_FAILURE;
    return sbpack::runCommandLine(argc, argv, std::cout, std::cerr);
}
#endif
