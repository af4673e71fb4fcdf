// Farm commands over shard.h (manifests, merge checks) and video.h (the encoder).
#include "app/farm.h"

#include "app/scene.h"
#include "app/shard.h"
#include "app/stats.h"
#include "app/video.h"

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace vista {
namespace {

// Single quotes for a POSIX shell.
std::string quote(const std::string& word) {
    std::string q = "'";
    for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::filesystem::path selfExecutable() {
    std::error_code ec;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path("vista") : self;
}

}  // namespace

int runEncode(const EncodeOptions& o) {
    std::vector<std::string> problems;
    std::vector<std::filesystem::path> frames = findFrameSequence(o.dir, problems);
    if (!problems.empty()) {
        for (const std::string& p : problems) std::fprintf(stderr, "vista: %s\n", p.c_str());
        return 2;
    }
    double fps = o.fps;
    if (fps <= 0.0) {
        fps = 24.0;
        for (const auto& file : findManifests(o.dir)) {
            Manifest m;
            if (Manifest::load(file, m).empty()) fps = m.fps;
        }
    }
    const std::filesystem::path out = o.out.empty() ? std::filesystem::path(o.dir) / "capture.mp4" : std::filesystem::path(o.out);
    std::string problem = encodeVideo(frames, out, {fps, o.crf, o.force});
    if (!problem.empty()) return fail(problem.find("already exists") != std::string::npos ? 2 : 1, problem);
    std::printf("vista: encoded %zu frame(s) at %g fps into %s\n", frames.size(), fps, out.c_str());
    return 0;
}

int runFarmMerge(const MergeOptions& o) {
    std::vector<LoadedManifest> manifests;
    std::vector<std::string> problems;
    for (const std::string& dir : o.dirs) {
        if (!std::filesystem::is_directory(dir)) {
            problems.push_back(dir + ": not a directory");
            continue;
        }
        std::vector<std::filesystem::path> files = findManifests(dir);
        if (files.empty()) problems.push_back(dir + ": no manifest*.json (not a vista capture directory)");
        for (const auto& file : files) {
            LoadedManifest m{file, {}};
            if (std::string problem = Manifest::load(file, m.manifest); !problem.empty())
                problems.push_back(problem);
            else
                manifests.push_back(std::move(m));
        }
    }
    MergePlan plan = planMerge(manifests);
    problems.insert(problems.end(), plan.problems.begin(), plan.problems.end());
    if (!problems.empty()) {
        for (const std::string& p : problems) std::fprintf(stderr, "vista: %s\n", p.c_str());
        std::fprintf(stderr, "vista: %zu problem(s); nothing encoded\n", problems.size());
        return 2;
    }
    std::printf("vista: %zu manifest(s) agree (version %s, scene %s, path %s); %zu frames present once each, "
                "checksums match\n",
                manifests.size(), manifests[0].manifest.version.c_str(), manifests[0].manifest.scene_hash.c_str(),
                manifests[0].manifest.path_hash.c_str(), plan.frames.size());
    if (o.check_only) return 0;
    const std::filesystem::path out =
        o.out.empty() ? std::filesystem::path(o.dirs.front()) / "capture.mp4" : std::filesystem::path(o.out);
    std::string problem = encodeVideo(plan.frames, out, {plan.fps, o.crf, o.force});
    if (!problem.empty()) return fail(problem.find("already exists") != std::string::npos ? 2 : 1, problem);
    std::printf("vista: encoded %zu frame(s) at %g fps into %s\n", plan.frames.size(), plan.fps, out.c_str());
    return 0;
}

std::string slurmScript(const SlurmOptions& o, const std::filesystem::path& scripts_dir) {
    const std::string vista = o.vista.empty() ? selfExecutable().string() : o.vista;
    std::string common = "--chdir=" + quote(std::filesystem::current_path().string());
    if (!o.partition.empty()) common += " --partition=" + quote(o.partition);
    if (!o.time_limit.empty()) common += " --time=" + quote(o.time_limit);
    std::string array = "sbatch --parsable " + common + " --job-name=vista-capture --array=0-" + std::to_string(o.tasks - 1);
    if (!o.gres.empty()) array += " --gres=" + quote(o.gres);
    array += " --output=" + quote(o.out + "/slurm-%A_%a.log") + " " + quote((scripts_dir / "capture-array.sbatch").string()) +
             " " + quote(vista) + " " + quote(o.backend) + " --out " + quote(o.out);
    for (const std::string& a : o.capture_args) array += " " + quote(a);
    std::string merge = "sbatch --parsable " + common + " --job-name=vista-merge --dependency=afterok:\"$array_job\"" +
                        " --output=" + quote(o.out + "/slurm-merge-%j.log") + " " +
                        quote((scripts_dir / "merge.sbatch").string()) + " " + quote(vista) + " " + quote(o.out) +
                        " --crf " + std::to_string(o.crf);
    return "mkdir -p " + quote(o.out) + " &&\narray_job=$(" + array + ") &&\nmerge_job=$(" + merge +
           ") &&\necho \"vista: capture array job $array_job (" + std::to_string(o.tasks) +
           " tasks), merge job $merge_job\"\n";
}

int runFarmSlurm(const SlurmOptions& o) {
    const std::filesystem::path scripts = vistaRoot() / "tools" / "slurm";
    if (!std::filesystem::exists(scripts / "capture-array.sbatch"))
        return fail(1, (scripts / "capture-array.sbatch").string() + ": missing (tools/slurm/ of the vista checkout)");
    std::string script = slurmScript(o, scripts);
    if (!o.submit) {
        std::printf("%s", script.c_str());
        return 0;
    }
    std::fflush(stdout);
    int status = std::system(script.c_str());
    if (status != 0) return fail(1, "sbatch failed (exit status " + std::to_string(status) + "); the commands were:\n" + script);
    return 0;
}

}  // namespace vista
