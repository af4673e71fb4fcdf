// The pass kit: what a full-screen pass does, written once. A pass names its program, its
// inputs (texture units 0, 1, ... in order), its storage buffers, its target and its uniform
// block; the kit declares them to the frame graph, binds them, applies the pipeline state and
// draws. Uniforms travel as one std140 block per pass, declared once in a file C++ and GLSL
// both include (renderer/shaders/pass_block.glsl): no literal uniform locations.
#pragma once

#include "renderer/bindings.h"
#include "renderer/frame_graph.h"
#include "renderer/program_key.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace vista {

// The fixed-function state a pass draws with. apply() sets all of it, so a pass never
// depends on what the one before it left; PipelineState{} (nothing tested, written to depth,
// blended or culled) is what every kit pass leaves behind.
struct PipelineState {
    enum class Depth : std::uint8_t {
        Off,           // no test (so no write); the depth mask is left on, GL's default
        Greater,       // reversed Z: test, no write
        GreaterWrite,  // reversed Z: test and write
    };
    enum class Blend : std::uint8_t {
        Off,
        Add,          // dst + src
        Premultiplied,  // src + dst * (1 - src alpha)
    };
    Depth depth = Depth::Off;
    Blend blend = Blend::Off;
    bool cull_back = false;

    void apply() const;
    bool operator==(const PipelineState&) const = default;
};

// Uploads a pass block (PASS_BLOCK in renderer/shaders/pass_block.glsl) for the next draws of
// `program`, and checks once per program that GLSL lays it out as C++ does.
template <class Block>
void bindPassBlock(const RenderContext& rc, GLuint program, const Block& block) {
    static_assert(sizeof(Block) % 16 == 0, "a pass block's members come in whole 16-byte rows");
    static_assert(std::is_trivially_copyable_v<Block>);
    rc.shaders.checkBlock(program, Block::kBlockName, sizeof(Block));
    rc.device.bindUniforms(binding::kPassBlock, &block, sizeof(Block));
}

// The same outside a frame (work done once at load, with no ring to stream through): `block`
// goes into a buffer of its own, bound at binding::kPassBlock; keep the buffer until the draws
// or dispatches that read it have been issued.
template <class Block>
[[nodiscard]] gl::Buffer bindPassBlockOnce(ShaderLibrary& shaders, GLuint program, const Block& block) {
    static_assert(sizeof(Block) % 16 == 0, "a pass block's members come in whole 16-byte rows");
    static_assert(std::is_trivially_copyable_v<Block>);
    shaders.checkBlock(program, Block::kBlockName, sizeof(Block));
    gl::Buffer buffer = gl::Buffer::create(GLsizeiptr(sizeof(Block)), &block, 0, Block::kBlockName);
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::kPassBlock, buffer.id());
    return buffer;
}

// One full-screen pass writing a new target sized after its first input (or `size_from`).
struct FullscreenPass {
    FullscreenPass(std::string name_, ProgramKey program_, std::vector<TextureHandle> inputs_, std::string target_)
        : name(std::move(name_)), program(std::move(program_)), inputs(std::move(inputs_)), target(std::move(target_)) {}
    std::string name;                                    // the pass ("postfx.grade")
    ProgramKey program;                                  // file and defines
    std::vector<TextureHandle> inputs;                   // texture units 0, 1, ...; inputs[0] sizes the target
    std::vector<std::pair<int, GLuint>> textures;        // (unit, GL name): textures owned outside the graph
    std::vector<std::pair<int, BufferHandle>> buffers;   // (shader storage binding, buffer read)
    std::string target;                                  // the new target's name (colour attachment 0)
    std::vector<TextureHandle> also_writes;              // attachments 1, 2, ...: targets made earlier or imported
    std::optional<PixelFormat> format;                   // the target's format; inputs[0]'s when unset
    int divisor = 1;                                     // the target is inputs[0]'s size / divisor (at least 1), one level
    bool divide_up = false;                              // round that division up (tiles covering the image)
    TextureHandle size_from;                             // sizes (and formats) the target instead of inputs[0]
    PipelineState state;
};

