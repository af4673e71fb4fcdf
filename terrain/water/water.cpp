// The sea's passes and its GPU state: the ring grid's index buffer (made once per grid shape),
// the uniform block (waves packed for this frame's camera and time) and the three passes.
#include "terrain/water/water.h"

#include "terrain/water/grid_sectors.h"

#include "renderer/lighting/local_lights.h"
#include "renderer/bindings.h"
#include "renderer/pass_kit.h"
#include "sky/atmosphere.h"
#include "sky/weather/weather_model.h"
#include "terrain/water/shaders/water_bindings.glsl"

#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace vista {

namespace {

#include "terrain/water/shaders/water_surface_block.glsl"

constexpr const char* kCopyProgram = "terrain/water/shaders/water_copy.glsl";
constexpr const char* kUnderwaterProgram = "terrain/water/shaders/underwater.glsl";

bool sameWaves(const WaterSettings& a, const WaterSettings& b) {
    return a.wind_speed_m_s == b.wind_speed_m_s && a.wind_direction_deg == b.wind_direction_deg &&
           a.direction_spread_deg == b.direction_spread_deg && a.amplitude_scale == b.amplitude_scale &&
           a.choppiness == b.choppiness && a.waves == b.waves && a.min_wavelength_m == b.min_wavelength_m;
}

}  // namespace

// std140 mirror of WaterUniforms in terrain/water/shaders/waves.glsl.
struct Water::Uniforms {
    glm::vec4 wave_a[WATER_MAX_WAVES];
    glm::vec4 wave_b[WATER_MAX_WAVES];
    glm::vec4 grid, surface, scatter, absorption, foam, sun, sky_up, ground_up, misc, rain;
};

WaterGrid waterGrid(const WaterSettings& s, double height_above_m) {
    WaterGrid g;
    g.segments = std::max(s.grid_segments, 3);
    g.angle = 2.0 * std::numbers::pi / double(g.segments);
    g.ring_constant = std::max(double(s.grid_cell_m), 0.01 * std::abs(height_above_m)) / g.angle;
    g.rings = std::max(1, int(std::ceil(std::log1p(double(s.max_distance_m) / g.ring_constant) / g.angle)));
    return g;
}

void Water::buildGrid(int segments, int rings) {
    std::vector<std::uint32_t> indices;
    indices.reserve(std::size_t(rings) * std::size_t(segments) * 6);
    const auto at = [segments](int ring, int segment) { return std::uint32_t(ring * segments + segment % segments); };
    // Segment-major, each segment from the eye outwards: segment i's first `r` rings are the
    // indices [6 rings i, 6 (rings i + r)), so a frame draws any subset of segments and rings.
    for (int i = 0; i < segments; ++i)
        for (int j = 0; j < rings; ++j) {
            const std::uint32_t v00 = at(j, i), v01 = at(j, i + 1), v10 = at(j + 1, i), v11 = at(j + 1, i + 1);
            indices.insert(indices.end(), {v00, v10, v01, v01, v10, v11});
        }
    indices_ = gl::Buffer::create(GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(), 0, "water ring grid indices");
    vao_ = gl::createVertexArray("water ring grid");
    glVertexArrayElementBuffer(vao_.id(), indices_.id());
    built_segments_ = segments;
    built_rings_ = rings;
}

void Water::countDrawn(int segments) {
    stats_.segments = segments;
    // Each drawn segment's rings (its two edges' vertices: neighbours share one edge).
    const bool whole = segments == grid_.segments;
    stats_.vertices = std::uint64_t(grid_.rings + 1) * std::uint64_t(segments + (whole ? 0 : 1));
    stats_.triangles = 2 * std::uint64_t(grid_.rings) * std::uint64_t(segments);
}

