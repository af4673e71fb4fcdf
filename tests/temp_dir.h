#pragma once
// A fresh empty directory under the system temp dir, removed at scope exit (unit and GL tests).
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace vista::test {

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
    std::filesystem::path operator/(const std::string& file) const { return path / file; }
};

}  // namespace vista::test
