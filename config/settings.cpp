// The scene's settings: the application's own sections (window, camera, capture), and the
// describe() of the whole Settings that lists every feature's sections in file order.
#include "config/settings.h"

#include <array>

namespace vista {
namespace {

void describe(SettingsVisitor& v, WindowSettings& s) {
    v.section("window", "window and GL context");
    v.field({"width", "px", "window width"}, s.width, 1, 16384);
    v.field({"height", "px", "window height"}, s.height, 1, 16384);
    v.field({"fullscreen", "", "fullscreen on the primary monitor"}, s.fullscreen);
    v.field({"vsync", "", "wait for vertical sync"}, s.vsync);
    v.field({"gl_debug", "", "print GL errors and warnings through KHR_debug"}, s.gl_debug);
}

void describe(SettingsVisitor& v, CameraSettings& s) {
    v.section("camera", "start pose and free-fly controls");
    v.field({"position", "m", "start position x y z (y up)"}, s.position, -1e8, 1e8);
    v.field({"yaw_deg", "deg", "start heading, 0 looks along -z, positive turns right"}, s.yaw_deg, -360.0f, 360.0f);
    v.field({"pitch_deg", "deg", "start pitch, positive looks up"}, s.pitch_deg, -89.0f, 89.0f);
    v.field({"fov_deg", "deg", "vertical field of view"}, s.fov_deg, 5.0f, 120.0f);
    v.field({"near_m", "m", "near plane (the far plane is at infinity)"}, s.near_m, 0.001f, 100.0f);
    v.field({"move_speed", "m/s", "WASD speed"}, s.move_speed, 0.01f, 100000.0f);
    v.field({"fast_multiplier", "x", "speed factor with Shift"}, s.fast_multiplier, 1.0f, 1000.0f);
    v.field({"slow_multiplier", "x", "speed factor with Ctrl"}, s.slow_multiplier, 0.001f, 1.0f);
    v.field({"mouse_sensitivity", "deg/px", "mouse look"}, s.mouse_sensitivity, 0.001f, 10.0f);
    v.field({"zoom_sensitivity", "deg", "field of view change per scroll step"}, s.zoom_sensitivity, 0.0f, 30.0f);
    v.field({"updown_speed", "x", "factor on move_speed for Q/E"}, s.updown_speed, 0.0f, 100.0f);
    v.field({"follow_terrain", "", "walk: keep the eye at eye_height_m above the ground"}, s.follow_terrain);
    v.field({"eye_height_m", "m", "eye height above the ground when following the terrain"}, s.eye_height_m, 0.01f, 1000.0f);
    v.field({"allow_below_ground", "", "the free camera may go below the terrain surface"}, s.allow_below_ground);
}

void describe(SettingsVisitor& v, CaptureSettings& s) {
    static constexpr std::array<const char*, 3> formats{"png", "exr", "mp4"};
    v.section("capture", "headless rendering of a camera path");
    v.field({"path", "", "camera path file"}, s.path);
    v.field({"frames", "", "frames to render"}, s.frames, 1, 1000000);
    v.field({"fps", "1/s", "frames per second of path time"}, s.fps, 0.01f, 1000.0f);
    v.field({"width", "px", "image width"}, s.width, 1, 16384);
    v.field({"height", "px", "image height"}, s.height, 1, 16384);
    v.choice({"format", "", "png: 8-bit sRGB after tone mapping; exr: linear half-float HDR; mp4: the PNG frames, then "
                            "an H.264 video of them (out/capture.mp4, through ffmpeg)"},
             s.format, formats);
    v.field({"out", "", "output directory"}, s.out);
    v.field({"settle_frames", "frames",
             "frames rendered but not written before a run's first written frame (at the path times of the frames "
             "before it), so temporal state (auto exposure, autofocus, motion blur, weather, history) is the same "
             "whichever shard or resumed run renders a frame; adaptation settles by exp(-rate * settle_frames / fps)"},
            s.settle_frames, 0, 10000);
    v.field({"cut_settle_frames", "frames",
             "frames rendered but not written at the pose and time of a written frame the camera cuts to ([postfx.taa] "
             "cut_distance_m, cut_angle_deg; e.g. every frame of a path sampled seconds apart), so its history (TAA, "
             "temporal clouds; none rendered when both are off) is built as after settle_frames; 0: such a frame is one history-free frame"},
            s.cut_settle_frames, 0, 10000);
    v.field({"crf", "", "H.264 constant rate factor of mp4 output: 0 lossless, 18 visually lossless, 23 ffmpeg's "
                        "default, 51 worst"},
            s.crf, 0, 51);
}

}  // namespace

bool addNamedSection(Settings& s, std::string_view section) {
    constexpr std::string_view kMaterial = "terrain.material.";
    if (!section.starts_with(kMaterial) || !isValidListName(section.substr(kMaterial.size()))) return false;
    for (const TerrainMaterialSettings& m : s.terrain.materials)
        if (m.section == section) return true;
    TerrainMaterialSettings m;
    m.name = std::string(section.substr(kMaterial.size()));
    m.section = std::string(section);
    s.terrain.materials.push_back(std::move(m));
    return true;
}

void describe(SettingsVisitor& v, Settings& s) {
    describe(v, s.window);
    describe(v, s.camera);
    describe(v, s.capture);
    describe(v, s.debug);
    describe(v, s.terrain);
    describe(v, s.grass);
    describe(v, s.sky);
    describe(v, s.clouds);
    describe(v, s.shadows);
    describe(v, s.weather);
    describe(v, s.lights);  // renderer/lighting/light_settings.cpp
    describe(v, s.water);
    describe(v, s.objects);  // terrain/scatter/object_settings.cpp
    describe(v, s.postfx);
    describe(v, s.exposure);
    describe(v, s.tonemap);
    describe(v, s.bloom);
    describe(v, s.fxaa);
    describe(v, s.taa);
    describe(v, s.grade);
    describe(v, s.ssao);
    describe(v, s.dof);
    describe(v, s.motion_blur);
    describe(v, s.lens_flare);
    describe(v, s.night_vision);
    describe(v, s.scotopic);
}

}  // namespace vista
