#pragma once
// The message of the std::invalid_argument a call throws, for tests that check what a refusal
// says (tests/common, tests/families).

#include <stdexcept>
#include <string>

namespace sbpack {

inline std::string messageOf(auto&& call) {
    try {
        call();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no exception)";
}

} // namespace sbpack
