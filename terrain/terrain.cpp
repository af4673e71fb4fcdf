// Terrain loading (textures, quadtree, buffers: all once) and the per-frame selection/draw.
#include "terrain/terrain.h"

#include "renderer/bindings.h"
#include "renderer/pass_kit.h"
#include "terrain/dem.h"
#include "terrain/heightmap_rows.h"
#include "terrain/tile_cache.h"
#include "terrain/materials.h"
#include "terrain/tess_displacement.h"
#include "terrain/user_materials.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace vista {

#include "terrain/shaders/terrain_block.glsl"
static_assert(TERRAIN_BLOCK_LAYERS == kMaxMaterialLayers && kMaxMaterialLayers % 4 == 0,
              "terrain_block.glsl holds every material layer and packs their scales four a row");

namespace {
#include "terrain/shaders/normals_block.glsl"

// A selection larger than this is truncated (and says so): far beyond any sane LOD setting.
constexpr std::size_t kMaxInstances = 1 << 16;

// GL 4.6 / EXT_texture_filter_anisotropic (the loader is generated for 4.5 core without it).
constexpr GLenum kTextureMaxAnisotropy = 0x84FE, kMaxTextureMaxAnisotropy = 0x84FF;

// The largest anisotropy the GL offers (1 without the extension).
float maxAnisotropy() {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
        if (name && (std::strcmp(name, "GL_EXT_texture_filter_anisotropic") == 0 || std::strcmp(name, "GL_ARB_texture_filter_anisotropic") == 0)) {
            GLfloat max = 1.0f;
            glGetFloatv(kMaxTextureMaxAnisotropy, &max);
            return std::max(max, 1.0f);
        }
    }
    return 1.0f;
}

gl::Texture materialArray(const std::vector<std::uint8_t>& pixels, int size, int layers, GLenum format, const char* name) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    int levels = 1 + int(std::floor(std::log2(double(size))));
    glTextureStorage3D(id, levels, format, size, size, layers);
    glTextureSubImage3D(id, 0, 0, 0, 0, size, size, layers, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    glGenerateTextureMipmap(id);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glObjectLabel(GL_TEXTURE, id, -1, name);
    return gl::Texture::adopt(id, size, size, format);
}

// Appends the indices of a (q+1)^2-vertex grid of q x q quads, taking every stride-th vertex
// (q a multiple of stride); the vertex shader derives positions from gl_VertexID, so there is no
// vertex buffer.
void appendGridIndices(int q, int stride, std::vector<std::uint32_t>& indices) {
    auto at = [q](int x, int z) { return std::uint32_t(z * (q + 1) + x); };
    for (int z = 0; z < q; z += stride)
        for (int x = 0; x < q; x += stride) {
            std::uint32_t a = at(x, z), b = at(x + stride, z), c = at(x, z + stride), d = at(x + stride, z + stride);
            indices.insert(indices.end(), {a, c, b, b, c, d});
        }
}

}  // namespace

std::vector<std::string> terrainDefines(const TerrainSettings& s, int tier) {
    std::vector<std::string> defines;
    if (s.view != TerrainView::Shaded)
        defines.push_back("TERRAIN_VIEW=" + std::to_string(int(s.view)));  // the same for every tier
    else
        defines.push_back("MATERIAL_TIER=" + std::to_string(std::clamp(tier, 0, kMaterialTiers - 1)));
    // Parallax occlusion mapping only in the near tier: the relief is flat by [terrain.pom]
    // distance_m, which draw() keeps within detail_distance_m (where the near tier ends).
    if (s.pom.enabled && s.view == TerrainView::Shaded && tier == 0) defines.push_back("TERRAIN_POM");
    if (s.wireframe) defines.push_back("TERRAIN_WIREFRAME");
    // Splat maps place the layers instead of the height/slope rules (user_materials.h).
    for (std::string& d : splatDefines(s)) defines.push_back(std::move(d));
    // Heights and normals through the page table of the streamed pool (terrain/tile_stream.h).
    if (s.stream.enabled) defines.push_back("TERRAIN_STREAM");
    return defines;
}

std::vector<std::string> splatDefines(const TerrainSettings& s) {
    if (const std::size_t images = splatFiles(s).size(); images > 0)
        return {"TERRAIN_SPLAT=" + std::to_string(std::min<std::size_t>(images, kMaxSplatImages))};
    return {};
}

std::vector<std::string> terrainTessDefines(const TerrainSettings& s) {
    TerrainSettings no_pom = s;  // no POM: the displaced geometry is the relief
    no_pom.pom.enabled = false;
    return terrainDefines(no_pom, 0);
}

int materialTier(const TerrainSettings& s, double distance_m) {
    if (!s.material_tiers) return 0;
    // A quadrant is in a tier when every pixel of it could need that tier's features: the near
    // tier's detail fade and triplanar rock end at detail_distance_m, the mid tier's textures at
    // far_material_m. The margin covers float rounding of the drawn positions.
    constexpr double kMargin = 1.0;  // m
    if (distance_m < double(s.detail_distance_m) + kMargin) return 0;
    if (s.far_material_m <= 0.0f || distance_m < double(std::max(s.far_material_m, s.detail_distance_m)) + kMargin) return 1;
    return 2;
}

std::vector<std::string> Terrain::shadowDefines() const {
    if (stream_) return {"SHADOW_PASS", "TERRAIN_STREAM"};
    return {"SHADOW_PASS"};
}

ProgramList terrainPrograms() {
    ProgramList programs;
    for (int variant = 0; variant < 4; ++variant) {
        TerrainSettings s;
        s.wireframe = (variant & 1) != 0;
        s.stream.enabled = (variant & 2) != 0;
        for (int tier = 0; tier < kMaterialTiers; ++tier) programs.push_back({"terrain/shaders/terrain.glsl", terrainDefines(s, tier)});
        s.pom.enabled = true;
        programs.push_back({"terrain/shaders/terrain.glsl", terrainDefines(s, 0)});
        s.pom.enabled = false;
        for (TerrainView view : {TerrainView::Lod, TerrainView::Morph, TerrainView::Normals, TerrainView::Error, TerrainView::Material}) {
            s.view = view;
            programs.push_back({"terrain/shaders/terrain.glsl", terrainDefines(s, 0)});
        }
    }
    {  // splat maps (one and two images): every tier, POM, the material view
        TerrainSettings s;
        for (const char* splat : {"a.png", "a.png b.png"}) {
            s.splat_map = splat;
            for (int tier = 0; tier < kMaterialTiers; ++tier) programs.push_back({"terrain/shaders/terrain.glsl", terrainDefines(s, tier)});
            s.pom.enabled = true;
            programs.push_back({"terrain/shaders/terrain.glsl", terrainDefines(s, 0)});
            s.pom.enabled = false;
            s.view = TerrainView::Material;
            programs.push_back({"terrain/shaders/terrain.glsl", terrainDefines(s, 0)});
            s.view = TerrainView::Shaded;
        }
    }
    programs.push_back({"terrain/shaders/terrain.glsl", {"SHADOW_PASS"}});
    programs.push_back({"terrain/shaders/terrain.glsl", {"SHADOW_PASS", "TERRAIN_STREAM"}});
    for (TerrainView view : {TerrainView::Shaded, TerrainView::Normals}) {
        TerrainSettings s;
        s.view = view;
        programs.push_back({"terrain/shaders/terrain_tess.glsl", terrainTessDefines(s)});
    }
    programs.push_back({"terrain/shaders/terrain_tess.glsl", {"SHADOW_PASS"}});
    programs.push_back({"terrain/shaders/normals.glsl", {}});
    programs.push_back({"terrain/shaders/bounds.glsl", {}});
    return programs;
}

