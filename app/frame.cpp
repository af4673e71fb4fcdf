// The frame: which passes run, in which order, for the current settings.
#include "app/frame.h"

#include "postfx/chain.h"
#include "postfx/ssao.h"
#include "renderer/bindings.h"
#include "renderer/debug_grid.h"
#include "renderer/debug_view.h"
#include "renderer/nonfinite.h"
#include "renderer/reference_copy.h"
#include "renderer/velocity.h"
#include "renderer/temporal.h"
#include "app/light_placement.h"
#include "app/scene.h"
#include "config/ini.h"
#include "renderer/lighting/deferred.h"
#include "renderer/lighting/local_lights.h"
#include "renderer/shadows/shadow_view.h"
#include "sky/atmosphere.h"
#include "sky/day_cycle.h"
#include "sky/night_light.h"
#include "sky/clouds/cloud_model.h"
#include "sky/clouds/clouds.h"
#include "sky/clouds/sun_visibility.h"
#include "sky/weather/weather.h"
#include "sky/weather/weather_model.h"
#include "terrain/material_weights.h"
#include "terrain/scatter/scatter.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vista {

namespace {

// The ground under a point for the placement of objects: height, slope from central differences
// over 1 m, and the terrain's grass weight there (terrain/material_weights.h, as the terrain shades it).
// Safe on another thread (Terrain::heightSampler) while the terrain lives.
GroundFunction terrainGround(const Terrain& terrain, const TerrainSettings& ts) {
    return [height = terrain.heightSampler(), ts, m = terrain.mapping()](double x, double z) {
        GroundSample g;
        const double half = m.size_m * 0.5;
        if (std::abs(x - ts.origin.x) > half || std::abs(z - ts.origin.z) > half) return g;
        g.valid = true;
        g.height_m = height(x, z);
        const double dx = (height(x + 1.0, z) - height(x - 1.0, z)) * 0.5;
        const double dz = (height(x, z + 1.0) - height(x, z - 1.0)) * 0.5;
        g.slope = std::sqrt(dx * dx + dz * dz);
        const double normal_y = 1.0 / std::sqrt(1.0 + g.slope * g.slope);
        const double h = (g.height_m - ts.origin.y - m.height_offset_m) / m.height_scale_m;
        g.grass = material::grassAt(h, normal_y, {ts.sand_top, ts.grass_top, ts.snow_start, ts.band_blend}, ts.rock_slope);
        return g;
    };
}

}  // namespace

ProgramList allPrograms() {
    ProgramList programs = {
        {"renderer/shaders/copy.glsl", {}},
        {"renderer/shaders/grid.glsl", {}},
        {"renderer/shaders/debug_view.glsl", {}},
        {"renderer/shaders/nonfinite.glsl", {}},
    };
    for (const ProgramList& list : {skyPrograms(), lightingPrograms(), localLightPrograms(), lampGlowPrograms(), shadowPrograms(), cloudPrograms(),
                                    postfxPrograms(), taaPrograms(), velocityPrograms(), terrainPrograms(), grassPrograms(),
                                    weatherPrograms(), waterPrograms(), objectPrograms()})
        appendPrograms(programs, list);
    return programs;
}

