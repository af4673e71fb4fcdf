// Grass passes: per-frame placement box, wind and terrain parameters for grass.cull, and the
// two indirect draws of grass.gbuffer.
#include "terrain/grass/grass.h"

#include "renderer/bindings.h"
#include "renderer/pass_kit.h"
#include "terrain/cdlod.h"
#include "terrain/terrain.h"


#include <algorithm>
#include <cmath>

namespace vista {

#include "terrain/grass/shaders/grass_block.glsl"

namespace {

#include "terrain/grass/shaders/grass_cull_block.glsl"

constexpr std::uint32_t kMaxListBlades = 1u << 22;  // per list: 192 MiB of blades at most

struct DrawCommand {
    std::uint32_t count, instance_count, first, base_instance;
};

int farSegments(int near_segments) { return std::max(1, (near_segments + 1) / 2); }

}  // namespace

ProgramList grassPrograms() {
    ProgramList programs = {
        {"terrain/grass/shaders/grass.glsl", {}},
        {"terrain/grass/shaders/grass.glsl", {"SHADOW_PASS"}},
        {"terrain/grass/shaders/grass.glsl", {"GRASS_VELOCITY"}}};
    TerrainSettings ts;  // the cull with the height/slope rules, and with one and two splat images
    for (const char* splat : {"", "a.png", "a.png b.png"}) {
        ts.splat_map = splat;
        programs.push_back({"terrain/grass/shaders/grass_cull.glsl", splatDefines(ts)});
    }
    return programs;
}

bool grassInReach(const Terrain& terrain, const TerrainSettings& ts, const GrassSettings& s, const glm::dvec3& eye) {
    // The highest point under the square of side 2 radius_m around the eye, from the min/max
    // quadtree at the finest level whose nodes are at least that large (at most 2 x 2 nodes).
    const MinMaxQuadtree& tree = terrain.quadtree();
    if (tree.levels() == 0) return true;
    const TerrainMapping& m = terrain.mapping();
    const double r = s.radius_m;
    int level = 0;
    while (level + 1 < tree.levels() &&
           double(tree.leafTexels() << level) * std::min(m.texelSizeX(), m.texelSizeZ()) < 2.0 * r)
        ++level;
    const double n = double(tree.leafTexels() << level);
    const glm::ivec2 nodes = tree.nodesPerSide(level);
    auto node = [&](double world, double origin, double extent, double texel, int count) {
        double t = (world - origin + extent * 0.5) / texel / n;
        return std::clamp(int(std::floor(t)), 0, count - 1);
    };
    const int x0 = node(eye.x - r, ts.origin.x, m.sizeX(), m.texelSizeX(), nodes.x),
              x1 = node(eye.x + r, ts.origin.x, m.sizeX(), m.texelSizeX(), nodes.x);
    const int z0 = node(eye.z - r, ts.origin.z, m.sizeZ(), m.texelSizeZ(), nodes.y),
              z1 = node(eye.z + r, ts.origin.z, m.sizeZ(), m.texelSizeZ(), nodes.y);
    double top = -1e300;
    for (int z = z0; z <= z1; ++z)
        for (int x = x0; x <= x1; ++x) top = std::max(top, double(tree.minMax(level, x, z).y));
    return eye.y - (ts.origin.y + top) < r;
}

void Grass::allocate(const GrassSettings& s) {
    GrassLayout layout = grassLayout(s);
    if (allocated_ && layout.cells == layout_.cells && layout.blades_per_cell == layout_.blades_per_cell &&
        s.lod_distance_m == sized_for_.lod_distance_m && s.radius_m == sized_for_.radius_m) {
        layout_ = layout;  // shift or other per-frame values may differ
        return;
    }
    layout_ = layout;
    sized_for_ = s;
    const double candidates = double(layout.candidates());
    const double per_m2 = layout.blades_per_cell / (layout.cell_m * layout.cell_m);
    // Near list: every candidate within lod_distance_m; far list: half the box (the view
    // sees at most about a quarter of it within the radius, thinned).
    const double lod = std::min<double>(s.lod_distance_m, s.radius_m);
    double near = std::min(candidates, 3.2 * lod * lod * per_m2 + 4.0 * layout.blades_per_cell + 64.0);
    double far = std::min(candidates, std::max(65536.0, candidates * 0.5));
    near_capacity_ = std::uint32_t(std::min<double>(near, kMaxListBlades));
    far_capacity_ = std::uint32_t(std::min<double>(far, kMaxListBlades));
    blades_ = gl::Buffer::create(GLsizeiptr(std::size_t(near_capacity_ + far_capacity_) * kGrassBladeBytes), nullptr, 0,
                                 "grass blades");
    draws_ = gl::Buffer::create(GLsizeiptr(2 * sizeof(DrawCommand)), nullptr, GL_DYNAMIC_STORAGE_BIT, "grass draws");
    allocated_ = true;
}

BufferHandle Grass::addCullPass(FrameGraph& graph, const RenderContext& rc, Terrain& terrain, const TerrainSettings& ts,
                                const GrassSettings& s, CounterReadback& counters, bool count, double motion_dt_s) {
    allocate(s);
    const BufferHandle imported = graph.importBuffer("grass.blades", BufferDesc{std::size_t(blades_.size())}, blades_.id());

    struct CullData {
        BufferHandle blades;
    };
    const CullData& cull = graph.addPass<CullData>("grass.cull",
        [&](PassBuilder& b, CullData& d) { d.blades = b.write(imported); },
        [this, &rc, &terrain, &ts, &s, &counters, count, motion_dt_s](const CullData&, PassContext&) {
            const GrassLayout& l = layout_;
            const glm::dvec3 eye = rc.view.position;
            const glm::dvec2 eye_xz(eye.x, eye.z);
            const glm::ivec2 box_min = grassBoxMin(l, eye_xz, rc.matrices.forward);
            const glm::dvec2 eye_cells = eye_xz / l.cell_m;
            const glm::dvec2 camera_cell = glm::floor(eye_cells);
            const glm::dvec2 frac = eye_cells - camera_cell;
            const TerrainMapping& m = terrain.mapping();
            const glm::dvec3 rel = eye - ts.origin;
            const Frustum planes = frustumFromViewProj(glm::dmat4(rc.matrices.view_proj));
            const GrassWind w = grassWind(s, eye_xz, rc.time_s);
            // The same wind field motion_dt_s earlier, sampled from this camera (grass.velocity).
            const GrassWind before = grassWind(s, eye_xz, rc.time_s - motion_dt_s);

            const DrawCommand reset[2] = {{std::uint32_t(2 * s.segments + 1), 0, 0, 0},
                                          {std::uint32_t(2 * farSegments(s.segments) + 1), 0, 0, 0}};
            glNamedBufferSubData(draws_.id(), 0, sizeof reset, reset);

            GLuint program = rc.shaders.id("terrain/grass/shaders/grass_cull.glsl", splatDefines(ts));
            glUseProgram(program);
            GrassCullBlock block{};
            block.u_box = {box_min.x, box_min.y, l.cells, l.blades_per_cell};
            block.u_camera_cell = {int(camera_cell.x), int(camera_cell.y)};
            block.u_box_mod = grassWrapCell(box_min, glm::ivec2(0), l.cells);  // box_min mod cells, >= 0
            block.u_cell = {float(frac.x), float(frac.y), float(l.cell_m), float(l.candidates())};
            block.u_radius = {s.radius_m, std::min(s.thin_start, 0.999f) * s.radius_m, s.far_keep, s.lod_distance_m};
            block.u_blade = {s.blade_height_m, s.height_variation, s.blade_width_m, s.curvature};
            block.u_map = {float(-m.sizeX() * 0.5 - rel.x), float(-m.sizeZ() * 0.5 - rel.z), float(m.texelSizeX()),
                           float(m.texelSizeZ())};
            block.u_height_map = {float(m.height_scale_m), float(m.height_offset_m - rel.y)};
            block.u_tex_offset = {float(rel.x), float(rel.z)};
            const Terrain::TileRows tiles = terrain.tileRows();
            block.u_tiles = tiles.tiles;
            block.u_tile_layer = tiles.layer;
            block.u_bands = {ts.sand_top, ts.grass_top, ts.snow_start, ts.band_blend};
            block.u_material = {ts.band_jitter, ts.rock_slope, 0.031f / ts.texture_scale_m, 0.0f};
            for (std::size_t p = 0; p < 5; ++p) block.u_planes[p] = glm::vec4(planes[p]);
            block.u_wind_a = {w.dir.x, w.dir.y, w.gust_origin.x, w.gust_origin.y};
            block.u_wind_b = {w.inv_gust_scale, w.sway_phase, w.strength, w.gust};
            block.u_wind_c = {w.sway, before.gust_origin.x, before.gust_origin.y, motion_dt_s > 0.0 ? before.sway_phase : -1.0f};
            block.u_color = {s.color, s.color_variation};
            block.u_dry = {s.dry_color, s.dry_fraction};
            block.u_capacity = {near_capacity_, far_capacity_, near_capacity_, count ? 1u : 0u};
            const std::array<glm::ivec4, kMaxSplatImages> splat = terrain.splatLayers();
            std::copy(splat.begin(), splat.end(), block.u_splat_layers);
            bindPassBlock(rc, program, block);
            glBindTextureUnit(binding::kTex0, terrain.heightTexture());
            glBindTextureUnit(binding::kTex1, terrain.normalTexture());
            glBindTextureUnit(binding::kTex2, terrain.albedoTexture());
            if (!ts.splat_map.empty()) terrain.bindSplat();  // blades follow its grass channel
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kGrassDraws, draws_.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kGrassBlades, blades_.id());
            if (count)
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kCounters, counters.request(rc.frame, "grass.blades"));
            const std::uint64_t groups = std::uint64_t((l.candidates() + 63) / 64);
            const std::uint64_t gx = std::min<std::uint64_t>(groups, 65535), gy = (groups + gx - 1) / gx;
            if (groups > 0) glDispatchCompute(GLuint(gx), GLuint(gy), 1);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
        });
    return cull.blades;
}

