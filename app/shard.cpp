// Shards and manifests: the bookkeeping that lets frames rendered by different processes be
// checked, resumed and merged. The manifest is JSON (nlohmann) so scripts can read it too.
#include "app/shard.h"

#include "app/scene.h"
#include "config/ini.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#ifndef VISTA_COMMIT
#define VISTA_COMMIT ""
#endif

namespace vista {
namespace {

constexpr const char* kVersion = "0.1.0";

std::optional<std::string> readAll(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return std::nullopt;
    return text.str();
}

}  // namespace

std::string parseShard(const std::string& text, int& shard, int& shards) {
    int k = 0, n = 0;
    char slash = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &k, &slash, &n, &extra) != 3 || slash != '/' || n < 1 || n > 100000 ||
        k < 0 || k >= n)
        return "--shard " + text + ": expected K/N with 0 <= K < N <= 100000 (K counts from 0, e.g. 0/3, 1/3, 2/3)";
    shard = k;
    shards = n;
    return {};
}

std::string parseFrameRange(const std::string& text, FrameSpan& range) {
    int a = 0, b = 0;
    char colon = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &a, &colon, &b, &extra) != 3 || colon != ':' || a < 0 || b <= a)
        return "--frames-range " + text + ": expected A:B with 0 <= A < B (frames A to B-1, e.g. 0:100)";
    range = {a, b};
    return {};
}

FrameSpan shardFrames(FrameSpan span, int k, int n) {
    const long long count = span.count();
    return {span.first + int(count * k / n), span.first + int(count * (k + 1) / n)};
}

std::string selectFrames(const FrameSelection& selection, int total, FrameSpan& frames) {
    frames = {0, total};
    if (selection.range) {
        if (selection.range->end > total)
            return "--frames-range " + std::to_string(selection.range->first) + ":" + std::to_string(selection.range->end) +
                   ": the capture has " + std::to_string(total) + " frames (0.." + std::to_string(total - 1) +
                   "); B may be at most " + std::to_string(total);
        frames = *selection.range;
    }
    if (selection.shard >= 0) frames = shardFrames(frames, selection.shard, selection.shards);
    return {};
}

std::vector<FrameSpan> consecutiveRuns(const std::vector<int>& sorted_frames) {
    std::vector<FrameSpan> runs;
    for (int frame : sorted_frames) {
        if (!runs.empty() && runs.back().end == frame)
            ++runs.back().end;
        else
            runs.push_back({frame, frame + 1});
    }
    return runs;
}

std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash) {
    for (unsigned char c : bytes) {
        hash ^= c;
        hash *= 0x100000001b3ull;
    }
    return hash;
}

std::string hex64(std::uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

std::optional<std::string> fileChecksum(const std::filesystem::path& file) {
    std::optional<std::string> bytes = readAll(file);
    if (!bytes) return std::nullopt;
    return "fnv1a64:" + hex64(fnv1a64(*bytes));
}

std::string vistaVersion() {
    const std::string commit = VISTA_COMMIT;
    return commit.empty() ? kVersion : std::string(kVersion) + "+" + commit;
}

std::string sceneText(const Settings& settings) {
    Settings s = settings;
    s.capture.out.clear();
    s.capture.path.clear();
    s.capture.frames = 1;
    s.capture.crf = 0;
    if (s.capture.format == ImageFormat::Mp4) s.capture.format = ImageFormat::Png;  // the same PNG frames
    return saveIniString(s);
}

namespace {

// Files up to this size are hashed whole; a larger map (a 4 GB gen-heightmap TIFF, streamed from
// its tile cache) by its size, modification time and first kInputHashBytes: reading it all took
// longer than the time to first frame allows, and held it in memory twice.
constexpr std::uintmax_t kInputHashBytes = std::uintmax_t(256) << 20;

// hash, continued over an input file's bytes (read a chunk at a time); unchanged when unreadable.
std::uint64_t hashInput(const std::filesystem::path& file, std::uint64_t hash) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return hash;
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    if (!ec && size > kInputHashBytes) {
        const auto time = std::filesystem::last_write_time(file, ec).time_since_epoch().count();
        hash = fnv1a64("size " + std::to_string(size) + " time " + std::to_string(time), hash);
    }
    std::string chunk(std::size_t(1) << 20, '\0');
    for (std::uintmax_t done = 0; in && done < kInputHashBytes; done += chunk.size()) {
        in.read(chunk.data(), std::streamsize(chunk.size()));
        hash = fnv1a64(std::string_view(chunk.data(), std::size_t(in.gcount())), hash);
    }
    return hash;
}

}  // namespace

