// sbanalyze: thread-parallel analysis engine for stored packings (command line in cli/).
#include "cli/command_line.hpp"
#include "io/read_deadline.hpp"

#include <iostream>

int main(int argc, char** argv) {
    sbpack::armReadDeadline("sbanalyze", 60.0); // io/read_deadline.hpp
    return sbpack::runCommandLine(argc, argv, std::cout, std::cerr);
}
