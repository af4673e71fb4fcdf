// Weather passes: per-frame placement (in double), wind and light for weather.rain and
// weather.splash; two instanced quad draws with no buffers.
#include "sky/weather/weather.h"

#include "renderer/bindings.h"
#include "renderer/pass_kit.h"
#include "terrain/terrain.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vista {

#include "sky/weather/shaders/weather_rain_block.glsl"

namespace {

std::vector<std::string> rainDefines(bool snow, bool velocity) {
    std::vector<std::string> defines;
    if (snow) defines.push_back("SNOW");
    if (velocity) defines.push_back("RAIN_VELOCITY");
    return defines;
}

}  // namespace

ProgramList weatherPrograms() {
    ProgramList programs;
    for (bool snow : {false, true})
        for (bool velocity : {false, true}) programs.push_back({"sky/weather/shaders/weather_rain.glsl", rainDefines(snow, velocity)});
    programs.push_back({"sky/weather/shaders/weather_splash.glsl", {}});
    return programs;
}

glm::dvec3 Weather::cameraVelocity(const glm::dvec3& position, double time_s) {
    glm::dvec3 v(0.0);
    const double dt = time_s - previous_time_;
    frame_dt_s_ = 0.0;
    if (has_previous_ && dt > 0.0 && dt <= 1.0) {
        v = (position - previous_position_) / dt;
        frame_dt_s_ = dt;
    }
    const double speed = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (!(speed <= 1000.0)) v = glm::dvec3(0.0);  // a teleport (or NaN), not a motion
    previous_position_ = position;
    previous_time_ = time_s;
    has_previous_ = true;
    return v;
}

namespace {

#include "sky/weather/shaders/weather_splash_block.glsl"

// Blends premultiplied radiance over the HDR colour and keeps its alpha; depth test only.
void blendState() {
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // reversed-Z: nearer is greater
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
}

void restoreState() {
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
}

}  // namespace

