// "grass.cull": one thread per candidate blade of the placement box (terrain/grass/grass_placement.h).
// The slot's world cell comes from the integer toroidal wrap, the blade from a hash of the
// cell and its index; then, cheapest first: distance (blades thin out and shrink toward
// radius_m), the terrain's height and grass weight (terrain/shaders/material.glsl, the same
// as the terrain shader: the height/slope rules, or with TERRAIN_SPLAT the splat map's grass
// share), the view frustum. Survivors get their wind bend and are appended
// to the near or far list (atomic counts in the indirect draw commands); a list that is full
// gives its increment back, so its count ends at its capacity.
#ifdef COMPUTE_SHADER
#include "../../../renderer/shaders/common.glsl"
#include "../../../renderer/shaders/counters.glsl"
#include "../../shaders/tiles.glsl"
#include "../../shaders/material.glsl"
#include "grass_common.glsl"

layout(local_size_x = 64) in;

struct DrawCommand {
    uint count, instance_count, first, base_instance;
};
layout(std430, binding = BINDING_GRASS_DRAWS) buffer Draws { DrawCommand u_draws[2]; };  // near, far
layout(std430, binding = BINDING_GRASS_BLADES) writeonly buffer Blades { GrassBlade u_blades[]; };
layout(std430, binding = BINDING_COUNTERS) buffer Counter { uint u_drawn_low, u_drawn_high; };

layout(binding = BINDING_TEX_0) uniform sampler2DArray u_height;   // heightmap samples (R32F tiles)
layout(binding = BINDING_TEX_1) uniform sampler2DArray u_normals;  // world normals
layout(binding = BINDING_TEX_2) uniform sampler2DArray u_albedo;   // terrain material albedo (band jitter noise)

#include "grass_cull_block.glsl"
#ifdef TERRAIN_SPLAT
layout(binding = BINDING_TEX_5) uniform sampler2DArray u_splat;  // the terrain's splat weights (terrain.glsl's)
#endif

shared uint s_drawn;

// The full-resolution terrain surface at texel coordinates t (tiles.glsl).
float surfaceSample(vec2 t) {
    return tileSurfaceSample(u_height, t, u_tiles, u_tile_layer);
}

float keepShare(float d) {
    return 1.0 - (1.0 - u_radius.z) * smoothstep(u_radius.y, u_radius.x, d);
}

// Appends a blade to list (0 near, 1 far); false when the list is full.
bool append(uint list, GrassBlade blade) {
    uint capacity = list == 0u ? u_capacity.x : u_capacity.y;
    uint index = atomicAdd(u_draws[list].instance_count, 1u);
    if (index >= capacity) {
        atomicAdd(u_draws[list].instance_count, uint(-1));
        return false;
    }
    u_blades[(list == 0u ? 0u : u_capacity.z) + index] = blade;
    return true;
}

