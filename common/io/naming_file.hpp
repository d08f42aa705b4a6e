#pragma once
// One rule for an error about a file: its message names the file (docs/reliability.md, "Inputs").
// Readers name it themselves; an analysis's own message (the order metrics', the cell list's) does
// not, and gets the quoted name in front (issue 65 item 5).

#include <string>

namespace sbpack {

/// `message` if it already holds 'file' (quoted), else "'file': message".
inline std::string messageNamingFile(const std::string& message, const std::string& file) {
    const std::string quoted = "'" + file + "'";
    return message.find(quoted) == std::string::npos ? quoted + ": " + message : message;
}

} // namespace sbpack
