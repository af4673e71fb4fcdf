// The ffmpeg pipe: spawn, feed raw frames, collect its stderr into a log file beside the video
// (read back into the error message), rename on success.
#include "app/video.h"

#include "app/shard.h"

#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <map>
#include <regex>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace vista {
namespace {

// Reads a frame as 8-bit RGB; "" or why not.
std::string readRgb(const std::filesystem::path& file, int& width, int& height, std::vector<unsigned char>& rgb) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) return file.string() + ": cannot read (" + OIIO::geterror() + ")";
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.format != OIIO::TypeDesc::UINT8)
        return file.string() + ": video encodes 8-bit sRGB frames (PNG); this file holds " + spec.format.c_str() +
               " (an EXR capture is linear HDR: capture with --format png or mp4)";
    width = spec.width;
    height = spec.height;
    rgb.assign(std::size_t(width) * std::size_t(height) * 3, 0);
    // Channels 0..2 whatever the file has (grey files are not written by vista).
    bool ok = in->read_image(0, 0, 0, std::min(spec.nchannels, 3), OIIO::TypeDesc::UINT8, rgb.data(), 3);
    in->close();
    return ok ? std::string() : file.string() + ": " + in->geterror();
}

bool writeAll(int fd, const unsigned char* data, std::size_t size) {
    while (size > 0) {
        ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

std::string readLog(const std::filesystem::path& log) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    return s;
}

// Ignores SIGPIPE while alive: a dying ffmpeg must give EPIPE on write, not kill vista.
struct IgnoreSigpipe {
    struct sigaction old {};
    IgnoreSigpipe() {
        struct sigaction ignore {};
        ignore.sa_handler = SIG_IGN;
        sigaction(SIGPIPE, &ignore, &old);
    }
    ~IgnoreSigpipe() { sigaction(SIGPIPE, &old, nullptr); }
};

}  // namespace

std::string encodeVideo(const std::vector<std::filesystem::path>& frames, const std::filesystem::path& file,
                        const VideoOptions& options) {
    if (frames.empty()) return file.string() + ": no frames to encode";
    if (!options.force && std::filesystem::exists(file))
        return file.string() + " already exists; pass --force to replace it";
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
    std::string problem = readRgb(frames.front(), width, height, rgb);
    if (!problem.empty()) return problem;

    // Temporary names unique to this process, in the video's directory (same file system).
    const std::string pid = std::to_string(::getpid());
    std::filesystem::path tmp = file, log = file;
    tmp += ".part-" + pid;
    log += ".ffmpeg-" + pid + ".log";
    const char* env = std::getenv("VISTA_FFMPEG");
    const std::string program = env && *env ? env : "ffmpeg";
    char size[32], rate[32], crf[8];
    std::snprintf(size, sizeof size, "%dx%d", width, height);
    std::snprintf(rate, sizeof rate, "%.9g", options.fps);
    std::snprintf(crf, sizeof crf, "%d", options.crf);
    std::vector<std::string> args{program, "-hide_banner", "-loglevel", "error", "-y",
                                  "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", size, "-framerate", rate, "-i", "pipe:0",
                                  "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-preset", "medium",
                                  "-crf", crf, "-pix_fmt", "yuv420p", "-movflags", "+faststart", "-f", "mp4", tmp.string()};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    int pipe_fds[2];
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0) return file.string() + ": cannot create a pipe to ffmpeg (" + std::strerror(errno) + ")";
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[0], 0);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t child = 0;
    int spawned = posix_spawnp(&child, program.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(pipe_fds[0]);
    if (spawned != 0) {
        ::close(pipe_fds[1]);
        std::filesystem::remove(log);
        return file.string() + ": cannot run " + program + " (" + std::strerror(spawned) +
               "); install Debian's ffmpeg package or set VISTA_FFMPEG";
    }

    IgnoreSigpipe guard;
    bool fed = true;
    for (std::size_t i = 0; i < frames.size() && fed && problem.empty(); ++i) {
        int w = 0, h = 0;
        if (i > 0) problem = readRgb(frames[i], w, h, rgb);
        if (problem.empty() && i > 0 && (w != width || h != height))
            problem = frames[i].string() + ": " + std::to_string(w) + "x" + std::to_string(h) + " differs from the first frame's " +
                      size + " (" + frames.front().string() + ")";
        if (problem.empty()) fed = writeAll(pipe_fds[1], rgb.data(), rgb.size());
    }
    ::close(pipe_fds[1]);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    const bool encoded = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    std::string message = readLog(log);
    std::error_code ec;
    std::filesystem::remove(log, ec);
    if (problem.empty() && (!fed || !encoded)) {
        std::string why = WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                            : "killed by signal " + std::to_string(WTERMSIG(status));
        problem = file.string() + ": " + program + " failed (" + why + ")" + (message.empty() ? "" : ":\n" + message);
    }
    if (!problem.empty()) {
        std::filesystem::remove(tmp, ec);
        return problem;
    }
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
        std::filesystem::remove(tmp);
        return file.string() + ": cannot rename from " + tmp.string() + " (" + ec.message() + ")";
    }
    return {};
}

std::vector<std::filesystem::path> findFrameSequence(const std::filesystem::path& dir, std::vector<std::string>& problems) {
    static const std::regex name("frame_([0-9]+)\\.(png|exr)");
    std::map<int, std::filesystem::path> found;
    std::map<std::string, int> formats;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        std::smatch m;
        const std::string file = entry.path().filename().string();
        if (!entry.is_regular_file() || !std::regex_match(file, m, name)) continue;
        found[std::stoi(m[1].str())] = entry.path();
        ++formats[m[2].str()];
    }
    if (ec) problems.push_back(dir.string() + ": cannot list (" + ec.message() + ")");
    if (formats.size() > 1) problems.push_back(dir.string() + ": holds both PNG and EXR frames; encode one format");
    std::vector<std::filesystem::path> frames;
    std::vector<int> gaps;
    int next = found.empty() ? 0 : found.begin()->first;
    for (const auto& [index, path] : found) {
        for (; next < index; ++next) gaps.push_back(next);
        frames.push_back(path);
        next = index + 1;
    }
    if (!gaps.empty()) problems.push_back(dir.string() + ": frames missing from the sequence: " + listRanges(gaps));
    if (found.empty() && !ec) problems.push_back(dir.string() + ": no frame_NNNN.png files");
    return frames;
}

}  // namespace vista
