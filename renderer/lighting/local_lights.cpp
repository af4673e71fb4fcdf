// Local lights: CPU preparation, GPU buffers, the culling and shading passes.
#include "renderer/lighting/local_lights.h"

#include "renderer/lighting/light_settings.h"
#include "renderer/lighting/light_variants.h"
#include "renderer/bindings.h"
#include "renderer/pass_kit.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace vista {

namespace {

#include "renderer/lighting/shaders/light_shade_block.glsl"

struct GpuLight {
    glm::vec4 position_radius, color_scale, direction_offset, shadow;
};
static_assert(sizeof(GpuLight) == 4 * sizeof(glm::vec4), "GpuLight must match LocalLight in lights.glsl");
constexpr std::size_t kGpuLightVec4 = sizeof(GpuLight) / sizeof(glm::vec4);

// std140 mirror of LightGrid in renderer/lighting/shaders/lights.glsl.
struct GridUniforms {
    glm::uvec4 grid;    // light count, tile px, tiles x, tiles y
    glm::uvec4 grid2;   // slices, max per cell, pool capacity, hash levels
    glm::vec4 slices;   // near_0, 1 / ln ratio, ln ratio, tan(fov_y / 2)
    glm::vec4 hash_origin;  // camera - hash origin, node size
    glm::vec4 grid3;    // aspect
};

constexpr int kHashLevelWords = 16;
constexpr int kHashHeaderWords = (LightHash::kMaxLevels + 1) * kHashLevelWords;

}  // namespace

std::vector<Light> collectSceneLights(const LightsSettings& s, const GroundHeight& ground, double lux_per_hdr_unit) {
    std::vector<Light> out;
    for (const NamedLight& l : s.lights) {
        out.push_back(l.light);
        if (l.light.ground_m >= 0.0f && ground) out.back().position.y = ground(l.light.position.x, l.light.position.z) + l.light.ground_m;
    }
    for (const NamedLightVolume& v : s.volumes) {
        const std::size_t first = out.size();
        generateLights(v.volume, out);
        if (v.volume.ground_m < 0.0f) continue;
        const double floor_y = std::min(v.volume.min_m.y, v.volume.max_m.y);
        for (std::size_t i = first; i < out.size(); ++i)
            out[i].position.y = (ground ? ground(out[i].position.x, out[i].position.z) : floor_y) + v.volume.ground_m;
    }
    for (Light& l : out) l = resolveUnits(l, lux_per_hdr_unit, double(s.cutoff_lux));
    return out;
}

std::uint64_t sceneLightCount(const LightsSettings& s) {
    if (!s.enabled) return 0;
    std::uint64_t n = s.lights.size();
    for (const NamedLightVolume& v : s.volumes) n += lightCount(v.volume);
    return n;
}

bool sphereMeetsView(const glm::dvec3& center_rel, double radius, const ViewParams& view, const ViewMatrices& m) {
    const double ty = std::tan(glm::radians(view.fov_deg) * 0.5), tx = ty * double(view.width) / double(view.height);
    const double kx = std::sqrt(1.0 + tx * tx), ky = std::sqrt(1.0 + ty * ty);
    const glm::dvec3 c{glm::dot(center_rel, m.right), glm::dot(center_rel, m.up), glm::dot(center_rel, m.forward)};  // z: depth
    const double r = radius * (1.0 + 1e-4) + 1e-4 * glm::length(center_rel);
    return !(c.z < view.near_m - r || std::abs(c.x) > c.z * tx + r * kx || std::abs(c.y) > c.z * ty + r * ky);
}

ProgramList localLightPrograms() {
    ProgramList programs = variantPrograms<LightCullVariant>();
    appendPrograms(programs, variantPrograms<LightShadeVariant>());
    return programs;
}

void LocalLights::GpuBuffer::reserve(std::size_t bytes, std::string_view name) {
    bytes = std::max<std::size_t>(bytes, 16);
    if (buffer.id() != 0 && std::size_t(buffer.size()) >= bytes) return;
    std::size_t grown = std::max(bytes, std::size_t(buffer.size()) * 3 / 2);
    buffer = gl::Buffer::create(GLsizeiptr(grown), nullptr, GL_DYNAMIC_STORAGE_BIT, name);
}

void LocalLights::GpuBuffer::upload(const void* data, std::size_t bytes, std::string_view name) {
    reserve(bytes, name);
    if (bytes > 0) glNamedBufferSubData(buffer.id(), 0, GLsizeiptr(bytes), data);
}

