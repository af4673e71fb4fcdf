// The FrameRenderer a GL test file renders with, on the shared OSMesa context (gl_fixture.h).
// Internal linkage: every test file that includes this has its own renderer, made on first use.
#pragma once

#include "app/frame.h"
#include "app/scene.h"
#include "gl_fixture.h"

#include <string>

namespace vista::test {
namespace {

[[maybe_unused]] FrameRenderer& fileRenderer() {
    glContext();
    static FrameRenderer r(vistaRoot());
    return r;
}

// The same, with every program compiled once up front (a compile error fails the test).
[[maybe_unused]] FrameRenderer& compiledFileRenderer() {
    FrameRenderer& r = fileRenderer();
    static bool compiled = [&r] {
        std::string errors;
        REQUIRE_MESSAGE(r.compilePrograms(errors), errors);
        return true;
    }();
    (void)compiled;
    return r;
}

}  // namespace
}  // namespace vista::test
