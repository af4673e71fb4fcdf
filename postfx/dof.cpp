// Depth of field after the usual scatter-as-gather scheme (e.g. Jimenez 2014, Sousa 2013):
// each tap of a disk around the pixel contributes when its own CoC reaches the pixel, far
// taps no further than the pixel's own CoC (a sharp object is not covered by the blurred
// background behind it), near taps by their own CoC into a separate layer whose coverage is
// the share of the pixel the blurred foreground discs cover.
#include "postfx/dof.h"

#include <algorithm>
#include <cmath>

namespace vista {

namespace {

struct Lens {
    float focal_m, f_stop, sensor_m, height_px;
};

Lens lens(const DofSettings& s, int height) {
    return {s.focal_length_mm * 1e-3f, s.f_stop, s.sensor_height_mm * 1e-3f, float(height)};
}

}  // namespace

double dofCocRadiusPx(double distance_m, double focus_m, const DofSettings& s, int image_height) {
    const double f = double(s.focal_length_mm) * 1e-3, n = double(s.f_stop);
    const double p = 1.0 / focus_m, inv = std::isinf(distance_m) ? 0.0 : 1.0 / distance_m;
    const double diameter_m = f * f / n * (p - inv) / (1.0 - f * p);
    return 0.5 * diameter_m / (double(s.sensor_height_mm) * 1e-3) * double(image_height);
}

float dofClampDiopters(float diopters, const DofSettings& s) {
    return std::clamp(diopters, 0.0f, 0.5f / (s.focal_length_mm * 1e-3f));
}

DepthOfField::DepthOfField() {
    postfx::DofFocusState initial;
    state_ = gl::Buffer::create(sizeof initial, &initial, GL_DYNAMIC_STORAGE_BIT, "postfx.dof focus state");
}

postfx::DofFocusState DepthOfField::read() const {
    postfx::DofFocusState s;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(state_.id(), 0, sizeof s, &s);
    return s;
}

TextureHandle addDofCocPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image, TextureHandle depth,
                            const DofSettings& s, BufferHandle focus) {
    struct Data {
        TextureHandle image, depth, coc;
        BufferHandle focus;
    };
    const bool automatic = focus.valid();
    const float manual = dofClampDiopters(1.0f / s.focus_distance_m, s);
    const float near_m = float(rc.view.near_m), max_coc = s.max_coc_px;
    const float half_focal = 0.5f / (s.focal_length_mm * 1e-3f);
    return graph.addPass<Data>("postfx.dof.coc",
        [&](PassBuilder& b, Data& d) {
            d.image = b.read(image);
            d.depth = b.read(depth);
            if (automatic) d.focus = b.read(focus);
            const TextureDesc& desc = b.desc(image);
            d.coc = b.write(b.create("dof.coc", {desc.width, desc.height, PixelFormat::RGBA16F}));
        },
        [&rc, s, automatic, manual, near_m, max_coc, half_focal](const Data& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.coc);
            const Lens l = lens(s, desc.height);
            bindTarget(rc.device.framebuffer({ctx.texture(d.coc)}), desc.width, desc.height);
            std::vector<std::string> defines;
            if (automatic) defines.push_back("DOF_AUTOFOCUS");
            GLuint program = rc.shaders.id("postfx/shaders/dof_coc.glsl", defines);
            glUseProgram(program);
            glProgramUniform4f(program, 0, l.focal_m, l.f_stop, l.sensor_m, l.height_px);
            glProgramUniform4f(program, 1, manual, near_m, max_coc, half_focal);
            glBindTextureUnit(0, ctx.texture(d.image));
            glBindTextureUnit(1, ctx.texture(d.depth));
            if (automatic) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, postfx::kDofFocusBinding, ctx.buffer(d.focus));
            drawFullscreen(rc);
        }).coc;
}

