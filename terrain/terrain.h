// The terrain of a scene: heightmap, min/max quadtree, GPU textures (heights, normals,
// materials) and buffers, all made once at load; per frame a CDLOD selection for the main
// camera, reusable for shadow passes, and one instanced draw.
#pragma once

#include "config/input_error.h"
#include "renderer/camera.h"
#include "renderer/gl/objects.h"
#include "renderer/render_context.h"
#include "renderer/scene_targets.h"
#include "renderer/shadows/terrain_caster.h"  // TerrainInstance
#include "terrain/cdlod.h"
#include "terrain/lod_error.h"
#include "terrain/terrain_settings.h"
#include "terrain/tess_displacement.h"
#include "terrain/tile_stream.h"
#include "terrain/user_materials.h"

#include <array>
#include <functional>
#include <memory>
#include <span>

namespace vista {

// Material tiers of the terrain shader by distance (terrain.glsl MATERIAL_TIER): near (detail
// normals, triplanar rock), mid (albedo only), far (each layer's mean albedo).
inline constexpr int kMaterialTiers = 3;

// The terrain programs' uniform block (terrain/shaders/terrain_block.glsl, filled in terrain.cpp).
struct TerrainBlock;

struct TerrainCounters {
    std::int64_t triangles = 0, nodes = 0, draws = 0;
    std::array<std::int64_t, kMaterialTiers> tier_instances{};  // drawn quadrants per material tier
    double select_ms = 0.0;
    double base_range_m = 0.0;  // LOD 0 range in use (after the node-size and error bounds)
    std::int64_t tess_patches = 0;  // grid triangles drawn as tessellation patches ([terrain.tessellation])
    std::int64_t tess_shadow_patches = 0;  // the same in shadow passes (sun cascades, spot tiles, point cube faces)
    StreamCounters stream;  // [terrain.stream]: tiles resident, requested, loaded, evicted, missing (zero when not streaming)
};

// How the heightmap is split into texture-array layers: tile (i, j) is layer j * count.x + i
// and holds texels [i * span, i * span + layer.x) x [j * span, ...), clamped to the map.
struct TerrainTiles {
    glm::ivec2 count{1};  // tiles in x, z
    int span = 1;         // texels between tile origins
    glm::ivec2 layer{1};  // texels per layer
};

// Ground height (m) of a heightmap placed by mapping around origin ([terrain] origin) at world
// x/z, bilinear, clamped to the map's edge outside it: Terrain::heightAt(), and `vista check`
// without GL.
double terrainHeightAt(const Heightmap& map, const TerrainMapping& mapping, const glm::dvec3& origin, double x, double z);
// The same from sample(tx, tz): the map's units at continuous level-0 texel coordinates (a
// Heightmap's, a tile cache's through TileCacheSampler).
template <class Sample>
double placedHeightAt(const TerrainMapping& m, const glm::dvec3& origin, double x, double z, Sample&& sample) {
    const double tx = (x - origin.x + m.sizeX() * 0.5) / m.texelSizeX();
    const double tz = (z - origin.z + m.sizeZ() * 0.5) / m.texelSizeZ();
    return origin.y + m.height_offset_m + m.height_scale_m * double(sample(tx, tz));
}

// The tile cache a streamed terrain reads ([terrain.stream] cache, or next to the input),
// checked against its input and the settings. A missing or stale one is built (Build: as
// vista terrain-cache builds it), or, for `vista check` (Check), its input is read through and
// checked as building it would check it, nothing is written, and null comes back without errors.
enum class StreamCacheUse { Build, Check };
class TileCache;
std::unique_ptr<TileCache> openStreamCache(const TerrainSettings& s, StreamCacheUse use, InputErrors& errors);

class Terrain {
public:
    // Loads everything the settings name; on bad input returns null with errors (file, what
    // is accepted). Needs a current GL context and the shader library.
    static std::unique_ptr<Terrain> load(const TerrainSettings& s, ShaderLibrary& shaders, InputErrors& errors);
    // The checks load() makes without GL (heightmap or DEM file, samples, height range, grid),
    // for `vista check`; returns the map when they pass (empty otherwise, with errors), and its
    // mapping in *mapping: from the settings for a heightmap, from the data for a DEM.
    static Heightmap loadChecked(const TerrainSettings& s, InputErrors& errors, TerrainMapping* mapping = nullptr);
    // Same, from a heightmap already in memory (benchmarks, generated maps). max_texture
    // lowers the texture size limit the tiles must fit (tests; 0: GL_MAX_TEXTURE_SIZE).
    static std::unique_ptr<Terrain> create(Heightmap map, const TerrainSettings& s, ShaderLibrary& shaders,
                                           InputErrors& errors, int max_texture = 0);
    // Same with the mapping given (a DEM's, terrain/dem.h) rather than taken from s.
    static std::unique_ptr<Terrain> create(Heightmap map, const TerrainMapping& mapping, const TerrainSettings& s,
                                           ShaderLibrary& shaders, InputErrors& errors, int max_texture = 0);