namespace detail {
// Sets the pass's uniforms for `program`; gets the description of inputs[0].
using SetUniforms = std::function<void(const RenderContext&, GLuint program, const TextureDesc& input)>;
TextureHandle addFullscreenPass(FrameGraph& graph, const RenderContext& rc, FullscreenPass pass, SetUniforms uniforms);
}  // namespace detail

// Adds `pass`; returns its target. `block` is the pass's uniform block, or a function of
// inputs[0]'s TextureDesc that returns it (for uniforms that depend on the input's size).
template <class BlockOrMake>
TextureHandle addFullscreenPass(FrameGraph& graph, const RenderContext& rc, FullscreenPass pass, BlockOrMake block) {
    return detail::addFullscreenPass(graph, rc, std::move(pass),
        [block](const RenderContext& rc, GLuint program, const TextureDesc& input) {
            if constexpr (std::is_invocable_v<const BlockOrMake&, const TextureDesc&>)
                bindPassBlock(rc, program, block(input));
            else
                bindPassBlock(rc, program, block);
        });
}

// A pass without uniforms of its own.
TextureHandle addFullscreenPass(FrameGraph& graph, const RenderContext& rc, FullscreenPass pass);

// One compute dispatch over storage buffers (and textures it reads).
struct ComputePass {
    ComputePass(std::string name_, ProgramKey program_) : name(std::move(name_)), program(std::move(program_)) {}
    std::string name;
    ProgramKey program;
    std::vector<TextureHandle> inputs;                  // texture units 0, 1, ...
    std::vector<std::pair<int, BufferHandle>> reads;    // (shader storage binding, buffer read)
    std::vector<std::pair<int, BufferHandle>> writes;   // (binding, buffer written): made by earlier passes or imported
    struct NewBuffer {
        int binding;
        std::string name;
        BufferDesc desc;
    };
    std::vector<NewBuffer> creates;                     // buffers this pass makes and writes
    bool clear_writes = false;                          // zero the written and made buffers first
    // Work groups, from inputs[0]'s description (a default one without inputs).
    std::function<glm::uvec3(const TextureDesc& input)> groups = [](const TextureDesc&) { return glm::uvec3(1); };
};

namespace detail {
std::vector<BufferHandle> addComputePass(FrameGraph& graph, const RenderContext& rc, ComputePass pass,
                                         SetUniforms uniforms);
}  // namespace detail

// Adds `pass`; returns the written buffers' handles: those of `writes`, then those of `creates`. Every write is
// visible to later passes (shader storage, buffer reads and texture fetches) when it returns.
template <class Block>
std::vector<BufferHandle> addComputePass(FrameGraph& graph, const RenderContext& rc, ComputePass pass, Block block) {
    return detail::addComputePass(graph, rc, std::move(pass),
        [block](const RenderContext& rc, GLuint program, const TextureDesc&) { bindPassBlock(rc, program, block); });
}
std::vector<BufferHandle> addComputePass(FrameGraph& graph, const RenderContext& rc, ComputePass pass);

// Opaque geometry into the G-buffer (grass.gbuffer, objects.gbuffer): the pass reads `lists` (the
// culled lists it draws, so it follows their pass) and writes targets' hdr, albedo, normal and
// depth. before() runs first (work that binds a target of its own); then the three colour targets
// and depth are bound, depth tested GREATER and written, and draw() draws; the test is off after.
void addGbufferDrawPass(FrameGraph& graph, const RenderContext& rc, std::string name, BufferHandle lists,
                        SceneTargets& targets, std::function<void()> draw, std::function<void()> before = {});

// A pass drawn over targets.hdr where it is (lights.glow, water.underwater), reading targets.depth
// at texture unit 0: hdr is bound alone when draw() runs, which sets its program, inputs and
// blending and puts the blending back. Returns nothing: targets.hdr becomes the pass's.
void addOverHdrPass(FrameGraph& graph, const RenderContext& rc, std::string name, SceneTargets& targets,
                    std::function<void()> draw);

}  // namespace vista
