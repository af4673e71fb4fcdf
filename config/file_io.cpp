// Atomic outputs with a signal-safe registry of temporaries, and checked inputs.
#include "config/file_io.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <mutex>
#include <sys/stat.h>
#include <unistd.h>

namespace vista {
namespace {

// ---------------------------------------------------------------------------------------
// Registry of live temporaries. The signal handler may only read plain memory and call
// async-signal-safe functions (unlink, sigaction, raise), so each slot is a fixed buffer
// whose state is published with an atomic store after the path is copied in.
constexpr int kSlots = 128;
struct Slot {
    std::atomic<int> state{0};  // 0 free, 1 being filled, 2 live
    char path[PATH_MAX];
};
std::array<Slot, kSlots> g_slots;
struct sigaction g_previous_int, g_previous_term;

void removeLiveTemporaries() {
    for (Slot& s : g_slots)
        if (s.state.load(std::memory_order_acquire) == 2) ::unlink(s.path);
}

void onSignal(int sig) {
    removeLiveTemporaries();
    const struct sigaction& previous = sig == SIGINT ? g_previous_int : g_previous_term;
    if (previous.sa_handler == SIG_IGN) return;
    if (previous.sa_handler != SIG_DFL && !(previous.sa_flags & SA_SIGINFO)) {
        previous.sa_handler(sig);  // chain to a handler installed before ours (e.g. a window loop)
        return;
    }
    // Die of the same signal, so the parent sees how the process ended.
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    ::sigaction(sig, &dfl, nullptr);
    ::raise(sig);
}

int registerTemporary(const std::filesystem::path& tmp) {
    installTemporaryCleanup();
    const std::string& text = tmp.native();
    if (text.size() >= PATH_MAX) return -1;
    for (int i = 0; i < kSlots; ++i) {
        int expected = 0;
        if (!g_slots[std::size_t(i)].state.compare_exchange_strong(expected, 1)) continue;
        std::memcpy(g_slots[std::size_t(i)].path, text.c_str(), text.size() + 1);
        g_slots[std::size_t(i)].state.store(2, std::memory_order_release);
        return i;
    }
    return -1;  // more than kSlots outputs at once: still written, just not cleaned on a signal
}

void unregisterTemporary(int slot) {
    if (slot >= 0) g_slots[std::size_t(slot)].state.store(0, std::memory_order_release);
}

std::filesystem::path uniqueTemporary(const std::filesystem::path& file) {
    static std::atomic<unsigned> counter{0};
    std::filesystem::path tmp = file;
    char suffix[48];  // (snprintf: "." + to_string() trips a false -Wrestrict in GCC 12)
    std::snprintf(suffix, sizeof suffix, ".%ld.%u.part", long(::getpid()), counter++);
    tmp += suffix;
    return tmp;
}

// Publishes tmp as file. Without force, a file that appeared since is never replaced.
int publish(const std::filesystem::path& tmp, const std::filesystem::path& file, bool force) {
    if (force) return ::rename(tmp.c_str(), file.c_str()) == 0 ? 0 : errno;
    if (::renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, file.c_str(), RENAME_NOREPLACE) == 0) return 0;
    if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP) return errno;
    // File systems without RENAME_NOREPLACE: link() fails with EEXIST just the same.
    if (::link(tmp.c_str(), file.c_str()) != 0) return errno;
    ::unlink(tmp.c_str());
    return 0;
}

std::string describePublishError(const std::filesystem::path& file, int err) {
    if (err == EEXIST)
        return file.string() + ": another file appeared under this name while it was being written "
                               "(another vista writing the same output?); it was kept. Pass --force to replace it";
    return file.string() + ": cannot publish (" + std::strerror(err) + ")";
}

}  // namespace

void installTemporaryCleanup() {
    // Not once per process: a library (a test runner, a window toolkit) may have replaced the
    // handler since; ours is put back in front and chains to it.
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    for (auto [sig, previous] : {std::pair{SIGINT, &g_previous_int}, std::pair{SIGTERM, &g_previous_term}}) {
        struct sigaction current {};
        ::sigaction(sig, nullptr, &current);
        // Ours already, or an inherited "ignore" (nohup, a background job): then no signal comes.
        if (current.sa_handler == onSignal || current.sa_handler == SIG_IGN) continue;
        *previous = current;
        ::sigaction(sig, &action, nullptr);
    }
    // A file-size limit then fails the write with EFBIG, reported like a full disk.
    std::signal(SIGXFSZ, SIG_IGN);
}

int liveTemporaryCount() {
    int n = 0;
    for (const Slot& s : g_slots) n += s.state.load() == 2;
    return n;
}

