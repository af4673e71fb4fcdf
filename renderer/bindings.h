// Binding points shared with GLSL (renderer/shaders/bindings.glsl); a unit test checks
// that both agree.
#pragma once

namespace vista::binding {

constexpr int kFrameUniforms = 0;  // uniform block: FrameUniforms
constexpr int kCounters = 0;       // shader storage: GPU counters (uint)
constexpr int kImageOutput = 0;    // image unit written by compute passes
constexpr int kTex0 = 0;           // texture units, in the order a pass declares its inputs
constexpr int kTex1 = 1;
constexpr int kTex2 = 2;
constexpr int kTex3 = 3;
constexpr int kTex4 = 4;
constexpr int kTerrainNodes = 1;   // shader storage: selected terrain node instances

}  // namespace vista::binding
