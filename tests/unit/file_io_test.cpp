// Fault injection for every writer and the input checks (config/file_io.h): a full disk
// (RLIMIT_FSIZE in a child process, SIGXFSZ ignored by the writer), two writers of one file,
// SIGTERM during a write, special files as inputs.
#include "../temp_dir.h"
#include "app/image_writer.h"
#include "app/quality_report.h"
#include "config/file_io.h"
#include "terrain/heightmap.h"
#include "terrain/terrain.h"

#include <doctest/doctest.h>

#include <OpenImageIO/imageio.h>

#include <csignal>
#include <fstream>
#include <functional>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace vista;

namespace {

using test::TempDir;

std::vector<std::string> listing(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Runs body in a child process whose files may grow to at most limit bytes (a disk that
// fills up after limit bytes); returns the child's exit status: 0 when body returned "",
// 3 when it reported an error, anything else when it died.
int withFileSizeLimit(rlim_t limit, const std::function<std::string()>& body) {
    pid_t pid = ::fork();
    if (pid == 0) {
        struct rlimit r {limit, limit};
        ::setrlimit(RLIMIT_FSIZE, &r);
        installTemporaryCleanup();  // ignores SIGXFSZ, as the CLI does first thing
        std::string problem = body();
        ::_exit(problem.empty() ? 0 : problem.find("File too large") != std::string::npos ? 3 : 4);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 100 + WTERMSIG(status);
}

std::vector<unsigned char> noise(int w, int h) {
    std::vector<unsigned char> rgba(std::size_t(w) * std::size_t(h) * 4);
    std::uint32_t x = 12345;
    for (auto& v : rgba) v = (x = x * 1664525u + 1013904223u) >> 24;
    return rgba;
}

}  // namespace

TEST_CASE("file io: a full disk is an error for every writer and leaves no file behind") {
    TempDir dir("full");
    const std::string megabyte(1 << 20, 'x');
    Heightmap map;
    map.width = map.height = 257;
    map.samples.assign(std::size_t(257) * 257, 0.0f);
    for (std::size_t i = 0; i < map.samples.size(); ++i) map.samples[i] = float((i * 2654435761u) % 1000) / 1000.0f;
    const std::vector<unsigned char> rgba = noise(256, 256);
    const std::vector<std::uint16_t> half(std::size_t(256) * 256 * 4, 0x3c00);
    const std::pair<const char*, std::function<std::string()>> writers[] = {
        {"text", [&] { return writeFileAtomic(dir.path / "stats.json", megabyte, false); }},
        {"png", [&] { return writePng(dir.path / "frame_0000.png", 256, 256, rgba, false); }},
        {"heightmap png", [&] { return saveHeightmapPng16(dir.path / "map.png", map, false); }},
        {"heightmap exr", [&] { return saveHeightmapExr(dir.path / "map.exr", map, false); }},
        {"streaming", [&] {
             AtomicWriter out(dir.path / "stream.bin", false);
             for (int i = 0; i < 64; ++i) out.write(megabyte.data(), 4096);
             return out.commit();
         }},
    };
    for (const auto& [name, write] : writers) {
        CAPTURE(name);
        // Before the fix the PNG writer said "" and left a truncated file.
        CHECK(withFileSizeLimit(4096, write) == 3);
        CHECK(listing(dir.path).empty());
        CHECK(withFileSizeLimit(RLIM_INFINITY, write) == 0);  // the same write fits without the limit
        CHECK(listing(dir.path).size() == 1);
        for (const auto& e : fs::directory_iterator(dir.path)) fs::remove(e.path());
    }
    (void)half;
}

TEST_CASE("file io: an existing output is kept without force and replaced with it") {
    TempDir dir("force");
    const fs::path file = dir.path / "out.json";
    REQUIRE(writeFileAtomic(file, "first", false) == "");
    const std::string refused = writeFileAtomic(file, "second", false);
    CHECK(refused.find("--force") != std::string::npos);
    CHECK(readAll(file) == "first");
    CHECK(writeFileAtomic(file, "third", true) == "");
    CHECK(readAll(file) == "third");
    CHECK(listing(dir.path) == std::vector<std::string>{"out.json"});
}

TEST_CASE("file io: two writers of one file use two temporaries and the second never replaces the first") {
    TempDir dir("race");
    const fs::path file = dir.path / "frame_0000.png";
    AtomicWriter a(file, false), b(file, false);
    REQUIRE(a.ok());
    REQUIRE(b.ok());
    CHECK(a.temporary() != b.temporary());  // was one shared frame_0000.png.part
    CHECK(liveTemporaryCount() >= 2);
    a.write("from a");
    b.write("from b");
    CHECK(a.commit() == "");
    const std::string second = b.commit();
    CHECK(second.find("appeared") != std::string::npos);
    CHECK(readAll(file) == "from a");
    CHECK(listing(dir.path) == std::vector<std::string>{"frame_0000.png"});
    CHECK(liveTemporaryCount() == 0);
}

TEST_CASE("file io: SIGTERM and SIGINT during a write remove the temporary") {
    for (int sig : {SIGTERM, SIGINT}) {
        CAPTURE(sig);
        TempDir dir("signal");
        pid_t pid = ::fork();
        if (pid == 0) {
            ::signal(sig, SIG_DFL);  // as in a fresh process (doctest installs its own handlers)
            AtomicWriter out(dir.path / "frame_0007.png", false);
            out.write(std::string(100000, 'x'));
            ::raise(sig);
            ::_exit(0);  // not reached
        }
        int status = 0;
        ::waitpid(pid, &status, 0);
        CHECK(WIFSIGNALED(status));
        CHECK(WTERMSIG(status) == sig);  // still dies of the signal, as the parent expects
        CHECK(listing(dir.path).empty());
    }
}

TEST_CASE("file io: a failed publish leaves no temporary") {
    TempDir dir("publish");
    fs::create_directories(dir.path / "taken");
    // Renaming a file over a directory fails, even with force.
    CHECK(writeFileAtomic(dir.path / "taken", "x", true) != "");
    CHECK(listing(dir.path) == std::vector<std::string>{"taken"});
    CHECK(writeFileAtomic(dir.path / "missing" / "x.json", "x", true).find("cannot write") != std::string::npos);
}

TEST_CASE("file io: outputs are checked before any work") {
    TempDir dir("outputs");
    CHECK(checkOutputFile(dir.path / "new.json", false, "--stats") == "");
    CHECK(checkOutputFile(dir.path, true, "--stats").find("is a directory") != std::string::npos);
    CHECK(checkOutputFile(dir.path / "no" / "x.json", true, "--stats").find("does not exist") != std::string::npos);
    std::ofstream(dir.path / "old.json") << "{}";
    CHECK(checkOutputFile(dir.path / "old.json", false, "--json").find("--force") != std::string::npos);
    CHECK(checkOutputFile(dir.path / "old.json", true, "--json") == "");
    CHECK(samePath(dir.path / "old.json", dir.path / "." / "old.json"));
    CHECK(samePath(dir.path / "a" / ".." / "new.json", dir.path / "new.json"));
    CHECK_FALSE(samePath(dir.path / "old.json", dir.path / "new.json"));
}

TEST_CASE("file io: inputs must be regular files under the size limit") {
    TempDir dir("inputs");
    const fs::path fifo = dir.path / "scene.fifo";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    fs::create_symlink("/dev/zero", dir.path / "zero.png");
    std::ofstream(dir.path / "ok.ini") << "[window]\n";
    std::ofstream(dir.path / "big.ini") << std::string(2000, ' ');
    std::string bytes;
    // A FIFO used to block the reader forever; /dev/zero (or a link to it) to fill memory.
    for (const fs::path& f : {fifo, fs::path("/dev/zero"), dir.path / "zero.png"}) {
        CAPTURE(f);
        CHECK(readInputFile(f, kMaxTextInputBytes, bytes).find("not a regular file") != std::string::npos);
    }
    CHECK(readInputFile(dir.path, kMaxTextInputBytes, bytes).find("directory") != std::string::npos);
    CHECK(readInputFile(dir.path / "big.ini", 1000, bytes).find("accepted: at most") != std::string::npos);
    CHECK(readInputFile(dir.path / "ok.ini", kMaxTextInputBytes, bytes) == "");
    CHECK(bytes == "[window]\n");

    // The heightmap loader: a link to /dev/zero and a FIFO are refused, naming the file.
    for (const fs::path& f : {fifo, dir.path / "zero.png"}) {
        InputErrors errors;
        CHECK(loadHeightmap(f, 0, 0, errors).samples.empty());
        REQUIRE(errors.size() == 1);
        CHECK(errors[0].file == f.string());
        CHECK(errors[0].message.find("not a regular file") != std::string::npos);
    }
    InputErrors errors;
    loadHeightmap(dir.path, 0, 0, errors);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].message.find("directory") != std::string::npos);  // was "Not a PNG file"
}

TEST_CASE("file io: heights outside the physical range and truncated images are refused") {
    TempDir dir("heights");
    Heightmap map;
    map.width = map.height = 9;
    map.samples.assign(81, 0.5f);
    map.samples[40] = 1e30f;
    REQUIRE(saveHeightmapExr(dir.path / "huge.exr", map) == "");
    TerrainSettings s;
    s.heightmap = (dir.path / "huge.exr").string();
    InputErrors errors;
    CHECK(Terrain::loadChecked(s, errors).samples.empty());
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == s.heightmap);
    CHECK(errors[0].message.find("outside the accepted") != std::string::npos);
    map.samples[40] = 0.5f;
    REQUIRE(saveHeightmapExr(dir.path / "huge.exr", map, true) == "");
    errors.clear();
    CHECK(Terrain::loadChecked(s, errors).samples.size() == 81);
    CHECK(errors.empty());