    // With [terrain.stream]: from the tile cache (built from the input first when missing or
    // stale), through a GPU page pool (terrain/tile_stream.h); the map is not kept.
    static std::unique_ptr<Terrain> loadStreamed(const TerrainSettings& s, ShaderLibrary& shaders, InputErrors& errors);
    bool streamed() const { return stream_ != nullptr; }
    TileStream* stream() { return stream_.get(); }
    // The depth-only program's defines (terrain.glsl SHADOW_PASS; TERRAIN_STREAM when streamed).
    std::vector<std::string> shadowDefines() const;

    // True when s names the same data and mapping (no reload needed).
    bool matches(const TerrainSettings& s) const;

    // Ground height (m) at world x/z, bilinear; clamped to the map's edge outside it.
    double heightAt(double x, double z) const;
    // heightAt for another thread (a streamed terrain's reads tiles through a sampler of its own);
    // valid while this terrain lives.
    std::function<double(double, double)> heightSampler() const;

    // Selects nodes for a camera (world position, camera-relative view-projection) and fills
    // the instance list with those in its frustum. error_scale is screenErrorScale() of the
    // view: the LOD keeps the vertical screen error within s.max_error_px for it. With
    // `caster_frustum` (the view frustum widened towards the sun, renderer/shadows/cascades.h) the
    // selection covers it instead, and shadow passes draw parts of it (shadowInstances()):
    // one selection per frame, so casters and receivers share one LOD. `extra` frusta (spot
    // shadow views, camera-relative) are covered too; the view draws only its own part.
    const Selection& select(const glm::dvec3& camera, const glm::dmat4& view_proj, const TerrainSettings& s,
                            double error_scale, const Frustum* caster_frustum = nullptr,
                            std::span<const Frustum> extra = {});
    const Selection& selection() const { return selection_; }
    const std::vector<TerrainInstance>& instances() const { return instances_; }
    const GridErrors& gridErrors() const { return errors_; }
    const DistanceBias& distanceBias() const { return bias_; }
    const TerrainCounters& counters() const { return counters_; }

    // Colour the grass band takes beyond the grass blades (linear albedo, strength; strength 0
    // = none) between fade.x and fade.y metres from the camera. Set by the grass feature.
    void setFarGrass(const glm::vec4& color_strength, const glm::vec2& fade) {
        far_grass_ = color_strength;
        far_grass_fade_ = fade;
    }

    // How wet the ground is (0 dry .. 1 soaked: darker, glossier). Set by the weather feature.
    void setWetness(float wetness) { wetness_ = wetness; }

    // Draws the current instances, front to back, one instanced draw per material tier with
    // programs[tier] (terrainDefines()); uploads a remade bias first. With [terrain.tessellation]
    // on, the near tier's quadrants within its range are drawn first as patches with tess_program
    // (terrainTessDefines()).
    void draw(const RenderContext& rc, const TerrainSettings& s, std::span<const GLuint, kMaterialTiers> programs,
              GLuint tess_program = 0);