bool cull(uint id, out GrassBlade blade, out uint list) {
    blade = GrassBlade(vec4(0.0), vec4(0.0), uvec4(0u));
    list = 0u;
    if (float(id) >= u_cell.w) return false;
    int per_cell = u_box.w, cells = u_box.z;
    int slot_index = int(id) / per_cell, j = int(id) - slot_index * per_cell;
    ivec2 slot = ivec2(slot_index % cells, slot_index / cells);
    // Integer toroidal wrap: the one world cell congruent to the slot inside the box (GLSL's %
    // is undefined for negative operands: u_box_mod is the box's min cell mod cells, >= 0).
    ivec2 cell = u_box.xy + (slot - u_box_mod + cells) % cells;
    uint h = grassHash(uint(cell.x), uint(cell.y), uint(j));
    vec2 offset = vec2(grassRandom(h, 0u), grassRandom(h, 1u));
    vec2 rel_xz = (vec2(cell - u_camera_cell) + offset - u_cell.xy) * u_cell.z;

    // Distance first (horizontal, a lower bound of the 3D one: the kept share only falls).
    float thin = grassRandom(h, 4u);
    float dh = length(rel_xz);
    if (dh >= u_radius.x || thin >= keepShare(dh)) return false;

    vec2 texel = (rel_xz - u_map.xy) / u_map.zw;
    if (any(lessThan(texel, vec2(0.0))) || any(greaterThan(texel, u_tile_layer.zw - 1.0))) return false;
    float s = surfaceSample(texel);
    vec3 root = vec3(rel_xz.x, u_height_map.x * s + u_height_map.y, rel_xz.y);
    float d = length(root);
    float keep = keepShare(d);
    float fade = clamp((keep - thin) / (0.2 * keep), 0.0, 1.0) * (1.0 - smoothstep(0.8 * u_radius.x, u_radius.x, d));
    if (fade <= 0.01) return false;

    // Where the terrain shader draws grass: the splat map's grass share, or the height/slope rules
    // (their band jitter noise sampled at the finest level).
    vec3 n = safeNormalize(textureLod(u_normals, tileCoord(texel, u_tiles, u_tile_layer), 0.0).xyz);
#ifdef TERRAIN_SPLAT
    vec4 splat_a, splat_b;
    splatWeightsAt(u_splat, u_splat_layers, u_tile_layer.zw, texel, splat_a, splat_b);
    float weight = splatShare(splat_a, splat_b, u_splat_layers, GRASS);
#else
    float noise = texelBilinearRepeat(u_albedo, (rel_xz + u_tex_offset) * u_material.z, ROCK).g;
    float bands = materialBands(s + bandJitter(noise, u_material.x), u_bands);
    float rock = rockWeight(n.y, u_material.y);
    float weight = grassWeight(bands, rock, dirtWeight(n.y, u_material.y, rock, bands));
#endif
    if (grassRandom(h, 5u) >= weight) return false;

    float len = u_blade.x * (1.0 + u_blade.y * (grassRandom(h, 3u) * 2.0 - 1.0)) * fade * mix(0.6, 1.0, weight);
    float width = u_blade.z / sqrt(keep);
    vec3 centre = root + vec3(0.0, 0.5 * len, 0.0);
    float radius = 0.75 * len + width;
    for (int p = 0; p < 5; ++p)
        if (dot(u_planes[p].xyz, centre) + u_planes[p].w < -radius) return false;

    // Bend: a rest curve over the blade's face plus the wind.
    float facing = 6.2831853 * grassRandom(h, 2u);
    vec2 face = vec2(-sin(facing), cos(facing));
    GrassWind wind = GrassWind(u_wind_a.xy, u_wind_a.zw, u_wind_b.x, u_wind_b.y, u_wind_b.z, u_wind_b.w, u_wind_c.x);
    int step = 6 + min(int(grassRandom(h, 8u) * 5.0), 4);
    float phase = 6.2831853 * grassRandom(h, 7u);
    vec2 tilt = grassWindTilt(wind, rel_xz, phase, step);
    vec2 bend = face * (u_blade.w * grassRandom(h, 6u)) + tilt;
    // The wind's tilt one frame earlier, as a change of the bend (grass.velocity): the same
    // field at the previous time (gust origin and sway phase of that time, this camera).
    vec2 bend_change = vec2(0.0);
    if (u_wind_c.w >= 0.0) {
        GrassWind before = wind;
        before.gust_origin = u_wind_c.yz;
        before.sway_phase = u_wind_c.w;
        bend_change = grassWindTilt(before, rel_xz, phase, step) - tilt;
    }

    vec3 color = mix(u_color.rgb, u_dry.rgb, u_dry.w * grassRandom(h, 9u) * grassRandom(h, 9u));
    color *= 1.0 + u_color.w * (grassRandom(h, 10u) * 2.0 - 1.0) * 0.5;
    blade.root_width = vec4(root, width);
    blade.shape = vec4(len, facing, bend);
    blade.look = uvec4(packUnorm4x8(vec4(sqrt(clamp(color, 0.0, 1.0)), 0.0)), packSnorm4x8(vec4(n, 0.0)), id,
                       packHalf2x16(bend_change));
    list = d < u_radius.w ? 0u : 1u;
    return true;
}

void main() {
    if (gl_LocalInvocationIndex == 0u) s_drawn = 0u;
    barrier();
    uint id = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationIndex;
    GrassBlade blade;
    uint list;
    if (cull(id, blade, list) && append(list, blade)) atomicAdd(s_drawn, 1u);
    barrier();
    if (gl_LocalInvocationIndex == 0u && u_capacity.w != 0u) ADD_COUNTER64(u_drawn_low, u_drawn_high, s_drawn);
}
#endif