namespace {

bool checkGrid(int grid, InputErrors& errors) {
    if (grid % 4 == 0) return true;  // quadrants must start on even vertices for the morph
    errors.push_back({"[terrain] grid", 0, "grid = " + std::to_string(grid) + " is not accepted; accepted: a multiple of 4 in 4..256"});
    return false;
}

// The user's materials and splat maps (Terrain::create reads them again for the GPU): `vista
// check` runs the same checks.
bool checkMaterials(const TerrainSettings& s, int width, int height, InputErrors& errors) {
    if (!usesUserMaterials(s)) return true;
    return loadMaterialSet(s, width, height, errors).images.layers > 0;
}

// A streamed terrain's missing or stale tile cache, built as `vista terrain-cache` builds it (the
// same file): a one-channel heightmap image (TIFF, 16-bit PNG) a band of rows at a time, a raw
// .r16 and a DEM a row at a time, never whole, with loadChecked's checks on the size and each
// row; anything else (EXR, RGB, a DEM with nodata to fill) loaded whole through loadChecked,
// then dropped. reason: why it is built. Check only (StreamCacheUse::Check): the input is read
// through and checked the same way, and nothing is written.
bool buildStreamCache(const TerrainSettings& s, const TileCacheKey& key, const std::filesystem::path& file,
                      const std::string& reason, StreamCacheUse use, InputErrors& errors) {
    const bool write = use == StreamCacheUse::Build;
    const std::string input = s.dem.empty() ? s.heightmap : s.dem;
    auto announce = [&] {
        if (write)
            std::fprintf(stderr, "building the tile cache %s (tile %d) for %s: %s\n", file.string().c_str(), s.grid,
                         input.c_str(), reason.c_str());
    };
    std::string why;
    std::unique_ptr<HeightmapRows> image_rows;
    std::unique_ptr<DemRows> dem_rows;
    bool fill_whole = false;
    if (s.dem.empty()) {
        image_rows = HeightmapRows::open(s.heightmap, why, s.raw_width, s.raw_height);
    } else {
        dem_rows = DemRows::open(s.dem, s.dem_nodata, s.dem_vertical_scale, errors, fill_whole);
        if (!dem_rows && !fill_whole) return false;
    }
    if (!image_rows && !dem_rows) {
        TerrainMapping mapping;
        Heightmap map = Terrain::loadChecked(s, errors, &mapping);
        if (map.samples.empty()) return false;
        if (!write) return true;
        announce();
        why = buildTileCache(map, mapping, key, s.grid, file, true);
        if (!why.empty()) errors.push_back({file.string(), 0, why});
        return why.empty();
    }
    const int width = image_rows ? image_rows->width() : dem_rows->width();
    const int height = image_rows ? image_rows->height() : dem_rows->height();
    if (!checkMaterials(s, width, height, errors)) return false;
    announce();
    const TerrainMapping mapping = image_rows ? TerrainMapping{s.size_m, s.height_scale_m, s.height_offset_m, width, height}
                                              : demMapping(dem_rows->info(), width, height);
    std::string bad;  // what is wrong with the input, naming it
    auto read = [&](int z, float* row) {
        if (dem_rows) return bad = dem_rows->read(z, row);
        bad = image_rows->read(z, row);
        if (bad.empty()) bad = heightRowProblem(row, width, z, s.height_scale_m, s.height_offset_m);
        return bad;
    };
    if (write) {
        why = buildTileCache(width, height, read, mapping, key, s.grid, file, true);
    } else {
        std::vector<float> row(static_cast<std::size_t>(width));
        for (int z = 0; z < height && bad.empty(); ++z) read(z, row.data());
    }
    if (!bad.empty()) {
        const std::string prefix = input + ": ";
        errors.push_back({input, 0, bad.rfind(prefix, 0) == 0 ? bad.substr(prefix.size()) : bad});
        return false;
    }
    if (!why.empty()) errors.push_back({file.string(), 0, why});
    return why.empty();
}

}  // namespace

Heightmap Terrain::loadChecked(const TerrainSettings& s, InputErrors& errors, TerrainMapping* mapping) {
    if (!checkGrid(s.grid, errors)) return {};
    if (!s.dem.empty()) {
        Dem dem = loadDem(s.dem, s.dem_nodata, s.dem_vertical_scale, errors);
        if (dem.map.samples.empty() || !checkMaterials(s, dem.map.width, dem.map.height, errors)) return {};
        if (mapping) *mapping = demMapping(dem.info, dem.map.width, dem.map.height);
        return std::move(dem.map);
    }
    Heightmap map = loadHeightmap(s.heightmap, s.raw_width, s.raw_height, errors);
    if (map.samples.empty() || !checkHeightRange(map, s.height_scale_m, s.height_offset_m, s.heightmap, errors)) return {};
    if (!checkMaterials(s, map.width, map.height, errors)) return {};
    if (mapping) *mapping = TerrainMapping{s.size_m, s.height_scale_m, s.height_offset_m, map.width, map.height};
    return map;
}

std::unique_ptr<Terrain> Terrain::load(const TerrainSettings& s, ShaderLibrary& shaders, InputErrors& errors) {
    if (s.stream.enabled) return loadStreamed(s, shaders, errors);
    TerrainMapping mapping;
    Heightmap map = loadChecked(s, errors, &mapping);
    if (map.samples.empty()) return nullptr;
    return create(std::move(map), mapping, s, shaders, errors);
}

std::unique_ptr<Terrain> Terrain::create(Heightmap heightmap, const TerrainSettings& s, ShaderLibrary& shaders,
                                         InputErrors& errors, int max_texture) {
    TerrainMapping mapping{s.size_m, s.height_scale_m, s.height_offset_m, heightmap.width, heightmap.height};
    return create(std::move(heightmap), mapping, s, shaders, errors, max_texture);
}