LocalLights::LocalLights() {
    for (gl::Buffer& b : overflow_ring_) {
        const std::uint32_t zero[2] = {0, 0};
        b = gl::Buffer::create(sizeof(zero), zero, GL_DYNAMIC_STORAGE_BIT, "lights.overflow");  // overflow, pool demand
    }
}

LocalLights::~LocalLights() {
    for (GLsync f : overflow_fence_)
        if (f) glDeleteSync(f);
}

void LocalLights::readOverflow() {
    // The oldest buffer of the ring (written three frames ago), if the GPU is done with it (never waits).
    const std::size_t slot = write_slot_;
    GLsync& fence = overflow_fence_[slot];
    if (!fence) return;
    if (glClientWaitSync(fence, 0, 0) == GL_TIMEOUT_EXPIRED) return;
    glDeleteSync(fence);
    fence = nullptr;
    std::uint32_t values[2] = {0, 0};  // overflowed cells, pool entries asked for
    glGetNamedBufferSubData(overflow_ring_[slot].id(), 0, sizeof(values), values);
    const std::uint32_t value = values[0];
    pool_demand_ = values[1];
    stats_.overflow = value;
    if (value > 0 && !overflow_warned_)
        std::fprintf(stderr,
                     "vista: lights: %u tile/cluster light lists overflowed [lights] max_lights_per_cell = %d; "
                     "those cells shade every light (correct, slower). Raise max_lights_per_cell (1..4096) or "
                     "lower the light radii.\n",
                     value, max_lights_per_cell_);
    overflow_warned_ = value > 0;
}

