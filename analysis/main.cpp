// sbanalyze: thread-parallel analysis engine for stored packings (command line in cli/). Built
// with SBPACK_WITH_MPI, the same program runs on the ranks of mpirun (docs/scale-out.md).
#include "cli/command_line.hpp"
#include "io/read_guard.hpp"

#include <iostream>

#ifdef SBPACK_WITH_MPI
#include "mpi/mpi_communicator.hpp"

#include <sstream>

int main(int argc, char** argv) {
    sbpack::armReadGuard("sbanalyze", 60.0); // io/read_guard.hpp
    const sbpack::MpiSession session(argc, argv);
    const sbpack::MpiCommunicator world;
    if (world.rank() == 0) return sbpack::runCommandLine(argc, argv, std::cout, std::cerr, world);
    // Rank 0 prints the agreed errors and the outputs; the others' stage lines still go to stderr.
    std::ostringstream quiet;
    return sbpack::runCommandLine(argc, argv, quiet, quiet, world);
}
#else
int main(int argc, char** argv) {
    sbpack::armReadGuard("sbanalyze", 60.0); // io/read_guard.hpp
    return sbpack::runCommandLine(argc, argv, std::cout, std::cerr);
}
#endif