std::string sceneHash(const Settings& settings) {
    std::uint64_t hash = fnv1a64(sceneText(settings));
    if (settings.terrain.enabled && !settings.terrain.heightmap.empty())
        hash = hashInput(resolveInput(settings.terrain.heightmap), hash);
    if (settings.terrain.enabled && !settings.terrain.dem.empty())  // a VRT's own text only, not its sources
        hash = hashInput(resolveInput(settings.terrain.dem), hash);
    return hex64(hash);
}

std::string pathHash(const std::filesystem::path& file) {
    std::optional<std::string> bytes = readAll(file);
    return bytes ? hex64(fnv1a64(*bytes)) : std::string("unreadable");
}

std::string Manifest::json() const {
    nlohmann::json j;
    j["vista_version"] = version;
    j["scene_hash"] = scene_hash;
    j["path_hash"] = path_hash;
    j["path"] = path_file;
    j["total_frames"] = total_frames;
    j["fps"] = fps;
    j["size"] = {width, height};
    j["format"] = format;
    if (shard >= 0) j["shard"] = {shard, shards};
    j["span"] = {span.first, span.end};
    j["settle_frames"] = settle_frames;
    j["settle_ms"] = settle_ms;
    j["wall_s"] = wall_s;
    j["complete"] = complete;
    nlohmann::json list = nlohmann::json::array();
    for (const ManifestFrame& f : frames)
        list.push_back({{"index", f.index}, {"file", f.file}, {"checksum", f.checksum}, {"render_ms", f.render_ms}});
    j["frames"] = std::move(list);
    j["settings"] = settings;
    return j.dump(2) + "\n";
}

