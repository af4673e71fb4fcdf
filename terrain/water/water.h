// The sea in the frame (Gerstner waves: terrain/water/waves.h). After the deferred lighting and before
// the aerial perspective and the sky:
//   "water.copy"       the opaque HDR and depth, copied (refraction and reflection read them
//                      while the surface pass writes the targets);
//   "water.surface"    the displaced ring grid around the camera, shaded forward (reflection,
//                      refraction with absorption, foam, sun glitter, the sun through its
//                      cascaded shadows, the sky and the culled local lights), writing colour and depth so that the aerial
//                      perspective fogs it and the sky stays behind it;
// and after the sky, when the camera may be under the surface:
//   "water.underwater" absorption and scattering between the eye and each pixel.
// Only exists while [water] is enabled (the frame drops it otherwise: no pass, no buffers).
#pragma once

#include "renderer/frame_graph.h"
#include "renderer/gl/objects.h"
#include "renderer/lighting/light_variants.h"
#include "renderer/program_key.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"
#include "renderer/shadows/sun_shadows.h"
#include "terrain/water/water_settings.h"
#include "terrain/water/waves.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vista {

class LocalLights;
class SkyAtmosphere;

// The variants of "water.surface" (shaders/water_surface.glsl): shaded with or without the
// local lights (by their culling method) and the sun's cascades, the pass of the lights past the
// first chunk, or a debug view. The pass asks for defines(); all() is every variant a frame can
// request (waterPrograms(), for allPrograms() and the shader test).
struct WaterSurfaceVariant {
    static constexpr const char* kFile = "terrain/water/shaders/water_surface.glsl";
    WaterView view = WaterView::Shaded;  // WATER_VIEW=N: the colour replaced by a debug output
    std::optional<LightCulling> lights;  // LIGHTS_*: the local lights, by their culling method
    bool sun_shadow = false;             // HAS_SUN_SHADOW: the sun through its cascades
    bool light_chunk = false;            // WATER_LIGHT_CHUNK: one further chunk of local lights alone
    bool velocity = false;               // WATER_VELOCITY: the surface's own motion into temporal.velocity
    bool pcss = true;                    // false: SHADOW_NO_PCSS, the cascades' filter is hard or pcf (needs sun_shadow)

    // The rules between the fields: a debug view replaces the colour, so it takes neither lights
    // nor shadows; a further chunk adds local light only, so it needs lights and no sun.
    // The motion-vector pass shades nothing: none of the others.
    bool valid() const {
        if (!pcss && !sun_shadow) return false;
        if (velocity) return view == WaterView::Shaded && !lights && !sun_shadow && !light_chunk;
        if (view != WaterView::Shaded) return !lights && !sun_shadow && !light_chunk;
        return !light_chunk || (lights && !sun_shadow);
    }

    std::vector<std::string> defines() const {
        std::vector<std::string> d;
        if (view != WaterView::Shaded) d.push_back("WATER_VIEW=" + std::to_string(int(view)));
        if (lights) d.push_back(lightMethodDefine(*lights));
        if (sun_shadow) d.push_back("HAS_SUN_SHADOW");
        if (!pcss) d.push_back("SHADOW_NO_PCSS");
        if (light_chunk) d.push_back("WATER_LIGHT_CHUNK");
        if (velocity) d.push_back("WATER_VELOCITY");
        return d;
    }
    ProgramKey key() const { return {kFile, defines()}; }

    static std::vector<WaterSurfaceVariant> all() {
        std::vector<std::optional<LightCulling>> methods = {std::nullopt};
        for (LightCulling m : kLightMethods) methods.push_back(m);
        std::vector<WaterSurfaceVariant> out;
        for (WaterView view : {WaterView::Shaded, WaterView::Normals, WaterView::Foam, WaterView::Depth})
            for (const auto& lights : methods)
                for (bool shadow : {false, true})
                    for (bool chunk : {false, true})
                        for (bool pcss : {true, false})
                            if (WaterSurfaceVariant v{view, lights, shadow, chunk, false, pcss}; v.valid()) out.push_back(v);
        out.push_back(WaterSurfaceVariant{WaterView::Shaded, std::nullopt, false, false, true});
        return out;
    }
};

// The light the water is lit by (renderer/lighting/deferred.h SunAndSky), RGB in HDR units.
struct WaterLight {
    glm::vec3 sun_irradiance{0.0f};
    glm::vec3 sky_up{0.0f};
    glm::vec3 ground_up{0.0f};
};

