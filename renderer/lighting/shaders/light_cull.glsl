// "lights.cull": builds the per-tile (LIGHTS_TILED) or per-cluster (LIGHTS_CLUSTERED) light
// lists on the GPU, one workgroup of 8 x 8 threads per screen tile (16 or 32 px).
//   1. The tile's depth range from its pixels (sky pixels ignored); clustered also marks the
//      depth slices its pixels fall in.
//   2. Every light's bounding sphere (view space) against the tile's frustum, four side planes
//      and the depth range, 64 lights at a time; hits are compacted in light order (so lists,
//      and images, do not depend on thread timing).
//   3. Tiled: the tile's list goes to a slot taken from a pool (atomic counter).
//      Clustered: for each occupied slice (one thread each), the tile's lights that touch the
//      box around the cluster's pixels (the tile's frustum between the least and the greatest
//      depth of its pixels in that slice) go to a slot taken from the pool.
// A list longer than max_lights_per_cell (at most kSharedCap), or one the pool has no room for,
// is not cut: the cell is marked kOverflowCount, which shading reads as "every light"
// (conservative), and the overflow counter is raised. The pool counter also records the demand
// of lists that did not fit, so the CPU can grow the pool (LocalLights). Unoccupied clusters get
// empty lists. LIGHTS_FORWARD builds lists that also cover every depth in front of the opaque
// surface (and every depth where the tile sees the sky), for forward-shaded transparent surfaces.
#ifdef COMPUTE_SHADER
#include "../../shaders/common.glsl"
#include "../../shaders/gbuffer.glsl"
#include "brdf.glsl"
#include "lights.glsl"

const uint kSide = 8u, kThreads = kSide * kSide;  // threads per tile
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = BINDING_TEX_0) uniform sampler2D u_depth;
layout(std430, binding = BINDING_LIGHT_SPHERES) readonly buffer Spheres { vec4 u_spheres[]; };  // view space centre, radius
layout(std430, binding = BINDING_COUNTERS) buffer Overflow { uint u_overflow; };
layout(std430, binding = BINDING_AUX) buffer Pool { uint u_pool_used; };
// lights.shade's indirect draw (count, instances, first, base instance): the CPU sets 0
// instances, any tile with a light sets 1, so a frame whose lights reach no tile shades nothing.
layout(std430, binding = BINDING_LIGHT_SHADE_DRAW) buffer ShadeDraw { uint u_shade_draw[4]; };

const uint kSharedCap = 4096u;  // tile list capacity in shared memory (16 KiB)
shared uint s_depth_min, s_depth_max;  // float bits of view depths (positive: ordered as uints)
shared bool s_sky;                     // a pixel of the tile sees the sky (depth 0)
shared uint s_slices[8];               // occupied slices (clustered)
shared uint s_mask[kThreads / 32u];    // hits of the current kThreads lights
shared uint s_count;                   // tile list length (may exceed the capacity)
shared uint s_list[kSharedCap];
shared uint s_offset;                  // the tile list's slot in the pool (tiled)
#ifdef LIGHTS_CLUSTERED
shared uint s_slice_min[256], s_slice_max[256];  // float bits of each slice's pixel depths
#endif

// The tile frustum's side planes in view space (camera looking along -z): inward normals.
vec3 plane(float slope, float sgn, bool horizontal) {
    vec3 n = horizontal ? vec3(0.0, sgn, sgn * slope) : vec3(sgn, 0.0, sgn * slope);
    return n * inversesqrt(1.0 + slope * slope);
}

