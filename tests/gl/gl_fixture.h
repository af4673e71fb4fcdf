// A headless OSMesa GL 4.5 context for the GL tests, made once per test process.
#pragma once

#include "app/gl_context.h"

#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <string>

namespace vista::test {

inline GlContext& glContext() {
    static std::unique_ptr<GlContext> context = [] {
        std::string error;
        auto c = createContext(Backend::OSMesa, ContextOptions{64, 64, false, false, false, true, "test"}, error);
        if (!c) FAIL("cannot create an OSMesa context: " << error);
        return c;
    }();
    return *context;
}

// A fresh empty directory under the system temp dir, removed at scope exit.
struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& name) {
        path = std::filesystem::temp_directory_path() / ("vista-test-" + name + "-" + std::to_string(::getpid()));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

}  // namespace vista::test
