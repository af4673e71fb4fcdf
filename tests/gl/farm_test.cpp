// Capture shards against one sequential run: frame k is the same whichever run renders it
// (settle frames after FrameRenderer::resetHistory()), --resume keeps only what its manifest
// vouches for, and an mp4 capture leaves a video. Small sizes, few frames.
#include "app/capture.h"
#include "app/scene.h"
#include "app/shard.h"
#include "config/ini.h"
#include "gl_fixture.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

using namespace vista;

namespace {

CaptureJob farmJob(const std::filesystem::path& out, const std::vector<std::string>& overrides, int frames,
                   float fps = 4.0f) {
    CaptureJob job;
    REQUIRE(loadScene(defaultScenePath(), overrides, job.settings).empty());
    job.settings.capture.out = out.string();
    job.settings.capture.frames = frames;
    job.settings.capture.fps = fps;  // 4: 0.25 s steps, adaptation is far from settled between frames
    job.settings.capture.width = 64;
    job.settings.capture.height = 36;
    job.progress = false;
    return job;
}

std::vector<unsigned char> pixels(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    REQUIRE(in);
    std::vector<unsigned char> p(std::size_t(in->spec().width) * in->spec().height * in->spec().nchannels);
    REQUIRE(in->read_image(0, 0, 0, -1, OIIO::TypeDesc::UINT8, p.data()));
    return p;
}

struct Difference {
    int worst = 0;               // largest 8-bit difference of any channel
    double psnr_db = 1.0e9;      // PSNR of the 8-bit RGB images (peak 255); huge when identical
};

Difference difference(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::vector<unsigned char> pa = pixels(a), pb = pixels(b);
    REQUIRE(pa.size() == pb.size());
    Difference d;
    double sum = 0.0;
    for (std::size_t i = 0; i < pa.size(); ++i) {
        const int e = std::abs(int(pa[i]) - int(pb[i]));
        d.worst = std::max(d.worst, e);
        sum += double(e) * e;
    }
    if (sum > 0.0) d.psnr_db = 10.0 * std::log10(255.0 * 255.0 / (sum / double(pa.size())));
    return d;
}

// Renders frames sequentially and as shards of 2; the largest 8-bit difference and the lowest
// PSNR of any frame.
Difference shardDifference(const std::string& name, const std::vector<std::string>& overrides, int frames,
                           float fps = 4.0f) {
    test::TempDir dir(name);
    CaptureJob seq = farmJob(dir.path / "seq", overrides, frames, fps);
    REQUIRE(runCapture(seq).exit_code == 0);
    for (int k = 0; k < 2; ++k) {
        CaptureJob shard = farmJob(dir.path / "shards", overrides, frames, fps);
        shard.selection.shard = k;
        shard.selection.shards = 2;
        CaptureResult r = runCapture(shard);
        REQUIRE(r.exit_code == 0);
        CHECK(r.images.size() == std::size_t(frames / 2));
        // The run's settle frames, and cut_settle_frames more before each written frame the camera cuts to.
        const int settle = shard.settings.capture.settle_frames, cut_settle = shard.settings.capture.cut_settle_frames;
        CHECK(r.settle_frames >= settle);
        if (cut_settle > 0) CHECK((r.settle_frames - settle) % cut_settle == 0);
        CHECK(std::filesystem::exists(dir.path / "shards" / ("manifest-shard-" + std::to_string(k) + "-of-2.json")));
    }
    Difference worst;
    for (int i = 0; i < frames; ++i) {
        const Difference d = difference(captureFileName(dir.path / "seq", i, ImageFormat::Png),
                                        captureFileName(dir.path / "shards", i, ImageFormat::Png));
        worst.worst = std::max(worst.worst, d.worst);
        worst.psnr_db = std::min(worst.psnr_db, d.psnr_db);
    }
    // The shards fit together as one capture.
    std::vector<LoadedManifest> manifests;
    for (const auto& file : findManifests(dir.path / "shards")) {
        LoadedManifest m{file, {}};
        REQUIRE(Manifest::load(file, m.manifest) == "");
        manifests.push_back(m);
    }
    MergePlan plan = planMerge(manifests);
    CHECK(plan.problems.empty());
    CHECK(plan.frames.size() == std::size_t(frames));
    return worst;
}

}  // namespace

TEST_CASE("gl: capture shards with finite-memory state (motion blur, weather) are bit-identical to a sequential run") {
    // Motion blur keeps the previous camera and weather its previous position: one frame of
    // memory, so two settle frames rebuild them exactly. Manual exposure: no infinite memory.
    // TAA and the clouds' accumulation off: their histories are exponential (the next test).
    const Difference d = shardDifference("farm-finite",
                                         {"postfx.motion_blur.enabled=true", "weather.enabled=true",
                                          "postfx.exposure.mode=manual", "postfx.taa.enabled=false",
                                          "clouds.temporal=false", "capture.settle_frames=2"},
                                         4);
    CHECK(d.worst == 0);
}