FrameRenderer::FrameRenderer(std::filesystem::path root)
    : shaders_(std::move(root)),
      empty_vao_(gl::createVertexArray("empty (attribute-less draws)")),
      frame_uniforms_(gl::Buffer::create(sizeof(FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT, "frame uniforms")) {
    shaders_.setListed(allPrograms());
    const GLubyte* name = glGetString(GL_RENDERER);
    timers_.setMode(timerModeFor(name ? reinterpret_cast<const char*>(name) : ""));
}

bool FrameRenderer::compilePrograms(std::string& errors) {
    errors.clear();
    for (const ProgramKey& p : allPrograms()) shaders_.get(p);
    errors = programErrors();
    return errors.empty();
}

std::string FrameRenderer::programErrors() const {
    std::string out;  // one program's error per line: ~90 failing programs were one 8 KB line
    for (const std::string& e : shaders_.errors()) {
        out += e;
        if (!out.empty() && out.back() != '\n') out += '\n';
    }
    return out;
}

InputErrors FrameRenderer::prepare(const Settings& s) {
    InputErrors errors = postfx_.prepare(s, s.grade.lut.empty() ? std::filesystem::path() : resolveInput(s.grade.lut));
    if (!s.terrain.enabled) {
        objects_next_ = {};  // waits for a placement reading the terrain
        objects_.release();  // objects stand on the terrain
        terrain_.release();  // a disabled feature keeps nothing allocated
        terrain_failed_ = false;
        return errors;
    }
    if (s.terrain.stream.enabled && (s.grass.enabled || (s.weather.enabled && s.weather.splashes))) {
        // Both read the whole map's height texture, which a streamed terrain does not have.
        errors.push_back({"[terrain.stream] enabled", 0, std::string("streaming does not work with ") +
                                                             (s.grass.enabled ? "[grass] enabled" : "[weather] splashes") +
                                                             " (it reads the whole map); accepted: turn that off, or "
                                                             "[terrain.stream] enabled = false"});
        return errors;
    }
    TerrainSettings wanted = s.terrain;
    wanted.heightmap = resolveInput(s.terrain.heightmap).string();
    wanted.dem = resolveInput(s.terrain.dem).string();
    if (!s.terrain.stream.cache.empty()) wanted.stream.cache = resolveInput(s.terrain.stream.cache).string();
    wanted = resolveMaterialPaths(std::move(wanted), resolveInput);
    bool same = terrain_ ? terrain_->matches(wanted) : terrain_failed_ && terrain_source_.heightmap == wanted.heightmap &&
                                                           terrain_source_.dem == wanted.dem && terrain_source_.grid == wanted.grid &&
                                                           terrain_source_.materials == wanted.materials &&
                                                           terrain_source_.splat_map == wanted.splat_map &&
                                                           terrain_source_.splat_layers == wanted.splat_layers;
    if (!same) {
        objects_next_ = {};
        objects_.release();  // placed on the old terrain
        terrain_.release();
        terrain_.adopt(Terrain::load(wanted, shaders_, errors));
        ++terrain_generation_;
        terrain_source_ = wanted;
        terrain_failed_ = !terrain_;
    }
    prepareObjects(s, errors);
    return errors;
}

void FrameRenderer::prepareObjects(const Settings& s, InputErrors& errors) {
    if (!terrain_ || !objectsWanted(s.objects)) {
        objects_next_ = {};
        objects_.release();  // nothing placed: no object, no buffers
        return;
    }
    if (!objects_ || !samePlacement(s.objects, objects_placed_for_)) {
        objects_next_ = {};  // placing other lists
        objects_.use();
        objects_placed_for_ = s.objects;
        ScatterArea area = terrainScatterArea(s.terrain.origin, terrain_->mapping().size_m);
        // Rules too dense for the whole terrain are placed around the camera: its start pose here,
        // then wherever a frame takes it (placeLocalObjects).
        objects_local_ = !scatterBudgetProblem(s.objects, area).empty();
        if (objects_local_) {
            objects_centre_ = {s.camera.position.x, s.camera.position.z};
            objects_reach_m_ = s.objects.max_distance_m;
            area = localScatterArea(objects_centre_, objects_reach_m_);
            if (std::string why = scatterBudgetProblem(s.objects, area, "the camera-local"); !why.empty()) {
                errors.push_back({"[objects]", 0, why});
                objects_.release();
                return;
            }
        }
        const std::size_t known = errors.size();
        const auto resolve = [](const std::string& f) { return resolveInput(f); };
        // A camera-local placement may hold no instance yet where it starts (over the sea).
        if (!objects_->place(placeObjects(s.objects, terrainGround(*terrain_, s.terrain), area), resolve, errors) &&
            !(objects_local_ && errors.size() == known)) {
            objects_.release();
            return;
        }
    }
    objects_->setEmissive(s.objects.emissive_nits);
}

bool FrameRenderer::placeLocalObjects(const Settings& s, glm::dvec3 camera) {
    if (!objects_local_ || !objects_) return false;
    const glm::dvec2 xz(camera.x, camera.z);
    const double reach = s.objects.max_distance_m;
    auto adopt = [&](const std::vector<ObjectPlacement>& placements, glm::dvec2 centre) {
        objects_centre_ = centre;
        objects_reach_m_ = reach;
        return objects_->replaceInstances(placements);
    };
    // A placement finished in the background, still covering the camera: swapped in.
    if (objects_next_.valid() && objects_next_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        const std::vector<ObjectPlacement> placements = objects_next_.get();
        if (objects_next_reach_m_ == reach && !localScatterStale(objects_next_centre_, xz, reach))
            return adopt(placements, objects_next_centre_);
    }
    // Past the margin (or another reach): placed now, the frame waits. Half way to it: the next
    // placement, around the camera here, on another thread.
    const double drift = localScatterDrift(objects_centre_, xz) / reach;
    const bool now = objects_reach_m_ != reach || drift > kLocalScatterReach - 1.0;
    const bool soon = !objects_next_.valid() && drift > 0.5 * (kLocalScatterReach - 1.0);
    if (!now && !soon) return false;
    const ScatterArea area = localScatterArea(xz, reach);
    if (!scatterBudgetProblem(s.objects, area, "the camera-local").empty()) return false;  // keeps the last placement
    if (now) {
        objects_next_ = {};
        return adopt(placeObjects(s.objects, terrainGround(*terrain_, s.terrain), area), xz);
    }
    objects_next_centre_ = xz;
    objects_next_reach_m_ = reach;
    objects_next_ = std::async(std::launch::async, [objects = s.objects, ground = terrainGround(*terrain_, s.terrain), area] {
        return placeObjects(objects, ground, area);
    });
    return false;
}

void FrameRenderer::adoptTerrain(std::unique_ptr<Terrain> terrain) {
    objects_next_ = {};
    ++terrain_generation_;
    terrain_.adopt(std::move(terrain));
    terrain_failed_ = false;
}

RenderContext FrameRenderer::context(const ViewParams& view, const Settings& settings, double time_s,
                                     glm::dvec2 jitter_px, std::uint32_t screen_noise_frame) {
    RenderContext rc{shaders_, device_, empty_vao_.id(), view, viewMatrices(view), frame_, time_s};
    if (jitter_px != glm::dvec2(0.0)) {
        applyJitter(rc.matrices, jitter_px, view.width, view.height);
        rc.jitter_ndc = glm::vec2(2.0 * jitter_px / glm::dvec2(std::max(view.width, 1), std::max(view.height, 1)));
    }
    rc.pre_exposure = pre_exposure_;
    FrameUniforms u{};
    u.view = rc.matrices.view;
    u.proj = rc.matrices.proj;
    u.view_proj = rc.matrices.view_proj;
    u.inv_view_proj = rc.matrices.inv_view_proj;
    u.camera_world = glm::vec4(glm::vec3(view.position), 1.0f);
    // The sun itself for the CPU passes that want it (the lens flare); the key light (the sun, or
    // the moon at night) is the one directional light the GPU passes shade.
    rc.sun_direction = sunDirection(settings.sky);
    rc.sun_illuminance = settings.sky.sun_illuminance;
    // The lens flare's strength: the sun through the atmosphere and the clouds (a red sun at the
    // horizon or one behind a cloud does not flare at full strength).
    if (settings.lens_flare.enabled)
        rc.sun_visibility = float(sunVisibility(sky_lighting_.get(settings.sky, view.position), settings.sky,
                                                settings.clouds, view.position, time_s).share());
    rc.cd_per_value = luxPerHdrUnit(settings.sky.sun_illuminance);
    const glm::dvec3 key = sky_lighting_.get(settings.sky, view.position).keyDirection();
    u.sun_dir = glm::vec4(glm::vec3(key), rc.sun_illuminance);
    u.viewport = glm::vec4(float(view.width), float(view.height), 1.0f / float(view.width), 1.0f / float(view.height));
    u.time = glm::vec4(float(time_s), float(frame_), float(sequence_index_ % 65536), float(screen_noise_frame % 65536));
    u.near = glm::vec4(float(view.near_m), 0.0f, 0.0f, 0.0f);
    u.exposure = glm::vec4(float(pre_exposure_), 0.0f, 0.0f, 0.0f);
    glNamedBufferSubData(frame_uniforms_.id(), 0, sizeof u, &u);
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::kFrameUniforms, frame_uniforms_.id());
    glBindTextureUnit(binding::kBlueNoise, blue_noise_.id());
    return rc;
}

double FrameRenderer::measureReferenceCopy(int width, int height) {
    RenderContext rc{shaders_, device_, empty_vao_.id(), {}, {}, frame_, 0.0};
    return measureReferenceCopyMs(rc, timers_.mode(), width, height);
}