std::unique_ptr<Terrain> Terrain::create(Heightmap heightmap, const TerrainMapping& mapping, const TerrainSettings& s,
                                         ShaderLibrary& shaders, InputErrors& errors, int max_texture) {
    if (!checkGrid(s.grid, errors)) return nullptr;
    std::unique_ptr<Terrain> t(new Terrain);
    t->source_ = s;
    t->map_ = std::move(heightmap);
    const Heightmap& map = t->map_;
    t->mapping_ = mapping;
    t->tree_ = MinMaxQuadtree(map, t->mapping_, s.grid);
    t->errors_ = GridErrors(map, t->mapping_, s.grid, t->tree_.levels());

    // Heights and normals live in texture arrays of tiles, so maps larger than the GL texture
    // limit (16384 on llvmpipe; the bench goes to 16385^2) work. Tiles share their border
    // texels, so bilinear filtering never needs a neighbouring tile.
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    if (max_texture > 0) max_size = std::min(max_size, std::max(max_texture, 3));
    TerrainTiles& tiles = t->tiles_;
    tiles.span = 1;
    while (tiles.span * 2 <= max_size - 1) tiles.span *= 2;
    tiles.count = {(map.width - 2) / tiles.span + 1, (map.height - 2) / tiles.span + 1};
    tiles.layer = {tiles.count.x == 1 ? map.width : tiles.span + 1, tiles.count.y == 1 ? map.height : tiles.span + 1};
    int layers = tiles.count.x * tiles.count.y;
    auto makeArray = [&](GLenum format, const char* name) {
        GLuint id = 0;
        glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
        glTextureStorage3D(id, 1, format, tiles.layer.x, tiles.layer.y, layers);
        glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glObjectLabel(GL_TEXTURE, id, -1, name);
        return gl::Texture::adopt(id, tiles.layer.x, tiles.layer.y, format);
    };
    t->height_ = makeArray(GL_R32F, "terrain heights");
    t->normals_ = makeArray(GL_RGBA8_SNORM, "terrain normals");
    std::vector<float> row(std::size_t(tiles.layer.x));
    for (int ty = 0; ty < tiles.count.y; ++ty)
        for (int tx = 0; tx < tiles.count.x; ++tx)
            for (int y = 0; y < tiles.layer.y; ++y) {  // rows clamped to the map: padding repeats the edge
                int z = std::min(ty * tiles.span + y, map.height - 1);
                for (int x = 0; x < tiles.layer.x; ++x) row[std::size_t(x)] = map.at(std::min(tx * tiles.span + x, map.width - 1), z);
                glTextureSubImage3D(t->height_.id(), 0, 0, y, ty * tiles.count.x + tx, tiles.layer.x, 1, 1, GL_RED,
                                    GL_FLOAT, row.data());
            }
    ShaderLibrary::Program* normals = shaders.get("terrain/shaders/normals.glsl");
    if (!normals) {
        errors.push_back({"terrain/shaders/normals.glsl", 0, shaders.lastError()});
        return nullptr;
    }
    glUseProgram(normals->id());
    const Terrain::TileRows rows = t->tileRows();
    const NormalsBlock block{{float(t->mapping_.texelSizeX()), float(t->mapping_.texelSizeZ())},
                             float(t->mapping_.height_scale_m), 0.0f, rows.tiles, rows.layer};
    const gl::Buffer block_buffer = bindPassBlockOnce(shaders, normals->id(), block);
    glBindTextureUnit(binding::kTex0, t->height_.id());
    glBindImageTexture(binding::kImageOutput, t->normals_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA8_SNORM);
    glDispatchCompute(GLuint((tiles.layer.x + 15) / 16), GLuint((tiles.layer.y + 15) / 16), GLuint(layers));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    // Once at load, not per frame: a failed allocation must not leave a silently flat terrain.
    if (GLenum e = glGetError(); e != GL_NO_ERROR) {
        errors.push_back({s.dem.empty() ? s.heightmap : s.dem, 0, "the GL could not hold the terrain (" + std::to_string(map.width) + "x" +
                                              std::to_string(map.height) + " in " + std::to_string(layers) +
                                              " tiles), GL error " + std::to_string(e)});
        return nullptr;
    }

    return finishCreate(*t, s, shaders, errors) ? std::move(t) : nullptr;
}

bool Terrain::finishCreate(Terrain& terrain, const TerrainSettings& s, ShaderLibrary& shaders, InputErrors& errors) {
    Terrain* t = &terrain;
    MaterialSet set = loadMaterialSet(s, t->mapping_.width, t->mapping_.height, errors);
    if (set.images.layers == 0) return false;
    const MaterialImages& materials = set.images;
    t->layer_count_ = materials.layers;
    std::copy(set.repeat_m.begin(), set.repeat_m.end(), t->layer_repeat_m_.begin());
    if (set.splat_images > 0) {
        // Weights between height samples are bilinear, as the heights are; clamped at the map's edge.
        GLuint id = 0;
        glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
        glTextureStorage3D(id, 1, GL_RGBA8, set.splat_width, set.splat_height, set.splat_images);
        glTextureSubImage3D(id, 0, 0, 0, 0, set.splat_width, set.splat_height, set.splat_images, GL_RGBA, GL_UNSIGNED_BYTE,
                            set.splat.data());
        glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glObjectLabel(GL_TEXTURE, id, -1, "terrain splat weights");
        t->splat_ = gl::Texture::adopt(id, set.splat_width, set.splat_height, GL_RGBA8);
        t->splat_images_ = set.splat_images;
        for (std::size_t c = 0; c < set.splat_layers.size(); ++c) t->splat_layers_[c] = set.splat_layers[c];
    }
    // The far tier's colours: each layer's mean albedo, decoded from sRGB first (what the
    // texture's last mip level holds), and mean roughness.
    const std::size_t layer_texels = std::size_t(materials.size) * std::size_t(materials.size);
    for (int l = 0; l < std::min(materials.layers, int(t->layer_mean_.size())); ++l) {
        glm::dvec4 sum(0.0);
        for (std::size_t i = 0; i < layer_texels; ++i) {
            const std::uint8_t* px = &materials.albedo[(std::size_t(l) * layer_texels + i) * 4];
            for (int c = 0; c < 3; ++c) {
                double v = px[c] / 255.0;
                sum[c] += v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
            }
            sum.w += px[3] / 255.0;
        }
        t->layer_mean_[std::size_t(l)] = glm::vec4(sum / double(layer_texels));
    }
    t->albedo_ = materialArray(materials.albedo, materials.size, materials.layers, GL_SRGB8_ALPHA8, "terrain albedo");
    // Detail normals with the relief height in alpha (materials.h): one fetch gives POM both, and
    // both want the same mips and filtering.
    t->detail_ = materialArray(materials.normal, materials.size, materials.layers, GL_RGBA8, "terrain detail normals + heights");
    t->max_anisotropy_ = maxAnisotropy();
    t->bias_.clear(t->tree_, t->mapping_);
    glm::ivec2 corners = t->bias_.cornerCount();
    t->bias_texture_ = gl::Texture::create2D(corners.x, corners.y, GL_R32F, 1, "terrain distance bias");

    t->shaders_ = &shaders;
    // The full grid, then the grid with every 2nd, 4th, ... vertex (coarser shadow casters).
    std::vector<std::uint32_t> indices;
    const int quads = s.grid / 2;
    for (int stride = 1; stride <= quads && quads % stride == 0; stride *= 2) {
        const std::size_t offset = indices.size();
        appendGridIndices(quads, stride, indices);
        t->decimated_.emplace_back(GLsizei(offset), GLsizei(indices.size() - offset));
    }
    t->index_count_ = t->decimated_[0].second;
    t->grid_indices_ = gl::Buffer::create(GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(), 0, "terrain grid");
    t->vao_ = gl::createVertexArray("terrain grid");
    glVertexArrayElementBuffer(t->vao_.id(), t->grid_indices_.id());
    t->instance_buffer_ = gl::Buffer::create(GLsizeiptr(kMaxInstances * sizeof(TerrainInstance)), nullptr,
                                             GL_DYNAMIC_STORAGE_BIT, "terrain instances");
    t->instances_.reserve(kMaxInstances);
    return true;
}