void main() {
    uint t = gl_LocalInvocationIndex;
    uvec2 tile = gl_WorkGroupID.xy;
    uint tile_px = u_grid.y;
    if (t == 0u) {
        s_depth_min = floatBitsToUint(3.0e38);
        s_depth_max = 0u;
        s_count = 0u;
        s_sky = false;
    }
    if (t < 8u) s_slices[t] = 0u;
#ifdef LIGHTS_CLUSTERED
    for (uint k = t; k < 256u; k += kThreads) {
        s_slice_min[k] = floatBitsToUint(3.0e38);
        s_slice_max[k] = 0u;
    }
#endif
    barrier();

    // 1. Depth range (and occupied slices) of the tile's pixels; each thread takes
    //    (tile_px / kSide)^2 of them.
    ivec2 size = textureSize(u_depth, 0);
    uint per = tile_px / kSide;
    for (uint j = 0u; j < per * per; ++j) {
        ivec2 p = ivec2(tile * tile_px + gl_LocalInvocationID.xy * per + uvec2(j % per, j / per));
        if (any(greaterThanEqual(p, size))) continue;
        float depth = texelFetch(u_depth, p, 0).r;
        if (depth <= 0.0) {
            s_sky = true;
            continue;
        }
        float z = linearDepth(depth);
        atomicMin(s_depth_min, floatBitsToUint(z));
        atomicMax(s_depth_max, floatBitsToUint(z));
#ifdef LIGHTS_CLUSTERED
        uint k = sliceOf(z);
        atomicOr(s_slices[k >> 5], 1u << (k & 31u));
        atomicMin(s_slice_min[k], floatBitsToUint(z));
        atomicMax(s_slice_max[k], floatBitsToUint(z));
#endif
    }
    barrier();
    float zmin = uintBitsToFloat(s_depth_min) * (1.0 - 1e-4), zmax = uintBitsToFloat(s_depth_max) * (1.0 + 1e-4);
    bool empty = s_depth_max == 0u;
#ifdef LIGHTS_FORWARD
    // Lists for forward-shaded (transparent) surfaces too: they may lie anywhere in front of
    // the opaque depth, or at any depth where the tile sees the sky.
    const float kFar = 1.0e30;  // "infinity" that keeps 0 * far finite
    zmin = 0.0;
    if (s_sky || empty) zmax = kFar;
    empty = false;
#endif

    // The tile's edges as view-space slopes x / depth, y / depth (renderer/lighting/cluster_grid.h).
    vec2 inv = u_viewport.zw * 2.0;
    vec2 lo = (vec2(tile * tile_px) * inv - 1.0), hi = (vec2(min((tile + 1u) * tile_px, uvec2(size))) * inv - 1.0);
    float sx = u_slices.w * u_grid3.x, sy = u_slices.w;
    vec4 slopes = vec4(lo.x * sx, hi.x * sx, lo.y * sy, hi.y * sy);
    vec3 left = plane(slopes.x, 1.0, false), right = plane(slopes.y, -1.0, false);
    vec3 bottom = plane(slopes.z, 1.0, true), top = plane(slopes.w, -1.0, true);

    // 2. Lights against the tile, compacted in light order.
    uint light_count = empty ? 0u : u_grid.x;
    uint cell_cap = min(u_grid2.y, kSharedCap);
    for (uint base = 0u; base < light_count; base += kThreads) {
        if (t < kThreads / 32u) s_mask[t] = 0u;
        barrier();
        uint i = base + t;
        bool hit = false;
        if (i < light_count) {
            vec4 s = u_spheres[i];
            float r = s.w * (1.0 + 1e-4) + 1e-4 * length(s.xyz);  // guard against float rounding
            float depth = -s.z;
            hit = s.w > 0.0 && depth + r >= zmin && depth - r <= zmax && dot(left, s.xyz) >= -r &&
                  dot(right, s.xyz) >= -r && dot(bottom, s.xyz) >= -r && dot(top, s.xyz) >= -r;
        }
        if (hit) atomicOr(s_mask[t >> 5], 1u << (t & 31u));
        barrier();
        if (hit) {
            uint pos = s_count + bitCount(s_mask[t >> 5] & ((1u << (t & 31u)) - 1u));
            for (uint w = 0u; w < (t >> 5); ++w) pos += bitCount(s_mask[w]);
            if (pos < kSharedCap) s_list[pos] = i;
        }
        barrier();
        if (t == 0u) {
            uint n = 0u;
            for (uint w = 0u; w < kThreads / 32u; ++w) n += bitCount(s_mask[w]);
            s_count += n;
        }
        barrier();
    }

    if (t == 0u && s_count > 0u) u_shade_draw[1] = 1u;
#ifdef LIGHTS_TILED
    // 3. The tile's list into the pool, copied by all threads.
    uint cell = tile.x + u_grid.z * tile.y;
    if (t == 0u) {
        bool overflow = s_count > cell_cap;
        s_offset = overflow || s_count == 0u ? 0u : atomicAdd(u_pool_used, s_count);
        overflow = overflow || s_offset + s_count > u_grid2.z;
        u_light_cells[cell] = uvec2(s_offset, overflow ? kOverflowCount : s_count);
        if (overflow) {
            atomicAdd(u_overflow, 1u);
            s_offset = kOverflowCount;
        }
    }
    barrier();
    if (s_offset != kOverflowCount)
        for (uint j = t; j < s_count; j += kThreads) u_light_indices[s_offset + j] = s_list[j];
#else
    // 3. A thread per slice (thread t takes slices t, t + kThreads, ...): the tile's lights that
    //    touch the cluster's view-space box.
    uint slices = u_grid2.x;
    for (uint k = t; k < slices; k += kThreads) {
        uint cell = tile.x + u_grid.z * (tile.y + u_grid.w * k);
#ifdef LIGHTS_FORWARD
        float slice_near = k == 0u ? 0.0 : u_slices.x * exp(float(k) * u_slices.z);
        bool occupied = slice_near <= zmax;
#else
        bool occupied = ((s_slices[k >> 5] >> (k & 31u)) & 1u) != 0u;
#endif
        if (!occupied || empty) {
            u_light_cells[cell] = uvec2(0u, 0u);
            continue;
        }
        if (s_count > kSharedCap) {  // the tile list itself overflowed
            u_light_cells[cell] = uvec2(0u, kOverflowCount);
            atomicAdd(u_overflow, 1u);
            continue;
        }
        // The depth range of the tile's pixels in this slice (within the slice's bounds
        // near_k = near_0 * ratio^k by construction), widened against rounding.
#ifdef LIGHTS_FORWARD
        // Forward: the whole slice in front of the tile's farthest opaque pixel.
        float dn = slice_near * (1.0 - 1e-4);
        float df = min(k + 1u >= slices ? kFar : u_slices.x * exp(float(k + 1u) * u_slices.z) * (1.0 + 1e-4), zmax);
#else
        float dn = uintBitsToFloat(s_slice_min[k]) * (1.0 - 1e-4);
        float df = uintBitsToFloat(s_slice_max[k]) * (1.0 + 1e-4);
#endif
        vec3 box_min = vec3(min(slopes.x * dn, slopes.x * df), min(slopes.z * dn, slopes.z * df), -df);
        vec3 box_max = vec3(max(slopes.y * dn, slopes.y * df), max(slopes.w * dn, slopes.w * df), -dn);
        uint count = 0u;
        for (uint j = 0u; j < s_count; ++j) {
            vec4 s = u_spheres[s_list[j]];
            float r = s.w * (1.0 + 1e-4) + 1e-4 * length(s.xyz);
            vec3 d = s.xyz - clamp(s.xyz, box_min, box_max);
            if (dot(d, d) <= r * r) ++count;
        }
        uint offset = 0u;
        bool overflow = count > cell_cap;
        if (!overflow && count > 0u) {
            offset = atomicAdd(u_pool_used, count);  // may pass the capacity: the demand is read back
            overflow = offset + count > u_grid2.z;
        }
        if (overflow) {
            u_light_cells[cell] = uvec2(0u, kOverflowCount);
            atomicAdd(u_overflow, 1u);
            continue;
        }
        uint n = 0u;
        for (uint j = 0u; j < s_count && n < count; ++j) {
            vec4 s = u_spheres[s_list[j]];
            float r = s.w * (1.0 + 1e-4) + 1e-4 * length(s.xyz);
            vec3 d = s.xyz - clamp(s.xyz, box_min, box_max);
            if (dot(d, d) <= r * r) u_light_indices[offset + n++] = s_list[j];
        }
        u_light_cells[cell] = uvec2(offset, count);
    }
#endif
}
#endif
