// Timed full-screen copy.
#include "renderer/reference_copy.h"

#include <algorithm>
#include <chrono>
#include <vector>

namespace vista {

double measureReferenceCopyMs(const RenderContext& rc, TimerMode mode, int width, int height, int repeats) {
    gl::Texture source = gl::Texture::create2D(width, height, GL_RGBA16F, 1, "reference copy source");
    gl::Texture target = gl::Texture::create2D(width, height, GL_RGBA16F, 1, "reference copy target");
    gl::Framebuffer fb = gl::createFramebuffer("reference copy");
    glNamedFramebufferTexture(fb.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
    const float grey[4] = {0.5f, 0.25f, 0.125f, 1.0f};
    glClearTexImage(source.id(), 0, GL_RGBA, GL_FLOAT, grey);
    bindTarget(fb.id(), width, height);
    glUseProgram(rc.shaders.id("renderer/shaders/copy.glsl"));
    glBindTextureUnit(0, source.id());

    drawFullscreen(rc);  // warm-up: first-use costs (shader JIT on llvmpipe) are not the copy's
    std::vector<double> ms;
    if (mode == TimerMode::Finish) {
        for (int i = 0; i < repeats; ++i) {
            glFinish();
            auto start = std::chrono::steady_clock::now();
            drawFullscreen(rc);
            glFinish();
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
    } else {
        std::vector<gl::Query> queries;
        for (int i = 0; i < repeats; ++i) {
            queries.push_back(gl::createQuery(GL_TIME_ELAPSED));
            glBeginQuery(GL_TIME_ELAPSED, queries.back().id());
            drawFullscreen(rc);
            glEndQuery(GL_TIME_ELAPSED);
        }
        for (const auto& q : queries) {
            GLuint64 ns = 0;
            glGetQueryObjectui64v(q.id(), GL_QUERY_RESULT, &ns);
            ms.push_back(double(ns) * 1e-6);
        }
    }
    std::nth_element(ms.begin(), ms.begin() + std::ptrdiff_t(ms.size() / 2), ms.end());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return ms[ms.size() / 2];
}

}  // namespace vista
