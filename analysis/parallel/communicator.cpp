#include "parallel/communicator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <exception>

namespace sbpack {

void collectively(const Communicator& communicator, const std::function<void()>& work) {
    if (communicator.size() == 1) {
        work();
        return;
    }
    std::string error;
    try {
        work();
    } catch (const CollectiveError& e) {
        error = e.what(); // already agreed inside: every rank has it
    } catch (const std::exception& e) {
        error = e.what();
    }
    const std::vector<std::string> errors = communicator.allGather(error);
    std::string message;
    int failing = 0;
    for (std::size_t r = 0; r < errors.size(); ++r)
        if (!errors[r].empty()) {
            message += fmt::format("{}rank {}: {}", message.empty() ? "" : "\n  ", r, errors[r]);
            ++failing;
        }
    if (failing == 0) return;
    // The same error on every rank (e.g. an option) is said once.
    const bool same = failing == communicator.size() &&
                      std::all_of(errors.begin(), errors.end(),
                                  [&](const std::string& e) { return e == errors.front(); });
    throw CollectiveError(same ? errors.front() : message);
}

} // namespace sbpack
