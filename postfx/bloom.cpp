// Bloom: each level is a transient RGBA16F target; the upsample chain mixes rather than adds
// (up = mix(down, tent(coarser), radius), then image = mix(image, tent(up1), intensity)), so
// the weights of all levels sum to one: bloom moves energy around and never creates it.
#include "postfx/bloom.h"

#include "renderer/pass_kit.h"

#include <algorithm>

namespace vista {
namespace {

#include "postfx/shaders/bloom_block.glsl"

TextureHandle addUpPass(FrameGraph& graph, const RenderContext& rc, const std::string& name, TextureHandle coarse,
                        TextureHandle fine, float mix, bool composite) {
    std::vector<std::string> defines;
    if (composite) defines.push_back("BLOOM_COMPOSITE");
    // The target takes the fine level's size and format: inputs[0] is the fine level.
    const std::string target = composite ? "bloom.out" : "bloom." + name.substr(name.rfind('.') + 1);
    return addFullscreenPass(graph, rc, FullscreenPass(name, {"postfx/shaders/bloom_up.glsl", defines}, {fine, coarse}, target),
                             BloomBlock{glm::vec2(0.0f), 0.0f, mix});
}

}  // namespace

TextureHandle addBloomPasses(FrameGraph& graph, const RenderContext& rc, TextureHandle image, const BloomSettings& s) {
    std::vector<TextureHandle> levels;
    TextureHandle source = image;
    for (int level = 1; level <= std::max(1, s.levels); ++level) {
        std::vector<std::string> defines;
        if (level == 1) defines.push_back("BLOOM_FIRST");
        const std::string index = std::to_string(level);
        FullscreenPass pass("postfx.bloom.down" + index, {"postfx/shaders/bloom_down.glsl", defines}, {source},
                            "bloom.down" + index);
        pass.format = PixelFormat::RGBA16F;
        pass.divisor = 2;
        source = addFullscreenPass(graph, rc, std::move(pass),
                                   [clamp = s.clamp](const TextureDesc& in) {
                                       return BloomBlock{1.0f / glm::vec2(float(in.width), float(in.height)), clamp, 0.0f};
                                   });
        levels.push_back(source);
    }
    TextureHandle up = levels.back();
    for (int level = int(levels.size()) - 1; level >= 1; --level)
        up = addUpPass(graph, rc, "postfx.bloom.up" + std::to_string(level), up, levels[std::size_t(level - 1)], s.radius,
                       false);
    return addUpPass(graph, rc, "postfx.bloom.composite", up, image, s.intensity, true);
}

ProgramList bloomPrograms() {
    return {{"postfx/shaders/bloom_down.glsl", {}},
            {"postfx/shaders/bloom_down.glsl", {"BLOOM_FIRST"}},
            {"postfx/shaders/bloom_up.glsl", {}},
            {"postfx/shaders/bloom_up.glsl", {"BLOOM_COMPOSITE"}}};
}

}  // namespace vista