// The camera-centred ring grid for an eye h metres above (or below) the still surface: ring j
// at radius c (e^(a j) - 1), a = 2 pi / segments, c = max(grid_cell_m, 0.01 h) / a, rings out
// to max_distance_m. Its index buffer is segment by segment (each from the eye outwards), so the
// segments that can be in view (terrain/water/grid_sectors.h) are drawn and the rest skipped.
struct WaterGrid {
    int segments = 0, rings = 0;
    double ring_constant = 0.0;  // c, m
    double angle = 0.0;          // a, rad
};
WaterGrid waterGrid(const WaterSettings& s, double height_above_m);

struct WaterStats {
    std::uint64_t vertices = 0, triangles = 0;  // of the grid drawn this frame
    int segments = 0;           // of the grid's segments, those drawn (the rest cannot be in view)
    int waves = 0;
    bool underwater = false;    // the eye is below the surface at its own x, z
    bool near_surface = false;  // the eye may be below the surface somewhere on the near plane: water.underwater runs
    double surface_height_m = 0.0;  // world height of the surface at the eye's x, z
};

class Water {
public:
    // The CPU side of a frame: wave set (rebuilt when the settings change), grid, uniforms.
    // ground_m: the terrain's height at the eye's x, z (NaN: no terrain); an eye on ground above
    // the waves' reach is never under water.
    // rain_ripples: intensity (0..1) of the rain's rings on the surface (sky/weather/shaders/rain_ripples.glsl), 0: none.
    // motion_dt_s: the time since the previous frame (0: none, a cut), for addVelocityPass.
    void prepare(const WaterSettings& s, const ViewParams& view, double time_s, const WaterLight& light,
                 const SkyAtmosphere* sky, double ground_m, float rain_ripples = 0.0f, double motion_dt_s = 0.0);
    // water.copy and water.surface over targets (hdr and depth). sky: this frame's atmosphere
    // after addLutPasses (null: no sky); lights: the local lights whose passes ran this frame
    // (null: none) — their lists must cover forward depths (LightPassOptions::forward); past
    // their first chunk (LocalLights::chunks()) the surface is drawn again per chunk, additively.
    // shadows: this frame's sun cascades (invalid: none).
    void addSurfacePasses(FrameGraph& graph, const RenderContext& rc, SceneTargets& targets, const SkyAtmosphere* sky,
                          const LocalLights* lights, const SunShadowInput& shadows);
    // "water.velocity": the surface's own motion written over the frame's motion vectors
    // (renderer/velocity.h) where the surface is what the pixel shows (depth EQUAL to the
    // surface's): each vertex also at its previous-frame displacement (waves.glsl
    // previousDisplacement, the phases motion_dt_s earlier), projected by prev_clip_from_relative
    // (renderer/temporal.h previousClipFromRelative). Returns the new velocity handle.
    TextureHandle addVelocityPass(FrameGraph& graph, const RenderContext& rc, TextureHandle depth, TextureHandle velocity,
                                  const glm::dmat4& prev_clip_from_relative);
    // water.underwater over targets.hdr when stats().near_surface (after the sky).
    void addUnderwaterPass(FrameGraph& graph, const RenderContext& rc, SceneTargets& targets);

    const WaterStats& stats() const { return stats_; }
    std::size_t memoryBytes() const { return std::size_t(indices_.size()) + std::size_t(uniforms_.size()); }  // GPU bytes held
    const WaveSet& waves() const { return waves_; }
    // The uniform block as uploaded this frame (tests bind it for probes).
    GLuint uniformBuffer() const { return uniforms_.id(); }

private:
    struct Uniforms;
    void buildGrid(int segments, int rings);
    // Updates stats_ for the segments drawn this frame.
    void countDrawn(int segments);
    // The draw of the segments that can be in view this frame (the one range per segment).
    std::function<void()> visibleDraw(const RenderContext& rc);

    WaterSettings waves_for_{};
    bool have_waves_ = false;
    WaveSet waves_;
    WaterGrid grid_;
    double height_above_m_ = 0.0;  // the eye above the still surface (m; negative below it)
    int built_segments_ = 0, built_rings_ = 0;
    bool sector_cull_ = true;  // as prepared: [water] sector_cull
    gl::VertexArray vao_;
    gl::Buffer indices_, uniforms_;
    WaterStats stats_;
    WaterView view_ = WaterView::Shaded;  // as prepared: the surface program's WATER_VIEW variant
};

// Every program the water uses (for FrameRenderer::allPrograms()).
ProgramList waterPrograms();

}  // namespace vista