void Weather::addPasses(FrameGraph& graph, const RenderContext& rc, const WeatherSettings& s,
                        const CloudsSettings& clouds, const SunAndSky& light, const Terrain* terrain,
                        const TerrainSettings& ts, SceneTargets& targets, CounterReadback& counters, bool count) {
    const glm::dvec3 camera_velocity = cameraVelocity(rc.view.position, rc.time_s);
    stats_ = {};
    stats_.camera_velocity = camera_velocity;
    rain_.reset();
    if (s.intensity <= 0.0f) return;  // nothing falls
    const bool snow = s.kind == WeatherKind::Snow;
    const double inv_pi = 1.0 / std::numbers::pi;
    // What a drop sends back: the light around it (sky from above, ground from below) and the sun.
    const glm::vec3 ambient = float(double(s.brightness) * 0.5 * inv_pi) * (light.sky_up + light.ground_up);
    const glm::vec3 sun = float(double(s.brightness) * inv_pi) * light.sun_irradiance;

    const DropLayout layout = dropLayout(s);
    const DropFrame frame = dropFrame(layout, rc.view.position, dropFieldOffset(s, clouds, rc.time_s), rc.time_s);
    const glm::dvec2 wind = weatherWindVelocity(s, clouds, rc.time_s);
    const glm::dvec3 relative = glm::dvec3(wind.x, -double(s.drop_speed_m_s), wind.y) - camera_velocity;
    const glm::vec3 motion(relative);
    const float opacity = (snow ? 0.8f : 0.5f) * (0.4f + 0.6f * s.intensity);
    // Cells that can show a drop: widened by the streak (it reaches back from the drop), the
    // sway and the quad's width.
    const double reach = std::sqrt(glm::dot(relative, relative)) * double(s.streak_time_s) + (snow ? kSnowSwayM : 0.0) +
                         double(s.drop_width_m) + 0.05;
    visibleDropCells(layout, frame, frustumFromViewProj(glm::dmat4(rc.matrices.view_proj)), double(s.radius_m), reach, cells_);
    const int per_cell = dropsDrawnPerCell(layout, s.intensity);
    stats_.drop_cells = std::int64_t(cells_.size());
    stats_.drop_candidates = std::int64_t(cells_.size()) * per_cell;
    if (cells_.empty() || per_cell == 0) return;
    const GLsizeiptr bytes = GLsizeiptr(cells_.size() * sizeof(std::uint32_t));
    if (cell_buffer_.size() < bytes)
        cell_buffer_ = gl::Buffer::create(std::max<GLsizeiptr>(bytes, GLsizeiptr(layout.cells) * layout.cells * layout.cells * 4),
                                          nullptr, GL_DYNAMIC_STORAGE_BIT, "weather drop cells");
    // Once per frame, for weather.rain and weather.velocity (the graph may run either first).
    glNamedBufferSubData(cell_buffer_.id(), 0, bytes, cells_.data());
    const float keep_below = s.intensity * float(layout.drops_per_cell);
    const GLsizei instances = GLsizei(stats_.drop_candidates);

    auto block = std::make_shared<WeatherRainBlock>();
    block->u_box_min = {frame.box_min, layout.cells};
    block->u_layout = {layout.half, per_cell, count ? 1 : 0, 0};
    block->u_frac = {frame.frac, float(layout.cell_m)};
    block->u_motion = {motion, s.streak_time_s};
    block->u_shape = {s.radius_m, s.near_fade_m, s.drop_width_m, keep_below};
    block->u_ambient = {ambient, opacity};
    block->u_sun = {sun, 0.0f};
    block->u_sway = {float(kSnowSwayM), frame.sway_phase, float(2.0 * std::numbers::pi * kSnowSwayHz), 0.0f};
    block->u_camera_motion = {glm::vec3(camera_velocity), float(frame_dt_s_)};
    rain_ = RainDraw{block, instances, snow};

    struct Data {
        TextureHandle hdr, depth;
    };
    const Data& rain = graph.addPass<Data>("weather.rain",
        [&](PassBuilder& b, Data& d) {
            d.hdr = b.write(targets.hdr);
            d.depth = b.read(targets.depth);
        },
        [this, &rc, &counters, block, snow, count, instances](const Data& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.hdr);
            bindTarget(rc.device.framebuffer({ctx.texture(d.hdr)}, ctx.texture(d.depth)), desc.width, desc.height);
            GLuint program = rc.shaders.id("sky/weather/shaders/weather_rain.glsl", rainDefines(snow, false));
            glUseProgram(program);
            bindPassBlock(rc, program, *block);
            bindCells();
            if (count)
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kCounters, counters.request(rc.frame, "weather.drops"));
            glBindVertexArray(rc.empty_vao);
            blendState();
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, instances);
            restoreState();
        });
    targets.hdr = rain.hdr;

    if (snow || !s.splashes || !terrain || s.splash_rate <= 0.0f) return;
    // No splash within reach when the ground under the camera is farther than splash_radius_m
    // (flying; a slope nearer than that under a high camera is rare and only loses far splashes).
    const glm::dvec3 eye = rc.view.position;
    if (std::abs(eye.y - terrain->heightAt(eye.x, eye.z)) > double(s.splash_radius_m)) return;
    const SplashLayout sl = splashLayout(s);
    const double kept = splashesKept(sl, s);
    const int slots = std::min(sl.slots, int(std::ceil(kept)));
    if (slots == 0) return;
    stats_.splash_candidates = std::int64_t(sl.cells) * sl.cells * slots;
    const SplashFrame sf = splashFrame(sl, glm::dvec2(rc.view.position.x, rc.view.position.z), rc.time_s);
    const float splash_keep = float(kept);
    const Data& splash = graph.addPass<Data>("weather.splash",
        [&](PassBuilder& b, Data& d) {
            d.hdr = b.write(targets.hdr);
            d.depth = b.read(targets.depth);
        },
        [this, &rc, &s, &ts, &counters, terrain, sl, sf, slots, splash_keep, ambient, sun, count](const Data& d,
                                                                                                 PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.hdr);
            bindTarget(rc.device.framebuffer({ctx.texture(d.hdr)}, ctx.texture(d.depth)), desc.width, desc.height);
            GLuint program = rc.shaders.id("sky/weather/shaders/weather_splash.glsl");
            glUseProgram(program);
            const TerrainMapping& m = terrain->mapping();
            const glm::dvec3 rel = rc.view.position - ts.origin;
            WeatherSplashBlock block{};
            block.u_box = sf.box_min;
            block.u_layout = {sl.cells, sl.half, slots, count ? 1 : 0};
            block.u_cycle = {sf.frac, sf.cycle_frac, splash_keep};
            block.u_look = {s.splash_size_m, s.splash_radius_m, 0.2f + 0.25f * s.intensity, float(kSplashCellM)};
            block.u_ambient = {ambient, 0.0f};
            block.u_sun = {sun, 0.0f};
            block.u_map_min = {float(-m.sizeX() * 0.5 - rel.x), float(-m.sizeZ() * 0.5 - rel.z)};
            block.u_texel_m = {float(m.texelSizeX()), float(m.texelSizeZ())};
            block.u_height_map = {float(m.height_scale_m), float(m.height_offset_m - rel.y)};
            const Terrain::TileRows tiles = terrain->tileRows();
            block.u_tiles = tiles.tiles;
            block.u_tile_layer = tiles.layer;
            block.u_cycle_index = {sf.cycle, 0u, 0u, 0u};
            bindPassBlock(rc, program, block);
            glBindTextureUnit(binding::kTex0, terrain->heightTexture());
            if (count)
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kCounters, counters.request(rc.frame, "weather.splashes"));
            glBindVertexArray(rc.empty_vao);
            blendState();
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(stats_.splash_candidates));
            restoreState();
        });
    targets.hdr = splash.hdr;
}

void Weather::bindCells() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kWeatherCells, cell_buffer_.id());
}

TextureHandle Weather::addVelocityPass(FrameGraph& graph, const RenderContext& rc, TextureHandle depth, TextureHandle velocity,
                                       const glm::dmat4& prev_clip_from_relative) {
    if (!rain_) return velocity;  // no drop drawn this frame
    auto block = std::make_shared<WeatherRainBlock>(*rain_->block);
    block->u_layout.z = 0;  // counted once, by weather.rain
    block->u_prev_clip = glm::mat4(prev_clip_from_relative);
    block->u_velocity_cover = {rc.jitter_ndc.x, rc.jitter_ndc.y, kRainVelocityOpacity, 0.0f};
    const RainDraw draw = *rain_;
    struct Data {
        TextureHandle depth, velocity;
    };
    return graph.addPass<Data>("weather.velocity",
        [&](PassBuilder& b, Data& d) {
            d.depth = b.read(depth);
            d.velocity = b.write(velocity);
        },
        [this, &rc, block, draw](const Data& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.velocity);
            bindTarget(rc.device.framebuffer({ctx.texture(d.velocity)}, ctx.texture(d.depth)), desc.width, desc.height);
            const GLuint program = rc.shaders.id("sky/weather/shaders/weather_rain.glsl", rainDefines(draw.snow, true));
            glUseProgram(program);
            bindPassBlock(rc, program, *block);
            bindCells();
            glBindVertexArray(rc.empty_vao);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_GREATER);  // reversed-Z: in front of the scene
            glDepthMask(GL_FALSE);
            glDisable(GL_CULL_FACE);
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, draw.instances);
            restoreState();
        }).velocity;
}

}  // namespace vista