namespace {

// The counters a shadow scheme for local lights reports (spot atlas, point cubes): how many
// lights asked, got a tile or cube, went without, and the caster instances drawn for them.
template <class Stats>
void reportShadowedLights(FrameReport& report, const std::string& prefix, const Stats& st) {
    report.counters[prefix + "candidates"] = double(st.candidates);
    report.counters[prefix + "shadowed"] = double(st.shadowed);
    report.counters[prefix + "unshadowed"] = double(st.unshadowed);
    report.counters[prefix + "caster_instances"] = double(st.caster_instances);
}

// Reads a texture back top row first (GL's rows start at the bottom).
template <class T>
void readTexture(GLuint texture, int width, int height, GLenum type, std::vector<T>& out, GLenum format = GL_RGBA) {
    std::size_t row = std::size_t(width) * (format == GL_RGBA ? 4 : 1);
    out.resize(row * std::size_t(height));
    glGetTextureImage(texture, 0, format, type, GLsizei(out.size() * sizeof(T)), out.data());
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(out.begin() + std::ptrdiff_t(row * std::size_t(y)),
                         out.begin() + std::ptrdiff_t(row * std::size_t(y + 1)),
                         out.begin() + std::ptrdiff_t(row * std::size_t(height - 1 - y)));
}

// "frame.clear": creates the scene targets and clears them once; scene passes draw over them.
// The G-buffer (albedo, normal) only when something opaque will be lit.
SceneTargets addClearPass(FrameGraph& graph, const RenderContext& rc, bool gbuffer) {
    struct Data {
        SceneTargets t;
    };
    return graph.addPass<Data>("frame.clear",
        [&](PassBuilder& b, Data& d) {
            const int w = rc.view.width, h = rc.view.height;
            d.t.hdr = b.write(b.create("scene.hdr", {w, h, PixelFormat::RGBA16F}));
            d.t.depth = b.write(b.create("scene.depth", {w, h, PixelFormat::Depth32F}));
            if (gbuffer) {
                d.t.albedo = b.write(b.create("gbuffer.albedo", {w, h, PixelFormat::RGBA8}));
                d.t.normal = b.write(b.create("gbuffer.normal", {w, h, PixelFormat::RGB10A2}));
            }
        },
        [&rc](const Data& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.t.hdr);
            GLuint fb = d.t.albedo.valid()
                ? rc.device.framebuffer({ctx.texture(d.t.hdr), ctx.texture(d.t.albedo), ctx.texture(d.t.normal)},
                                        ctx.texture(d.t.depth))
                : rc.device.framebuffer({ctx.texture(d.t.hdr)}, ctx.texture(d.t.depth));
            bindTarget(fb, desc.width, desc.height);
            glClearColor(0, 0, 0, 0);  // G-buffer: normal.a = 0 is "unlit"
            glClearDepth(0.0);         // reversed-Z: 0 is infinitely far
            glDepthMask(GL_TRUE);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        }).t;
}

struct SinkData {
    TextureHandle source;
};

// "capture.readback" (or "capture.readback_hdr"): copies source into a CPU buffer (a root).
template <typename T>
void addReadbackPass(FrameGraph& graph, const char* name, TextureHandle source, GLenum type, std::vector<T>& out,
                     GLenum format = GL_RGBA) {
    graph.addPass<SinkData>(name,
        [&](PassBuilder& b, SinkData& d) {
            d.source = b.read(source);
            b.sideEffect();
        },
        [type, format, &out](const SinkData& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.source);
            readTexture(ctx.texture(d.source), desc.width, desc.height, type, out, format);
        });
}

// "present": blits the display image to the window's framebuffer (a root).
void addPresentPass(FrameGraph& graph, const RenderContext& rc, TextureHandle display) {
    graph.addPass<SinkData>("present",
        [&](PassBuilder& b, SinkData& d) {
            d.source = b.read(display);
            b.sideEffect();
        },
        [&rc](const SinkData& d, PassContext& ctx) {
            const TextureDesc& desc = ctx.desc(d.source);
            GLuint fb = rc.device.framebuffer({ctx.texture(d.source)});
            glBlitNamedFramebuffer(fb, 0, 0, 0, desc.width, desc.height, 0, 0, rc.view.width, rc.view.height,
                                   GL_COLOR_BUFFER_BIT, GL_NEAREST);
        });
}

// The lowest world height a sun-shadow receiver can have: the terrain's lowest sample, the sea's
// lowest trough (when on), the bottom of the lowest placed object's bounding sphere.
double lowestReceiver(const Terrain& terrain, const Settings& s, const Objects* objects) {
    const MinMaxQuadtree& tree = terrain.quadtree();
    double lowest = std::numeric_limits<double>::infinity();
    if (tree.levels() > 0) {
        const glm::ivec2 top = tree.nodesPerSide(tree.levels() - 1);
        for (int z = 0; z < top.y; ++z)
            for (int x = 0; x < top.x; ++x) lowest = std::min(lowest, double(tree.minMax(tree.levels() - 1, x, z).x));
    } else {
        return -std::numeric_limits<double>::infinity();  // no tree: no floor known
    }
    if (s.water.enabled) lowest = std::min(lowest, double(s.water.level_m) - makeWaves(s.water).max_height);
    if (objects && s.objects.enabled) lowest = std::min(lowest, objects->lowestPoint());
    return lowest;
}

// The settings the sun cascades' casters are drawn from, as text, and the terrain's generation.
std::string casterKey(const Settings& s, std::uint64_t terrain_generation) {
    Settings casters;
    casters.terrain = s.terrain;
    casters.objects = s.objects;
    casters.shadows = s.shadows;
    return saveIniString(casters) + std::to_string(terrain_generation);
}

}  // namespace

SunShadowInput FrameRenderer::addTerrainAndShadowPasses(FrameGraph& graph, const RenderContext& rc, const Settings& s,
                                                        const ViewParams* fit_view, FrameReport& report,
                                                        const ShadowCaster& extra) {
    const glm::dmat4 view_proj(rc.matrices.view_proj);
    const double error_scale = screenErrorScale(rc.view.fov_deg, rc.view.height);
    const glm::dvec3 sun = sunDirection(s.sky);
    // The shadowed spot and point lights' views are covered by the same selection (one LOD for all).
    light_shadow_frusta_.clear();
    if (spot_shadows_) light_shadow_frusta_ = spot_shadows_->frusta();
    if (point_shadows_)
        light_shadow_frusta_.insert(light_shadow_frusta_.end(), point_shadows_->frusta().begin(), point_shadows_->frusta().end());
    const std::span<const Frustum> spots(light_shadow_frusta_);
    if (!sunCastsShadows(s.shadows, sun)) {
        sun_shadows_.release();  // no sun shadows: no passes, no shadow map
        terrain_->select(rc.view.position, view_proj, s.terrain, error_scale, nullptr, spots);
        return {};
    }
    SunShadows& sun_shadows = sun_shadows_.use();
    if (s.shadows.cache_frames > 1 && s.shadows.cache_cascades > 0) {
        // A kept cascade shows the casters as they were drawn: any change to what casts (the
        // terrain, its settings, the objects, the shadow settings) draws every cascade again.
        std::string key = casterKey(s, terrain_generation_);
        if (key != shadow_caster_key_) sun_shadows.forgetKept();
        shadow_caster_key_ = std::move(key);
    }
    sun_shadows.prepare(s.shadows, s.sky.sun_angular_radius_deg, sun, rc.view, fit_view ? *fit_view : rc.view, sequence_index_);
    // One selection covers the view and every caster of its shadows (one LOD for both).
    const Frustum casters = sun_shadows_->casterFrustum(view_proj);
    terrain_->select(rc.view.position, view_proj, s.terrain, error_scale, &casters, spots);
    SunShadowInput shadows = sun_shadows_->addPasses(graph, rc, &terrain_caster_, extra,
                                                     lowestReceiver(*terrain_, s, objects_.get()));
    const SunShadowStats& st = sun_shadows_->stats();
    report.counters["shadows.cascades"] = double(st.cascades);
    report.counters["shadows.drawn"] = double(st.drawn);
    report.counters["shadows.caster_instances"] = double(st.caster_instances);
    report.counters["shadows.casters_skipped"] = double(st.casters_skipped);
    report.counters["shadows.caster_triangles"] = double(st.caster_triangles);
    report.counters["shadows.cascades_cached"] = double(st.cached);
    return shadows;
}

