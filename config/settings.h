// The scene's settings: the one Settings aggregate of every section of a scene file. Each
// feature owns its settings struct and its describe() (the one description of its keys, units
// and ranges that the ini loader, the writer, `vista check` and the ImGui panel share) in its
// own folder; this file gathers them and adds the sections of the application itself (window,
// camera, capture). It names every feature, so it sits just under app/ (tools/check_layers.py).
#pragma once

#include "config/visitor.h"
#include "postfx/postfx_settings.h"  // PostChainSettings: the post chain's part of Settings
#include "postfx/ssao_settings.h"
#include "postfx/taa_settings.h"
#include "renderer/debug_settings.h"
#include "renderer/lighting/light_settings.h"
#include "renderer/shadows/shadow_settings.h"
#include "sky/clouds/cloud_settings.h"
#include "sky/sky_settings.h"
#include "sky/weather/weather_settings.h"
#include "terrain/grass/grass_settings.h"
#include "terrain/scatter/object_settings.h"
#include "terrain/terrain_settings.h"
#include "terrain/water/water_settings.h"

#include <glm/vec3.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace vista {

struct WindowSettings {
    int width = 1280;       //!< px
    int height = 720;       //!< px
    bool fullscreen = false;
    bool vsync = true;
    bool gl_debug = false;  //!< KHR_debug callback printing GL errors and warnings
};

struct CameraSettings {
    glm::dvec3 position{0.0, 60.0, 0.0};  //!< m, world space (y up)
    float yaw_deg = 0.0f;                 //!< deg, 0 looks along -z, positive turns right
    float pitch_deg = -10.0f;             //!< deg, positive looks up
    float fov_deg = 60.0f;                //!< deg, vertical field of view
    float near_m = 0.1f;                  //!< m, near plane (the far plane is at infinity)
    float move_speed = 40.0f;             //!< m/s
    float fast_multiplier = 8.0f;         //!< speed factor while Shift is held
    float slow_multiplier = 0.125f;       //!< speed factor while Ctrl is held
    float mouse_sensitivity = 0.15f;      //!< deg per pixel of mouse motion
    float zoom_sensitivity = 2.0f;        //!< deg of field of view per scroll step
    float updown_speed = 1.0f;            //!< factor on move_speed for Q/E
    bool follow_terrain = false;          //!< walk: keep the eye at eye_height_m above the ground
    float eye_height_m = 1.7f;            //!< m above the ground when following the terrain
    bool allow_below_ground = false;      //!< free camera may go below the terrain surface
};

enum class ImageFormat : int { Png, Exr, Mp4 };  // Mp4: PNG frames, then an H.264 video of them

struct CaptureSettings {
    std::string path = "data/paths/default.path";  //!< camera path, relative to the vista root
    int frames = 8;                                //!< frames to render
    float fps = 2.0f;                              //!< frames per second of path time
    int width = 320;                               //!< px
    int height = 180;                              //!< px
    ImageFormat format = ImageFormat::Png;
    std::string out = "out";                       //!< output directory
    int settle_frames = 8;                         //!< unwritten frames before a run's first written frame, 0..10000
    int cut_settle_frames = 8;                     //!< unwritten frames at a cut-to frame's own pose and time, 0..10000
    int crf = 18;                                  //!< H.264 constant rate factor of mp4 output, 0 (lossless)..51
};

// The post chain's sections (postfx, exposure, tonemap, bloom, fxaa, grade, dof, motion_blur,
// lens_flare, night_vision, scotopic) come from PostChainSettings, so the chain takes a scene's
// settings as they are and sees only its own.
struct Settings : PostChainSettings {
    WindowSettings window;
    CameraSettings camera;
    CaptureSettings capture;
    DebugSettings debug;
    TerrainSettings terrain;
    GrassSettings grass;        // [grass]
    SkySettings sky;
    CloudsSettings clouds;      // [clouds], [clouds.low], [clouds.high]
    ShadowSettings shadows;
    WeatherSettings weather;    // [weather]
    LightsSettings lights;      // [lights], with the light.NAME / volume.NAME lists
    WaterSettings water;        // [water]
    ObjectsSettings objects;    // [objects], with the object.NAME / scatter.NAME lists
    TaaSettings taa;            // [postfx.taa]
    SsaoSettings ssao;          // [postfx.ssao]
};

// Lists every section and field of s to v, in file order.
void describe(SettingsVisitor& v, Settings& s);

// Adds the named section `section` (a family of sections with a NAME: terrain.material.NAME) to s
// when it is one and not there yet. True when s now has it (the ini loader and --set then set its
// keys); false for a name no family takes.
bool addNamedSection(Settings& s, std::string_view section);

}  // namespace vista
