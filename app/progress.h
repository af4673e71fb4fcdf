// Progress of a long job (capture frames, cache tiles): a redrawn bar (count, rate, ETA) on a
// terminal, plain lines otherwise (logs, CI). Either is written at most once per whole
// percent or per few seconds, so a job of millions of steps prints a few hundred lines, not
// one per step; the first and the last step are always written.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace vista {

class Progress {
public:
    // unit: what is counted, plural ("frames", "tiles").
    Progress(int total, std::string label, std::FILE* out = stderr, std::string unit = "frames");
    void update(int done);
    void finish();

private:
    using Clock = std::chrono::steady_clock;
    bool due(int done, Clock::time_point now) const;

    int total_;
    std::string label_;
    std::string unit_;
    std::FILE* out_;
    bool tty_;
    Clock::time_point start_;
    Clock::time_point last_written_;
    int last_percent_ = -1;
    int last_done_ = -1;
};

}  // namespace vista