bool FrameRenderer::prepareLocalLights(const RenderContext& rc, const Settings& s, FrameReport& report) {
    if (sceneLightCount(s.lights) == 0) {
        local_lights_.release();  // no local lights: no passes, no buffers
        return false;
    }
    // LocalLights re-collects when the entries change; the sea they stand on is ours to watch.
    const std::pair<bool, float> water{s.water.enabled, s.water.level_m};
    if (water != light_water_) local_lights_.release();
    light_water_ = water;
    local_lights_.use();
    GroundHeight terrain;
    if (terrain_) terrain = [t = terrain_.get()](double x, double z) { return t->heightAt(x, z); };
    const GroundHeight ground = lightGround(terrain, s.water);  // the sea's surface where it covers the terrain
    const bool any = local_lights_->prepare(s.lights, rc.view, rc.matrices, rc.time_s, ground,
                                            luxPerHdrUnit(s.sky.sun_illuminance), float(pre_exposure_));
    const LocalLightStats& st = local_lights_->stats();
    report.counters["lights.count"] = double(st.count);
    report.counters["lights.visible"] = double(st.visible);
    report.counters["lights.max_radius_m"] = st.max_radius_m;  // auto radii resolved (candela, cutoff_lux)
    report.counters["lights.skipped"] = double(st.skipped);  // below [lights] min_screen_px
    report.counters["lights.build_ms"] = st.build_ms;
    report.counters["lights.chunks"] = double(st.chunks);  // draws per pass that shades them (local_lights.h kLightChunk)
    return any;
}

bool FrameRenderer::prepareSpotShadows(const RenderContext& rc, const Settings& s) {
    if (s.shadows.enabled && s.shadows.spot_enabled) {
        if (spot_shadows_.use().prepare(s.shadows, local_lights_->lights(), rc.view, rc.matrices)) return true;
    }
    spot_shadows_.release();  // no shadowed spot light: no pass, no atlas
    return false;
}

bool FrameRenderer::preparePointShadows(const RenderContext& rc, const Settings& s) {
    if (s.shadows.enabled && s.shadows.point_enabled) {
        if (point_shadows_.use().prepare(s.shadows, local_lights_->lights(), rc.view, rc.matrices)) return true;
    }
    point_shadows_.release();  // no shadowed point light: no pass, no cubes
    return false;
}

PointShadowInput FrameRenderer::addPointShadowPass(FrameGraph& graph, const RenderContext& rc, const Settings& s,
                                                   const ShadowCaster& extra, FrameReport& report) {
    PointShadowInput input = point_shadows_->addPass(graph, rc, &terrain_caster_, extra);
    local_lights_->setPointShadowSlots(*point_shadows_);
    reportShadowedLights(report, "shadows.point_", point_shadows_->stats());
    return input;
}

SpotShadowInput FrameRenderer::addSpotShadowPass(FrameGraph& graph, const RenderContext& rc, const Settings& s,
                                                 const ShadowCaster& extra, FrameReport& report) {
    SpotShadowInput input = spot_shadows_->addPass(graph, rc, &terrain_caster_, extra);
    local_lights_->setShadowSlots(*spot_shadows_);
    reportShadowedLights(report, "shadows.spot_", spot_shadows_->stats());
    return input;
}

void FrameRenderer::resetHistory() {
    postfx_.resetHistory();
    weather_.release();  // its previous camera (streak velocity); recreated by the next frame with weather
    if (taa_) taa_->reset();
    if (clouds_) clouds_->resetHistory();
    has_last_view_ = false;
    temporal_index_ = 0;
}

// One frame's inputs as every phase sees them.
struct FrameRenderer::Frame {
    const Settings& s;          // the sky at this time, lights pre-exposed (settingsAt)
    const ViewParams& view;
    double time_s;
    RenderContext rc;
    bool cut;                   // a camera cut (or a new run): every history is rejected
    ViewParams previous_view;   // the motion vectors' previous camera (the view itself on a cut)
    double motion_dt_s;         // time since the previous frame for per-vertex motion (0 on a cut)
    bool taa;                   // [postfx.taa] this frame
    bool terrain;               // [terrain] on and loaded: everything opaque stands on it
    bool shadow_view;           // [debug] view = shadow: lighting.sun's output, nothing on top
    bool clouds;                // [clouds] draws something (they are lit through the sky's LUTs)
    SkyLighting sky_light;      // the sun, moon and sky at the camera (CPU), once per frame
    SunAndSky light;            // what the lighting, the sea, glass and weather are lit by
    bool local_lights = false;  // some local light can light a visible point (prepareFeatures)
};

FrameReport FrameRenderer::render(const Settings& input, const ViewParams& view, double time_s,
                                  const FrameRequest& request) {
    Settings at_time;
    const Settings& s = settingsAt(input, view, time_s, at_time);
    Frame f = beginFrame(s, view, time_s, request);
    FrameGraph graph;
    FrameReport report;
    SceneTargets scene = addClearPass(graph, f.rc, f.terrain);
    f.local_lights = prepareFeatures(f, report);
    const Casters casters = addCullPasses(graph, f, request, report);
    const Shadows shadows = addShadowPasses(graph, f, casters, request, report);
    addGeometryPasses(graph, f, casters, scene, report);
    addLightingPasses(graph, f, shadows, scene, request);
    addSkyAndTransparentPasses(graph, f, casters, shadows, scene, request, report);
    addTemporalPasses(graph, f, casters, scene, request, report);
    addSceneReadbacks(graph, f, scene, request);
    const TextureHandle display = addPostAndDebugPasses(graph, f, scene, shadows, request);
    addOutputPasses(graph, f.rc, scene, display, request);
    execute(graph, request, report);
    reportAfterFrame(f, report);
    return report;
}

const Settings& FrameRenderer::settingsAt(const Settings& input, const ViewParams& view, double time_s,
                                          Settings& at_time) {
    // Pre-exposure (sky/night_light.h): every light of the frame scaled so that a night's radiances
    // stay inside the half-float target. The sky's lights all scale with sun_illuminance; the local
    // lights take the factor at upload (LocalLights::prepare) and auto exposure divides it out.
    // The day/night cycle ([sky] time_scale) first: the sky of this scene time.
    const SkySettings sky = skyAtTime(input.sky, time_s);
    pre_exposure_ = sky.enabled ? preExposure(sky_lighting_.get(sky, view.position).upLux(sky.sun_illuminance)) : 1.0;
    if (pre_exposure_ == 1.0 && sky.time_of_day_h == input.sky.time_of_day_h) return input;
    at_time = input;
    at_time.sky = sky;
    at_time.sky.sun_illuminance = float(double(sky.sun_illuminance) * pre_exposure_);
    return at_time;
}