bool LocalLights::prepare(const LightsSettings& s, const ViewParams& view, const ViewMatrices& m, double time_s,
                          const GroundHeight& ground, double lux_per_hdr_unit, float radiance_scale) {
    const auto start = std::chrono::steady_clock::now();
    readOverflow();
    max_lights_per_cell_ = s.max_lights_per_cell;
    // Collect when the entries change (compared field by field, nothing copied on a steady
    // frame); animate every frame when something moves.
    const bool changed = !collected_ || s.lights != lights_ || s.volumes != volumes_ || bool(ground) != had_ground_ ||
                         lux_per_hdr_unit != lux_per_hdr_unit_ || s.cutoff_lux != cutoff_lux_;
    if (changed) {
        base_ = s.enabled ? collectSceneLights(s, ground, lux_per_hdr_unit) : std::vector<Light>{};
        lux_per_hdr_unit_ = lux_per_hdr_unit;
        cutoff_lux_ = s.cutoff_lux;
        lights_ = s.lights;
        volumes_ = s.volumes;
        had_ground_ = bool(ground);
        collected_ = true;
        hash_built_ = false;
    }
    const bool animated = s.animation.motion != LightMotion::None && s.animation.period_s > 0.0f;
    if (changed || animated || !(animation_ == s.animation)) {
        if (animated)
            animateLights(base_, s.animation, time_s, animated_);
        else
            animated_ = base_;
        animation_ = s.animation;
        world_spheres_.resize(animated_.size());
        for (std::size_t i = 0; i < animated_.size(); ++i) world_spheres_[i] = boundingSphere(animated_[i]);
        hash_uploaded_ = hash_uploaded_ && !changed && !animated;
    }
    stats_.count = animated_.size();
    if (changed) {
        stats_.max_radius_m = 0.0;
        for (const Light& l : base_) stats_.max_radius_m = std::max(stats_.max_radius_m, double(l.radius_m));
    }
    stats_.longest_range = 0;
    stats_.chunks = 1;
    if (animated_.empty()) return false;

    // The method: hashed needs its octree; when it cannot be built within the memory bound,
    // clustered serves instead (said once).
    stats_.method = s.culling;
    if (s.culling == LightCulling::Hashed) {
        LightHashSettings hs;
        hs.node_size_m = s.hash_node_m;
        hs.memory_budget_bytes = std::size_t(double(s.hash_memory_mb) * 1024.0 * 1024.0);
        hs.slack = s.hash_slack;
        const bool same_settings = hs.node_size_m == hash_settings_.node_size_m &&
                                   hs.memory_budget_bytes == hash_settings_.memory_budget_bytes &&
                                   hs.slack == hash_settings_.slack;
        if (!hash_built_ || !same_settings) {
            hash_settings_ = hs;
            stats_.hash = hash_.build(world_spheres_, hs);
            hash_built_ = true;
            hash_uploaded_ = false;
        } else if (!hash_uploaded_) {
            stats_.hash = hash_.update(world_spheres_);
        }
        if (!stats_.hash.ok || stats_.hash.degraded) {
            if (stats_.hash.message != hash_message_)
                std::fprintf(stderr, "vista: lights: hashed culling: %s%s\n", stats_.hash.message.c_str(),
                             stats_.hash.ok ? "" : "; using clustered culling instead");
            hash_message_ = stats_.hash.message;
        }
        if (!stats_.hash.ok) stats_.method = LightCulling::Clustered;
    } else if (hash_built_ || hash_buf_.buffer.id()) {
        hash_ = LightHash();  // another method: the octree's memory goes
        hash_built_ = false;
        hash_buf_ = {};
        hash_words_.clear();
    }

    // The lights the GPU sees. Tiled and clustered take only those whose bounding sphere meets
    // the view frustum (no other can light a visible point); naive loops over all by definition,
    // and hashed's octree indexes all of them.
    const bool screen_culled = screenCulled(stats_.method);
    const double ty = std::tan(glm::radians(view.fov_deg) * 0.5);
    // A sphere at depth z > r spans about r / z * focal pixels in radius: below min_screen_px it
    // lights at most a few pixels, faintly (its falloff reaches 0 at the radius), and would still
    // cost a test in every tile.
    const double focal_px = 0.5 * double(view.height) / ty;
    const double min_px = double(s.min_screen_px);
    stats_.skipped = 0;
    std::vector<glm::vec4>& spheres = spheres_scratch_;  // view space, for the culling pass
    std::vector<std::uint32_t>& order = order_scratch_;  // members: their memory is reused every frame
    spheres.clear();
    order.clear();
    for (std::size_t i = 0; i < animated_.size(); ++i) {
        if (!screen_culled) {
            order.push_back(std::uint32_t(i));
            continue;
        }
        const glm::dvec3 rel = world_spheres_[i].center - view.position;
        const glm::dvec3 c{glm::dot(rel, m.right), glm::dot(rel, m.up), glm::dot(rel, m.forward)};  // z: depth
        const double r = world_spheres_[i].radius * (1.0 + 1e-4) + 1e-4 * glm::length(rel);
        if (world_spheres_[i].radius <= 0.0 || !sphereMeetsView(rel, world_spheres_[i].radius, view, m)) continue;
        if (min_px > 0.0 && c.z > r && r * focal_px < min_px * (c.z - r)) {  // r / (z - r): the widest it can look
            ++stats_.skipped;
            continue;
        }
        order.push_back(std::uint32_t(i));
        spheres.push_back(glm::vec4(glm::vec3(c.x, c.y, -c.z), float(world_spheres_[i].radius)));
    }
    stats_.visible = order.size();
    if (order.empty()) {
        stats_.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        return false;  // nothing can light a visible point: no passes
    }

    // Light buffer, camera-relative (the subtraction in double keeps far-out scenes exact).
    const std::size_t n = order.size();
    std::vector<glm::vec4>& gpu = light_scratch_;  // GpuLight: 4 vec4 per light
    gpu.resize(kGpuLightVec4 * n);
    for (std::size_t k = 0; k < n; ++k) {
        const Light& l = animated_[order[k]];
        const SpotCone cone = spotCone(l);
        const glm::vec3 dir = glm::length(l.direction) > 0.0f ? glm::normalize(l.direction) : glm::vec3(0, -1, 0);
        glm::vec4* g = &gpu[kGpuLightVec4 * k];
        g[0] = glm::vec4(glm::vec3(l.position - view.position), std::max(l.radius_m, 0.0f));
        g[1] = glm::vec4(l.color * (l.intensity * radiance_scale), cone.scale);
        g[2] = glm::vec4(dir, cone.offset);
        g[3] = glm::vec4(-1.0f, -1.0f, 0.0f, 0.0f);  // unshadowed until setShadowSlots() / setPointShadowSlots()
    }
    lights_buf_.upload(gpu.data(), n * sizeof(GpuLight), "lights");

    GridUniforms u{};
    u.grid = glm::uvec4(std::uint32_t(n), 16u, 1u, 1u);
    u.slices = glm::vec4(float(view.near_m), 1.0f, 1.0f, float(ty));
    u.grid3 = glm::vec4(float(double(view.width) / double(view.height)), 0.0f, 0.0f, 0.0f);
    stats_.tiles_x = stats_.tiles_y = stats_.slices = 0;
    if (screen_culled) {
        ClusterGridParams p;
        p.width_px = view.width;
        p.height_px = view.height;
        p.tile_px = tilePixels(s.tile_size);
        p.fov_y_deg = view.fov_deg;
        p.near0_m = s.cluster_near_m > 0.0f ? double(s.cluster_near_m) : view.near_m;
        p.far_m = std::max(double(s.cluster_far_m), p.near0_m * 2.0);
        p.slices = s.cluster_slices;
        p.max_slices = kMaxAutoSlices;
        grid_ = makeClusterGrid(p);
        const bool clustered = stats_.method == LightCulling::Clustered;
        const int slices = clustered ? grid_.slices : 1;
        stats_.tiles_x = grid_.tiles_x;
        stats_.tiles_y = grid_.tiles_y;
        stats_.slices = slices;
        const std::size_t tiles = std::size_t(grid_.tiles_x) * std::size_t(grid_.tiles_y);
        const std::size_t cap = std::size_t(std::min(s.max_lights_per_cell, kMaxLightsPerCell));
        // The list pool: 64 entries per tile to start, then grown to 1.5x what the last frames
        // asked for (read back a few frames late; meanwhile lists that do not fit overflow,
        // which stays correct). It never shrinks while the lights stay.
        std::size_t entries = std::max<std::size_t>(pool_entries_, tiles * 64);
        if (pool_demand_ * 5 > entries * 4) entries = std::size_t(pool_demand_) * 3 / 2;
        entries = std::min<std::size_t>(entries, std::size_t(1) << 26);
        pool_entries_ = entries;
        cells_buf_.reserve(tiles * std::size_t(slices) * 8, "lights.cells");
        indices_buf_.reserve(entries * 4, "lights.indices");
        pool_buf_.reserve(4, "lights.pool");
        u.grid = glm::uvec4(std::uint32_t(n), std::uint32_t(grid_.tile_px), std::uint32_t(grid_.tiles_x),
                            std::uint32_t(grid_.tiles_y));
        u.grid2 = glm::uvec4(std::uint32_t(slices), std::uint32_t(cap), std::uint32_t(entries), 0u);
        u.slices = glm::vec4(float(grid_.near0_m), float(1.0 / grid_.log_ratio), float(grid_.log_ratio),
                             float(grid_.tan_half_fov_y));
        spheres_buf_.upload(spheres.data(), n * sizeof(glm::vec4), "lights.spheres");
    } else {
        cells_buf_ = {};
        spheres_buf_ = {};
        pool_buf_ = {};
        pool_entries_ = 0;
        pool_demand_ = 0;
        if (stats_.method == LightCulling::Naive) indices_buf_ = {};
    }
    if (stats_.method == LightCulling::Hashed) {
        if (!hash_uploaded_) uploadHash();
        const glm::dvec3 o = view.position - hash_.origin();
        u.grid2.w = std::uint32_t(hash_.levels());
        u.hash_origin = glm::vec4(glm::vec3(o), float(hash_.nodeSize()));
    }
    grid_ubo_.upload(&u, sizeof(u), "lights.grid");

    // The draws each lit pass makes (lights.glsl chunkOf): a pixel's range holds at most every
    // light on the GPU (naive, an overflowed cell; tiled and clustered lists stop at 4,096), or
    // for hashed its list (the octree's longest). Said once: past one chunk every pass that
    // shades local lights (lights.shade, water.surface, objects.transparent) draws again.
    stats_.longest_range = stats_.method == LightCulling::Hashed ? std::uint64_t(stats_.hash.longest_list) : n;
    stats_.chunks = std::uint32_t(std::max<std::uint64_t>(1, (stats_.longest_range + kLightChunk - 1) / kLightChunk));
    if (stats_.chunks > 1 && !chunks_warned_)
        std::fprintf(stderr,
                     "vista: lights: %s %llu lights, more than one shader invocation may loop over on llvmpipe "
                     "(65,535 iterations in all): every pass that shades local lights (lights.shade, water.surface, "
                     "objects.transparent) draws %u times, %u lights a draw (lights.chunks)%s.\n",
                     stats_.method == LightCulling::Hashed ? "the longest hashed light list holds" : "a pixel may shade all",
                     (unsigned long long)stats_.longest_range, stats_.chunks, kLightChunk,
                     stats_.method == LightCulling::Naive || stats_.method == LightCulling::Hashed
                         ? ""
                         : "; the draws past the first shade only overflowed cells (lights.overflow)");
    chunks_warned_ = chunks_warned_ || stats_.chunks > 1;

    stats_.memory_bytes = 0;
    for (const GpuBuffer* b : {&lights_buf_, &spheres_buf_, &cells_buf_, &indices_buf_, &hash_buf_, &grid_ubo_, &pool_buf_})
        stats_.memory_bytes += b->buffer.id() ? std::size_t(b->buffer.size()) : 0;
    stats_.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return true;
}

