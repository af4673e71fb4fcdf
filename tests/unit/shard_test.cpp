// Shard bookkeeping without GL: frame selection, manifests, the merge's checks and the
// encoder's failure path.
#include "app/image_writer.h"
#include "app/shard.h"
#include "app/video.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <unistd.h>

using namespace vista;

namespace {

struct Dir {
    std::filesystem::path path;
    explicit Dir(const std::string& name)
        : path(std::filesystem::temp_directory_path() / ("vista-unit-" + name + "-" + std::to_string(::getpid()))) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~Dir() { std::filesystem::remove_all(path); }
};

// A shard's manifest over frames [first, end) with real (tiny) files.
LoadedManifest shardManifest(const std::filesystem::path& dir, int first, int end, int total, const std::string& scene = "s1") {
    Manifest m;
    m.version = "v";
    m.scene_hash = scene;
    m.path_hash = "p";
    m.total_frames = total;
    m.fps = 2.0;
    m.width = 4;
    m.height = 2;
    m.format = "png";
    m.span = {first, end};
    for (int i = first; i < end; ++i) {
        const std::string name = "frame_" + std::to_string(i) + ".png";
        std::ofstream(dir / name) << "frame " << i;
        m.frames.push_back({i, name, *fileChecksum(dir / name), 1.0});
    }
    Manifest parsed;
    REQUIRE(Manifest::parse(m.json(), "test", parsed) == "");
    return {dir / ("manifest-" + std::to_string(first) + ".json"), parsed};
}

}  // namespace

TEST_CASE("farm: shards split the frames into contiguous blocks, each frame exactly once") {
    for (int total : {1, 2, 7, 100, 1001})
        for (int n : {1, 2, 3, 7, 16}) {
            std::vector<int> count(std::size_t(total), 0);
            int previous_end = 0;
            for (int k = 0; k < n; ++k) {
                FrameSpan s = shardFrames({0, total}, k, n);
                CHECK(s.first == previous_end);
                CHECK(s.count() >= total / n);
                CHECK(s.count() <= total / n + 1);
                for (int i = s.first; i < s.end; ++i) ++count[std::size_t(i)];
                previous_end = s.end;
            }
            CHECK(previous_end == total);
            CHECK(std::all_of(count.begin(), count.end(), [](int c) { return c == 1; }));
        }
    FrameSelection sel;
    sel.range = FrameSpan{10, 20};
    sel.shard = 1;
    sel.shards = 2;
    FrameSpan frames;
    CHECK(selectFrames(sel, 100, frames) == "");
    CHECK(frames == FrameSpan{15, 20});
    CHECK(selectFrames(sel, 19, frames).find("at most 19") != std::string::npos);
    CHECK(manifestName(sel) == "manifest-frames-10-20-shard-1-of-2.json");
}

TEST_CASE("farm: --shard and --frames-range parse K/N and A:B and name what they accept") {
    int k = 0, n = 0;
    CHECK(parseShard("2/3", k, n) == "");
    CHECK((k == 2 && n == 3));
    for (const char* bad : {"3/3", "-1/3", "1", "1/0", "a/b", "1/3x"}) CHECK(parseShard(bad, k, n).find("0 <= K < N") != std::string::npos);
    FrameSpan r;
    CHECK(parseFrameRange("5:9", r) == "");
    CHECK(r == FrameSpan{5, 9});
    for (const char* bad : {"9:5", "5:5", "-1:3", "5", "5:9:1"}) CHECK(parseFrameRange(bad, r).find("A:B") != std::string::npos);
    CHECK(listRanges({0, 1, 2, 5, 7, 8}) == "0-2, 5, 7-8");
    CHECK(consecutiveRuns({1, 2, 4}).size() == 2);
}