std::unique_ptr<TileCache> openStreamCache(const TerrainSettings& s, StreamCacheUse use, InputErrors& errors) {
    if (!checkGrid(s.grid, errors)) return nullptr;
    if (s.tessellation.enabled) {
        errors.push_back({"[terrain.stream] enabled", 0, "streaming does not work with [terrain.tessellation] enabled (its "
                                                         "displacement reads the full-resolution map); accepted: one of them"});
        return nullptr;
    }
    const std::string input = s.dem.empty() ? s.heightmap : s.dem;
    const std::filesystem::path file = s.stream.cache.empty() ? defaultTileCachePath(input) : std::filesystem::path(s.stream.cache);
    // A cache built from this input (when the input is there to compare) is used if it has tiles
    // of the grid's size and, for a heightmap, the settings' mapping; a missing or stale one is
    // built now (buildStreamCache).
    TileCacheKey key;
    const bool have_input = tileCacheKey(input, key).empty();
    std::string why;
    std::unique_ptr<TileCache> cache = TileCache::open(file, why);
    if (cache && !(have_input && !(cache->key() == key))) {
        // Up to date, but made for other settings: refused rather than replaced (it may be a user's).
        const TerrainMapping& m = cache->mapping();
        std::string wrong;
        if (cache->tileSize() != s.grid)
            wrong = "tiles of " + std::to_string(cache->tileSize()) + " samples, and [terrain] grid = " + std::to_string(s.grid) +
                    " needs tiles of the grid's size (vista terrain-cache --tile " + std::to_string(s.grid) + " --force)";
        else if (s.dem.empty() && (m.sizeX() != double(s.size_m) || m.sizeZ() != double(s.size_m) ||
                                   m.height_scale_m != double(s.height_scale_m) || m.height_offset_m != double(s.height_offset_m)))
            wrong = "another size_m or height scale/offset than [terrain]'s (rebuild it with vista terrain-cache --size-m, "
                    "--height-scale-m, --height-offset-m, --force)";
        if (!wrong.empty()) {
            errors.push_back({file.string(), 0, "the tile cache has " + wrong});
            return nullptr;
        }
    }
    if (!cache || (have_input && !(cache->key() == key))) {
        if (!have_input) {
            errors.push_back({file.string(), 0, why + "; and its input " + input + " cannot be read to build it"});
            return nullptr;
        }
        const std::string reason = cache ? "it was built from another version of " + input
                                         : std::filesystem::exists(file) ? why : "there is none yet";
        cache.reset();
        if (!buildStreamCache(s, key, file, reason, use, errors) || use == StreamCacheUse::Check) return nullptr;
        cache = TileCache::open(file, why);
        if (!cache) {
            errors.push_back({file.string(), 0, why});
            return nullptr;
        }
    }
    return cache;
}

std::unique_ptr<Terrain> Terrain::loadStreamed(const TerrainSettings& s, ShaderLibrary& shaders, InputErrors& errors) {
    std::unique_ptr<TileCache> cache = openStreamCache(s, StreamCacheUse::Build, errors);
    if (!cache) return nullptr;
    const std::filesystem::path file = cache->file();
    std::string why;
    std::unique_ptr<Terrain> t(new Terrain);
    t->source_ = s;
    t->mapping_ = cache->mapping();
    t->stream_ = TileStream::open(std::move(cache), s.stream.pool_pages, s.stream.threads, why);
    if (!t->stream_) {
        errors.push_back({"[terrain.stream] pool_pages", 0, why});
        return nullptr;
    }
    t->tree_ = t->stream_->quadtree();
    if (t->tree_.levels() == 0) {
        errors.push_back({file.string(), 0, "the tile cache's index does not match its map size"});
        return nullptr;
    }
    if (!t->stream_->cache().gridErrors(t->errors_, why)) {
        errors.push_back({file.string(), 0, why});
        return nullptr;
    }
    if (t->errors_.levels() != t->tree_.levels()) {
        errors.push_back({file.string(), 0, "the tile cache's grid errors do not match its quadtree"});
        return nullptr;
    }
    // The tile uniforms carry the map's size (material.glsl, the bias field); no tiles of heights.
    t->tiles_.count = {1, 1};
    t->tiles_.span = t->mapping_.width;
    t->tiles_.layer = {t->mapping_.width, t->mapping_.height};
    if (GLenum e = glGetError(); e != GL_NO_ERROR) {
        errors.push_back({file.string(), 0, "the GL could not hold the terrain's page pool (" +
                                                std::to_string(s.stream.pool_pages) + " pages), GL error " + std::to_string(e)});
        return nullptr;
    }
    return finishCreate(*t, s, shaders, errors) ? std::move(t) : nullptr;
}

bool Terrain::matches(const TerrainSettings& s) const {
    return s.stream.enabled == source_.stream.enabled && s.stream.cache == source_.stream.cache &&
           s.stream.pool_pages == source_.stream.pool_pages && s.stream.threads == source_.stream.threads &&
           s.heightmap == source_.heightmap && s.raw_width == source_.raw_width && s.raw_height == source_.raw_height &&
           s.size_m == source_.size_m && s.height_scale_m == source_.height_scale_m &&
           s.height_offset_m == source_.height_offset_m && s.grid == source_.grid && s.dem == source_.dem &&
           s.dem_nodata == source_.dem_nodata && s.dem_vertical_scale == source_.dem_vertical_scale &&
           s.materials == source_.materials && s.splat_map == source_.splat_map && s.splat_layers == source_.splat_layers;
}

double terrainHeightAt(const Heightmap& map, const TerrainMapping& mapping, const glm::dvec3& origin, double x, double z) {
    return placedHeightAt(mapping, origin, x, z, [&](double tx, double tz) { return map.sample(tx, tz); });
}

double Terrain::heightAt(double x, double z) const {
    if (!stream_) return terrainHeightAt(map_, mapping_, source_.origin, x, z);
    return placedHeightAt(mapping_, source_.origin, x, z, [&](double tx, double tz) { return stream_->sample(tx, tz); });
}

std::function<double(double, double)> Terrain::heightSampler() const {
    // The placement and origin as they are now, by value: select() rewrites the origin each frame.
    const TerrainMapping m = mapping_;
    const glm::dvec3 o = source_.origin;
    if (!stream_) return [map = &map_, m, o](double x, double z) { return terrainHeightAt(*map, m, o, x, z); };
    auto sampler = std::make_shared<TileCacheSampler>(stream_->cache());
    return [sampler, m, o](double x, double z) {
        return placedHeightAt(m, o, x, z, [&](double tx, double tz) { return sampler->sample(tx, tz); });
    };
}

void Terrain::updateStream(const TerrainSettings& s, const Selection& drawn) {
    TileStream& st = *stream_;
    st.beginFrame();
    // A node at LOD level L draws tile (L, x, z) of the cache (tile = grid: one node, one tile);
    // a quadrant of a level-L node (node_level L - 1) lies in its parent's tile.
    auto wantNodes = [&](const Selection& sel) {
        for (const SelectedNode& n : sel.nodes) {
            const int shift = n.level - n.node_level;
            st.want(n.level, n.x >> shift, n.z >> shift);
        }
    };
    wantNodes(selection_);  // the view's nodes and the shadow casters' beyond it
    // Prefetch: the selection of the camera moved on by its last frame's motion, prefetch_frames times.
    const glm::dvec3 camera = camera_ - s.origin;
    if (have_last_camera_ && s.stream.prefetch_frames > 0) {
        const glm::dvec3 ahead = camera + (camera - last_camera_) * double(s.stream.prefetch_frames);
        if (ahead != camera) {
            selectNodes(tree_, mapping_, lod_, ahead, frusta_, prefetch_, s.lod_metric == LodMetric::Error ? &bias_ : nullptr);
            wantNodes(prefetch_);
        }
    }
    last_camera_ = camera;
    have_last_camera_ = true;
    st.endFrame(s.stream.uploads_per_frame);
    // What missing tiles cost: a node drawn at its ancestor's level A errs by up to that tile's
    // grid error (m), seen from the node's nearest point.
    StreamCounters& c = st.counters();
    for (const SelectedNode& n : drawn.nodes) {
        const int shift = n.level - n.node_level;
        const int tx = n.x >> shift, tz = n.z >> shift;
        const int level = st.residentLevel(n.level, tx, tz);
        if (level == n.level) continue;
        ++c.missing;
        const TileCache::Entry& e = st.cache().entry(level, tx >> (level - n.level), tz >> (level - n.level));
        const glm::dvec3 p = glm::clamp(glm::dvec3(0.0), n.min_rel, n.max_rel);
        c.missing_error_px = std::max(c.missing_error_px, missingTileErrorPx(e.error_m, error_scale_, glm::length(p), near_m_));
    }
    counters_.stream = c;
}

