#include "parallel/available_memory.hpp"

#include <fstream>
#include <string>

namespace sbpack {

std::optional<double> availableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    double value = 0.0;
    std::string unit;
    while (meminfo >> key >> value >> unit)
        if (key == "MemAvailable:") return value * (unit == "kB" ? 1024.0 : 1.0);
    return std::nullopt;
}

} // namespace sbpack
