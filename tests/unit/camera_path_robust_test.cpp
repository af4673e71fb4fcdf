// Camera paths against hostile contents (issue 19): a byte order mark, key times 0.001 s
// apart that binary rounding puts a hair under the minimum step.
#include "app/camera_path.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <string>

using namespace vista;

TEST_CASE("camera path: a UTF-8 byte order mark is skipped, not reported as an invisible field") {
    InputErrors errors;
    CameraPath p = CameraPath::parse("\xEF\xBB\xBF" "0 0 10 0 0 0\n1 5 10 0 0 0\n", "bom.path", errors, 60.0);
    CHECK(errors.empty());
    CHECK(p.endTime() == doctest::Approx(1.0));
}

TEST_CASE("camera path: keys 0.001 s apart are accepted at every time, closer ones refused") {
    for (double t0 : {0.3, 1.1, 100.2, 12345.678, 1e6 + 0.7}) {
        CAPTURE(t0);
        char text[128];
        std::snprintf(text, sizeof text, "%.3f 0 10 0 0 0\n%.3f 1 10 0 0 0\n", t0, t0 + 0.001);
        InputErrors errors;
        CameraPath::parse(text, "step.path", errors, 60.0);
        CHECK(errors.empty());
        std::snprintf(text, sizeof text, "%.4f 0 10 0 0 0\n%.4f 1 10 0 0 0\n", t0, t0 + 0.0005);
        errors.clear();
        CameraPath::parse(text, "step.path", errors, 60.0);
        CHECK(errors.size() == 1);
    }
}