void Water::prepare(const WaterSettings& s, const ViewParams& view, double time_s, const WaterLight& light,
                    const SkyAtmosphere* sky, double ground_m, float rain_ripples, double motion_dt_s) {
    if (!have_waves_ || !sameWaves(s, waves_for_)) {
        waves_ = makeWaves(s);
        waves_for_ = s;
        have_waves_ = true;
    }
    const double height = view.position.y - double(s.level_m);
    grid_ = waterGrid(s, height);
    height_above_m_ = height;
    // The grid at the surface itself has the most rings: the index buffer is made for that.
    const WaterGrid largest = waterGrid(s, 0.0);
    if (largest.segments != built_segments_ || largest.rings != built_rings_) buildGrid(largest.segments, largest.rings);

    const glm::dvec2 eye{view.position.x, view.position.z};
    stats_.waves = int(waves_.waves.size());
    countDrawn(grid_.segments);
    sector_cull_ = s.sector_cull;
    stats_.surface_height_m = double(s.level_m) + evaluateWaves(waves_, eye, time_s).displacement.y;
    // Dry land at the eye (ground above every wave there): no water around it.
    const bool dry = ground_m > double(s.level_m) + waves_.max_height;
    stats_.underwater = !dry && view.position.y < stats_.surface_height_m;
    // The near plane reaches about near / cos(half the diagonal field of view) from the eye.
    stats_.near_surface = !dry && height < waves_.max_height + 4.0 * view.near_m;

    Uniforms u{};
    std::vector<glm::vec4> a, b;
    packWaves(waves_, eye, time_s, a, b, motion_dt_s);
    for (std::size_t i = 0; i < a.size() && i < std::size_t(WATER_MAX_WAVES); ++i) {
        u.wave_a[i] = a[i];
        u.wave_b[i] = b[i];
    }
    const bool sky_lut = sky && !sky->frameInSpace();
    u.grid = glm::vec4(float(grid_.ring_constant), float(grid_.angle), float(grid_.segments), float(a.size()));
    u.surface = glm::vec4(float(-height), s.roughness, s.refraction_strength, s.foam_depth_m);
    u.scatter = glm::vec4(s.scatter_color, s.whitecaps);
    u.absorption = glm::vec4(s.absorption_per_m, 0.0f);
    view_ = s.view;
    // Foam bands drift up the shore at 0.8 rad/s, wrapped in double.
    u.foam = glm::vec4(s.foam_color, float(std::fmod(0.8 * time_s, 2.0 * std::numbers::pi)));
    u.sun = glm::vec4(light.sun_irradiance, sky_lut ? 1.0f : 0.0f);
    u.sky_up = glm::vec4(light.sky_up, s.reflection == WaterReflection::Ssr ? float(s.ssr_steps) : 0.0f);
    u.ground_up = glm::vec4(light.ground_up, s.ssr_max_distance_m);
    u.misc = glm::vec4(float(waves_.max_height), 0.0f, 0.0f, 0.0f);
    // Rain rings: the pattern's period wraps the camera's x, z and the time in double.
    const RippleInput ripple = rainRippleWrap(eye, time_s);
    u.rain = glm::vec4(ripple.xz.x, ripple.xz.y, ripple.time, std::clamp(rain_ripples, 0.0f, 1.0f));
    if (!uniforms_) uniforms_ = gl::Buffer::create(sizeof(Uniforms), nullptr, GL_DYNAMIC_STORAGE_BIT, "water uniforms");
    glNamedBufferSubData(uniforms_.id(), 0, sizeof u, &u);
}

std::function<void()> Water::visibleDraw(const RenderContext& rc) {
    // The segments that can be in view (from the matrix the vertex stage uses, jitter included),
    // each drawn from the eye out to this frame's last ring: one range per segment.
    const SectorRange sectors =
        sector_cull_ ? visibleSectors(grid_, height_above_m_, waves_.max_height, waves_.max_chop,
                                      frustumFromViewProj(glm::dmat4(rc.matrices.view_proj)))
                     : SectorRange{0, grid_.segments};
    countDrawn(sectors.count);
    std::vector<GLsizei> counts(std::size_t(sectors.count), GLsizei(6 * grid_.rings));
    std::vector<const void*> offsets;
    for (int k = 0; k < sectors.count; ++k) {
        const std::size_t segment = std::size_t((sectors.first + k) % grid_.segments);
        offsets.push_back(reinterpret_cast<const void*>(segment * std::size_t(built_rings_) * 6 * sizeof(std::uint32_t)));
    }
    return [counts = std::move(counts), offsets = std::move(offsets)] {
        if (!counts.empty())
            glMultiDrawElements(GL_TRIANGLES, counts.data(), GL_UNSIGNED_INT, offsets.data(), GLsizei(counts.size()));
    };
}