    // The instances of the current selection inside planes (camera-relative), for a shadow pass;
    // with `keep`, only the nodes whose camera-relative box (lo, hi) it accepts (`skipped`, when
    // given, gets how many instances inside the planes it left out). With [terrain.tessellation]
    // on and `tessellate` (the shadow view serves ground within the displacement's reach), those
    // within range_m of the camera in x, z come first and their count is returned: drawShadow()
    // draws them displaced as the view draws them (factors and relief for the main camera), so
    // casters sink with the surface they shadow. Their grid triangles add to
    // counters().tess_shadow_patches (reset by select()). With coarsest_step_m > 0 the others are
    // grouped by casterDecimation() (their b.w = k), finest grid first.
    std::size_t shadowInstances(const TerrainSettings& s, const Frustum& planes, std::vector<TerrainInstance>& out,
                                bool tessellate,
                                const std::function<bool(const glm::dvec3& lo, const glm::dvec3& hi)>& keep = {},
                                std::size_t* skipped = nullptr, double coarsest_step_m = 0.0);
    // Draws instances depth-only with program (terrain.glsl with SHADOW_PASS) through matrix
    // (camera-relative world -> the shadow view's clip) into slot 0..kShadowSlots-1 of the shadow
    // instance buffer (made on first use); the first `tess` of them (shadowInstances()) as patches
    // with terrain_tess.glsl's shadow program; the others with every 2^k-th grid vertex (k their
    // b.w, set by shadowInstances()).
    static constexpr int kShadowSlots = TerrainCaster::kSlots;
    void drawShadow(const RenderContext& rc, const TerrainSettings& s, GLuint program, const glm::mat4& matrix,
                    const std::vector<TerrainInstance>& instances, std::size_t tess, int slot);
    // The triangles instances draw (patches counted as their grid triangles).
    std::int64_t triangles(const std::vector<TerrainInstance>& instances) const;
    // Draws several instance lists depth-only (spot shadow tiles, point cube faces): all are
    // uploaded at once, then list i is drawn through the matrix before(i) returns (after it has set
    // its viewport); its first tess[i] instances as patches. Empty lists are skipped.
    void drawShadowLists(const RenderContext& rc, const TerrainSettings& s, GLuint program,
                         std::span<const std::vector<TerrainInstance>> lists, std::span<const std::size_t> tess,
                         const std::function<glm::mat4(std::size_t)>& before);
    // The displacement's relief, depth and fade for s (terrain/tess_displacement.h: the shader's
    // uniforms and the CPU mirror).
    TessRelief tessRelief(const TerrainSettings& s) const;
    // Where the displacement has ended (m from the camera): shadow views that serve only ground
    // beyond it need no tessellated casters.
    double tessReach(const TerrainSettings& s) const { return s.tessellation.enabled ? tessRelief(s).fade_end_m : 0.0; }
    // Draws the selected nodes' boxes as lines (debug view; its buffer is made on first use).
    void drawBounds(GLuint program);

