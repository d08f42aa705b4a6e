#include "io/atomic_file.hpp"

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <string_view>
#include <sys/file.h>
#include <system_error>
#include <unistd.h>

namespace sbpack {

namespace fs = std::filesystem;

namespace {

fs::path directoryOf(const fs::path& file) {
    return file.has_parent_path() ? file.parent_path() : fs::path(".");
}

/// fsync so that a crash after the rename cannot leave an empty file behind.
void syncToDisk(const fs::path& path, int flags, const fs::path& reportAs) {
    const int fd = ::open(path.c_str(), flags);
    if (fd < 0 || ::fsync(fd) != 0) {
        const std::string reason = std::strerror(errno);
        if (fd >= 0) ::close(fd);
        throw OutputPathError("cannot flush '" + path.string() + "' while writing '" +
                              reportAs.string() + "': " + reason);
    }
    ::close(fd);
}

/// `.NAME<suffix>`, the hidden sibling of `target`'s file NAME. A NAME too long for the whole,
/// with `reserve` more bytes appended later, to stay within NAME_MAX (255 bytes) is cut and
/// ends in `~` and the FNV-1a hash of the full NAME in hex, so two long names that share their
/// beginning (an output and its checkpoint) get different siblings.
std::string hiddenSibling(const fs::path& target, std::string_view suffix, std::size_t reserve) {
    const std::size_t longest = 255 - 1 - suffix.size() - reserve;
    const std::string name = target.filename().string();
    std::string hidden = "."; // appended piecewise: GCC 12 misreports "." + string (-Wrestrict)
    if (name.size() <= longest) {
        hidden += name;
    } else {
        std::uint64_t hash = 14695981039346656037ull;
        for (const unsigned char c : name)
            hash = (hash ^ c) * 1099511628211ull;
        char tag[18];
        std::snprintf(tag, sizeof tag, "~%016llx", static_cast<unsigned long long>(hash));
        hidden += name.substr(0, longest - (sizeof tag - 1));
        hidden += tag;
    }
    hidden += suffix;
    return hidden;
}

} // namespace

fs::path linkTarget(const fs::path& file) {
    fs::path path = file;
    for (int hops = 0; hops <= 40; ++hops) {
        std::error_code ec;
        if (!fs::is_symlink(fs::symlink_status(path, ec))) return path;
        const fs::path target = fs::read_symlink(path, ec);
        if (ec)
            throw OutputPathError("cannot write '" + file.string() + "': cannot read the link '" +
                                  path.string() + "': " + ec.message());
        path = target.is_absolute() ? target : directoryOf(path) / target;
    }
    throw OutputPathError("cannot write '" + file.string() +
                          "': more than 40 symbolic links in a chain (a loop?)");
}

OutputLock::OutputLock(const fs::path& file) {
    const fs::path target = linkTarget(file);
    path_ = directoryOf(target) / hiddenSibling(target, ".lock", 0);
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
        throw OutputPathError("cannot lock '" + file.string() + "': " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        char holder[32] = {};
        const ssize_t n = ::pread(fd_, holder, sizeof holder - 1, 0);
        ::close(fd_);
        throw OutputPathError(
            "'" + file.string() + "' is being written by another process" +
            (n > 0 ? " (pid " + std::string(holder, static_cast<std::size_t>(n)) + ")"
                   : std::string()) +
            ": two runs would replace each other's files; name another file");
    }
    // The holder's pid, for the message above (a failure to note it leaves the lock intact).
    const std::string pid = std::to_string(::getpid());
    const bool noted = ::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, pid.data(), pid.size(), 0) > 0;
    static_cast<void>(noted);
}

OutputLock::~OutputLock() {
    // Removed while still held, then released: no debris after a run (kill -9 leaves the file,
    // which the next run reuses; the kernel released its lock).
    std::error_code ec;
    fs::remove(path_, ec);
    ::close(fd_);
}

bool sameDestination(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    if (fs::equivalent(a, b, ec)) return true;
    auto resolved = [&ec](const fs::path& p) {
        return fs::weakly_canonical(fs::absolute(linkTarget(p), ec), ec);
    };
    return resolved(a) == resolved(b);
}

