// Statistics aggregation and the stats JSON.
#include "app/stats.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cerrno>
#include <cstring>
#include <fstream>

namespace vista {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    auto mid = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), mid, values.end());
    if (values.size() % 2 == 1) return *mid;
    double upper = *mid;
    double lower = *std::max_element(values.begin(), mid);
    return 0.5 * (lower + upper);
}

void RunStats::addFrame(std::uint64_t index, double cpu_ms) {
    FrameStats& f = frames_[index];
    f.index = index;
    f.cpu_ms = cpu_ms;
}

void RunStats::addCounter(std::uint64_t index, const std::string& name, double value) {
    // GPU counters arrive frames late, so a warm-up frame's readback can come in after the first
    // recorded frame: it must not become a frame entry of its own (cpu_ms 0, no passes).
    auto it = frames_.find(index);
    if (it != frames_.end()) it->second.counters[name] = value;
}

void RunStats::addTimings(const std::vector<FrameTiming>& timings) {
    for (const auto& t : timings) {
        auto it = frames_.find(t.frame);
        if (it == frames_.end()) continue;  // warm-up frames are not recorded
        it->second.gpu_ms = t.gpu_ms;
        it->second.passes = t.passes;
    }
}

std::vector<PassSummary> RunStats::passSummary() const {
    std::vector<std::string> order;
    std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> samples;
    for (const auto& [index, f] : frames_)
        for (const auto& p : f.passes) {
            if (!samples.count(p.name)) order.push_back(p.name);
            samples[p.name].first.push_back(p.gpu_ms);
            samples[p.name].second.push_back(p.cpu_ms);
        }
    std::vector<PassSummary> out;
    for (const auto& name : order) {
        PassSummary s{name, median(samples[name].first), median(samples[name].second), 0.0};
        s.copies = reference_copy_ms > 0.0 ? s.gpu_ms / reference_copy_ms : 0.0;
        out.push_back(s);
    }
    return out;
}

double RunStats::gpuMedian() const {
    std::vector<double> v;
    for (const auto& [i, f] : frames_) v.push_back(f.gpu_ms);
    return median(v);
}

double RunStats::cpuMedian() const {
    std::vector<double> v;
    for (const auto& [i, f] : frames_) v.push_back(f.cpu_ms);
    return median(v);
}

std::string RunStats::json() const {
    using nlohmann::json;
    json frames = json::array();
    for (const auto& [index, f] : frames_) {
        json passes = json::object();
        for (const auto& p : f.passes) passes[p.name] = {{"gpu_ms", p.gpu_ms}, {"cpu_ms", p.cpu_ms}};
        json counters = json::object();
        for (const auto& [name, value] : f.counters) {
            // Counts print as integers, timings as decimals.
            if (value == std::floor(value) && std::abs(value) < 9.0e15)
                counters[name] = std::int64_t(value);
            else
                counters[name] = value;
        }
        frames.push_back({{"index", index}, {"cpu_ms", f.cpu_ms}, {"gpu_ms", f.gpu_ms}, {"passes", passes},
                          {"counters", counters}});
    }
    json doc = {{"renderer", renderer},
                {"backend", backend},
                {"gpu_timer", gpu_timer},
                {"size", {width, height}},
                {"passes_executed", executed},
                {"passes_culled", culled},
                {"reference_copy_ms", reference_copy_ms},
                {"frames", frames},
                {"summary", {{"gpu_ms_median", gpuMedian()}, {"cpu_ms_median", cpuMedian()}}}};
    return doc.dump(2) + "\n";
}

std::string RunStats::table() const {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "%-28s %10s %10s %10s\n", "pass", "GPU ms", "CPU ms", "copies");
    out += line;
    for (const auto& p : passSummary()) {
        std::snprintf(line, sizeof line, "%-28s %10.3f %10.3f %10.2f\n", p.name.c_str(), p.gpu_ms, p.cpu_ms, p.copies);
        out += line;
    }
    std::snprintf(line, sizeof line, "%-28s %10.3f %10.3f %10.2f\n", "frame (median)", gpuMedian(), cpuMedian(),
                  reference_copy_ms > 0 ? gpuMedian() / reference_copy_ms : 0.0);
    out += line;
    std::snprintf(line, sizeof line, "reference copy (RGBA16F %dx%d): %.3f ms GPU; renderer: %s (%s, %s timer)\n",
                  width, height, reference_copy_ms, renderer.c_str(), backend.c_str(), gpu_timer.c_str());
    out += line;
    return out;
}

int fail(int code, const std::string& message) {
    std::fprintf(stderr, "vista: %s\n", message.c_str());
    return code;
}

int writeBenchJson(const std::filesystem::path& file, const std::string& text, bool force) {
    if (file.empty()) return 0;
    std::string problem = writeFileAtomic(file, text, force);
    return problem.empty() ? 0 : fail(1, problem);
}

double passMs(const FrameTiming& t, const std::string& name) {
    for (const auto& p : t.passes)
        if (p.name == name) return p.gpu_ms;
    return 0.0;
}

}  // namespace vista