TEST_CASE("gl: capture shards of the default scene (auto exposure, TAA, temporal clouds) stay within the stated tolerance") {
    // Auto exposure, TAA and the clouds' accumulation all blend exponentially (infinite
    // memory): a shard's first frame keeps a trace of a history that started S frames later
    // than the sequential run's, so frames are not bit-identical. The jitter and blue-noise
    // index follow the path frame (not the frames since the reset), so that trace is all that
    // differs. 24 fps: the default path moves ~18 m a frame, under the 100 m camera cut (at 4
    // fps every frame would be a cut and keep no history). The tolerance docs/farm.md states for
    // the default settle frames (8): PSNR of every 8-bit frame against the sequential run's
    // >= 40 dB (measured on the default path at 320x180: 44.4 dB).
    const Difference d =
        shardDifference("farm-temporal", {"postfx.taa.enabled=true", "clouds.temporal=true"}, 4, 24.0f);
    MESSAGE("default scene, shards of 2 against a sequential run: largest difference " << d.worst << ", lowest PSNR "
                                                                                       << d.psnr_db << " dB");
    CHECK(d.psnr_db >= 40.0);
}

TEST_CASE("gl: a capture settles each frame the camera cuts to at its own pose, and shards render the same") {
    // 4 fps: every frame of the default path is a camera cut (> 100 m a frame), so without
    // cut_settle_frames each written frame is one history-free frame. Frame 2 against the same
    // frame settled far longer (32): 8 cut settle frames must bring it much closer than none.
    // Manual exposure, so only the histories (TAA, temporal clouds) differ.
    test::TempDir dir("farm-cut");
    auto frame2 = [&](int cut_settle) {
        CaptureJob job = farmJob(dir.path / std::to_string(cut_settle),
                                 {"postfx.exposure.mode=manual", "capture.cut_settle_frames=" + std::to_string(cut_settle)}, 3);
        job.settings.capture.width = 160;
        job.settings.capture.height = 90;
        const CaptureResult r = runCapture(job);
        REQUIRE(r.exit_code == 0);
        CHECK(r.settle_frames == job.settings.capture.settle_frames + 2 * cut_settle);  // frames 1 and 2 are cuts
        return captureFileName(dir.path / std::to_string(cut_settle), 2, ImageFormat::Png);
    };
    const auto converged = frame2(32), none = frame2(0), settled = frame2(8);
    const double none_db = difference(none, converged).psnr_db, settled_db = difference(settled, converged).psnr_db;
    MESSAGE("frame 2 (a cut) against 32 cut settle frames: none " << none_db << " dB, 8: " << settled_db << " dB");
    CHECK(settled_db > none_db + 3.0);

    // Shards of 2 against one run: the cut frames settle alike whichever process renders them.
    const Difference d = shardDifference("farm-cut-shards", {}, 4);
    MESSAGE("default scene at 4 fps (every frame a cut), shards against a sequential run: largest difference " << d.worst
            << ", lowest PSNR " << d.psnr_db << " dB");
    CHECK(d.psnr_db >= 40.0);
}

TEST_CASE("gl: capture --resume keeps frames matching the manifest and renders the rest") {
    test::TempDir dir("farm-resume");
    // Checksums must match, so no exponential history: TAA, the clouds' accumulation and auto
    // exposure off (the blue noise changes the clouds' grain with the frame index, so frames -1
    // and 0, both at the path's start, no longer give the adaptation the same image); one settle
    // frame rebuilds everything else.
    const std::vector<std::string> overrides{"capture.settle_frames=1", "postfx.taa.enabled=false", "clouds.temporal=false",
                                             "postfx.exposure.mode=manual"};
    CaptureJob job = farmJob(dir.path, overrides, 3);
    REQUIRE(runCapture(job).exit_code == 0);
    const auto frame1 = captureFileName(dir.path, 1, ImageFormat::Png);
    const std::string before = *fileChecksum(frame1);
    std::filesystem::remove(captureFileName(dir.path, 2, ImageFormat::Png));
    {
        std::ofstream damaged(frame1, std::ios::binary | std::ios::trunc);
        damaged << "not a png";
    }
    CHECK(runCapture(job).exit_code == 2);  // files exist, neither --force nor --resume
    job.resume = true;
    CaptureResult r = runCapture(job);
    REQUIRE(r.exit_code == 0);
    CHECK(r.kept == 1);                    // frame 0
    CHECK(r.images.size() == 2);           // frame 1 (damaged) and 2 (missing)
    CHECK(r.settle_frames == 1);  // one run of frames, 1..2 (cuts, but no history to settle)
    CHECK(*fileChecksum(frame1) == before);  // the same frame as the first run's
    Manifest m;
    REQUIRE(Manifest::load(dir.path / "manifest.json", m) == "");
    CHECK(m.complete);
    CHECK(m.frames.size() == 3);

    // A manifest of another scene is not resumed.
    std::vector<std::string> other_overrides = overrides;
    other_overrides.push_back("sky.sun_elevation_deg=20");
    CaptureJob other = farmJob(dir.path, other_overrides, 3);
    other.resume = true;
    CHECK(runCapture(other).exit_code == 2);
}

TEST_CASE("gl: capture --format mp4 writes the frames and an H.264 video") {
    test::TempDir dir("farm-mp4");
    CaptureJob job = farmJob(dir.path, {"capture.settle_frames=0"}, 2);
    job.settings.capture.format = ImageFormat::Mp4;
    CaptureResult r = runCapture(job);
    REQUIRE(r.exit_code == 0);
    CHECK(r.video == dir.path / "capture.mp4");
    CHECK(std::filesystem::file_size(dir.path / "capture.mp4") > 100);
    auto in = OIIO::ImageInput::open(captureFileName(dir.path, 1, ImageFormat::Png).string());
    CHECK(in);
}