void LocalLights::uploadHash() {
    // After an incremental update only the table entries and index-list entries that changed
    // are written (PerfectSpatialHash::dirty(), LightHash::indicesDirtyBegin()); after a full
    // build, a table rebuilt with new sizes, or a buffer that must grow, everything.
    const int levels = hash_.levels();
    auto table = [&](int l, bool data) -> const PerfectSpatialHash& {
        return data ? hash_.dataTable(l) : hash_.nodeTable(l);
    };
    auto header = [](int l, bool data) { return std::size_t(l) * kHashLevelWords + (data ? 8 : 0); };
    bool full = hash_words_.empty() || stats_.hash.full_rebuild || levels != hash_levels_uploaded_;
    for (int l = 0; l <= levels && !full; ++l)
        for (bool data : {false, true})
            if ((data ? l >= 1 : l < levels) && table(l, data).dirty().resized) full = true;
    if (full) {
        hash_words_.assign(kHashHeaderWords, 0u);
        auto append = [&](const PerfectSpatialHash& t, std::size_t h, bool data) {
            hash_words_[h + 0] = std::uint32_t(hash_words_.size());
            for (std::uint64_t v : t.values()) {
                hash_words_.push_back(std::uint32_t(v));
                if (data) hash_words_.push_back(std::uint32_t(v >> 32));
            }
            hash_words_[h + 1] = std::uint32_t(hash_words_.size());
            hash_words_.insert(hash_words_.end(), t.offsets().begin(), t.offsets().end());
            const std::uint32_t r = std::uint32_t(t.offsetSide());
            hash_words_[h + 2] = std::uint32_t(std::max(t.tableSide(), 1));
            hash_words_[h + 3] = std::max(r * r * r, 1u);
            hash_words_[h + 4] = std::uint32_t(t.quotientSide());
        };
        for (int l = 0; l < levels; ++l) append(hash_.nodeTable(l), header(l, false), false);
        for (int l = 1; l <= levels; ++l) append(hash_.dataTable(l), header(l, true), true);
        hash_buf_.upload(hash_words_.data(), hash_words_.size() * 4, "lights.hash");
        hash_levels_uploaded_ = levels;
        stats_.hash_upload_bytes = hash_words_.size() * 4;
    } else {
        stats_.hash_upload_bytes = 0;
        auto write = [&](std::size_t first, std::size_t count) {
            if (count == 0) return;
            glNamedBufferSubData(hash_buf_.buffer.id(), GLintptr(first * 4), GLsizeiptr(count * 4), &hash_words_[first]);
            stats_.hash_upload_bytes += count * 4;
        };
        for (int l = 0; l <= levels; ++l)
            for (bool data : {false, true}) {
                if (!(data ? l >= 1 : l < levels)) continue;
                const PerfectSpatialHash& t = table(l, data);
                const PerfectSpatialHash::Dirty& d = t.dirty();
                const std::size_t h = header(l, data), w = data ? 2 : 1;
                if (d.slot_begin < d.slot_end) {
                    const std::size_t base = hash_words_[h + 0];
                    for (std::uint32_t i = d.slot_begin; i < d.slot_end; ++i) {
                        const std::uint64_t v = t.values()[i];
                        hash_words_[base + w * i] = std::uint32_t(v);
                        if (data) hash_words_[base + w * i + 1] = std::uint32_t(v >> 32);
                    }
                    write(base + w * d.slot_begin, w * (d.slot_end - d.slot_begin));
                }
                if (d.offset_begin < d.offset_end) {
                    const std::size_t base = hash_words_[h + 1];
                    for (std::uint32_t i = d.offset_begin; i < d.offset_end; ++i) hash_words_[base + i] = t.offsets()[i];
                    write(base + d.offset_begin, d.offset_end - d.offset_begin);
                }
            }
    }
    const std::span<const std::uint32_t> indices = hash_.indices();
    const std::size_t dirty = hash_.indicesDirtyBegin();
    if (full || indices.size_bytes() > std::size_t(indices_buf_.buffer.size()) || indices_buf_.buffer.id() == 0 ||
        dirty == 0) {
        indices_buf_.upload(indices.data(), indices.size_bytes(), "lights.indices");
        stats_.hash_upload_bytes += indices.size_bytes();
    } else if (dirty < indices.size()) {
        glNamedBufferSubData(indices_buf_.buffer.id(), GLintptr(dirty * 4), GLsizeiptr((indices.size() - dirty) * 4),
                             indices.data() + dirty);
        stats_.hash_upload_bytes += (indices.size() - dirty) * 4;
    }
    hash_.clearDirty();
    hash_uploaded_ = true;
}