const Selection& Terrain::select(const glm::dvec3& camera, const glm::dmat4& view_proj, const TerrainSettings& s,
                                double error_scale, const Frustum* caster_frustum, std::span<const Frustum> extra) {
    auto start = std::chrono::steady_clock::now();
    source_.origin = s.origin;  // moving the terrain needs no reload
    camera_ = camera;
    error_scale_ = error_scale;
    // The error bound depends on the settings and the view's pixels per radian only: remade
    // when one changes (a resize, a slider), not per frame.
    bool error_metric = s.lod_metric == LodMetric::Error;
    std::array<double, 7> key{double(error_metric), error_scale, s.max_error_px, s.bias_slope, s.base_range_m,
                              s.range_ratio, s.morph_start};
    // A camera path's field of view, interpolated between equal keys, wobbles in its last bits:
    // a relative change of error_scale below 1e-6 keeps the bias (rebuilding it took 50-100 ms a
    // frame on a 32,769² map, in pairs of frames along a flight).
    std::array<double, 7> same = key;
    if (std::abs(error_scale - bias_key_[1]) <= 1e-6 * std::abs(bias_key_[1])) same[1] = bias_key_[1];
    if (same != bias_key_) {
        bias_key_ = key;
        lod_.range_ratio = s.range_ratio;
        lod_.morph_start = s.morph_start;
        lod_.base_range_m = s.base_range_m;
        lod_.base_range_m = calibratedBaseRange(tree_, errors_, mapping_, lod_, error_scale, s.max_error_px);
        lod_.bias_slope = error_metric ? usableBiasSlope(tree_, mapping_, lod_, lod_.base_range_m, s.bias_slope) : 0.0;
        if (error_metric)
            bias_.build(tree_, errors_, mapping_, lod_, error_scale, s.max_error_px);
        else
            bias_.clear(tree_, mapping_);
        bias_dirty_ = true;
    }
    // The mapping is centred on the origin: select with the camera relative to the terrain.
    const Frustum view = frustumFromViewProj(view_proj);
    near_m_ = -view[4].w;  // the camera (the origin) lies near_m behind the normalised near plane
    frusta_.assign(1, caster_frustum ? *caster_frustum : view);
    frusta_.insert(frusta_.end(), extra.begin(), extra.end());
    selectNodes(tree_, mapping_, lod_, camera - s.origin, frusta_, selection_, error_metric ? &bias_ : nullptr);
    const Selection* drawn = &selection_;
    if (caster_frustum || !extra.empty()) {
        cullSelection(selection_, view, visible_);
        drawn = &visible_;
    }
    instances_.clear();
    appendInstances(drawn->nodes, instances_, &distances_);
    sortInstances(s, distances_);
    counters_.nodes = std::int64_t(drawn->nodes.size());
    counters_.draws = 0;
    for (int tier = 0; tier < kMaterialTiers; ++tier) {
        counters_.tier_instances[std::size_t(tier)] = std::int64_t(tier_counts_[std::size_t(tier)]);
        counters_.draws += tier_counts_[std::size_t(tier)] > 0 ? 1 : 0;
    }
    counters_.triangles = std::int64_t(instances_.size()) * (index_count_ / 3);
    // Tessellated: the near tier's nearest quadrants (sorted front to back) within the range.
    tess_count_ = 0;
    if (s.tessellation.enabled)
        while (tess_count_ < tier_counts_[0] && distances_sorted_[tess_count_] < s.tessellation.range_m) ++tess_count_;
    counters_.tess_patches = std::int64_t(tess_count_) * (index_count_ / 3);
    counters_.tess_shadow_patches = 0;  // shadowInstances() adds the shadow passes' patches
    counters_.base_range_m = selection_.ranges.empty() ? 0.0 : selection_.ranges[0];
    if (stream_) updateStream(s, *drawn);
    counters_.select_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return selection_;
}

void Terrain::appendInstances(const std::vector<SelectedNode>& nodes, std::vector<TerrainInstance>& out,
                              std::vector<float>* distances) const {
    const std::size_t first = out.size();
    if (distances) distances->clear();
    glm::dvec2 map_max = 0.5 * glm::dvec2(mapping_.sizeX(), mapping_.sizeZ()) -
                         glm::dvec2(camera_.x - source_.origin.x, camera_.z - source_.origin.z);
    for (const SelectedNode& node : nodes) {
        // The mesh is a half-node grid: a whole node is drawn as its four quadrants, a
        // partial node (one quadrant of a level-L node, see SelectedNode) as one.
        bool whole = node.node_level == node.level;
        glm::dvec2 step = node.size_m * (whole ? 1.0 : 2.0) / double(source_.grid);
        glm::dvec2 half = step * double(source_.grid / 2);
        glm::dvec2 c = selection_.morph_consts[std::size_t(node.level)];
        for (int q = 0; q < (whole ? 4 : 1) && out.size() - first < kMaxInstances; ++q) {
            glm::dvec2 o = node.origin_rel + glm::dvec2(q & 1, q >> 1) * half;
            if (o.x >= map_max.x || o.y >= map_max.y) continue;  // a quadrant wholly past the map's edge
            out.push_back({glm::vec4(float(o.x), float(o.y), float(step.x), float(node.level)),
                           glm::vec4(float(c.x), float(c.y), float(step.y), 0.0f)});
            if (distances) {  // nearest point of the quadrant's box to the camera (the origin)
                glm::dvec3 lo(o.x, node.min_rel.y, o.y), hi(o.x + half.x, node.max_rel.y, o.y + half.y);
                glm::dvec3 d = glm::max(glm::max(lo, -hi), glm::dvec3(0.0));
                distances->push_back(float(glm::length(d)));
            }
        }
    }
}

void Terrain::sortInstances(const TerrainSettings& s, const std::vector<float>& distances) {
    // Front to back, so the depth test rejects hidden fragments before they are shaded (a
    // grazing view's quadtree order is back to front for half the screen); grouped by tier
    // first, one draw each. Near tiers are nearer anyway, so the order stays front to back.
    order_.resize(instances_.size());
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    auto key = [&](std::uint32_t i) { return std::make_pair(materialTier(s, distances[i]), distances[i]); };
    std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    sorted_.resize(instances_.size());
    distances_sorted_.resize(instances_.size());
    tier_counts_.fill(0);
    for (std::size_t k = 0; k < order_.size(); ++k) {
        sorted_[k] = instances_[order_[k]];
        distances_sorted_[k] = distances[order_[k]];
        ++tier_counts_[std::size_t(materialTier(s, distances[order_[k]]))];
    }
    instances_.swap(sorted_);
}