    const TerrainMapping& mapping() const { return mapping_; }
    const MinMaxQuadtree& quadtree() const { return tree_; }
    const Heightmap& heightmap() const { return map_; }
    std::size_t memoryBytes() const;
    // Of that, what lives on the GPU: height, normal and material textures, index and instance buffers.
    std::size_t gpuMemoryBytes() const;
    GLuint heightTexture() const { return height_.id(); }
    GLuint normalTexture() const { return normals_.id(); }   // world normals (RGBA8 snorm tiles)
    GLuint albedoTexture() const { return albedo_.id(); }    // material albedo array (sRGB, A = roughness)
    // The height texture's tile layout as tiles.glsl takes it: count.xy, span; layer.xy, map size.
    struct TileRows {
        glm::ivec4 tiles;
        glm::vec4 layer;
    };
    TileRows tileRows() const;
    // With a splat map: binds its weights to BINDING_TEX_5 (programs with splatDefines()).
    void bindSplat() const;
    // The layer each splat channel weighs (material.glsl splatWeightsAt; -1: none).
    std::array<glm::ivec4, kMaxSplatImages> splatLayers() const;

private:
    Terrain() = default;
    // What create() and loadStreamed() share after the heights: materials, bias, grid, buffers.
    static bool finishCreate(Terrain& t, const TerrainSettings& s, ShaderLibrary& shaders, InputErrors& errors);
    // Streaming: requests the tiles of the selection (and of the camera's predicted selection),
    // uploads, and counts what is drawn from coarser tiles.
    void updateStream(const TerrainSettings& s, const Selection& drawn);
    // Appends the draw instances (quadrants) of nodes to out, at most kMaxInstances in all;
    // with tiers, the nearest distance (m) from the camera to each quadrant's box goes there too.
    void appendInstances(const std::vector<SelectedNode>& nodes, std::vector<TerrainInstance>& out,
                         std::vector<float>* distances = nullptr) const;
    // Orders instances_ by material tier, then front to back, and counts each tier's.
    void sortInstances(const TerrainSettings& s, const std::vector<float>& distances);
    // Sets the vertex stage's terrain uniforms in block (the first instance 0: the whole bound
    // range) and binds its textures (the shadow pass needs only these).
    void setVertexState(const TerrainSettings& s, TerrainBlock& block);
    // Sets terrain_tess.glsl's uniforms in block (factors for the main camera, relief) and the patch size.
    void setTessState(const TerrainSettings& s, TerrainBlock& block);
    // Draws instances [first, first + count) of the bound shadow instance range as patches with
    // the tessellated shadow program through matrix, then makes program current again.
    void drawShadowPatches(const RenderContext& rc, const TerrainSettings& s, GLuint program, const glm::mat4& matrix,
                           std::size_t first, std::size_t count);
    // Draws instances [first, end) of the bound range, a draw per run of equal decimation (b.w).
    void drawCasterRuns(const RenderContext& rc, GLuint program, TerrainBlock& block, const std::vector<TerrainInstance>& list,
                        std::size_t first);
    // shadowInstances()'s steps: the displaced quadrants first (their count), then out[first..]
    // grouped by casterDecimation().
    std::size_t shadowPatchesFirst(const TerrainSettings& s, std::vector<TerrainInstance>& out, bool tessellate);
    void decimateCasters(std::vector<TerrainInstance>& out, std::size_t first, double coarsest_step_m);

    TerrainSettings source_;  // what was loaded (file, mapping)
    Heightmap map_;
    TerrainMapping mapping_;
    MinMaxQuadtree tree_;
    LodSettings lod_;
    Selection selection_;       // what select() chose: the view's nodes, or the caster frustum's
    Selection visible_;         // the view's nodes of a caster selection
    mutable Selection culled_;  // scratch for shadowInstances()
    std::vector<Frustum> frusta_;  // scratch for select(): what the selection covers
    GridErrors errors_;
    DistanceBias bias_;
    std::array<double, 7> bias_key_{};  // what bias_ and lod_.base_range_m were made for
    bool bias_dirty_ = true;            // bias_ not yet in bias_texture_
    std::vector<TerrainInstance> instances_;
    std::vector<float> distances_;              // scratch for select(): nearest distance per instance
    std::vector<float> distances_sorted_;       // the same, in instances_' order
    std::vector<std::uint32_t> order_;          // scratch for sortInstances()
    std::vector<TerrainInstance> sorted_;       // scratch for sortInstances()
    std::array<std::size_t, kMaterialTiers> tier_counts_{};  // instances_ per tier, in order
    std::array<glm::vec4, kMaxMaterialLayers> layer_mean_{};  // each material layer's mean linear albedo, roughness
    std::array<float, kMaxMaterialLayers> layer_repeat_m_{};    // m per repeat of a user layer (0: generated)
    std::array<GLint, 4 * kMaxSplatImages> splat_layers_{-1, -1, -1, -1, -1, -1, -1, -1};  // layer per splat channel
    int splat_images_ = 0;                      // splat map images (0: height/slope rules)
    int layer_count_ = 0;                       // material array layers
    TerrainCounters counters_;
    glm::dvec3 camera_{0.0};
    glm::vec4 far_grass_{0.0f};
    glm::vec2 far_grass_fade_{0.0f, 1.0f};
    float wetness_ = 0.0f;
    double error_scale_ = 1.0;          // the main camera's pixels per (length / distance), from select()
    double near_m_ = 0.1;               // the main camera's near plane (m), from select()
    std::size_t tess_count_ = 0;        // instances_ (a prefix of the near tier) drawn tessellated
    std::vector<TerrainInstance> shadow_split_;  // scratch for shadowInstances(): beyond the tessellated range, then by decimation
    ShaderLibrary* shaders_ = nullptr;  // for the tessellated shadow program
    float max_anisotropy_ = 1.0f;  // the GL's limit (1 without the extension)
    float anisotropy_ = 1.0f;      // what the material textures are set to

