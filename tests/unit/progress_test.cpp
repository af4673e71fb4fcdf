// Progress lines: a job of millions of steps writes a bounded number of lines, a short job
// one per step, and the last step always.
#include <doctest/doctest.h>

#include <cstdio>
#include <string>

#include "app/progress.h"

namespace {

// Everything a Progress wrote to a file that is not a terminal.
std::string progressText(int total, int step, const char* unit) {
    std::FILE* f = std::tmpfile();
    REQUIRE(f != nullptr);
    {
        vista::Progress p(total, "job", f, unit);
        for (int done = step; done <= total; done += step) p.update(done);
        p.finish();
    }
    std::string text;
    std::rewind(f);
    for (int c; (c = std::fgetc(f)) != EOF;) text += char(c);
    std::fclose(f);
    return text;
}

int lines(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

}  // namespace

TEST_CASE("progress: millions of steps write about one line per percent, naming the unit") {
    const std::string text = progressText(2'000'000, 1, "tiles");
    CHECK(lines(text) >= 100);
    CHECK(lines(text) <= 101 + 10);  // a percent each, and a line per few seconds if it is slow
    CHECK(text.rfind("job: 2000000/2000000 tiles", std::string::npos) != std::string::npos);
    CHECK(text.find("frame") == std::string::npos);
}

TEST_CASE("progress: a short job writes every step") {
    const std::string text = progressText(8, 1, "frames");
    CHECK(lines(text) == 8);
    CHECK(text.find("job: 1/8 frames") == 0);
    CHECK(text.find("job: 8/8 frames") != std::string::npos);
}