void checkWritable(const fs::path& file) {
    if (file.empty() || !file.has_filename())
        throw OutputPathError("output path '" + file.string() + "' does not name a file");
    const fs::path dir = directoryOf(linkTarget(file));
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw OutputPathError("cannot write '" + file.string() + "': directory '" + dir.string() +
                              "' does not exist");
    if (::access(dir.c_str(), W_OK | X_OK) != 0)
        throw OutputPathError("cannot write '" + file.string() + "': directory '" + dir.string() +
                              "' is not writable");
    const fs::file_status status = fs::status(file, ec);
    if (fs::is_directory(status))
        throw OutputPathError("cannot write '" + file.string() + "': it is a directory");
    if (fs::exists(status) && !fs::is_regular_file(status))
        throw OutputPathError("cannot write '" + file.string() +
                              "': it is not a regular file (a device, FIFO or socket), which the "
                              "write through a temporary and a rename would replace; name a "
                              "regular file");
}

bool isStreamDevice(const fs::path& file) {
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    return fs::is_character_file(status) || fs::is_fifo(status);
}

void writeToStreamDevice(const fs::path& file, std::string_view text) {
    // Non-blocking open: a FIFO that no process reads fails at once (ENXIO) instead of waiting
    // for a reader that may never come; the writes then block as usual.
    const int fd = ::open(file.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        throw OutputPathError("cannot write '" + file.string() + "': " +
                              (errno == ENXIO ? std::string("a FIFO that no process is reading")
                                              : std::string(std::strerror(errno))));
    const bool blocking = ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK) == 0;
    std::size_t done = 0;
    while (blocking && done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        done += static_cast<std::size_t>(n);
    }
    const int error = done == text.size() ? 0 : errno;
    ::close(fd);
    if (error != 0 || done != text.size())
        throw OutputPathError("cannot write '" + file.string() + "': " + std::strerror(error));
}

void checkNotInput(const fs::path& output, const fs::path& input, const std::string& what) {
    std::error_code ec;
    if (fs::equivalent(output, input, ec))
        throw OutputPathError("'" + output.string() + "' is also the input (" + what + " '" +
                              input.string() + "'): write the output elsewhere");
}

namespace {

/// Removes the temporaries `prefix<pid>` in `dir` whose process is gone (killed before it
/// could remove them); those of live processes stay.
void removeStaleTemporaries(const fs::path& dir, const std::string& prefix) {
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(prefix, 0) != 0) continue;
        const std::string pid = name.substr(prefix.size());
        if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
        if (::kill(static_cast<pid_t>(std::stol(pid)), 0) != 0 && errno == ESRCH)
            fs::remove(entry.path(), ec);
    }
}

} // namespace

AtomicOutput::AtomicOutput(fs::path finalPath)
    : final_(std::move(finalPath)), target_(linkTarget(final_)) {
    checkWritable(final_);
    const std::string prefix = hiddenSibling(target_, ".tmp-", 10); // `.NAME.tmp-<pid>`
    removeStaleTemporaries(directoryOf(target_), prefix);
    temporary_ = directoryOf(target_) / (prefix + std::to_string(::getpid()));
    std::error_code ec;
    fs::remove(temporary_, ec); // a stale temporary of an earlier process with our pid
}

AtomicOutput::~AtomicOutput() {
    if (committed_) return;
    std::error_code ec;
    fs::remove(temporary_, ec);
}

void AtomicOutput::write(std::string_view bytes) {
    const int fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0)
        throw OutputPathError("cannot write '" + final_.string() + "': " + std::strerror(errno));
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const std::string reason = n < 0 ? std::strerror(errno) : "no progress";
            ::close(fd);
            throw OutputPathError("cannot write '" + final_.string() + "': " + reason);
        }
        done += static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0)
        throw OutputPathError("cannot write '" + final_.string() + "': " + std::strerror(errno));
}

void AtomicOutput::commit() {
    if (committed_) throw OutputPathError("'" + final_.string() + "' was already committed");
    syncToDisk(temporary_, O_RDONLY, final_);
    std::error_code ec;
    fs::rename(temporary_, target_, ec);
    if (ec)
        throw OutputPathError("cannot rename '" + temporary_.string() + "' to '" +
                              target_.string() + "': " + ec.message());
    committed_ = true;
    syncToDisk(directoryOf(target_), O_RDONLY | O_DIRECTORY, final_);
}

} // namespace sbpack
