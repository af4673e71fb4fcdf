// Motion blur: the CPU decides whether anything moved (no pass otherwise) and builds the
// reprojection in double; the GPU does the rest in four full-screen passes.
#include "postfx/motion_blur.h"

#include "renderer/pass_kit.h"
#include "renderer/velocity.h"

#include <glm/gtc/matrix_transform.hpp>

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

#include "postfx/shaders/motion_blur_block.glsl"

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
    MotionBlurBlock block{};
    block.u_vel_pass = {scale, float(tile), float(rc.view.near_m), 0.0f};
    block.u_gather = {float(s.samples), s.depth_extent, float(tile), 0.0f};
    block.u_tiles = {0, tile, 0, 0};

    FullscreenPass velocity_pass("postfx.motion_blur.velocity", {"postfx/shaders/motion_blur_velocity.glsl", {}},
                                 {depth, motion}, "motion_blur.velocity");
    velocity_pass.size_from = image;
    velocity_pass.format = PixelFormat::RGBA16F;
    const TextureHandle velocity = addFullscreenPass(graph, rc, std::move(velocity_pass), block);

    // Largest motion per k x k tile, then per tile and its 8 neighbours.
    const auto tilePass = [&](const char* name, const char* target, TextureHandle in, int mode) {
        FullscreenPass pass(name, {"postfx/shaders/motion_blur_tiles.glsl", {}}, {in}, target);
        pass.size_from = velocity;
        pass.divisor = tile;
        pass.divide_up = true;
        pass.format = PixelFormat::RG16F;
        MotionBlurBlock tiles = block;
        tiles.u_tiles.x = mode;
        return addFullscreenPass(graph, rc, std::move(pass), tiles);
    };
    const TextureHandle tiles = tilePass("postfx.motion_blur.tiles", "motion_blur.tiles", velocity, 0);
    const TextureHandle neighbors = tilePass("postfx.motion_blur.neighbors", "motion_blur.neighbors", tiles, 1);

    return addFullscreenPass(graph, rc,
        FullscreenPass("postfx.motion_blur.gather", {"postfx/shaders/motion_blur_gather.glsl", {}},
                       {image, velocity, neighbors}, "motion_blur.out"),
        block);
}

ProgramList motionBlurPrograms() {
    return {{"postfx/shaders/motion_blur_velocity.glsl", {}},
            {"postfx/shaders/motion_blur_tiles.glsl", {}},
            {"postfx/shaders/motion_blur_gather.glsl", {}}};
}

}  // namespace vista
