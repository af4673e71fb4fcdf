// The GL tests' shared harness: a headless OSMesa GL 4.5 context made once per test process,
// texture readback, a full-screen probe runner (GPU functions against their CPU mirrors) and
// a frame-graph readback pass.
#pragma once

#include "../temp_dir.h"
#include "app/gl_context.h"
#include "renderer/frame_graph.h"
#include "renderer/gl/objects.h"
#include "renderer/shader_library.h"

#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace vista::test {

// The context, made on first use and made current on every call. From then on every new ShaderLibrary (each FrameRenderer's)
// throws on a request for a variant outside its list and on a failed compile (strict mode): a
// reachable variant missing from allPrograms() fails the test that reaches it.
inline GlContext& glContext() {
    static std::unique_ptr<GlContext> context = [] {
        ShaderLibrary::unlisted_default = UnlistedProgram::Fail;
        std::string error;
        auto c = createContext(Backend::OSMesa, ContextOptions{64, 64, false, false, false, true, "test"}, error);
        if (!c) FAIL("cannot create an OSMesa context: " << error);
        return c;
    }();
    // A capture run by a test makes, and destroys, a context of its own.
    if (!context->makeCurrent()) FAIL("cannot make the test's OSMesa context current again");
    return *context;
}

// Reads mip 0 of a w x h texture back as RGBA floats (row 0 at the bottom, as GL stores it).
inline std::vector<float> readRgba(GLuint texture, int w, int h) {
    std::vector<float> texels(std::size_t(w) * std::size_t(h) * 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
    return texels;
}

// Draws a full-screen probe program (tests/gl/shaders/: a GPU function evaluated per pixel) into
// a w x h RGBA32F target and reads it back (row 0 at the bottom). bind runs after the target is
// bound, before the draw, for what the probe reads (buffers, uniforms).
template <class Bind>
std::vector<float> drawProbe(ShaderLibrary& shaders, const std::string& shader, const std::vector<std::string>& defines,
                             int w, int h, Bind&& bind) {
    shaders.addListed({shader, defines});  // a test's own program, beside a renderer's list
    auto* program = shaders.get(shader, defines);
    REQUIRE_MESSAGE(program, shader);
    gl::Texture target = gl::Texture::create2D(w, h, GL_RGBA32F, 1, "probe");
    gl::Framebuffer fb = gl::createFramebuffer("probe");
    glNamedFramebufferTexture(fb.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
    gl::VertexArray vao = gl::createVertexArray("probe");
    glBindFramebuffer(GL_FRAMEBUFFER, fb.id());
    glViewport(0, 0, w, h);
    glUseProgram(program->id());
    bind();
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<float> texels = readRgba(target.id(), w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return texels;
}

inline std::vector<float> drawProbe(ShaderLibrary& shaders, const std::string& shader, int w, int h) {
    return drawProbe(shaders, shader, {}, w, h, [] {});
}

// Adds a side-effect pass that reads `texture` back as RGBA floats into `out` when the graph runs.
inline void addReadback(FrameGraph& graph, TextureHandle texture, std::vector<float>& out) {
    struct Data {
        TextureHandle t;
    };
    graph.addPass<Data>("test.readback",
        [&](PassBuilder& b, Data& d) {
            d.t = b.read(texture);
            b.sideEffect();
        },
        [&out](const Data& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.t);
            out = readRgba(ctx.texture(d.t), desc.width, desc.height);
        });
}

}  // namespace vista::test