    std::unique_ptr<TileStream> stream_;
    Selection prefetch_;              // scratch: the predicted camera's selection
    glm::dvec3 last_camera_{0.0};
    bool have_last_camera_ = false;

    TerrainTiles tiles_;
    gl::Texture height_, normals_, albedo_, detail_, bias_texture_, splat_;
    gl::Buffer grid_indices_, instance_buffer_, bounds_buffer_, shadow_instances_, shadow_lists_;
    GLsizeiptr shadow_slot_bytes_ = 0;
    gl::VertexArray vao_;
    GLsizei index_count_ = 0;  // the full grid's; the buffer holds the decimated grids after it
    // The grid with every 2^k-th vertex (k = 0: the full grid): offset and count in grid_indices_.
    std::vector<std::pair<GLsizei, GLsizei>> decimated_;
    std::vector<float> caster_steps_;  // scratch for decimateCasters()
    std::size_t max_instances_ = 0;
};

// "terrain.gbuffer": the selected nodes into the G-buffer (targets.albedo, .normal, .depth; needs them);
// with [terrain] bounds, "terrain.bounds" draws their boxes over it.
void addTerrainPass(FrameGraph& graph, const RenderContext& rc, Terrain& terrain, const TerrainSettings& s,
                    SceneTargets& targets);

// The G-buffer program's defines for a material tier (0 near .. 2 far) and the settings' debug
// view and wireframe (terrain.glsl: debug views are variants, so the shaded image pays nothing).
std::vector<std::string> terrainDefines(const TerrainSettings& s, int tier);
// TERRAIN_SPLAT=images when a splat map places the layers (material.glsl splatWeightsAt): the
// terrain's programs and the grass cull's, so blades grow where the splat map puts grass.
std::vector<std::string> splatDefines(const TerrainSettings& s);
// The tessellated near tier's program defines (terrain_tess.glsl), and its shadow program's.
std::vector<std::string> terrainTessDefines(const TerrainSettings& s);
// Material tier of a quadrant whose box is distance_m from the camera at its nearest.
int materialTier(const TerrainSettings& s, double distance_m);

// Shadow casters drawn coarser than the view draws them, for a shadow map whose texels need no
// finer grid: for quadrants of q x q quads with grid steps `steps` (m; the selection's, each the
// finest times a power of two), the k (0 .. the largest with 2^k dividing q) with which each is
// drawn with every 2^k-th vertex. Every quadrant finer than a common step S goes to S: S is the
// finest step times the largest power of two that reaches at most coarsest_step_m and that every
// quadrant can reach. The vertices kept lie on the surface (even ones do not morph), and
// neighbours at S share theirs, so the coarser casters have no cracks. coarsest_step_m <= 0: all 0.
std::vector<int> casterDecimation(std::span<const float> steps, int quads, double coarsest_step_m);

ProgramList terrainPrograms();

}  // namespace vista
