// The pass kit (renderer/pass_kit.h): a block declared once reaches GLSL at the offsets C++
// wrote; a block whose rows break std140 is refused by name; pipeline state is set whole and
// left at the default.
#include "gl_fixture.h"

#include "app/scene.h"
#include "renderer/gl_device.h"
#include "renderer/pass_kit.h"

#include <doctest/doctest.h>

#include <stdexcept>

namespace vista {
namespace {
#include "shaders/probe_block.glsl"
#include "shaders/broken_block.glsl"
}  // namespace

TEST_CASE("gl: a pass block reaches GLSL at the offsets C++ wrote") {
    test::glContext();
    ShaderLibrary shaders(vistaRoot());
    shaders.unlisted = UnlistedProgram::Fail;
    GlDevice device;
    RenderContext rc{shaders, device, 0};
    ProbeBlock block{};
    block.u_a = {1, 2, 3};
    block.u_b = 4;
    block.u_c = {5, 6};
    block.u_d = {7, 8};
    block.u_e = 9;
    block.u_f = 10;
    block.u_g = {11, 12};
    block.u_h = 13;
    block.u_i = 14;
    block.u_j = 15;
    block.u_k = 16;
    block.u_l = {17, 18, 19, 20};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) block.u_m[c][r] = float(21 + 4 * c + r);
    // Another block first, so the probe's range does not start at the ring's offset 0.
    device.bindUniforms(binding::kPassBlock, &block, 48);
    const std::string probe = "tests/gl/shaders/pass_block_probe.glsl";
    shaders.addListed({probe, {}});
    const GLuint program = shaders.id(probe);
    const std::vector<float> rows = test::drawProbe(shaders, probe, {}, 9, 1, [&] { bindPassBlock(rc, program, block); });
    for (int i = 0; i < 36; ++i) CHECK_MESSAGE(rows[std::size_t(i)] == float(i + 1), "member value " << i + 1);
}

TEST_CASE("gl: a pass block whose rows break std140 is refused, naming it") {
    test::glContext();
    ShaderLibrary shaders(vistaRoot());
    shaders.unlisted = UnlistedProgram::Fail;
    GlDevice device;
    RenderContext rc{shaders, device, 0};
    const ProgramKey key{"tests/gl/shaders/pass_block_probe.glsl", {"BROKEN"}};
    shaders.addListed(key);
    const GLuint program = shaders.id(key);
    REQUIRE(program != 0);
    CHECK_THROWS_WITH_AS(bindPassBlock(rc, program, BrokenBlock{}), doctest::Contains("BrokenBlock"), std::logic_error);
    // Production prints it once and goes on.
    ShaderLibrary lenient(vistaRoot());
    lenient.unlisted = UnlistedProgram::Log;
    lenient.addListed(key);
    const GLuint again = lenient.id(key);
    CHECK_NOTHROW(lenient.checkBlock(again, BrokenBlock::kBlockName, sizeof(BrokenBlock)));
}

TEST_CASE("gl: pipeline state is applied whole and PipelineState{} is GL's default") {
    test::glContext();
    PipelineState{.depth = PipelineState::Depth::Greater, .blend = PipelineState::Blend::Premultiplied, .cull_back = true}
        .apply();
    GLboolean mask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
    CHECK(glIsEnabled(GL_DEPTH_TEST));
    CHECK(mask == GL_FALSE);
    CHECK(glIsEnabled(GL_BLEND));
    CHECK(glIsEnabled(GL_CULL_FACE));
    PipelineState{}.apply();
    glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
    CHECK_FALSE(glIsEnabled(GL_DEPTH_TEST));
    CHECK(mask == GL_TRUE);  // a later glClear of depth still clears
    CHECK_FALSE(glIsEnabled(GL_BLEND));
    CHECK_FALSE(glIsEnabled(GL_CULL_FACE));
}

}  // namespace vista
