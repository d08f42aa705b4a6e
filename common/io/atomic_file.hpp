#pragma once
// Write-to-temporary-then-rename output, used by every writer (docs/design.md §4, §6): a reader
// never sees a half-written packing, results file or checkpoint, and a failed run leaves no debris.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sbpack {

/// An output path that cannot be written, or a commit that failed.
class OutputPathError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Throws OutputPathError unless `file` could be created or replaced: the directory of its
/// linkTarget exists and is writable, and `file` is not itself a directory or another non-regular
/// file (a device or FIFO would be replaced by the rename). Lets a program reject a bad output path
/// before any work starts.
void checkWritable(const std::filesystem::path& file);

/// True where `file` exists and is a character device or a FIFO (/dev/null, /dev/stdout, a named
/// pipe): a stream, written in place, which a temporary and a rename would replace. For the small
/// text outputs that a reader may want to discard or pipe (sbanalyze --json), not for files.
bool isStreamDevice(const std::filesystem::path& file);

/// Writes `text` to the stream device `file` in place (isStreamDevice); OutputPathError naming
/// it where the open or the write fails, at once for a FIFO that no process reads (never a
/// wait for a reader).
void writeToStreamDevice(const std::filesystem::path& file, std::string_view text);

/// Throws OutputPathError when `output` names the same file as `input` (by device and inode,
/// so through links and other spellings too); `what` says which input, e.g. "--resume".
void checkNotInput(const std::filesystem::path& output, const std::filesystem::path& input,
                   const std::string& what);

/// Where writing `file` lands: `file` itself, or, when it is a symbolic link (dangling or not),
/// the file at the end of its chain of links, so that the link survives and its target is
/// written. Throws OutputPathError for a chain of more than 40 links (a loop).
std::filesystem::path linkTarget(const std::filesystem::path& file);

/// Whether writing `a` and writing `b` would land on the same file (through links and other
/// spellings, existing or not): two outputs that must not replace each other.
bool sameDestination(const std::filesystem::path& a, const std::filesystem::path& b);

/// While alive, no other process holding an OutputLock of the same destination (linkTarget) can
/// take one: an advisory lock (flock) on `.NAME.lock` beside it, released by the kernel when the
/// process ends, kill -9 included. Two long runs writing one output or checkpoint would replace
/// each other's files ("last writer wins"); the second is refused at its start instead, with
/// OutputPathError naming the file and the holder's pid.
class OutputLock {
  public:
    explicit OutputLock(const std::filesystem::path& file);
    OutputLock(const OutputLock&) = delete;
    OutputLock& operator=(const OutputLock&) = delete;
    ~OutputLock();

  private:
    std::filesystem::path path_;
    int fd_ = -1;
};

/// A temporary file `.NAME.tmp-<pid>` next to `NAME`; commit() renames it onto `NAME`
/// atomically (same directory). `NAME` is linkTarget(finalPath): a symbolic link stays a link
/// to the new file. Destroying an uncommitted AtomicOutput removes the temporary;
/// the temporaries of `NAME` left by processes that are gone (kill -9) are removed when the
/// next AtomicOutput of `NAME` is made.
class AtomicOutput {
  public:
    /// Checks the destination with checkWritable().
    explicit AtomicOutput(std::filesystem::path finalPath);
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;
    ~AtomicOutput();

    const std::filesystem::path& finalPath() const { return final_; }
    /// Where a writer that opens the file itself writes; it must close it before commit().
    const std::filesystem::path& temporaryPath() const { return temporary_; }
    /// Writes `bytes` as the whole temporary, every write and the close checked: a full disk
    /// or an I/O error throws OutputPathError naming finalPath() and the system's reason
    /// ("No space left on device"), and the earlier file at finalPath() stays as it was. Every
    /// sbpack writer builds its file in memory and writes it through here.
    void write(std::string_view bytes);
    /// Flushes the temporary to disk and renames it onto finalPath(); throws OutputPathError.
    void commit();

  private:
    std::filesystem::path final_;
    std::filesystem::path target_; ///< linkTarget(final_)
    std::filesystem::path temporary_;
    bool committed_ = false;
};

} // namespace sbpack