void Water::addSurfacePasses(FrameGraph& graph, const RenderContext& rc, SceneTargets& targets, const SkyAtmosphere* sky,
                             const LocalLights* lights, const SunShadowInput& shadows) {
    struct CopyData {
        TextureHandle hdr, depth, color, depth_copy;
    };
    const CopyData& c = graph.addPass<CopyData>("water.copy",
        [&](PassBuilder& b, CopyData& d) {
            d.hdr = b.read(targets.hdr);
            d.depth = b.read(targets.depth);
            TextureDesc desc = b.desc(targets.hdr);
            d.color = b.write(b.create("water.scene_color", desc));
            desc.format = PixelFormat::R32F;
            d.depth_copy = b.write(b.create("water.scene_depth", desc));
        },
        [&rc](const CopyData& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.color);
            bindTarget(rc.device.framebuffer({ctx.texture(d.color), ctx.texture(d.depth_copy)}), desc.width, desc.height);
            glUseProgram(rc.shaders.id(kCopyProgram));
            glBindTextureUnit(binding::kTex0, ctx.texture(d.hdr));
            glBindTextureUnit(binding::kTex1, ctx.texture(d.depth));
            drawFullscreen(rc);
        });

    const bool sky_lut = sky && !sky->frameInSpace();
    struct SurfaceData {
        TextureHandle color, depth_copy, sky_view, shadow, hdr, depth;
    };
    // A debug view is a variant (the shaded surface pays nothing for it); it replaces the
    // colour, so it needs neither lights nor shadows.
    WaterSurfaceVariant variant{view_};
    if (view_ == WaterView::Shaded) {
        if (lights) variant.lights = lights->stats().method;
        variant.sun_shadow = shadows.valid();
        variant.pcss = !variant.sun_shadow || shadows.pcss;
    }
    auto draw = visibleDraw(rc);
    const SurfaceData& d = graph.addPass<SurfaceData>("water.surface",
        [&](PassBuilder& b, SurfaceData& data) {
            data.color = b.read(c.color);
            data.depth_copy = b.read(c.depth_copy);
            if (sky_lut) data.sky_view = b.read(sky->frameSkyView());
            if (shadows.valid()) data.shadow = b.read(shadows.map);
            data.hdr = b.write(targets.hdr);
            data.depth = b.write(targets.depth);
        },
        [this, &rc, sky, lights, variant, shadows, draw](const SurfaceData& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.hdr);
            bindTarget(rc.device.framebuffer({ctx.texture(data.hdr)}, ctx.texture(data.depth)), desc.width, desc.height);
            const GLuint program = rc.shaders.id(variant.key());
            glUseProgram(program);
            glBindBufferBase(GL_UNIFORM_BUFFER, WATER_BINDING_UNIFORMS, uniforms_.id());
            if (sky) glBindBufferBase(GL_UNIFORM_BUFFER, WATER_BINDING_ATMOSPHERE, sky->frameUniformBuffer());
            if (lights) lights->bindForForward();
            glBindTextureUnit(binding::kTex0, ctx.texture(data.color));
            glBindTextureUnit(binding::kTex1, ctx.texture(data.depth_copy));
            if (data.sky_view.valid()) glBindTextureUnit(binding::kTex2, ctx.texture(data.sky_view));
            if (data.shadow.valid()) shadows.bind(ctx.texture(data.shadow));
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_GREATER);
            glDepthMask(GL_TRUE);
            glDisable(GL_CULL_FACE);  // seen from above and from below
            glBindVertexArray(vao_.id());
            const bool lit = lights && view_ == WaterView::Shaded;
            WaterSurfaceBlock block{};
            if (lit) block.u_light_chunk = {0u, kLightChunk};
            bindPassBlock(rc, program, block);
            draw();
            if (lit && lights->chunks() > 1) {
                // The lights past the first chunk (lights.glsl chunkOf): the surface again, its
                // local light only, added where the depth is the surface's own.
                const GLuint chunk = rc.shaders.id(WaterSurfaceVariant{WaterView::Shaded, variant.lights, false, true}.key());
                glUseProgram(chunk);
                glDepthFunc(GL_EQUAL);
                glDepthMask(GL_FALSE);
                glEnable(GL_BLEND);
                glBlendFunc(GL_ONE, GL_ONE);
                for (std::uint32_t k = 1; k < lights->chunks(); ++k) {
                    block.u_light_chunk = {k * kLightChunk, kLightChunk};
                    bindPassBlock(rc, chunk, block);
                    draw();
                }
                glDisable(GL_BLEND);
                glBlendFunc(GL_ONE, GL_ZERO);
                glDepthMask(GL_TRUE);
            }
            glBindVertexArray(rc.empty_vao);
            glDisable(GL_DEPTH_TEST);
            if (data.shadow.valid()) SunShadowInput::unbind();
        });
    targets.hdr = d.hdr;
    targets.depth = d.depth;
}

