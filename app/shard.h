// Splitting a capture across processes and machines: which frames a shard or a frame range
// renders, the manifest each run writes beside its images (scene and path hashes, vista
// version, settings, every written frame with its checksum and time), and the checks that
// shards fit together before `vista farm merge` encodes them. No GL here: the unit tests
// cover it all (tests/unit/shard_test.cpp).
#pragma once

#include "config/settings.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vista {

// Frames [first, end) of a camera path capture.
struct FrameSpan {
    int first = 0;
    int end = 0;
    int count() const { return end - first; }
    bool operator==(const FrameSpan&) const = default;
};

// Which part of the path's frames a capture renders: --frames-range A:B (half-open, like
// Python's slices), then --shard K/N of that (K counts from 0, as SLURM_ARRAY_TASK_ID of an
// array --array=0-(N-1)).
struct FrameSelection {
    std::optional<FrameSpan> range;
    int shard = -1;  // -1: no --shard
    int shards = 0;
};

// "K/N" with 0 <= K < N <= 100000: "" or the message (naming --shard and what is accepted).
std::string parseShard(const std::string& text, int& shard, int& shards);
// "A:B" with 0 <= A < B: "" or the message.
std::string parseFrameRange(const std::string& text, FrameSpan& range);

// Shard k of n over span: contiguous blocks whose sizes differ by at most one frame (a block
// keeps one settle prologue, where interleaving would need one per frame). Empty when n > frames.
FrameSpan shardFrames(FrameSpan span, int k, int n);
// The frames selection renders out of total; "" or why not (range beyond the path's frames).
std::string selectFrames(const FrameSelection& selection, int total, FrameSpan& frames);

// The written frames as maximal runs of consecutive indices: each run gets its own settle
// frames (a resumed run renders the gaps it finds, each as a run of its own).
std::vector<FrameSpan> consecutiveRuns(const std::vector<int>& sorted_frames);

// 64-bit FNV-1a, as 16 hex digits; a checksum against truncation and mix-ups, not an attacker.
std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash = 0xcbf29ce484222325ull);
std::string hex64(std::uint64_t value);
// "fnv1a64:<hex>" of a file's bytes, or nullopt when it cannot be read.
std::optional<std::string> fileChecksum(const std::filesystem::path& file);

// vista's version and, when the build knew it, the commit: "0.1.0+3f2a9c1e0b7d". Shards of
// one capture must come from the same one.
std::string vistaVersion();
// Hash of everything that decides a frame's pixels: every setting (with [capture] out,
// frames, path, format and crf blanked: they do not change a frame) and the heightmap's
// bytes. The camera path has its own hash (pathHash: the file's bytes).
std::string sceneHash(const Settings& settings);
std::string pathHash(const std::filesystem::path& file);
// The settings as scene-file text (what sceneHash hashes, minus the heightmap's bytes).
std::string sceneText(const Settings& settings);

struct ManifestFrame {
    int index = 0;
    std::string file;      // relative to the manifest's directory
    std::string checksum;  // fileChecksum() of it
    double render_ms = 0;  // wall time to render, read back and write the frame
};

struct Manifest {
    std::string version, scene_hash, path_hash;
    std::string path_file;   // the camera path as given
    std::string settings;    // sceneText()
    int total_frames = 0;    // frames of the whole capture ([capture] frames)
    double fps = 0;
    int width = 0, height = 0;
    std::string format;      // png or exr (the frames' files)
    int shard = -1, shards = 0;
    FrameSpan span;          // the frames this run was asked for
    int settle_frames = 0;
    double settle_ms = 0;    // wall time of every settle frame of the run (all its runs of frames)
    double wall_s = 0;       // wall time of the run, start-up included
    bool complete = false;   // every frame of span written
    std::vector<ManifestFrame> frames;  // by index

    std::string json() const;
    // "" or the problem (file name and what is wrong).
    static std::string parse(const std::string& text, const std::string& name, Manifest& out);
    static std::string load(const std::filesystem::path& file, Manifest& out);
    const ManifestFrame* find(int index) const;
};

// The manifest's file name for a selection: manifest.json, manifest-shard-1-of-3.json,
// manifest-frames-10-20.json, manifest-frames-10-20-shard-1-of-3.json.
std::string manifestName(const FrameSelection& selection);

// Every manifest*.json directly in dir, sorted.
std::vector<std::filesystem::path> findManifests(const std::filesystem::path& dir);

struct LoadedManifest {
    std::filesystem::path file;
    Manifest manifest;
};

// What `vista farm merge` checks: the manifests share version, scene, path, frame count, fps and
// size; every frame 0..total-1 is present exactly once; every frame file still has its
// checksum (verify_files). problems is empty when they fit; frames then lists the files in
// frame order.
struct MergePlan {
    std::vector<std::string> problems;
    std::vector<std::filesystem::path> frames;
    double fps = 0;
    int width = 0, height = 0;
};
MergePlan planMerge(const std::vector<LoadedManifest>& manifests, bool verify_files = true);

// "3, 5-9, 12" for sorted indices.
std::string listRanges(const std::vector<int>& sorted);

}  // namespace vista
