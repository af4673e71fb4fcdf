// The render-farm commands: `vista encode DIR` (a finished image sequence to H.264),
// `vista farm merge DIR...` (check the shards' manifests fit together, then encode) and
// `vista farm slurm` (the sbatch commands of a job array of shards and a dependent merge job,
// printed or run). docs/farm.md has the whole workflow.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vista {

struct EncodeOptions {
    std::string dir;
    std::string out;    // default DIR/capture.mp4
    double fps = 0.0;   // 0: the manifest's fps, else 24
    int crf = 18;
    bool force = false;
};
// Exit code: 0, 2 (gaps, no frames), 1 (encoder failure).
int runEncode(const EncodeOptions& o);

struct MergeOptions {
    std::vector<std::string> dirs;
    std::string out;    // default FIRST_DIR/capture.mp4
    int crf = 18;
    bool force = false;
    bool check_only = false;  // check, do not encode
};
// Exit code: 0, 2 (mismatched scenes, overlapping or missing frames: all listed), 1 (encoder).
int runFarmMerge(const MergeOptions& o);

struct SlurmOptions {
    std::string vista;              // the executable the nodes run (default: this one, absolute)
    std::vector<std::string> capture_args;  // passed to every `vista capture` (path, size, --set ...)
    std::string out;                // the shards' common output directory (shared file system)
    int tasks = 1;
    std::string backend = "egl";    // egl on GPU nodes, osmesa on CPU nodes
    std::string partition;          // empty: the cluster's default
    std::string time_limit;         // sbatch --time, empty: the partition's default
    std::string gres;               // e.g. gpu:1 for GPU nodes
    int crf = 18;
    bool submit = false;            // run sbatch instead of printing the commands
};
// The two sbatch commands (array, then merge with --dependency=afterok) as shell text.
std::string slurmScript(const SlurmOptions& o, const std::filesystem::path& scripts_dir);
int runFarmSlurm(const SlurmOptions& o);

}  // namespace vista