void LocalLights::writeShadowSlots(std::span<const SpotShadowPick> picks, const std::function<int(std::size_t)>& slot_of,
                                   int component) {
    // order_scratch_ (GPU index -> light index) is ascending, so a light's GPU index is a search.
    const std::vector<std::uint32_t>& order = order_scratch_;
    for (std::size_t k = 0; k < picks.size(); ++k) {
        const std::uint32_t light = picks[k].light;
        auto it = std::lower_bound(order.begin(), order.end(), light);
        if (it == order.end() || *it != light) continue;  // not on the GPU this frame: nothing to shadow
        const float slot = float(slot_of(k));
        const auto index = std::size_t(it - order.begin());
        glNamedBufferSubData(lights_buf_.buffer.id(),
                             GLintptr(index * sizeof(GpuLight) + 3 * sizeof(glm::vec4) + std::size_t(component) * sizeof(float)),
                             sizeof slot, &slot);
    }
}

void LocalLights::setShadowSlots(const SpotShadows& shadows) {
    writeShadowSlots(shadows.picks(), [&](std::size_t k) { return shadows.slotOf(k); }, 0);
}

void LocalLights::setPointShadowSlots(const PointShadows& shadows) {
    writeShadowSlots(shadows.picks(), [&](std::size_t k) { return shadows.slotOf(k); }, 1);
}

