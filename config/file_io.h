// Files in and out, the one place that touches them for every command.
//
// Outputs are written under a temporary name unique to this process (<file>.<pid>.<n>.part,
// created with O_EXCL), every write and the close are checked, and the complete file is
// published by a rename. Without force the rename refuses to replace a file that appeared
// since the command started (renameat2(RENAME_NOREPLACE), or link()+unlink() where the file
// system lacks it), so two processes writing the same output never replace each other's
// files silently. Live temporaries sit in an async-signal-safe registry: SIGINT and SIGTERM
// remove them before the process dies, and SIGXFSZ is ignored so a file-size limit is a
// write error (EFBIG) like a full disk, not a kill.
//
// Inputs are opened only when they are regular files (after following links) no larger than
// a limit, so a FIFO, /dev/zero or a symlink to it is refused instead of blocking forever or
// filling memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace vista {

// Writes bytes to file atomically (see above). force: replace a file already there. "" on
// success, else why (naming the file); on failure nothing is left behind.
std::string writeFileAtomic(const std::filesystem::path& file, std::string_view bytes, bool force);

// The streaming variant: write() as often as needed, then commit(). Destroying an
// uncommitted writer removes its temporary.
class AtomicWriter {
public:
    AtomicWriter(const std::filesystem::path& file, bool force);
    ~AtomicWriter();
    AtomicWriter(const AtomicWriter&) = delete;
    AtomicWriter& operator=(const AtomicWriter&) = delete;

    // False once anything failed; error() says why.
    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }
    bool write(const void* data, std::size_t size);
    bool write(std::string_view text) { return write(text.data(), text.size()); }
    // Flushes, closes and publishes. "" on success, else why; the temporary is gone either way.
    std::string commit();
    // The temporary's path while it exists (tests).
    const std::filesystem::path& temporary() const { return tmp_; }

private:
    void fail(const std::string& why);
    void discard();

    std::filesystem::path file_, tmp_;
    bool force_ = false;
    int fd_ = -1;
    int slot_ = -1;
    std::string error_;
};

// Checks an output before any work is done: its folder exists and is writable, it is not a
// folder, and without force it does not exist yet. "" when fine, else why (naming the option).
std::string checkOutputFile(const std::filesystem::path& file, bool force, std::string_view option);
// True when a and b name the same file (or would: equal after normalising, when neither exists).
bool samePath(const std::filesystem::path& a, const std::filesystem::path& b);

// Temporaries currently registered (removed on SIGINT/SIGTERM); for tests.
int liveTemporaryCount();
// Installs the SIGINT/SIGTERM cleanup and ignores SIGXFSZ; called by the first writer, and
// early by the CLI. Idempotent.
void installTemporaryCleanup();

// Size limits for inputs: text (scene, camera path, .cube LUT) and binary (heightmaps).
constexpr std::uintmax_t kMaxTextInputBytes = std::uintmax_t(256) << 20;
constexpr std::uintmax_t kMaxBinaryInputBytes = std::uintmax_t(4) << 30;

// "" when file is a regular file (links followed) of at most max_bytes, else why, naming it.
std::string checkInputFile(const std::filesystem::path& file, std::uintmax_t max_bytes);
// The same reason without the file name in front, for messages that name the file elsewhere.
std::string inputFileProblem(const std::filesystem::path& file, std::uintmax_t max_bytes);
// Reads a whole input after checkInputFile. "" on success, else why; a short read is an error.
std::string readInputFile(const std::filesystem::path& file, std::uintmax_t max_bytes, std::string& bytes);

}  // namespace vista
