// The pass kit's GL side (renderer/pass_kit.h).
#include "renderer/pass_kit.h"

#include <algorithm>

namespace vista {

void PipelineState::apply() const {
    if (depth == Depth::Off) {
        glDisable(GL_DEPTH_TEST);
    } else {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
    }
    // Without the test nothing is written to depth either; the mask stays GL's default (on), so
    // a later glClear of depth works.
    glDepthMask(depth == Depth::Greater ? GL_FALSE : GL_TRUE);
    switch (blend) {
        case Blend::Off: glDisable(GL_BLEND); break;
        case Blend::Add:
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ONE);
            break;
        case Blend::Premultiplied:
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            break;
    }
    if (cull_back) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    } else {
        glDisable(GL_CULL_FACE);
    }
}

namespace detail {

TextureHandle addFullscreenPass(FrameGraph& graph, const RenderContext& rc, FullscreenPass pass, SetUniforms uniforms) {
    struct Data {
        std::vector<TextureHandle> inputs;
        std::vector<std::pair<int, BufferHandle>> buffers;
        TextureHandle out;
        std::vector<TextureHandle> also;
    };
    std::string name = pass.name;
    const Data& d = graph.addPass<Data>(std::move(name),
        [&](PassBuilder& b, Data& data) {
            for (TextureHandle in : pass.inputs) data.inputs.push_back(b.read(in));
            for (TextureHandle out : pass.also_writes) data.also.push_back(b.write(out));
            for (const auto& [binding, buffer] : pass.buffers) data.buffers.emplace_back(binding, b.read(buffer));
            const TextureDesc& first = b.desc(pass.size_from.valid() ? pass.size_from : pass.inputs.front());
            const int divisor = std::max(pass.divisor, 1), up = pass.divide_up ? divisor - 1 : 0;
            const TextureDesc desc{std::max(1, (first.width + up) / divisor), std::max(1, (first.height + up) / divisor),
                                   pass.format.value_or(first.format), 1};
            data.out = b.write(b.create(pass.target, desc));
        },
        [&rc, program = std::move(pass.program), textures = std::move(pass.textures), state = pass.state,
         uniforms = std::move(uniforms)](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.out);
            std::vector<GLuint> attachments{ctx.texture(data.out)};
            for (TextureHandle out : data.also) attachments.push_back(ctx.texture(out));
            bindTarget(rc.device.framebuffer(attachments), desc.width, desc.height);
            state.apply();
            const GLuint id = rc.shaders.id(program);
            glUseProgram(id);
            if (uniforms) uniforms(rc, id, ctx.desc(data.inputs.front()));
            for (std::size_t i = 0; i < data.inputs.size(); ++i) glBindTextureUnit(GLuint(i), ctx.texture(data.inputs[i]));
            for (const auto& [unit, texture] : textures) glBindTextureUnit(GLuint(unit), texture);
            for (const auto& [binding, buffer] : data.buffers)
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(binding), ctx.buffer(buffer));
            drawFullscreen(rc);
            if (!(state == PipelineState{})) PipelineState{}.apply();
        });
    return d.out;
}

std::vector<BufferHandle> addComputePass(FrameGraph& graph, const RenderContext& rc, ComputePass pass,
                                         SetUniforms uniforms) {
    struct Data {
        std::vector<TextureHandle> inputs;
        std::vector<std::pair<int, BufferHandle>> reads, writes;
    };
    std::string name = pass.name;
    const Data& d = graph.addPass<Data>(std::move(name),
        [&](PassBuilder& b, Data& data) {
            for (TextureHandle in : pass.inputs) data.inputs.push_back(b.read(in));
            for (const auto& [binding, buffer] : pass.reads) data.reads.emplace_back(binding, b.read(buffer));
            for (const auto& [binding, buffer] : pass.writes) data.writes.emplace_back(binding, b.write(buffer));
            for (const auto& made : pass.creates) data.writes.emplace_back(made.binding, b.write(b.create(made.name, made.desc)));
        },
        [&rc, program = std::move(pass.program), clear = pass.clear_writes, groups = std::move(pass.groups),
         uniforms = std::move(uniforms)](const Data& data, PassContext& ctx) {
            if (clear) {
                for (const auto& [binding, buffer] : data.writes)
                    glClearNamedBufferData(ctx.buffer(buffer), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
                glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
            }
            const GLuint id = rc.shaders.id(program);
            glUseProgram(id);
            const TextureDesc input = data.inputs.empty() ? TextureDesc{} : ctx.desc(data.inputs.front());
            if (uniforms) uniforms(rc, id, input);
            for (std::size_t i = 0; i < data.inputs.size(); ++i) glBindTextureUnit(GLuint(i), ctx.texture(data.inputs[i]));
            for (const auto& list : {&data.reads, &data.writes})
                for (const auto& [binding, buffer] : *list)
                    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(binding), ctx.buffer(buffer));
            const glm::uvec3 n = groups(input);
            glDispatchCompute(n.x, n.y, n.z);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        });
    std::vector<BufferHandle> out;
    for (const auto& [binding, buffer] : d.writes) out.push_back(buffer);
    return out;
}

}  // namespace detail

std::vector<BufferHandle> addComputePass(FrameGraph& graph, const RenderContext& rc, ComputePass pass) {
    return detail::addComputePass(graph, rc, std::move(pass), nullptr);
}

TextureHandle addFullscreenPass(FrameGraph& graph, const RenderContext& rc, FullscreenPass pass) {
    return detail::addFullscreenPass(graph, rc, std::move(pass), nullptr);
}

void addGbufferDrawPass(FrameGraph& graph, const RenderContext& rc, std::string name, BufferHandle lists,
                        SceneTargets& targets, std::function<void()> draw, std::function<void()> before) {
    struct Data {
        BufferHandle lists;
        SceneTargets t;
    };
    const Data& d = graph.addPass<Data>(std::move(name),
        [&](PassBuilder& b, Data& data) {
            data.lists = b.read(lists);
            data.t = targets;
            data.t.hdr = b.write(targets.hdr);
            data.t.albedo = b.write(targets.albedo);
            data.t.normal = b.write(targets.normal);
            data.t.depth = b.write(targets.depth);
        },
        [&rc, draw = std::move(draw), before = std::move(before)](const Data& data, PassContext& ctx) {
            if (before) before();
            const TextureDesc& desc = ctx.desc(data.t.hdr);
            GLuint fb = rc.device.framebuffer({ctx.texture(data.t.hdr), ctx.texture(data.t.albedo), ctx.texture(data.t.normal)},
                                              ctx.texture(data.t.depth));
            bindTarget(fb, desc.width, desc.height);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_GREATER);
            glDepthMask(GL_TRUE);
            draw();
            glDisable(GL_DEPTH_TEST);
        });
    targets = d.t;
}

void addOverHdrPass(FrameGraph& graph, const RenderContext& rc, std::string name, SceneTargets& targets,
                    std::function<void()> draw) {
    struct Data {
        TextureHandle depth, hdr;
    };
    const Data& d = graph.addPass<Data>(std::move(name),
        [&](PassBuilder& b, Data& data) {
            data.depth = b.read(targets.depth);
            data.hdr = b.write(targets.hdr);
        },
        [&rc, draw = std::move(draw)](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.hdr);
            bindTarget(rc.device.framebuffer({ctx.texture(data.hdr)}), desc.width, desc.height);
            glBindTextureUnit(binding::kTex0, ctx.texture(data.depth));
            draw();
        });
    targets.hdr = d.hdr;
}

}  // namespace vista