// ---------------------------------------------------------------------------------------
AtomicWriter::AtomicWriter(const std::filesystem::path& file, bool force) : file_(file), force_(force) {
    tmp_ = uniqueTemporary(file);
    slot_ = registerTemporary(tmp_);
    fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ < 0) {
        fail("cannot write (" + std::string(std::strerror(errno)) + ")");
        unregisterTemporary(slot_);
        slot_ = -1;
        tmp_.clear();
    }
}

AtomicWriter::~AtomicWriter() { discard(); }

void AtomicWriter::fail(const std::string& why) {
    if (error_.empty()) error_ = file_.string() + ": " + why;
}

void AtomicWriter::discard() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!tmp_.empty()) ::unlink(tmp_.c_str());
    tmp_.clear();
    unregisterTemporary(slot_);
    slot_ = -1;
}

bool AtomicWriter::write(const void* data, std::size_t size) {
    if (!ok()) return false;
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        ssize_t n = ::write(fd_, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            fail("write failed (" + std::string(n < 0 ? std::strerror(errno) : "no progress") + ")");
            return false;
        }
        p += n;
        size -= std::size_t(n);
    }
    return true;
}

std::string AtomicWriter::commit() {
    if (ok() && ::fdatasync(fd_) != 0 && errno != EINVAL && errno != EROFS)
        fail("write failed (" + std::string(std::strerror(errno)) + ")");
    if (fd_ >= 0 && ::close(fd_) != 0 && ok()) fail("close failed (" + std::string(std::strerror(errno)) + ")");
    fd_ = -1;
    if (ok()) {
        int err = publish(tmp_, file_, force_);
        if (err != 0) error_ = describePublishError(file_, err);
    }
    std::string result = error_;
    discard();  // after a successful publish the temporary name no longer exists
    return result;
}

std::string writeFileAtomic(const std::filesystem::path& file, std::string_view bytes, bool force) {
    AtomicWriter out(file, force);
    out.write(bytes);
    return out.commit();
}

// ---------------------------------------------------------------------------------------
std::string checkOutputFile(const std::filesystem::path& file, bool force, std::string_view option) {
    const std::string name = std::string(option) + " " + file.string();
    if (file.empty()) return std::string(option) + ": empty file name";
    struct stat st {};
    if (::stat(file.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) return name + ": is a directory; expected a file name";
        if (!force) return name + ": already exists; pass --force to overwrite, or choose another name";
        if (!S_ISREG(st.st_mode)) return name + ": is not a regular file; only regular files are replaced";
    }
    std::filesystem::path dir = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) return name + ": folder " + dir.string() + " does not exist";
    if (::access(dir.c_str(), W_OK | X_OK) != 0) return name + ": folder " + dir.string() + " is not writable";
    return {};
}

bool samePath(const std::filesystem::path& a, const std::filesystem::path& b) {
    if (a.empty() || b.empty()) return false;
    std::error_code ec;
    if (std::filesystem::equivalent(a, b, ec)) return true;
    return std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec);
}

std::string inputFileProblem(const std::filesystem::path& file, std::uintmax_t max_bytes) {
    struct stat st {};
    if (::stat(file.c_str(), &st) != 0) return std::string("cannot be opened: ") + std::strerror(errno);
    if (S_ISDIR(st.st_mode)) return std::string("cannot be opened: ") + std::strerror(EISDIR) + "; accepted: a regular file";
    if (!S_ISREG(st.st_mode)) return "cannot be opened: not a regular file (a FIFO, device or socket); accepted: regular files";
    if (std::uintmax_t(st.st_size) > max_bytes)
        return "cannot be opened: it is " + std::to_string(std::uintmax_t(st.st_size)) + " bytes; accepted: at most " +
               std::to_string(max_bytes >> 20) + " MiB";
    return {};
}

std::string checkInputFile(const std::filesystem::path& file, std::uintmax_t max_bytes) {
    std::string why = inputFileProblem(file, max_bytes);
    return why.empty() ? why : file.string() + ": " + why;
}

std::string readInputFile(const std::filesystem::path& file, std::uintmax_t max_bytes, std::string& bytes) {
    std::string problem = checkInputFile(file, max_bytes);
    if (!problem.empty()) return problem;
    // O_NONBLOCK: if the file was swapped for a FIFO since the check, open does not block.
    int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return file.string() + ": cannot be opened: " + std::strerror(errno);
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || std::uintmax_t(st.st_size) > max_bytes) {
        ::close(fd);
        return file.string() + ": cannot be opened: it changed while being opened; accepted: regular files";
    }
    bytes.assign(std::size_t(st.st_size), '\0');
    std::size_t done = 0;
    while (done < bytes.size()) {
        ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        done += std::size_t(n);
    }
    ::close(fd);
    if (done != bytes.size()) return file.string() + ": cannot be read: got " + std::to_string(done) + " of " + std::to_string(bytes.size()) + " bytes";
    return {};
}

}  // namespace vista
