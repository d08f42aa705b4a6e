// sbanalyze: thread-parallel analysis engine for stored packings (command line in cli/).
#include "cli/command_line.hpp"
#include "io/read_guard.hpp"

#include <iostream>

int main(int argc, char** argv) {
    sbpack::armReadGuard("sbanalyze", 60.0); // io/read_guard.hpp
    return sbpack::runCommandLine(argc, argv, std::cout, std::cerr);
}