TextureHandle Water::addVelocityPass(FrameGraph& graph, const RenderContext& rc, TextureHandle depth, TextureHandle velocity,
                                     const glm::dmat4& prev_clip_from_relative) {
    struct Data {
        TextureHandle depth, velocity;
    };
    WaterSurfaceBlock block{};
    block.u_prev_clip = glm::mat4(prev_clip_from_relative);
    block.u_jitter = glm::vec4(rc.jitter_ndc.x, rc.jitter_ndc.y, 0.0f, 0.0f);
    auto draw = visibleDraw(rc);
    return graph.addPass<Data>("water.velocity",
        [&](PassBuilder& b, Data& d) {
            d.depth = b.read(depth);
            d.velocity = b.write(velocity);
        },
        [this, &rc, block, draw](const Data& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.velocity);
            bindTarget(rc.device.framebuffer({ctx.texture(d.velocity)}, ctx.texture(d.depth)), desc.width, desc.height);
            const GLuint program = rc.shaders.id(WaterSurfaceVariant{WaterView::Shaded, std::nullopt, false, false, true}.key());
            glUseProgram(program);
            bindPassBlock(rc, program, block);
            glBindBufferBase(GL_UNIFORM_BUFFER, WATER_BINDING_UNIFORMS, uniforms_.id());
            // Only where the surface is what the pixel shows (gl_Position is invariant).
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_EQUAL);
            glDepthMask(GL_FALSE);
            glDisable(GL_CULL_FACE);
            glBindVertexArray(vao_.id());
            draw();
            glBindVertexArray(rc.empty_vao);
            glDepthMask(GL_TRUE);
            glDepthFunc(GL_GREATER);
            glDisable(GL_DEPTH_TEST);
        }).velocity;
}

void Water::addUnderwaterPass(FrameGraph& graph, const RenderContext& rc, SceneTargets& targets) {
    addOverHdrPass(graph, rc, "water.underwater", targets, [this, &rc] {
        glUseProgram(rc.shaders.id(kUnderwaterProgram));
        glBindBufferBase(GL_UNIFORM_BUFFER, WATER_BINDING_UNIFORMS, uniforms_.id());
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_SRC1_COLOR);  // hdr = in-scattering + hdr * transmittance
        drawFullscreen(rc);
        glDisable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ZERO);  // Mesa refuses multi-target draws while a dual-source factor is set
    });
}

ProgramList waterPrograms() {
    ProgramList programs = {{kCopyProgram, {}}, {kUnderwaterProgram, {}}};
    appendPrograms(programs, variantPrograms<WaterSurfaceVariant>());
    return programs;
}

}  // namespace vista
