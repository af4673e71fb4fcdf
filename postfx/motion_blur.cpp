// Motion blur: the CPU decides whether anything moved (no pass otherwise) and builds the
// reprojection in double; the GPU does the rest in four full-screen passes.
#include "postfx/motion_blur.h"

#include "renderer/velocity.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace vista {

glm::dmat4 reprojectionMatrix(const ViewParams& previous, const ViewParams& current) {
    const glm::dmat4 prev_vp(viewMatrices(previous).view_proj);
    const glm::dmat4 cur_inv = glm::inverse(glm::dmat4(viewMatrices(current).view_proj));
    // A point camera-relative to the current camera is at (p + current - previous) relative to
    // the previous one.
    const glm::dmat4 shift = glm::translate(glm::dmat4(1.0), current.position - previous.position);
    return prev_vp * shift * cur_inv;
}

namespace {

bool sameView(const ViewParams& a, const ViewParams& b) {
    return a.position == b.position && a.yaw_deg == b.yaw_deg && a.pitch_deg == b.pitch_deg && a.fov_deg == b.fov_deg &&
           a.near_m == b.near_m && a.width == b.width && a.height == b.height;
}

}  // namespace

TextureHandle MotionBlur::addPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                                    TextureHandle depth, TextureHandle motion, const MotionBlurSettings& s, double dt_s,
                                    bool reset) {
    const bool usable = has_previous_ && !reset && dt_s > 0.0 && s.shutter_deg > 0.0f && !sameView(previous_, rc.view);
    const ViewParams previous = previous_;
    previous_ = rc.view;
    has_previous_ = true;
    if (!usable) return image;

    // The frame's shared motion vectors, or the same pass from this effect's own previous camera
    // when the caller has none (the chain on its own, as in tests).
    if (!motion.valid()) motion = addVelocityPass(graph, rc, depth, previous);
    const double exposure_s = double(s.shutter_deg) / 360.0 / double(s.frame_rate);
    const float scale = float(exposure_s / dt_s);
    const int tile = std::max(1, int(std::ceil(s.max_blur_px * 0.5f)));
    const float near_m = float(rc.view.near_m);

    struct VelocityData {
        TextureHandle depth, motion, velocity;
    };
    const TextureHandle velocity = graph.addPass<VelocityData>("postfx.motion_blur.velocity",
        [&](PassBuilder& b, VelocityData& d) {
            d.depth = b.read(depth);
            d.motion = b.read(motion);
            const TextureDesc& desc = b.desc(image);
            d.velocity = b.write(b.create("motion_blur.velocity", {desc.width, desc.height, PixelFormat::RGBA16F}));
        },
        [&rc, scale, tile, near_m](const VelocityData& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.velocity);
            bindTarget(rc.device.framebuffer({ctx.texture(d.velocity)}), desc.width, desc.height);
            GLuint program = rc.shaders.id("postfx/shaders/motion_blur_velocity.glsl");
            glUseProgram(program);
            glProgramUniform4f(program, 1, scale, float(tile), near_m, 0.0f);
            glBindTextureUnit(0, ctx.texture(d.depth));
            glBindTextureUnit(1, ctx.texture(d.motion));
            drawFullscreen(rc);
        }).velocity;

    struct TileData {
        TextureHandle in, out;
    };
    const auto tilePass = [&](const char* name, const char* target, TextureHandle in, int mode) {
        return graph.addPass<TileData>(name,
            [&](PassBuilder& b, TileData& d) {
                d.in = b.read(in);
                const TextureDesc& full = b.desc(velocity);
                d.out = b.write(b.create(target, {(full.width + tile - 1) / tile, (full.height + tile - 1) / tile,
                                                  PixelFormat::RG16F}));
            },
            [&rc, mode, tile](const TileData& d, PassContext& ctx) {
                const TextureDesc& desc = ctx.desc(d.out);
                bindTarget(rc.device.framebuffer({ctx.texture(d.out)}), desc.width, desc.height);
                GLuint program = rc.shaders.id("postfx/shaders/motion_blur_tiles.glsl");
                glUseProgram(program);
                glProgramUniform2i(program, 0, mode, tile);
                glBindTextureUnit(0, ctx.texture(d.in));
                drawFullscreen(rc);
            }).out;
    };
    const TextureHandle tiles = tilePass("postfx.motion_blur.tiles", "motion_blur.tiles", velocity, 0);
    const TextureHandle neighbors = tilePass("postfx.motion_blur.neighbors", "motion_blur.neighbors", tiles, 1);

    struct GatherData {
        TextureHandle image, velocity, neighbors, out;
    };
    const glm::vec4 params{float(s.samples), s.depth_extent, float(tile), 0.0f};
    return graph.addPass<GatherData>("postfx.motion_blur.gather",
        [&](PassBuilder& b, GatherData& d) {
            d.image = b.read(image);
            d.velocity = b.read(velocity);
            d.neighbors = b.read(neighbors);
            TextureDesc desc = b.desc(image);
            desc.levels = 1;
            d.out = b.write(b.create("motion_blur.out", desc));
        },
        [&rc, params](const GatherData& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.out);
            bindTarget(rc.device.framebuffer({ctx.texture(d.out)}), desc.width, desc.height);
            GLuint program = rc.shaders.id("postfx/shaders/motion_blur_gather.glsl");
            glUseProgram(program);
            glProgramUniform4f(program, 0, params.x, params.y, params.z, params.w);
            glBindTextureUnit(0, ctx.texture(d.image));
            glBindTextureUnit(1, ctx.texture(d.velocity));
            glBindTextureUnit(2, ctx.texture(d.neighbors));
            drawFullscreen(rc);
        }).out;
}

ProgramList motionBlurPrograms() {
    return {{"postfx/shaders/motion_blur_velocity.glsl", {}},
            {"postfx/shaders/motion_blur_tiles.glsl", {}},
            {"postfx/shaders/motion_blur_gather.glsl", {}}};
}

}  // namespace vista
