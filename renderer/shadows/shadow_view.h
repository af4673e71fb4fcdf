// The shadow debug views' one pass body: a full-screen program that reads a shadow depth
// texture (cascades, spot atlas or point cubes) through its depth sampler and draws it in grey
// levels into a new RGBA8 image the size of the view.
#pragma once

#include "renderer/frame_graph.h"
#include "renderer/render_context.h"

#include <glm/vec4.hpp>

namespace vista {

struct ShadowViewPass {
    const char* name;     // the pass and its target ("shadows.view")
    const char* program;  // the view's shader file
    TextureHandle depth;  // the shadow texture this frame; invalid when nothing cast shadows
    GLuint sampler;       // its depth (non-comparing) sampler
    int unit;             // the texture unit the program reads it from
    glm::ivec4 info;      // ShadowViewBlock: x the layout's count (zeroed when `depth` is invalid), y, z, w the view's own
};

TextureHandle addShadowViewPass(FrameGraph& graph, const RenderContext& rc, ShadowViewPass pass);

ProgramList shadowPrograms();

}  // namespace vista