void Grass::drawLists(const RenderContext& rc, GLuint program, const GrassSettings& s, GrassBlock block) const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kGrassBlades, blades_.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, draws_.id());
    glDisable(GL_CULL_FACE);  // blades are two-sided
    const int segments[2] = {s.segments, farSegments(s.segments)};
    const std::uint32_t first[2] = {0, near_capacity_};
    for (int list = 0; list < 2; ++list) {
        block.u_segments = segments[list];
        block.u_first = first[list];
        bindPassBlock(rc, program, block);
        glDrawArraysIndirect(GL_TRIANGLE_STRIP, reinterpret_cast<const void*>(std::uintptr_t(list) * sizeof(DrawCommand)));
    }
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

void Grass::drawShadow(const RenderContext& rc, const GrassSettings& s, const glm::mat4& matrix) const {
    GLuint program = rc.shaders.id("terrain/grass/shaders/grass.glsl", {"SHADOW_PASS"});
    glUseProgram(program);
    glBindVertexArray(rc.empty_vao);
    GrassBlock block{};
    block.u_shadow_matrix = matrix;
    drawLists(rc, program, s, block);
}

TextureHandle Grass::addVelocityPass(FrameGraph& graph, const RenderContext& rc, const GrassSettings& s, BufferHandle blades,
                                     TextureHandle depth, TextureHandle velocity, const glm::dmat4& prev_clip_from_relative) {
    struct Data {
        BufferHandle blades;
        TextureHandle depth, velocity;
    };
    GrassBlock block{};
    block.u_prev_clip = glm::mat4(prev_clip_from_relative);
    block.u_jitter = glm::vec4(rc.jitter_ndc.x, rc.jitter_ndc.y, 0.0f, 0.0f);
    return graph.addPass<Data>("grass.velocity",
        [&](PassBuilder& b, Data& d) {
            d.blades = b.read(blades);
            d.depth = b.read(depth);
            d.velocity = b.write(velocity);
        },
        [this, &rc, &s, block](const Data& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.velocity);
            bindTarget(rc.device.framebuffer({ctx.texture(d.velocity)}, ctx.texture(d.depth)), desc.width, desc.height);
            const GLuint program = rc.shaders.id("terrain/grass/shaders/grass.glsl", {"GRASS_VELOCITY"});
            glUseProgram(program);
            // Only where a blade is what the pixel shows (gl_Position is invariant).
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_EQUAL);
            glDepthMask(GL_FALSE);
            glBindVertexArray(rc.empty_vao);
            drawLists(rc, program, s, block);
            glDepthMask(GL_TRUE);
            glDepthFunc(GL_GREATER);
            glDisable(GL_DEPTH_TEST);
        }).velocity;
}

void Grass::addGbufferPass(FrameGraph& graph, const RenderContext& rc, const GrassSettings& s, BufferHandle blades,
                           SceneTargets& targets) {
    addGbufferDrawPass(graph, rc, "grass.gbuffer", blades, targets, [this, &rc, &s] {
        GLuint program = rc.shaders.id("terrain/grass/shaders/grass.glsl");
        glUseProgram(program);
        GrassBlock block{};
        block.u_look = {s.root_darkening, s.roughness, s.normal_blend, wetness_};
        glBindVertexArray(rc.empty_vao);
        drawLists(rc, program, s, block);
    });
}

}  // namespace vista
