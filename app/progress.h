// Progress of a long capture: a redrawn bar (frames, fps, ETA) on a terminal, plain
// lines otherwise (logs, CI).
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace vista {

class Progress {
public:
    Progress(int total, std::string label, std::FILE* out = stderr);
    void update(int done);
    void finish();

private:
    int total_;
    std::string label_;
    std::FILE* out_;
    bool tty_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace vista