    // A TIFF cut in half rendered with half its samples 0.
    {
        const fs::path tiff = dir.path / "cut.tif";
        auto out = OIIO::ImageOutput::create("tiff");
        OIIO::ImageSpec spec(256, 256, 1, OIIO::TypeDesc::UINT16);
        std::vector<std::uint16_t> px(256 * 256, 30000);
        REQUIRE(out->open(tiff.string(), spec));
        REQUIRE(out->write_image(OIIO::TypeDesc::UINT16, px.data()));
        REQUIRE(out->close());
        fs::resize_file(tiff, fs::file_size(tiff) / 2);
        InputErrors cut;
        CHECK(loadHeightmap(tiff, 0, 0, cut).samples.empty());
        REQUIRE(cut.size() == 1);
        CHECK(cut[0].file == tiff.string());
    }
}

TEST_CASE("file io: an interrupted quality report says it is incomplete") {
    QualityReport r;
    r.planned_runs = 3;
    r.runs.resize(1);
    r.runs[0].name = "reference";
    r.runs[0].kind = "preset";
    CHECK_FALSE(r.complete());
    CHECK(qualityCsv(r).rfind("# INCOMPLETE: 1 of 3 runs", 0) == 0);
    CHECK(qualityPassesCsv(r).rfind("# INCOMPLETE", 0) == 0);
    CHECK(qualityMarkdown(r, false).find("INCOMPLETE: 1 of 3 runs") != std::string::npos);
    r.runs.resize(3);
    CHECK(r.complete());
    CHECK(qualityCsv(r).rfind("name,", 0) == 0);
    CHECK(qualityMarkdown(r, false).find("INCOMPLETE") == std::string::npos);
}
