// Terminal progress bar / plain progress lines.
#include "app/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdint>

namespace vista {

namespace {
constexpr double kLineSeconds = 5.0;  // a line at least this often while the percent stands still
constexpr double kBarSeconds = 0.2;   // a redrawn bar at most this often
}  // namespace

Progress::Progress(int total, std::string label, std::FILE* out, std::string unit)
    : total_(std::max(total, 1)), label_(std::move(label)), unit_(std::move(unit)), out_(out),
      tty_(isatty(fileno(out)) != 0), start_(Clock::now()), last_written_(start_) {}

bool Progress::due(int done, Clock::time_point now) const {
    if (done == last_done_) return false;
    if (last_done_ < 0 || done >= total_) return true;
    double since = std::chrono::duration<double>(now - last_written_).count();
    int percent = int(std::int64_t(done) * 100 / total_);
    if (tty_) return since >= kBarSeconds;
    return percent != last_percent_ || since >= kLineSeconds;
}

void Progress::update(int done) {
    const auto now = Clock::now();
    if (!due(done, now)) return;
    last_written_ = now;
    last_done_ = done;
    last_percent_ = int(std::int64_t(done) * 100 / total_);
    double elapsed = std::chrono::duration<double>(now - start_).count();
    double rate = elapsed > 0.0 ? done / elapsed : 0.0;
    double eta = rate > 0.0 ? (total_ - done) / rate : 0.0;
    if (tty_) {
        constexpr int kWidth = 30;
        int filled = int(std::int64_t(std::clamp(done, 0, total_)) * kWidth / total_);
        std::fprintf(out_, "\r%s [%s%s] %d/%d %s  %.1f/s  ETA %.0f s ", label_.c_str(),
                     std::string(std::size_t(filled), '#').c_str(), std::string(std::size_t(kWidth - filled), ' ').c_str(),
                     done, total_, unit_.c_str(), rate, eta);
    } else {
        std::fprintf(out_, "%s: %d/%d %s (%.1f/s, ETA %.0f s)\n", label_.c_str(), done, total_, unit_.c_str(), rate, eta);
    }
    std::fflush(out_);
}

void Progress::finish() {
    if (tty_) std::fprintf(out_, "\n");
    std::fflush(out_);
}

}  // namespace vista
