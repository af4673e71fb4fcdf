// "clouds.shadow": the sun's transmittance through the cloud layers over a square of the ground
// around the camera (R16F, 1 = clear). A texel stands for the vertical line that meets the
// reference plane y = 0 at its centre; the sun ray through that point crosses each layer at
// x/z offsets sun.xz / sun.y * altitude (flat layers: at a few km the curvature is below a
// metre). lighting.sun projects each lit point onto the same plane along the sun's direction.
#include "../../../renderer/shaders/fullscreen.glsl"

#ifdef FRAGMENT_SHADER
#include "../../../renderer/shaders/common.glsl"
#include "clouds_common.glsl"
in vec2 v_uv;
layout(location = 0) out vec4 o_shadow;

const int kShadowSamples = 4;  // samples through each layer

void main() {
    vec2 ref = c_shadow.xy + (v_uv - 0.5) * c_shadow.z;  // camera-relative x/z on y = 0
    vec2 slope = c_sun.xz / c_sun.w;
    float tau = 0.0;
    for (int i = 0; i < c_count.x; ++i) {
        CloudLayer L = c_layers[i];
        int octaves = max(int(L.noise.w) - 1, 1);
        float step_len = L.shell.w / float(kShadowSamples) / c_sun.w;
        for (int s = 0; s < kShadowSamples; ++s) {
            float h01 = (float(s) + 0.5) / float(kShadowSamples);
            float altitude = L.shell.z + h01 * L.shell.w;
            tau += cloudDensity(i, ref + slope * altitude, h01, octaves) * step_len;
        }
    }
    o_shadow = vec4(exp(-tau), 0.0, 0.0, 1.0);
}
#endif