std::size_t Terrain::shadowInstances(const TerrainSettings& s, const Frustum& planes, std::vector<TerrainInstance>& out,
                                     bool tessellate,
                                     const std::function<bool(const glm::dvec3& lo, const glm::dvec3& hi)>& keep,
                                     std::size_t* skipped, double coarsest_step_m) {
    out.clear();
    cullSelection(selection_, planes, culled_);
    appendInstances(culled_.nodes, out);
    if (keep) {
        const std::size_t inside = out.size();  // counted in instances, as the pass draws them
        std::erase_if(culled_.nodes, [&keep](const SelectedNode& n) { return !keep(n.min_rel, n.max_rel); });
        out.clear();
        appendInstances(culled_.nodes, out);
        if (skipped) *skipped = inside - out.size();
    }
    const std::size_t tess = shadowPatchesFirst(s, out, tessellate);
    if (coarsest_step_m > 0.0 && tess < out.size()) decimateCasters(out, tess, coarsest_step_m);
    return tess;
}

void Terrain::decimateCasters(std::vector<TerrainInstance>& out, std::size_t first, double coarsest_step_m) {
    caster_steps_.clear();
    for (std::size_t i = first; i < out.size(); ++i) caster_steps_.push_back(out[i].a.z);
    const std::vector<int> k = casterDecimation(caster_steps_, source_.grid / 2, coarsest_step_m);
    // Grouped by k (a draw each), finest first; the order within a group is kept.
    shadow_split_.assign(out.begin() + std::ptrdiff_t(first), out.end());
    std::size_t at = first;
    for (int level = 0; level < int(decimated_.size()); ++level)
        for (std::size_t i = 0; i < k.size(); ++i)
            if (k[i] == level) {
                out[at] = shadow_split_[i];
                out[at++].b.w = float(level);
            }
}

std::size_t Terrain::shadowPatchesFirst(const TerrainSettings& s, std::vector<TerrainInstance>& out, bool tessellate) {
    if (!s.tessellation.enabled || !tessellate || !shaders_) return 0;
    // The quadrants within the range in x, z (a superset of the view's, which measures in 3D: an
    // extra one is beyond the displacement's reach and draws as it would untessellated) go first.
    const float range = s.tessellation.range_m, half = float(source_.grid / 2);
    auto near = [&](const TerrainInstance& i) {
        const glm::vec2 lo(i.a.x, i.a.y), hi = lo + glm::vec2(i.a.z, i.b.z) * half;
        return glm::length(glm::max(glm::max(lo, -hi), glm::vec2(0.0f))) < range;
    };
    shadow_split_.clear();
    std::size_t tess = 0;
    for (const TerrainInstance& i : out)
        if (near(i))
            out[tess++] = i;
        else
            shadow_split_.push_back(i);
    std::copy(shadow_split_.begin(), shadow_split_.end(), out.begin() + std::ptrdiff_t(tess));
    counters_.tess_shadow_patches += std::int64_t(tess) * (index_count_ / 3);
    return tess;
}

void Terrain::bindSplat() const {
    if (splat_images_ > 0) glBindTextureUnit(binding::kTex5, splat_.id());
}

std::array<glm::ivec4, kMaxSplatImages> Terrain::splatLayers() const {
    std::array<glm::ivec4, kMaxSplatImages> layers{};
    for (std::size_t i = 0; i < layers.size(); ++i)
        layers[i] = {splat_layers_[4 * i], splat_layers_[4 * i + 1], splat_layers_[4 * i + 2], splat_layers_[4 * i + 3]};
    return layers;
}

Terrain::TileRows Terrain::tileRows() const {
    return {{tiles_.count.x, tiles_.count.y, tiles_.span, 0},
            {float(tiles_.layer.x), float(tiles_.layer.y), float(mapping_.width), float(mapping_.height)}};
}

void Terrain::setVertexState(const TerrainSettings& s, TerrainBlock& block) {
    if (bias_dirty_) {
        glm::ivec2 corners = bias_.cornerCount();
        glTextureSubImage2D(bias_texture_.id(), 0, 0, 0, corners.x, corners.y, GL_RED, GL_FLOAT, bias_.corners().data());
        bias_dirty_ = false;
    }
    glm::dvec3 rel = camera_ - s.origin;  // camera relative to the map centre
    block.u_quads = s.grid / 2;
    block.u_map_min = {float(-mapping_.sizeX() * 0.5 - rel.x), float(-mapping_.sizeZ() * 0.5 - rel.z)};
    block.u_texel_m = {float(mapping_.texelSizeX()), float(mapping_.texelSizeZ())};
    block.u_height_map = {float(mapping_.height_scale_m), float(mapping_.height_offset_m - rel.y)};
    block.u_map_max = {float(mapping_.sizeX() * 0.5 - rel.x), float(mapping_.sizeZ() * 0.5 - rel.z)};
    const TileRows rows = tileRows();
    block.u_tiles = rows.tiles;
    block.u_tile_layer = rows.layer;
    block.u_bias_cells = {bias_.cornerCount().x - 1, bias_.cornerCount().y - 1, bias_.leafTexels(),
                          s.lod_metric == LodMetric::Error ? 1 : 0};
    block.u_first_instance = 0;
    glBindTextureUnit(binding::kTex4, bias_texture_.id());
    if (stream_) {
        glBindTextureUnit(binding::kTex0, stream_->heightPages());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kTerrainPages, stream_->pageTable());
    } else {
        glBindTextureUnit(binding::kTex0, height_.id());
    }
    glBindVertexArray(vao_.id());
}

TessRelief Terrain::tessRelief(const TerrainSettings& s) const {
    // The relief (the rock layer's) repeats every texture_scale_m, or a user rock's tiling_m.
    const float rock_repeat = layer_repeat_m_[std::size_t(MaterialLayer::Rock)];
    return vista::tessRelief(s.tessellation.depth_m, s.tessellation.range_m,
                             double(rock_repeat > 0.0f ? rock_repeat : s.texture_scale_m));
}

void Terrain::setTessState(const TerrainSettings& s, TerrainBlock& block) {
    const TerrainTessSettings& t = s.tessellation;
    const TessRelief r = tessRelief(s);
    glm::dvec3 rel = camera_ - s.origin;
    block.u_tess = {t.edge_px, float(error_scale_), t.range_m, t.max_factor};
    block.u_tess_relief = {float(r.depth_m), float(1.0 / r.period_m), float(std::fmod(rel.x, r.period_m)),
                           float(std::fmod(rel.z, r.period_m))};
    block.u_tess_fade = {float(r.fade_start_m), float(r.fade_end_m), float(r.layer), 0.0f};
    glPatchParameteri(GL_PATCH_VERTICES, 3);
    glBindTextureUnit(binding::kTex3, detail_.id());
}