FrameRenderer::Frame FrameRenderer::beginFrame(const Settings& s, const ViewParams& view, double time_s,
                                               const FrameRequest& request) {
    // A camera cut (or time running backwards: a new run) rejects every history this frame.
    const bool cut = !has_last_view_ || time_s < last_time_s_ ||
                     cameraCut(last_view_, view, s.taa.cut_distance_m, s.taa.cut_angle_deg);
    const ViewParams previous_view = cut ? view : last_view_;
    const double motion_dt_s = cut ? 0.0 : time_s - last_time_s_;
    if (cut && sun_shadows_) sun_shadows_->forgetKept();  // a kept cascade is history too
    last_view_ = view;
    last_time_s_ = time_s;
    has_last_view_ = true;
    const bool taa = s.taa.enabled && s.postfx.enabled;
    if (!taa) taa_.release(device_);  // off: no history kept
    // A frame without history (the first after a reset or a cut) is not jittered: nothing
    // would average its offset out, and it matches an image rendered without TAA.
    // The index comes from the frame's place in its sequence when the caller knows it (a capture's
    // path frame), so the jitter does not depend on how many frames this run rendered before;
    // 65,536 is a whole number of jitter cycles (8) and keeps the index exact in a float uniform.
    constexpr std::int64_t kIndexPeriod = 65536;
    sequence_index_ = request.sequence_frame
                          ? std::uint64_t(((*request.sequence_frame % kIndexPeriod) + kIndexPeriod) % kIndexPeriod)
                          : temporal_index_ % kIndexPeriod;
    const glm::dvec2 jitter = taa && !cut ? TemporalAA::jitterPx(sequence_index_) : glm::dvec2(0.0);
    ++temporal_index_;
    const SkyLighting sky_light = sky_lighting_.get(s.sky, view.position);
    return Frame{s,
                 view,
                 time_s,
                 context(view, s, time_s, jitter, taa || request.animate_screen_noise ? std::uint32_t(sequence_index_) : 0u),
                 cut,
                 previous_view,
                 motion_dt_s,
                 taa,
                 s.terrain.enabled && bool(terrain_),
                 s.debug.view == DebugView::Shadow,
                 s.sky.enabled && cloudsActive(s.clouds),
                 sky_light,
                 sunAndSky(sky_light, s.sky)};
}

bool FrameRenderer::prepareFeatures(const Frame& f, FrameReport& report) {
    const Settings& s = f.s;
    // Local lights first: the shadowed spot and point lights' views widen the terrain selection.
    const bool local_lights = f.terrain && !f.shadow_view && prepareLocalLights(f.rc, s, report);
    if (!f.terrain) local_lights_.release();
    if (!(local_lights && prepareSpotShadows(f.rc, s))) spot_shadows_.release();
    if (!(local_lights && preparePointShadows(f.rc, s))) point_shadows_.release();
    if (f.clouds)
        report.counters["clouds.layers"] = double(clouds_.use().prepare(f.rc, s.clouds, s.sky, f.sky_light.sky_irradiance_up));
    else
        clouds_.release(device_);
    return local_lights;
}

FrameRenderer::Casters FrameRenderer::addCullPasses(FrameGraph& graph, const Frame& f, const FrameRequest& request,
                                                    FrameReport& report) {
    const Settings& s = f.s;
    const RenderContext& rc = f.rc;
    Casters c;
    // Grass is culled first: the shadow passes draw the same blades.
    if (f.terrain && s.grass.enabled) {
        Grass& grass = grass_.use();
        grass.setWetness(weatherWetness(s.weather));
        const bool reach = grassInReach(*terrain_, s.terrain, s.grass, f.view.position);  // else nothing to draw
        // The blades' earlier bend only where motion vectors may run (a superset of addTemporalPasses').
        const bool vectors = f.taa || request.velocity || (s.postfx.enabled && s.motion_blur.enabled);
        if (reach)
            c.blades = grass.addCullPass(graph, rc, *terrain_, s.terrain, s.grass, counters_, request.count_grass,
                                         vectors ? f.motion_dt_s : 0.0);
        report.counters["grass.considered"] = reach ? double(grass.considered()) : 0.0;
    } else {
        grass_.release();  // a disabled feature keeps nothing allocated
    }
    if (c.blades.valid() && s.grass.cast_shadows)
        c.caster = {c.blades, double(s.grass.radius_m),
                    [this, &rc, &s](const glm::mat4& m) { grass_->drawShadow(rc, s.grass, m); }, {}};
    // Objects are culled next; their cull pass follows the grass's, so the one caster handle the
    // shadow passes read orders them after both.
    if (f.terrain && objects_ && s.objects.enabled && !f.shadow_view) {
        report.counters["objects.replaced"] = placeLocalObjects(s, f.view.position) ? 1.0 : 0.0;
        report.counters["objects.local"] = objects_local_ ? 1.0 : 0.0;
        c.object_lists = objects_->addCullPass(graph, rc, s.objects, counters_, request.count_objects, c.caster.reads);
        const ObjectStats& st = objects_->stats();
        report.counters["objects.models"] = double(st.models);
        report.counters["objects.placed"] = double(st.instances);
    } else if (!f.terrain) {
        objects_next_ = {};
        objects_.release();
    }
    if (c.object_lists.valid() && s.objects.cast_shadows) {
        auto grass_draw = c.caster.draw;
        c.caster = {c.object_lists, std::max(c.caster.valid() ? c.caster.reach_m : 0.0, double(s.objects.shadow_distance_m)),
                    [this, &rc, grass_draw](const glm::mat4& m) {
                        if (grass_draw) grass_draw(m);
                        objects_->drawShadow(rc, m);
                    },
                    {}};
    }
    // The point-light cubes draw only the casters near each light: the objects within its radius,
    // the grass (all within grass radius_m of the camera) where the light reaches into it.
    if (c.caster.valid()) {
        const bool grass_casts = c.blades.valid() && s.grass.cast_shadows;
        const bool objects_cast = c.object_lists.valid() && s.objects.cast_shadows;
        c.caster.draw_near = [this, &rc, &s, grass_casts, objects_cast, position = f.view.position](
                                 const glm::dvec3& centre, double radius, std::span<const glm::mat4> faces,
                                 const std::function<void(std::size_t)>& before) {
            if (grass_casts && glm::length(centre - position) < radius + double(s.grass.radius_m))
                for (std::size_t i = 0; i < faces.size(); ++i) {
                    before(i);
                    grass_->drawShadow(rc, s.grass, faces[i]);
                }
            if (objects_cast) objects_->drawShadowNear(rc, centre, radius, faces, before);
        };
    }
    return c;
}

