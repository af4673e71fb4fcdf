// Test probe for the GPU waves (tests/gl/water_test.cpp): evaluates terrain/water/shaders/waves.glsl at
// camera-relative rest points with the frame's water uniforms, for comparison with the CPU's
// double-precision evaluateWaves(); also the previous frame's displacement (the motion vectors').
#ifdef COMPUTE_SHADER
#include "../../../renderer/shaders/bindings.glsl"
#include "../../../terrain/water/shaders/waves.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = BINDING_AUX) readonly buffer Points { vec4 u_points[]; };  // x, z rest offset from the camera (m), footprint (m)
layout(std430, binding = BINDING_COUNTERS) writeonly buffer Results { vec4 u_results[]; };
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(u_points.length())) return;
    vec4 p = u_points[i];
    WaveSample ws = evaluateWaves(p.xy, p.z);
    u_results[3u * i] = vec4(ws.displacement, ws.jacobian);
    u_results[3u * i + 1u] = vec4(ws.normal, ws.lost_slope_variance);
    u_results[3u * i + 2u] = vec4(previousDisplacement(p.xy, p.z), 0.0);
}
#endif