void Terrain::draw(const RenderContext& rc, const TerrainSettings& s, std::span<const GLuint, kMaterialTiers> programs,
                   GLuint tess_program) {
    if (instances_.empty()) return;
    glNamedBufferSubData(instance_buffer_.id(), 0, GLsizeiptr(instances_.size() * sizeof(TerrainInstance)), instances_.data());
    glm::dvec3 rel = camera_ - s.origin;
    // Textures give way to the layer means over the last quarter before far_material_m (never
    // inside the near tier); 0 keeps them at every distance.
    const float far_end = s.far_material_m > 0.0f ? std::max(s.far_material_m, s.detail_distance_m) : 3.0e38f;
    const float far_start = s.far_material_m > 0.0f ? std::max(0.75f * far_end, s.detail_distance_m) : 2.0e38f;
    if (const float aniso = std::min(float(s.material_anisotropy), max_anisotropy_); aniso != anisotropy_) {
        anisotropy_ = aniso;  // a texture parameter, so set on change only
        for (const gl::Texture* t : {&albedo_, &detail_}) glTextureParameterf(t->id(), kTextureMaxAnisotropy, aniso);
    }
    glBindTextureUnit(binding::kTex1, stream_ ? stream_->normalPages() : normals_.id());
    glBindTextureUnit(binding::kTex2, albedo_.id());
    glBindTextureUnit(binding::kTex3, detail_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kTerrainNodes, instance_buffer_.id());
    // Texture coordinates per metre of each layer: a user material's tiling_m, else texture_scale_m
    // (the generated rock at half that scale: its strata want the larger repeat).
    TerrainBlock block{};
    for (std::size_t l = 0; l < std::size_t(kMaxMaterialLayers); ++l) {
        block.u_layer_scale[l / 4][int(l % 4)] =
            layer_repeat_m_[l] > 0.0f ? 1.0f / layer_repeat_m_[l]
                                      : (l == std::size_t(MaterialLayer::Rock) ? 0.5f : 1.0f) / s.texture_scale_m;
        block.u_layer_mean[l] = layer_mean_[l];
    }
    block.u_bands = {s.sand_top, s.grass_top, s.snow_start, s.band_blend};
    block.u_material = {s.band_jitter, s.rock_slope, 1.0f / s.texture_scale_m, s.detail_distance_m};
    block.u_tex_offset = {float(rel.x), float(rel.z)};
    block.u_far_fade = {far_start, far_end};
    block.u_max_error_px = s.max_error_px;
    block.u_grass_far = far_grass_;
    block.u_grass_fade = far_grass_fade_;
    block.u_wetness = wetness_;
    const std::array<glm::ivec4, kMaxSplatImages> splat = splatLayers();
    std::copy(splat.begin(), splat.end(), block.u_splat_layers);
    // The relief is gone where the near tier ends (the other tiers have no POM variant).
    const float pom_end = std::min(s.pom.distance_m, s.detail_distance_m);
    block.u_pom = {s.pom.depth_m, pom_end, s.pom.shadow, 0.0f};
    block.u_pom_steps = {s.pom.max_steps, s.pom.refine_steps, s.pom.shadow_steps, 0};
    if (!s.splat_map.empty()) bindSplat();
    std::size_t first = 0;
    for (int tier = 0; tier < kMaterialTiers; ++tier) {
        const std::size_t count = tier_counts_[std::size_t(tier)];
        if (count == 0) continue;
        // The tessellated quadrants: the first of the near tier, as patches of one grid triangle.
        const std::size_t tess = tier == 0 && tess_program ? tess_count_ : 0;
        for (int pass = tess > 0 ? 0 : 1; pass < 2; ++pass) {
            const GLuint program = pass == 0 ? tess_program : programs[std::size_t(tier)];
            const std::size_t n = pass == 0 ? tess : count - tess;
            if (n == 0) continue;
            glUseProgram(program);
            setVertexState(s, block);
            block.u_first_instance = GLint(first);
            if (pass == 0) setTessState(s, block);
            bindPassBlock(rc, program, block);
            glDrawElementsInstanced(pass == 0 ? GL_PATCHES : GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr, GLsizei(n));
            first += n;
        }
    }
}

void Terrain::drawShadowPatches(const RenderContext& rc, const TerrainSettings& s, GLuint program, const glm::mat4& matrix,
                                std::size_t first, std::size_t count) {
    const GLuint tess_program = shaders_->get("terrain/shaders/terrain_tess.glsl", {"SHADOW_PASS"})->id();
    glUseProgram(tess_program);
    TerrainBlock block{};
    block.u_shadow_matrix = matrix;
    setVertexState(s, block);
    setTessState(s, block);
    block.u_first_instance = GLint(first);
    bindPassBlock(rc, tess_program, block);
    glDrawElementsInstanced(GL_PATCHES, index_count_, GL_UNSIGNED_INT, nullptr, GLsizei(count));
    glUseProgram(program);
}

void Terrain::drawShadow(const RenderContext& rc, const TerrainSettings& s, GLuint program, const glm::mat4& matrix,
                         const std::vector<TerrainInstance>& instances, std::size_t tess, int slot) {
    if (instances.empty()) return;
    if (!shadow_instances_) {  // only scenes with sun shadows pay for it
        GLint align = 256;
        glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &align);
        GLsizeiptr bytes = GLsizeiptr(kMaxInstances * sizeof(TerrainInstance));
        shadow_slot_bytes_ = (bytes + align - 1) / align * align;
        shadow_instances_ = gl::Buffer::create(shadow_slot_bytes_ * kShadowSlots, nullptr, GL_DYNAMIC_STORAGE_BIT,
                                               "terrain shadow instances");
    }
    const GLsizeiptr bytes = GLsizeiptr(instances.size() * sizeof(TerrainInstance));
    const GLintptr offset = shadow_slot_bytes_ * std::clamp(slot, 0, kShadowSlots - 1);
    glNamedBufferSubData(shadow_instances_.id(), offset, bytes, instances.data());
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, binding::kTerrainNodes, shadow_instances_.id(), offset, bytes);
    tess = std::min(tess, instances.size());
    if (tess > 0) drawShadowPatches(rc, s, program, matrix, 0, tess);
    if (tess == instances.size()) return;
    TerrainBlock block{};
    block.u_shadow_matrix = matrix;
    setVertexState(s, block);
    drawCasterRuns(rc, program, block, instances, tess);
}

void Terrain::drawCasterRuns(const RenderContext& rc, GLuint program, TerrainBlock& block,
                             const std::vector<TerrainInstance>& list, std::size_t first) {
    for (std::size_t end = first; first < list.size(); first = end) {
        const float k = list[first].b.w;
        while (end < list.size() && list[end].b.w == k) ++end;
        const auto& [offset, count] = decimated_[std::min(std::size_t(k), decimated_.size() - 1)];
        block.u_first_instance = GLint(first);
        bindPassBlock(rc, program, block);
        glDrawElementsInstanced(GL_TRIANGLES, count, GL_UNSIGNED_INT,
                                reinterpret_cast<const void*>(std::uintptr_t(offset) * sizeof(std::uint32_t)),
                                GLsizei(end - first));
    }
}

std::int64_t Terrain::triangles(const std::vector<TerrainInstance>& instances) const {
    std::int64_t n = 0;
    for (const TerrainInstance& i : instances)
        n += decimated_[std::min(std::size_t(i.b.w), decimated_.size() - 1)].second / 3;
    return n;
}

std::vector<int> casterDecimation(std::span<const float> steps, int quads, double coarsest_step_m) {
    std::vector<int> k(steps.size(), 0);
    if (steps.empty() || coarsest_step_m <= 0.0) return k;
    int max_k = 0;  // 2^k must divide the quads per side
    while ((quads >> max_k) % 2 == 0 && (quads >> max_k) > 1) ++max_k;
    const double finest = *std::min_element(steps.begin(), steps.end());
    int j = 0;
    while (j < max_k && finest * double(2 << j) <= coarsest_step_m) ++j;
    const double common = finest * double(1 << j);
    for (std::size_t i = 0; i < steps.size(); ++i)
        if (double(steps[i]) < common) k[i] = std::clamp(int(std::lround(std::log2(common / double(steps[i])))), 0, j);
    return k;
}