FrameRenderer::Shadows FrameRenderer::addShadowPasses(FrameGraph& graph, const Frame& f, const Casters& casters,
                                                      const FrameRequest& request, FrameReport& report) {
    Shadows shadows;
    if (!f.terrain) return shadows;
    terrain_caster_.bind(*terrain_, f.s.terrain);  // what the shadow passes draw of the terrain, this frame
    shadows.sun = addTerrainAndShadowPasses(graph, f.rc, f.s, request.shadow_fit_view, report, casters.caster);
    if (spot_shadows_) shadows.spot = addSpotShadowPass(graph, f.rc, f.s, casters.caster, report);
    if (point_shadows_) shadows.point = addPointShadowPass(graph, f.rc, f.s, casters.caster, report);
    return shadows;
}

void FrameRenderer::addGeometryPasses(FrameGraph& graph, const Frame& f, const Casters& casters, SceneTargets& scene,
                                      FrameReport& report) {
    const Settings& s = f.s;
    if (f.terrain) {
        // Beyond the blades the terrain's grass band takes their mean colour.
        const float fade_start = std::min(s.grass.thin_start, 0.999f) * s.grass.radius_m;
        terrain_->setFarGrass(s.grass.enabled ? glm::vec4(grassMeanAlbedo(s.grass), s.grass.far_color_strength) : glm::vec4(0.0f),
                              glm::vec2(fade_start, s.grass.radius_m));
        terrain_->setWetness(weatherWetness(s.weather));  // 0 (dry) without rain
        addTerrainPass(graph, f.rc, *terrain_, s.terrain, scene);
        const TerrainCounters& c = terrain_->counters();
        report.counters["terrain.triangles"] = double(c.triangles);
        report.counters["terrain.nodes"] = double(c.nodes);
        report.counters["terrain.draws"] = double(c.draws);
        // Quadrants drawn with each material tier (terrain.glsl MATERIAL_TIER): near, mid, far.
        report.counters["terrain.tier_near"] = double(c.tier_instances[0]);
        report.counters["terrain.tier_mid"] = double(c.tier_instances[1]);
        report.counters["terrain.tier_far"] = double(c.tier_instances[2]);
        // Grid triangles drawn as tessellation patches ([terrain.tessellation]; absent when off): in
        // the view, and in the shadow passes (sun cascades, spot tiles, point cube faces) together.
        if (s.terrain.tessellation.enabled) {
            report.counters["terrain.tess_patches"] = double(c.tess_patches);
            report.counters["terrain.tess_shadow_patches"] = double(c.tess_shadow_patches);
        }
        report.counters["terrain.select_ms"] = c.select_ms;
        // [terrain.stream] (absent when off): pool pages holding a tile, tiles wanted but missing
        // (queued), uploaded and evicted this frame, nodes drawn from a coarser tile, and the
        // largest screen error (px) that adds.
        if (terrain_->streamed()) {
            report.counters["terrain.stream.resident"] = double(c.stream.resident);
            report.counters["terrain.stream.requested"] = double(c.stream.requested);
            report.counters["terrain.stream.loaded"] = double(c.stream.loaded);
            report.counters["terrain.stream.evicted"] = double(c.stream.evicted);
            report.counters["terrain.stream.missing"] = double(c.stream.missing);
            report.counters["terrain.stream.missing_error_px"] = c.stream.missing_error_px;
        }
    }
    if (casters.blades.valid()) grass_->addGbufferPass(graph, f.rc, s.grass, casters.blades, scene);
    if (casters.object_lists.valid()) objects_->addGbufferPass(graph, f.rc, s.objects, casters.object_lists, scene);
}

void FrameRenderer::addLightingPasses(FrameGraph& graph, const Frame& f, const Shadows& shadows, SceneTargets& scene,
                                      const FrameRequest& request) {
    const Settings& s = f.s;
    if (scene.albedo.valid()) {
        if (s.ssao.enabled) scene.ao = addSsaoPasses(graph, f.rc, scene, s.ssao);
        SunAndSky light = f.light;
        const glm::dvec3& sun = f.sky_light.sun_illuminance;
        if (f.clouds && s.clouds.shadows && sun.x + sun.y + sun.z > 0.0)
            scene.cloud_shadow = clouds_->addShadowPass(graph, f.rc, light.cloud_shadow_map);
        addSunLightingPass(graph, f.rc, light, scene, shadows.sun, s.debug.view);
        if (f.local_lights) {
            LightPassOptions options;
            options.count = request.count_lights;
            options.heat = s.debug.view == DebugView::Lights || request.light_heat;
            // water.surface and objects.transparent shade them forward
            options.forward = request.forward_lights || s.water.enabled || (objects_ && objects_->hasTransparent());
            options.spot_shadows = &shadows.spot;
            options.point_shadows = &shadows.point;
            local_lights_->addPasses(graph, f.rc, scene, counters_, options);
        }
    }
    // The debug grid on the lit ground, under the aerial perspective like the ground.
    if (s.debug.grid && !f.shadow_view) addGridPass(graph, f.rc, s.debug, s.sky.enabled, scene);
}

ForwardLight FrameRenderer::forwardLight(const Frame& f, const Shadows& shadows) {
    ForwardLight forward;
    forward.sun_irradiance = f.light.sun_irradiance;
    forward.sky_up = f.light.sky_up;
    forward.ground_up = f.light.ground_up;
    if (f.local_lights) {
        forward.lights_define = local_lights_->define();
        forward.bind_lights = [this] { local_lights_->bindForForward(); };
        forward.light_chunk = kLightChunk;
        forward.light_chunks = local_lights_->chunks();
    }
    if (shadows.sun.valid())
        forward.sun_shadow = {shadows.sun.map, [sun = shadows.sun](GLuint map) { sun.bind(map); }, &SunShadowInput::unbind};
    if (shadows.spot.valid())
        forward.spot_shadows = {shadows.spot.atlas, [spot = shadows.spot](GLuint map) { spot.bind(map); },
                                &SpotShadowInput::unbind};
    if (shadows.point.valid())
        forward.point_shadows = {shadows.point.cubes, [point = shadows.point](GLuint map) { point.bind(map); },
                                 &PointShadowInput::unbind};
    return forward;
}

