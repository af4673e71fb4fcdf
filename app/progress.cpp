// Terminal progress bar / plain progress lines.
#include "app/progress.h"

#include <unistd.h>

#include <algorithm>

namespace vista {

Progress::Progress(int total, std::string label, std::FILE* out)
    : total_(std::max(total, 1)), label_(std::move(label)), out_(out), tty_(isatty(fileno(out)) != 0),
      start_(std::chrono::steady_clock::now()) {}

void Progress::update(int done) {
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    double fps = elapsed > 0.0 ? done / elapsed : 0.0;
    double eta = fps > 0.0 ? (total_ - done) / fps : 0.0;
    if (tty_) {
        constexpr int kWidth = 30;
        int filled = done * kWidth / total_;
        std::fprintf(out_, "\r%s [%s%s] %d/%d frames  %.1f fps  ETA %.0f s ", label_.c_str(),
                     std::string(std::size_t(filled), '#').c_str(), std::string(std::size_t(kWidth - filled), ' ').c_str(),
                     done, total_, fps, eta);
    } else {
        std::fprintf(out_, "%s: frame %d/%d (%.1f fps, ETA %.0f s)\n", label_.c_str(), done, total_, fps, eta);
    }
    std::fflush(out_);
}

void Progress::finish() {
    if (tty_) std::fprintf(out_, "\n");
    std::fflush(out_);
}

}  // namespace vista
