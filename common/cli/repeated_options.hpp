#pragma once
// A repeated option is refused (issue 65 item 8): `--n 10 --n 20` took the last value without a
// word, so a script that appends an option to override another hid the first one. Both programs
// parse with CLI11's TakeLast policy and then call this, so the message names the option.

#include <stdexcept>
#include <string>

namespace sbpack {

/// Throws std::invalid_argument "option --NAME given K times: give it once" for the first
/// single-valued option or flag of `app` or its parsed subcommands given more than once (a
/// template: common does not link CLI11). Positionals and options that take lists are left out.
template <class App> void refuseRepeatedOptions(const App& app) {
    for (const auto* option : app.get_options()) {
        if (option->get_positional() || option->get_items_expected_max() > 1) continue;
        if (option->count() > 1)
            throw std::invalid_argument("option " + option->get_name() + " given " +
                                        std::to_string(option->count()) + " times: give it once");
    }
    for (const auto* sub : app.get_subcommands())
        refuseRepeatedOptions(*sub);
}

} // namespace sbpack