void FrameRenderer::addSkyAndTransparentPasses(FrameGraph& graph, const Frame& f, const Casters& casters,
                                               const Shadows& shadows, SceneTargets& scene, const FrameRequest& request,
                                               FrameReport& report) {
    const Settings& s = f.s;
    const RenderContext& rc = f.rc;
    if (!s.sky.enabled) sky_.release();  // a disabled feature keeps nothing allocated
    else if (!f.shadow_view) sky_.use().addLutPasses(graph, rc, s.sky);
    // The sea between the lighting and the aerial perspective (which fogs it as it fogs the terrain).
    const bool water = s.water.enabled && !f.shadow_view;
    if (water) {
        const double ground = f.terrain ? terrain_->heightAt(f.view.position.x, f.view.position.z) : std::nan("");
        const float ripples = s.weather.enabled && s.weather.kind == WeatherKind::Rain ? s.weather.intensity : 0.0f;
        water_.use().prepare(s.water, f.view, f.time_s, {f.light.sun_irradiance, f.light.sky_up, f.light.ground_up},
                             sky_.get(), ground, ripples, f.motion_dt_s);
    } else if (!s.water.enabled) {
        water_.release();  // a disabled feature keeps nothing allocated
    }
    // Glass and other BLEND materials (renderer/meshes/objects_forward.cpp): the parts beyond the
    // water plane from the eye before the sea (it refracts and absorbs them with the scene it
    // copies, and the aerial perspective fogs the sea's surface in front of them), the rest after
    // the aerial perspective, each surface fogged at its own distance.
    const bool transparent = casters.object_lists.valid() && objects_->hasTransparent() && scene.albedo.valid();
    ForwardLight forward;
    if (transparent) {
        forward = forwardLight(f, shadows);
        objects_->sortTransparent(rc, s.objects, water ? double(s.water.level_m) : std::nan(""),
                                  water ? water_->waves().max_height : 0.0);
        objects_->addTransparentPass(graph, rc, forward, scene, TransparentSide::BeyondWater);
        report.counters["objects.transparent"] = double(objects_->transparentDrawn());
        report.counters["objects.transparent_beyond_water"] = double(objects_->transparentBeyondWater());
        report.counters["objects.transparent_dropped"] = double(objects_->transparentDropped());
    }
    if (water) {
        Water& sea = *water_;
        sea.addSurfacePasses(graph, rc, scene, sky_.get(), f.local_lights ? local_lights_.get() : nullptr, shadows.sun);
        const WaterStats& st = sea.stats();
        report.counters["water.vertices"] = double(st.vertices);
        report.counters["water.triangles"] = double(st.triangles);
        report.counters["water.segments"] = double(st.segments);  // of the ring grid's, those that can be in view
        report.counters["water.waves"] = double(st.waves);
        report.counters["water.underwater"] = st.underwater ? 1.0 : 0.0;
    }
    const bool sky = !f.shadow_view && s.sky.enabled;
    if (sky) sky_->addSkyPass(graph, rc, scene);
    if (sky) sky_->addAerialPerspective(graph, rc, s.sky, scene);
    // The glass after the aerial perspective, fogging itself with its volume; without one (aerial
    // perspective off, or a camera in space, where sky.aerial marches each pixel) before it, as
    // an opaque surface (renderer/meshes/objects.h addTransparentPass).
    const AerialVolume fog = sky ? sky_->frameAerialVolume() : AerialVolume{};
    if (transparent && !fog.valid()) {
        objects_->addTransparentPass(graph, rc, forward, scene, TransparentSide::EyeSide);
        report.counters["objects.transparent_fogged"] = 0.0;
    }
    // The lamps' glow over the fogged scene, under the glass (which blends over what is behind it).
    addLampGlowPass(graph, f, scene, report);
    // The clouds stop at the depth they find. Over the glass when no cloud can be between it and
    // the eye (both below the lowest layer's base; the planet's curve lifts a point d away by at
    // most d^2 / 2R): the clouds behind a pane are then seen through it. Otherwise under it (the
    // clouds stop at the pane: those behind it are not seen through it).
    const double curve_m = double(s.objects.max_distance_m) * double(s.objects.max_distance_m) /
                           (2.0 * double(s.sky.planet_radius_km) * 1e3);
    const bool clouds_behind_glass = transparent && fog.valid() &&
                                     std::max(f.view.position.y, objects_->transparentTop() + curve_m) < cloudsLowestBaseM(s.clouds);
    auto addGlass = [&] {
        objects_->addTransparentPass(graph, rc, forward, scene, TransparentSide::EyeSide, fog);
        report.counters["objects.transparent_fogged"] = 1.0;
    };
    if (transparent && fog.valid() && !clouds_behind_glass) addGlass();
    if (sky && f.clouds) clouds_->addShellPass(graph, rc, *sky_, scene, f.cut);
    if (clouds_behind_glass) addGlass();
    if (water && water_->stats().near_surface) water_->addUnderwaterPass(graph, rc, scene);
    // Rain or snow over everything opaque and the sky; off: no object, no pass, dry terrain.
    if (s.weather.enabled && !f.shadow_view) {
        Weather& weather = weather_.use();
        weather.addPasses(graph, rc, s.weather, s.clouds, f.light, f.terrain ? terrain_.get() : nullptr, s.terrain, scene,
                          counters_, request.count_weather);
        report.counters["weather.drop_cells"] = double(weather.stats().drop_cells);
        report.counters["weather.drop_candidates"] = double(weather.stats().drop_candidates);
        report.counters["weather.splash_candidates"] = double(weather.stats().splash_candidates);
    } else {
        weather_.release();
    }
}

void FrameRenderer::addLampGlowPass(FrameGraph& graph, const Frame& f, SceneTargets& scene, FrameReport& report) {
    // The lamps' glow in fog over the fogged scene (renderer/lighting/lamp_glow.h): the lights of
    // this frame (prepareFeatures animated them), where the air around them is dense enough.
    const Settings& s = f.s;
    const bool wanted = s.sky.enabled && s.lights.glow && s.lights.glow_max_lights > 0 && f.terrain && !f.shadow_view &&
                        local_lights_ && scene.depth.valid();
    if (!wanted || !lamp_glow_.use().prepare(local_lights_->lights(), s.lights, s.sky, f.view, f.rc.matrices, pre_exposure_)) {
        lamp_glow_.release();
        return;
    }
    lamp_glow_->addPass(graph, f.rc, scene);
    report.counters["lights.glow"] = double(lamp_glow_->stats().glowing);
    report.counters["lights.glow_dropped"] = double(lamp_glow_->stats().dropped);
}

void FrameRenderer::addTemporalPasses(FrameGraph& graph, const Frame& f, const Casters& casters, SceneTargets& scene,
                                      const FrameRequest& request, FrameReport& report) {
    // The frame's motion vectors from the camera's motion since the previous frame (none on a cut).
    // Motion blur scales the same vectors by its shutter (the graph culls them when it adds no pass).
    const bool motion_blur = f.s.postfx.enabled && f.s.motion_blur.enabled &&
                             std::find(f.s.postfx.order.begin(), f.s.postfx.order.end(), PostEffect::MotionBlur) !=
                                 f.s.postfx.order.end();
    TextureHandle velocity;
    if ((f.taa || request.velocity || motion_blur) && scene.depth.valid())
        velocity = addVelocityPass(graph, f.rc, scene.depth, f.previous_view);
    // The sea's waves, the grass in the wind and the falling drops move on their own: their
    // motion replaces the camera's where they are seen.
    if (velocity.valid() && f.s.water.enabled && !f.shadow_view && water_.get() && !f.cut)
        velocity = water_->addVelocityPass(graph, f.rc, scene.depth, velocity,
                                           previousClipFromRelative(f.previous_view, f.view));
    if (velocity.valid() && casters.blades.valid() && !f.shadow_view && !f.cut)
        velocity = grass_->addVelocityPass(graph, f.rc, f.s.grass, casters.blades, scene.depth, velocity,
                                           previousClipFromRelative(f.previous_view, f.view));
    if (velocity.valid() && weather_.get() && !f.shadow_view && !f.cut)
        velocity = weather_->addVelocityPass(graph, f.rc, scene.depth, velocity, previousClipFromRelative(f.previous_view, f.view));
    scene.velocity = velocity;
    if (request.velocity && velocity.valid())
        addReadbackPass(graph, "temporal.velocity_readback", velocity, GL_FLOAT, *request.velocity);
    if (f.taa) {
        scene.hdr = taa_.use().addPass(graph, f.rc, scene.hdr, scene.depth, velocity, f.s.taa, f.cut);
        report.counters["postfx.taa.history_frames"] = double(taa_->historyFrames());
    }
    if (f.clouds) {
        report.counters["clouds.history_frames"] = double(clouds_->historyFrames());
        report.counters["clouds.marched_pixels"] = double(clouds_->marchedPixels());  // of the cloud target, this frame
    }
    report.counters["temporal.cut"] = f.cut ? 1.0 : 0.0;
}