TextureHandle DepthOfField::addPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                                      TextureHandle depth, const DofSettings& s, double dt_s, bool reset) {
    BufferHandle focus;
    if (s.autofocus) {
        struct FocusData {
            TextureHandle depth;
            BufferHandle state;
        };
        // Written, not declared read: the last frame's focus is this pass's own business.
        BufferHandle state = graph.importBuffer("dof.focus", BufferDesc{sizeof(postfx::DofFocusState)}, state_.id());
        const float dt = float(std::clamp(dt_s, 0.0, 1e6)), rate = s.autofocus_rate;
        const float near_m = float(rc.view.near_m), max_diopters = dofClampDiopters(1e30f, s);
        focus = graph.addPass<FocusData>("postfx.dof.focus",
            [&](PassBuilder& b, FocusData& d) {
                d.depth = b.read(depth);
                d.state = b.write(state);
            },
            [&rc, dt, rate, near_m, max_diopters, reset](const FocusData& d, PassContext& ctx) {
                GLuint program = rc.shaders.id("postfx/shaders/dof_focus.glsl");
                glUseProgram(program);
                glProgramUniform4f(program, 0, dt, rate, near_m, max_diopters);
                glProgramUniform1f(program, 1, reset ? 1.0f : 0.0f);
                glBindTextureUnit(0, ctx.texture(d.depth));
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, postfx::kDofFocusBinding, ctx.buffer(d.state));
                glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
                glDispatchCompute(1, 1, 1);
                glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
            }).state;
    }
    const TextureHandle coc = addDofCocPass(graph, rc, image, depth, s, focus);

    struct TileData {
        TextureHandle in, out;
    };
    const auto tilePass = [&](const char* name, const char* target, TextureHandle in, int mode, int reach) {
        return graph.addPass<TileData>(name,
            [&](PassBuilder& b, TileData& d) {
                d.in = b.read(in);
                const TextureDesc& full = b.desc(coc);
                const int t = postfx::kDofTile;
                d.out = b.write(b.create(target, {(full.width + t - 1) / t, (full.height + t - 1) / t, PixelFormat::R16F}));
            },
            [&rc, mode, reach](const TileData& d, PassContext& ctx) {
                const TextureDesc& desc = ctx.desc(d.out);
                bindTarget(rc.device.framebuffer({ctx.texture(d.out)}), desc.width, desc.height);
                GLuint program = rc.shaders.id("postfx/shaders/dof_tiles.glsl");
                glUseProgram(program);
                glProgramUniform2i(program, 0, mode, reach);
                glBindTextureUnit(0, ctx.texture(d.in));
                drawFullscreen(rc);
            }).out;
    };
    const TextureHandle tiles = tilePass("postfx.dof.tiles", "dof.tiles", coc, 0, 0);
    const int reach = int(std::ceil(s.max_coc_px / float(postfx::kDofTile)));
    const TextureHandle near = tilePass("postfx.dof.dilate", "dof.near", tiles, 1, reach);

    struct GatherData {
        TextureHandle coc, near, out;
    };
    const glm::vec4 params{float(s.samples), s.max_coc_px, s.debug ? 1.0f : 0.0f, 0.0f};
    return graph.addPass<GatherData>("postfx.dof.gather",
        [&](PassBuilder& b, GatherData& d) {
            d.coc = b.read(coc);
            d.near = b.read(near);
            TextureDesc desc = b.desc(image);
            desc.levels = 1;
            d.out = b.write(b.create("dof.out", desc));
        },
        [&rc, params](const GatherData& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.out);
            bindTarget(rc.device.framebuffer({ctx.texture(d.out)}), desc.width, desc.height);
            GLuint program = rc.shaders.id("postfx/shaders/dof_gather.glsl");
            glUseProgram(program);
            glProgramUniform4f(program, 0, params.x, params.y, params.z, params.w);
            glBindTextureUnit(0, ctx.texture(d.coc));
            glBindTextureUnit(1, ctx.texture(d.near));
            drawFullscreen(rc);
        }).out;
}

ProgramList dofPrograms() {
    return {{"postfx/shaders/dof_focus.glsl", {}},
            {"postfx/shaders/dof_coc.glsl", {}},
            {"postfx/shaders/dof_coc.glsl", {"DOF_AUTOFOCUS"}},
            {"postfx/shaders/dof_tiles.glsl", {}},
            {"postfx/shaders/dof_gather.glsl", {}}};
}

}  // namespace vista