TEST_CASE("farm: merge accepts fitting shards and lists overlaps, gaps, changed files and other scenes") {
    Dir dir("merge");
    std::vector<LoadedManifest> shards{shardManifest(dir.path, 0, 4, 10), shardManifest(dir.path, 4, 10, 10)};
    MergePlan ok = planMerge(shards);
    CHECK(ok.problems.empty());
    REQUIRE(ok.frames.size() == 10);
    CHECK(ok.frames[7] == dir.path / "frame_7.png");

    std::vector<LoadedManifest> gap{shards[0], shardManifest(dir.path, 6, 10, 10)};
    MergePlan g = planMerge(gap);
    REQUIRE(g.problems.size() == 1);
    CHECK(g.problems[0].find("2 of 10 frames missing: 4-5") != std::string::npos);

    std::vector<LoadedManifest> overlap{shards[0], shardManifest(dir.path, 3, 10, 10)};
    MergePlan o = planMerge(overlap);
    REQUIRE(o.problems.size() == 1);
    CHECK(o.problems[0].find("frame 3 is in 2 manifests") != std::string::npos);

    std::vector<LoadedManifest> other{shards[0], shardManifest(dir.path, 4, 10, 10, "s2")};
    CHECK(planMerge(other).problems.at(0).find("scene hash s2 differs") != std::string::npos);

    std::ofstream(dir.path / "frame_2.png") << "changed";
    MergePlan changed = planMerge({shardManifest(dir.path, 4, 10, 10), shards[0]});
    REQUIRE(changed.problems.size() == 1);
    CHECK(changed.problems[0].find("frame_2.png changed since its manifest") != std::string::npos);
    CHECK(planMerge({}).problems.size() == 1);
}

TEST_CASE("farm: manifests round-trip through JSON and reject paths outside their directory") {
    Dir dir("manifest");
    LoadedManifest m = shardManifest(dir.path, 2, 5, 8);
    CHECK(m.manifest.frames.size() == 3);
    CHECK(m.manifest.find(3) != nullptr);
    CHECK(m.manifest.find(5) == nullptr);
    Manifest bad;
    std::string text = m.manifest.json();
    text.replace(text.find("frame_2.png"), 11, "../secret");
    CHECK(Manifest::parse(text, "x.json", bad).find("plain file name") != std::string::npos);
    CHECK(Manifest::parse("{}", "x.json", bad).find("x.json: not a vista capture manifest") == 0);
}

TEST_CASE("farm: an encoder failure is reported with its message and leaves no video") {
    Dir dir("encode");
    std::vector<unsigned char> rgba(6 * 4 * 4, 128);
    std::vector<std::filesystem::path> frames;
    for (int i = 0; i < 2; ++i) {
        frames.push_back(dir.path / ("frame_000" + std::to_string(i) + ".png"));
        REQUIRE(writePng(frames.back(), 6, 4, rgba, /*force=*/false) == "");
    }
    // A stand-in encoder that says why and fails, as ffmpeg does on a full disk.
    const std::filesystem::path fake = dir.path / "fake-ffmpeg";
    std::ofstream(fake) << "#!/bin/sh\ncat > /dev/null\necho 'No space left on device' >&2\nexit 1\n";
    std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
    ::setenv("VISTA_FFMPEG", fake.c_str(), 1);
    std::string problem = encodeVideo(frames, dir.path / "out.mp4", {});
    ::unsetenv("VISTA_FFMPEG");
    CHECK(problem.find("failed (exit status 1)") != std::string::npos);
    CHECK(problem.find("No space left on device") != std::string::npos);
    for (const auto& entry : std::filesystem::directory_iterator(dir.path))
        CHECK(entry.path().filename().string().rfind("out.mp4", 0) != 0);  // no video, no temporary, no log

    std::vector<std::string> problems;
    CHECK(findFrameSequence(dir.path, problems).size() == 2);
    CHECK(problems.empty());
    std::filesystem::rename(frames[1], dir.path / "frame_0003.png");
    findFrameSequence(dir.path, problems);
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].find("missing from the sequence: 1-2") != std::string::npos);
}
