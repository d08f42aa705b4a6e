// sbanalyze: thread-parallel analysis engine for stored packings (command line in cli/).
#include "cli/command_line.hpp"

#include <iostream>

int main(int argc, char** argv) {
    return sbpack::runCommandLine(argc, argv, std::cout, std::cerr);
}