const char* LocalLights::define() const { return lightMethodDefine(stats_.method); }

void LocalLights::bindForForward() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::kLightGrid, grid_ubo_.buffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kLights, lights_buf_.buffer.id());
    if (cells_buf_.buffer.id()) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kLightCells, cells_buf_.buffer.id());
    if (indices_buf_.buffer.id()) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kLightIndices, indices_buf_.buffer.id());
    if (hash_buf_.buffer.id()) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kLightHash, hash_buf_.buffer.id());
}

void LocalLights::addPasses(FrameGraph& graph, const RenderContext& rc, SceneTargets& targets,
                            CounterReadback& counters, const LightPassOptions& options) {
    const LightCulling method = stats_.method;
    const bool culled = screenCulled(method);
    auto bindBuffers = [this]() {
        bindForForward();
        if (spheres_buf_.buffer.id()) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kLightSpheres, spheres_buf_.buffer.id());
    };

    if (culled) {
        struct Data {
            TextureHandle depth;
        };
        graph.addPass<Data>("lights.cull",
            [&](PassBuilder& b, Data& d) {
                d.depth = b.read(targets.depth);
                b.sideEffect();  // writes the light lists lights.shade reads
            },
            [this, &rc, &counters, method, bindBuffers, forward = options.forward, count = options.count](const Data& d,
                                                                                                      PassContext& ctx) {
                const std::size_t slot = write_slot_;
                write_slot_ = (write_slot_ + 1) % overflow_ring_.size();
                GLuint overflow = overflow_ring_[slot].id();
                if (overflow_fence_[slot]) {  // not read back yet: drop it, keep the ring going
                    glDeleteSync(overflow_fence_[slot]);
                    overflow_fence_[slot] = nullptr;
                }
                const std::uint32_t zero = 0;
                glClearNamedBufferData(overflow, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
                glClearNamedBufferData(pool_buf_.buffer.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
                if (!shade_draw_) shade_draw_ = gl::Buffer::create(16, nullptr, GL_DYNAMIC_STORAGE_BIT, "lights.shade draw");
                const std::uint32_t draw[4] = {3, 0, 0, 0};  // a full-screen triangle, no instance yet
                glNamedBufferSubData(shade_draw_.id(), 0, sizeof draw, draw);
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kLightShadeDraw, shade_draw_.id());
                glUseProgram(rc.shaders.id(LightCullVariant{method, forward}.key()));
                bindBuffers();
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kCounters, overflow);
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kAux, pool_buf_.buffer.id());
                glBindTextureUnit(binding::kTex0, ctx.texture(d.depth));
                glDispatchCompute(GLuint(grid_.tiles_x), GLuint(grid_.tiles_y), 1);
                glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
                // For the stats: a copy of the overflow count per frame; for the warning: the ring.
                GLuint stat = counters.request(rc.frame, "lights.overflow");
                glCopyNamedBufferSubData(overflow, stat, 0, 0, 4);
                // 1 when lights.shade draws this frame, 0 when no tile has a light (with the light counters).
                if (count) glCopyNamedBufferSubData(shade_draw_.id(), counters.request(rc.frame, "lights.shade_draws"), 4, 0, 4);
                glCopyNamedBufferSubData(pool_buf_.buffer.id(), overflow, 0, 4, 4);  // the pool's demand
                overflow_fence_[slot] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
            });
    }

    struct Data {
        TextureHandle depth, albedo, normal, hdr, heat, spot, point;
    };
    const Data& d = graph.addPass<Data>("lights.shade",
        [&](PassBuilder& b, Data& data) {
            if (options.spot_shadows && options.spot_shadows->valid()) data.spot = b.read(options.spot_shadows->atlas);
            if (options.point_shadows && options.point_shadows->valid()) data.point = b.read(options.point_shadows->cubes);
            data.depth = b.read(targets.depth);
            data.albedo = b.read(targets.albedo);
            data.normal = b.read(targets.normal);
            data.hdr = b.write(targets.hdr);
            if (options.heat) {
                TextureDesc desc = b.desc(targets.hdr);
                desc.format = PixelFormat::R32F;
                data.heat = b.write(b.create("lights.heat", desc));
            }
        },
        [this, &rc, &counters, method, culled, options, bindBuffers](const Data& data, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(data.hdr);
            GLuint fb = data.heat.valid() ? rc.device.framebuffer({ctx.texture(data.hdr), ctx.texture(data.heat)})
                                          : rc.device.framebuffer({ctx.texture(data.hdr)});
            bindTarget(fb, desc.width, desc.height);
            const LightShadeVariant variant{method, options.count, data.heat.valid(), data.spot.valid(), data.point.valid()};
            const GLuint program = rc.shaders.id(variant.key());
            glUseProgram(program);
            bindBuffers();
            if (data.spot.valid()) options.spot_shadows->bind(ctx.texture(data.spot));
            if (data.point.valid()) options.point_shadows->bind(ctx.texture(data.point));
            if (options.count) {
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kCounters, counters.request(rc.frame, "lights.evaluations"));
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kAux, counters.request(rc.frame, "lights.exact"));
            }
            glBindTextureUnit(binding::kTex0, ctx.texture(data.depth));
            glBindTextureUnit(binding::kTex1, ctx.texture(data.albedo));
            glBindTextureUnit(binding::kTex2, ctx.texture(data.normal));
            glEnablei(GL_BLEND, 0);
            glBlendFunci(0, GL_ONE, GL_ONE);
            if (data.heat.valid()) glDisablei(GL_BLEND, 1);
            // One draw per chunk of the ranges (lights.glsl chunkOf), added up.
            for (std::uint32_t k = 0; k < stats_.chunks; ++k) {
                bindPassBlock(rc, program, LightShadeBlock{{k * kLightChunk, kLightChunk}, {0u, 0u}});
                if (culled) {  // drawn only when lights.cull found a tile with a light
                    glBindVertexArray(rc.empty_vao);
                    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, shade_draw_.id());
                    glDrawArraysIndirect(GL_TRIANGLES, nullptr);
                    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
                } else {
                    drawFullscreen(rc);
                }
            }
            glDisablei(GL_BLEND, 0);
            if (data.spot.valid()) SpotShadowInput::unbind();
            if (data.point.valid()) PointShadowInput::unbind();
            if (options.count) glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        });
    targets.hdr = d.hdr;
    if (d.heat.valid()) targets.light_heat = d.heat;
}

}  // namespace vista