void FrameRenderer::addSceneReadbacks(FrameGraph& graph, const Frame& f, const SceneTargets& scene,
                                      const FrameRequest& request) {
    if (request.count_nonfinite) addNonfiniteCountPass(graph, f.rc, scene.hdr, counters_);
    if (request.light_heat && scene.light_heat.valid())
        addReadbackPass(graph, "lights.heat_readback", scene.light_heat, GL_FLOAT, *request.light_heat);
    if (request.depth && scene.depth.valid())
        addReadbackPass(graph, "capture.depth_readback", scene.depth, GL_FLOAT, *request.depth, GL_DEPTH_COMPONENT);
}

TextureHandle FrameRenderer::addPostAndDebugPasses(FrameGraph& graph, const Frame& f, const SceneTargets& scene,
                                                   const Shadows& shadows, const FrameRequest& request) {
    const Settings& s = f.s;
    const bool shown = request.capture_ldr || request.present;  // else the graph culls the chain
    const TextureHandle display = postfx_.addPasses(graph, f.rc, scene.hdr, s, scene.depth, shown, scene.velocity);
    switch (s.debug.view) {
        case DebugView::Final:
        case DebugView::Cascades:  // the final image, tinted by lighting.sun
            return display;
        case DebugView::ShadowMap:
            return addShadowMapViewPass(graph, f.rc, shadows.sun, sun_shadows_ ? int(sun_shadows_->cascades().size()) : 0);
        case DebugView::SpotAtlas:
            return addSpotAtlasViewPass(graph, f.rc, shadows.spot, spot_shadows_ ? spot_shadows_->tilesPerSide() : 0);
        case DebugView::PointShadows:
            return addPointShadowViewPass(graph, f.rc, shadows.point, point_shadows_ ? point_shadows_->cubes() : 0);
        default:
            return addDebugViewPass(graph, f.rc, s.debug, scene);
    }
}

void FrameRenderer::addOutputPasses(FrameGraph& graph, const RenderContext& rc, const SceneTargets& scene,
                                    TextureHandle display, const FrameRequest& request) {
    if (request.capture_ldr) addReadbackPass(graph, "capture.readback", display, GL_UNSIGNED_BYTE, *request.capture_ldr);
    if (request.capture_hdr)
        addReadbackPass(graph, request.capture_ldr ? "capture.readback_hdr" : "capture.readback", scene.hdr, GL_HALF_FLOAT,
                        *request.capture_hdr);
    if (request.present) addPresentPass(graph, rc, display);
}

void FrameRenderer::execute(FrameGraph& graph, const FrameRequest& request, FrameReport& report) {
    graph.compile();
    timers_.beginFrame(frame_);
    graph.execute(pool_, &timers_);
    timers_.endFrame();
    counters_.endFrame();
    pool_.endFrame();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    ++frame_;
    if (request.graph_dot) *request.graph_dot = graph.dot();
    report.executed = graph.executedPasses();
    report.culled = graph.culledPasses();
}

template <class F>
void FrameRenderer::forEachFeature(F&& f) const {
    f(terrain_), f(grass_), f(sky_), f(clouds_), f(local_lights_), f(lamp_glow_), f(sun_shadows_), f(spot_shadows_),
        f(point_shadows_), f(water_), f(objects_), f(weather_), f(taa_);
}

void FrameRenderer::reportAfterFrame(const Frame& f, FrameReport& report) const {
    // GPU memory held after the frame, per feature (only for features that exist this frame).
    forEachFeature([&report](const auto& slot) {
        if (slot && slot.memoryCounter()) report.counters[slot.memoryCounter()] = double(slot.memoryBytes());
    });
    if (const std::size_t postfx = postfx_.memoryBytes() + taa_.memoryBytes(); postfx > 0)
        report.counters["postfx.memory_bytes"] = double(postfx);
    report.counters["gpu.transient_bytes"] = double(pool_.bytes());
    report.counters["gpu.memory_bytes"] = double(gpuMemoryBytes());
    // Programs built so far (each variant once, on first use unless compilePrograms() ran) and
    // the requests outside allPrograms() (0 unless a variant struct misses a reachable variant).
    report.counters["shaders.compiled"] = double(shaders_.compiled());
    report.counters["shaders.unlisted"] = double(shaders_.unlistedRequests().size());
    const SkySettings& sky = f.s.sky;
    report.counters["sky.pre_exposure"] = pre_exposure_;
    if (f.s.exposure.enabled && f.s.exposure.mode == ExposureMode::Camera)
        report.counters["postfx.exposure.ev100"] = cameraEv100(f.s);
    if (f.s.lens_flare.enabled) report.counters["postfx.lens_flare.sun_visibility"] = f.rc.sun_visibility;
    if (sky.sun_mode == SunMode::Time) report.counters["sky.time_of_day_h"] = sky.time_of_day_h;
    report.counters["sky.sun_elevation_deg"] = glm::degrees(std::asin(std::clamp(sunDirection(sky).y, -1.0, 1.0)));
    report.counters["sky.lux"] = f.sky_light.upLux(sky.sun_illuminance);  // physical: the scaled units cancel
    if (sky.enabled && sky_.get()) {  // what the sky pass's variant draws (docs/atmosphere.md)
        const SkyShows& shows = sky_.get()->frameShows();
        report.counters["sky.shows_sun_disk"] = shows.sun_disk ? 1.0 : 0.0;
        report.counters["sky.shows_moon"] = shows.moon ? 1.0 : 0.0;
        report.counters["sky.shows_stars"] = shows.stars ? 1.0 : 0.0;
    }
}

std::size_t FrameRenderer::gpuMemoryBytes() const {
    std::size_t bytes = pool_.bytes() + std::size_t(frame_uniforms_.size()) + counters_.memoryBytes() +
                        postfx_.memoryBytes() + blue_noise_.bytes();
    forEachFeature([&bytes](const auto& slot) { bytes += slot.memoryBytes(); });
    return bytes;
}

}  // namespace vista