void Terrain::drawShadowLists(const RenderContext& rc, const TerrainSettings& s, GLuint program,
                              std::span<const std::vector<TerrainInstance>> lists, std::span<const std::size_t> tess,
                              const std::function<glm::mat4(std::size_t)>& before) {
    GLint align = 256;
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &align);
    std::vector<GLintptr> offsets(lists.size());
    GLsizeiptr total = 0;
    for (std::size_t i = 0; i < lists.size(); ++i) {
        offsets[i] = total;
        total += (GLsizeiptr(lists[i].size() * sizeof(TerrainInstance)) + align - 1) / align * align;
    }
    if (total == 0) return;
    if (!shadow_lists_ || shadow_lists_.size() < total)  // only scenes with shadowed spot lights pay for it
        shadow_lists_ = gl::Buffer::create(std::max(total, shadow_lists_.size() * 3 / 2), nullptr, GL_DYNAMIC_STORAGE_BIT,
                                           "terrain spot shadow instances");
    for (std::size_t i = 0; i < lists.size(); ++i)
        if (!lists[i].empty())
            glNamedBufferSubData(shadow_lists_.id(), offsets[i], GLsizeiptr(lists[i].size() * sizeof(TerrainInstance)),
                                 lists[i].data());
    for (std::size_t i = 0; i < lists.size(); ++i) {
        if (lists[i].empty()) continue;
        const glm::mat4 matrix = before(i);
        glBindBufferRange(GL_SHADER_STORAGE_BUFFER, binding::kTerrainNodes, shadow_lists_.id(), offsets[i],
                          GLsizeiptr(lists[i].size() * sizeof(TerrainInstance)));
        const std::size_t patches = i < tess.size() ? std::min(tess[i], lists[i].size()) : 0;
        if (patches > 0) drawShadowPatches(rc, s, program, matrix, 0, patches);
        if (patches == lists[i].size()) continue;
        TerrainBlock block{};
        block.u_shadow_matrix = matrix;
        setVertexState(s, block);
        drawCasterRuns(rc, program, block, lists[i], patches);
    }
}

void Terrain::drawBounds(GLuint program) {
    if (selection_.nodes.empty()) return;
    if (!bounds_buffer_)
        bounds_buffer_ = gl::Buffer::create(GLsizeiptr(kMaxInstances * 2 * sizeof(glm::vec4)), nullptr,
                                            GL_DYNAMIC_STORAGE_BIT, "terrain node bounds");
    std::vector<glm::vec4> boxes;
    boxes.reserve(selection_.nodes.size() * 2);
    for (const SelectedNode& n : selection_.nodes) {
        if (boxes.size() / 2 >= kMaxInstances) break;
        boxes.push_back(glm::vec4(glm::vec3(n.min_rel), float(n.level)));
        boxes.push_back(glm::vec4(glm::vec3(n.max_rel), 0.0f));
    }
    glNamedBufferSubData(bounds_buffer_.id(), 0, GLsizeiptr(boxes.size() * sizeof(glm::vec4)), boxes.data());
    glUseProgram(program);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kTerrainNodes, bounds_buffer_.id());
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_LINES, 0, GLsizei(boxes.size() / 2 * 24));
}

std::size_t Terrain::memoryBytes() const {
    if (stream_)
        return tree_.memoryBytes() + errors_.memoryBytes() + bias_.memoryBytes() + bias_.corners().size() * sizeof(float) +
               stream_->memoryBytes() + std::size_t(grid_indices_.size()) + std::size_t(instance_buffer_.size()) +
               std::size_t(bounds_buffer_.size()) + std::size_t(shadow_instances_.size());
    std::size_t texels = std::size_t(tiles_.layer.x) * std::size_t(tiles_.layer.y) * std::size_t(tiles_.count.x * tiles_.count.y);
    return tree_.memoryBytes() + errors_.memoryBytes() + bias_.memoryBytes() + bias_.corners().size() * sizeof(float) /* its texture */ +
           map_.samples.size() * sizeof(float) + texels * 4 /* R32F */ + texels * 4 /* normals */ +
           std::size_t(grid_indices_.size()) + std::size_t(instance_buffer_.size()) + std::size_t(bounds_buffer_.size()) +
           std::size_t(shadow_instances_.size());
}

std::size_t Terrain::gpuMemoryBytes() const {
    std::size_t bytes = 0;
    for (const gl::Texture* t : {&height_, &normals_, &albedo_, &detail_, &bias_texture_, &splat_}) bytes += t->bytes();
    for (const gl::Buffer* b : {&grid_indices_, &instance_buffer_, &bounds_buffer_, &shadow_instances_})
        bytes += std::size_t(b->size());
    return bytes + (stream_ ? stream_->gpuMemoryBytes() : 0);
}

void addTerrainPass(FrameGraph& graph, const RenderContext& rc, Terrain& terrain, const TerrainSettings& s,
                    SceneTargets& targets) {
    struct Data {
        SceneTargets t;
    };
    const Data& d = graph.addPass<Data>("terrain.gbuffer",
        [&](PassBuilder& b, Data& data) {
            data.t = targets;
            data.t.hdr = b.write(targets.hdr);
            data.t.albedo = b.write(targets.albedo);
            data.t.normal = b.write(targets.normal);
            data.t.depth = b.write(targets.depth);
        },
        [&rc, &terrain, &s](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.t.hdr);
            GLuint fb = rc.device.framebuffer(
                {ctx.texture(data.t.hdr), ctx.texture(data.t.albedo), ctx.texture(data.t.normal)}, ctx.texture(data.t.depth));
            bindTarget(fb, desc.width, desc.height);
            std::array<GLuint, kMaterialTiers> programs{};
            for (int tier = 0; tier < kMaterialTiers; ++tier)
                programs[std::size_t(tier)] = rc.shaders.id("terrain/shaders/terrain.glsl", terrainDefines(s, tier));
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_GREATER);
            glDepthMask(GL_TRUE);
            // The grid's triangles wind counter-clockwise seen from above: a heightfield's back
            // faces are always hidden behind its front faces, so they need no shading.
            glEnable(GL_CULL_FACE);
            glCullFace(GL_BACK);
            glFrontFace(GL_CCW);
            const GLuint tess = s.tessellation.enabled
                                    ? rc.shaders.id("terrain/shaders/terrain_tess.glsl", terrainTessDefines(s))
                                    : 0;
            terrain.draw(rc, s, programs, tess);
            glDisable(GL_CULL_FACE);
            glDisable(GL_DEPTH_TEST);
        });
    targets = d.t;
    if (!s.bounds) return;
    const Data& b = graph.addPass<Data>("terrain.bounds",
        [&](PassBuilder& builder, Data& data) {
            data.t.hdr = builder.write(targets.hdr);
            data.t.depth = builder.read(targets.depth);
        },
        [&rc, &terrain](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.t.hdr);
            bindTarget(rc.device.framebuffer({ctx.texture(data.t.hdr)}, ctx.texture(data.t.depth)), desc.width, desc.height);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_GEQUAL);
            glDepthMask(GL_FALSE);
            terrain.drawBounds(rc.shaders.id("terrain/shaders/bounds.glsl"));
            glDepthMask(GL_TRUE);
            glDisable(GL_DEPTH_TEST);
        });
    targets.hdr = b.t.hdr;
}

}  // namespace vista