std::string Manifest::parse(const std::string& text, const std::string& name, Manifest& out) {
    try {
        const nlohmann::json j = nlohmann::json::parse(text);
        Manifest m;
        m.version = j.at("vista_version").get<std::string>();
        m.scene_hash = j.at("scene_hash").get<std::string>();
        m.path_hash = j.at("path_hash").get<std::string>();
        m.path_file = j.value("path", "");
        m.total_frames = j.at("total_frames").get<int>();
        m.fps = j.at("fps").get<double>();
        m.width = j.at("size").at(0).get<int>();
        m.height = j.at("size").at(1).get<int>();
        m.format = j.at("format").get<std::string>();
        if (j.contains("shard")) {
            m.shard = j["shard"].at(0).get<int>();
            m.shards = j["shard"].at(1).get<int>();
        }
        m.span = {j.at("span").at(0).get<int>(), j.at("span").at(1).get<int>()};
        m.settle_frames = j.value("settle_frames", 0);
        m.settle_ms = j.value("settle_ms", 0.0);
        m.wall_s = j.value("wall_s", 0.0);
        m.complete = j.value("complete", false);
        m.settings = j.value("settings", "");
        for (const auto& f : j.at("frames")) {
            ManifestFrame frame{f.at("index").get<int>(), f.at("file").get<std::string>(), f.at("checksum").get<std::string>(),
                                f.value("render_ms", 0.0)};
            if (frame.file.empty() || frame.file.find('/') != std::string::npos || frame.file.find('\\') != std::string::npos)
                return name + ": frame " + std::to_string(frame.index) + ": file '" + frame.file +
                       "' must be a plain file name in the manifest's directory";
            m.frames.push_back(std::move(frame));
        }
        std::sort(m.frames.begin(), m.frames.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
        out = std::move(m);
        return {};
    } catch (const nlohmann::json::exception& e) {
        return name + ": not a vista capture manifest (" + e.what() + ")";
    }
}

std::string Manifest::load(const std::filesystem::path& file, Manifest& out) {
    std::optional<std::string> text = readAll(file);
    if (!text) return file.string() + ": cannot read the manifest";
    return parse(*text, file.string(), out);
}

const ManifestFrame* Manifest::find(int index) const {
    auto it = std::lower_bound(frames.begin(), frames.end(), index, [](const auto& f, int i) { return f.index < i; });
    return it != frames.end() && it->index == index ? &*it : nullptr;
}

std::string manifestName(const FrameSelection& selection) {
    std::string name = "manifest";
    if (selection.range) name += "-frames-" + std::to_string(selection.range->first) + "-" + std::to_string(selection.range->end);
    if (selection.shard >= 0) name += "-shard-" + std::to_string(selection.shard) + "-of-" + std::to_string(selection.shards);
    return name + ".json";
}

std::vector<std::filesystem::path> findManifests(const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file() && name.rfind("manifest", 0) == 0 && entry.path().extension() == ".json")
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::string listRanges(const std::vector<int>& sorted) {
    std::string text;
    for (const FrameSpan& run : consecutiveRuns(sorted)) {
        if (!text.empty()) text += ", ";
        text += std::to_string(run.first);
        if (run.count() > 1) text += "-" + std::to_string(run.end - 1);
    }
    return text;
}

MergePlan planMerge(const std::vector<LoadedManifest>& manifests, bool verify_files) {
    MergePlan plan;
    if (manifests.empty()) {
        plan.problems.push_back("no manifest*.json found: give the directories the capture shards wrote");
        return plan;
    }
    const LoadedManifest& first = manifests.front();
    const Manifest& ref = first.manifest;
    plan.fps = ref.fps;
    plan.width = ref.width;
    plan.height = ref.height;
    auto differs = [&](const LoadedManifest& m, const std::string& what, const std::string& value, const std::string& expected) {
        plan.problems.push_back(m.file.string() + ": " + what + " " + value + " differs from " + expected + " in " +
                                first.file.string());
    };
    std::map<int, std::vector<std::filesystem::path>> where;  // frame -> files naming it
    std::map<int, std::filesystem::path> file_of;
    for (const LoadedManifest& m : manifests) {
        const Manifest& x = m.manifest;
        if (x.version != ref.version) differs(m, "vista version", x.version, ref.version);
        if (x.scene_hash != ref.scene_hash) differs(m, "scene hash", x.scene_hash, ref.scene_hash);
        if (x.path_hash != ref.path_hash) differs(m, "camera path hash", x.path_hash, ref.path_hash);
        if (x.total_frames != ref.total_frames)
            differs(m, "frame count", std::to_string(x.total_frames), std::to_string(ref.total_frames));
        if (x.fps != ref.fps) differs(m, "fps", std::to_string(x.fps), std::to_string(ref.fps));
        if (x.width != ref.width || x.height != ref.height)
            differs(m, "size", std::to_string(x.width) + "x" + std::to_string(x.height),
                    std::to_string(ref.width) + "x" + std::to_string(ref.height));
        if (x.format != ref.format) differs(m, "format", x.format, ref.format);
        for (const ManifestFrame& f : x.frames) {
            const std::filesystem::path file = m.file.parent_path() / f.file;
            where[f.index].push_back(m.file);
            file_of[f.index] = file;
            if (f.index < 0 || f.index >= ref.total_frames) {
                plan.problems.push_back(m.file.string() + ": frame " + std::to_string(f.index) + " is outside the capture's 0.." +
                                        std::to_string(ref.total_frames - 1));
                continue;
            }
            if (!verify_files) continue;
            std::optional<std::string> sum = fileChecksum(file);
            if (!sum)
                plan.problems.push_back("frame " + std::to_string(f.index) + ": " + file.string() + " is missing or unreadable");
            else if (*sum != f.checksum)
                plan.problems.push_back("frame " + std::to_string(f.index) + ": " + file.string() +
                                        " changed since its manifest (checksum " + *sum + ", manifest " + f.checksum + ")");
        }
    }
    std::vector<int> missing;
    for (int i = 0; i < ref.total_frames; ++i) {
        auto it = where.find(i);
        if (it == where.end()) {
            missing.push_back(i);
        } else if (it->second.size() > 1) {
            std::string list;
            for (const auto& file : it->second) list += (list.empty() ? "" : ", ") + file.string();
            plan.problems.push_back("frame " + std::to_string(i) + " is in " + std::to_string(it->second.size()) +
                                    " manifests (overlapping shards): " + list);
        }
    }
    if (!missing.empty())
        plan.problems.push_back(std::to_string(missing.size()) + " of " + std::to_string(ref.total_frames) +
                                " frames missing: " + listRanges(missing) + " (rerun their shards with --resume)");
    if (plan.problems.empty())
        for (int i = 0; i < ref.total_frames; ++i) plan.frames.push_back(file_of[i]);
    return plan;
}

}  // namespace vista
