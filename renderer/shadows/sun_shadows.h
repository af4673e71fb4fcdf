// Sun shadows on the GPU: a depth texture array with one layer per cascade
// (renderer/shadows/cascades.h), "shadows.cascadeN" passes drawing the terrain's casters into it, and
// the uniforms lighting.sun reads (renderer/shadows/shaders/shadows.glsl). Made only while the sun
// casts shadows; a cascade with no caster adds no pass and is read as lit.
#pragma once

#include "renderer/frustum.h"
#include "renderer/gl/objects.h"
#include "renderer/render_context.h"
#include "renderer/shadows/cascades.h"
#include "renderer/shadows/shadow_binding.h"
#include "renderer/shadows/shadow_caster.h"
#include "renderer/shadows/shadow_settings.h"
#include "renderer/shadows/terrain_caster.h"

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace vista {


struct SunShadowStats {
    int cascades = 0;                // in use this frame (PSSM + far)
    int drawn = 0;                   // of those with casters (a pass each)
    std::int64_t caster_instances = 0;  // terrain quadrants drawn over all cascades
    std::int64_t casters_skipped = 0;   // quadrants in a cascade's box whose shadow cannot reach its receivers
    std::int64_t caster_triangles = 0;  // terrain triangles drawn over all cascades (after caster_step_texels)
    int cached = 0;                  // cascades whose map was kept from an earlier frame (no pass this frame)
    std::size_t memory_bytes = 0;    // shadow map + uniforms
};

// What lighting.sun needs to sample the cascades.
struct SunShadowInput {
    TextureHandle map;           // the cascades (written by this frame's passes)
    GLuint uniforms = 0;         // ShadowUniforms buffer
    GLuint compare_sampler = 0;  // depth compare, bilinear (PCF)
    GLuint depth_sampler = 0;    // raw depth, nearest (PCSS blocker search)
    unsigned drawn = 0;          // bit c: cascade c had casters (the others' layers are stale)
    bool pcss = false;           // [shadows] filter = pcss (else a reader may take SHADOW_NO_PCSS)
    bool valid() const { return map.valid(); }
    // Binds the uniforms and map (this pass's texture of `map`) with both samplers at the
    // kShadow* bindings shadows.glsl reads; unbind() takes the samplers off again.
    void bind(GLuint map_texture) const {
        bindShadowInput(kSunShadowBindings, uniforms, map_texture, compare_sampler, depth_sampler);
    }
    static void unbind() { unbindShadowInput(kSunShadowBindings); }
};

// Whether the sun casts shadows with these settings (enabled and above min_sun_elevation_deg).
bool sunCastsShadows(const ShadowSettings& s, const glm::dvec3& sun_dir);

// The cascades' view-depth slices: PSSM from the near plane to max_distance_m, then the far
// cascade to far_distance_m when it is on and reaches further.
std::vector<std::pair<double, double>> cascadeSlices(const ShadowSettings& s, double near_m);

class SunShadows {
public:
    // Fits the cascades for fit_view (normally the frame's view; or keeps frozen ones), with
    // matrices relative to view's camera. Call before the terrain selection; casterFrustum() is
    // then what the selection should cover. sequence_frame: the frame's place in its sequence
    // (a capture's path frame), on whose multiples of cache_frames kept cascades are redrawn.
    // sun_angular_radius_deg: the drawn sun's ([sky]), for PCSS penumbrae.
    void prepare(const ShadowSettings& s, float sun_angular_radius_deg, const glm::dvec3& sun_dir, const ViewParams& view,
                 const ViewParams& fit_view, std::uint64_t sequence_frame = 0);
    // Drops the kept cascades (a camera cut or a history reset): the next frame draws them all.
    void forgetKept();
    std::array<glm::dvec4, 6> casterFrustum(const glm::dmat4& view_proj) const;

    // One "shadows.cascadeN" pass per cascade with casters in the terrain's selection; `extra`
    // (grass; may be invalid) is drawn too into the cascades that start within its reach.
    // receivers_above_m: no receiver (terrain, sea, object) lies below this world height; a
    // cascade past the first then leaves out the terrain quadrants whose shadows, running away
    // from the sun down to there, cannot reach the view depths that read it (the nearer
    // cascades' receivers): the same shadows, fewer casters (shadows.casters_skipped).
    // The farthest cache_cascades cascades keep their map from the frame that drew them while
    // their snapped box and the sun stay put, up to cache_frames frames (shadows.cascades_cached);
    // one that draws `extra` (grass sways) is drawn every frame.
    SunShadowInput addPasses(FrameGraph& graph, const RenderContext& rc, TerrainCaster* terrain,
                             const ShadowCaster& extra = {},
                             double receivers_above_m = -std::numeric_limits<double>::infinity());

    const std::vector<ShadowCascade>& cascades() const { return cascades_; }
    const LightBasis& light() const { return light_; }
    const SunShadowStats& stats() const { return stats_; }
    std::size_t memoryBytes() const { return stats_.memory_bytes; }  // shadow map + uniforms
    GLuint mapTexture() const { return map_.id(); }

private:
    void allocate(int resolution, int layers);
    // Whether cascade i may show the map an earlier frame drew for it (see addPasses).
    bool keeps(int i, bool draws_extra) const;

    // What a cascade's layer holds: set when its pass ran, for the box and sun it ran with.
    struct Kept {
        bool valid = false;
        ShadowCascade box;
        glm::dvec3 sun{0.0};
    };

    ShadowSettings settings_;
    LightBasis light_;
    glm::dvec3 camera_{0.0};
    glm::dvec3 forward_{0.0, 0.0, -1.0};  // the view's (receivers' view depths are along it)
    std::array<glm::dvec4, 4> view_sides_{};  // the view frustum's side planes (camera-relative, unit normals)
    std::vector<ShadowCascade> cascades_;
    bool frozen_ = false;
    std::vector<std::vector<TerrainInstance>> instances_;  // per cascade, reused
    std::vector<std::size_t> tess_;  // per cascade: its first instances drawn tessellated (Terrain::shadowInstances)
    SunShadowStats stats_;
    float tan_sun_radius_ = 0.0f;
    std::uint64_t sequence_frame_ = 0;
    std::vector<Kept> kept_;  // per cascade

    gl::Texture map_;
    int map_resolution_ = 0, map_layers_ = 0;
    std::vector<gl::Framebuffer> layer_fbs_;
    ShadowReadObjects objects_;
};

// "shadows.view": the cascades' depth maps side by side ([debug] view = shadow_map), near the
// sun dark; returns the RGBA8 display image.
TextureHandle addShadowMapViewPass(FrameGraph& graph, const RenderContext& rc, const SunShadowInput& shadows,
                                   int cascades);


}  // namespace vista
