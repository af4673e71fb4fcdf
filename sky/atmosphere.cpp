// GPU atmosphere LUTs and the sky pass. The transmittance and multiple-scattering LUTs depend
// only on the atmosphere, so they live here across frames and are rebuilt when its settings
// change; the sky-view LUT also depends on the sun and the camera's altitude and is rebuilt
// when either crosses a grid step. A frame that rebuilds nothing adds "sky.aerial_volume" and
// "sky.aerial" (when it has depth and aerial perspective is on) and "sky.atmosphere".
#include "sky/atmosphere.h"
#include "sky/day_cycle.h"
#include "sky/night_light.h"

#include "renderer/bindings.h"
#include "renderer/camera.h"
#include "sky/atmosphere_reference.h"
#include "sky/atmosphere_spectral.h"
#include "sky/shaders/sky_bindings.glsl"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vista {

namespace {

constexpr int kMsPolarNodes = 8;    // per polar range, as the reference's default
constexpr int kMsAzimuthNodes = 6;  // over [0, pi]

gl::Texture makeLut(int width, int height, GLenum format, const char* name) {
    gl::Texture t = gl::Texture::create2D(width, height, format, 1, name);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

double cameraAltitudeM(const RenderContext& rc) { return std::max(rc.view.position.y, 0.0); }

// The sky-view LUT is built for the camera's altitude on a grid (1 m near the ground, 0.1% of
// the altitude higher up) and the sun's elevation on a grid of rebuild_sun_deg: it is rebuilt
// when either crosses a grid line, and a frame never depends on the frames drawn before it.
double lutAltitudeM(double altitude_m) {
    return 1000.0 * std::expm1(std::round(std::log1p(altitude_m / 1000.0) / 1e-3) * 1e-3);
}
double lutSunElevation(const glm::dvec3& sun, const SkySettings& sky) {
    const double elevation = std::asin(std::clamp(sun.y, -1.0, 1.0));
    const double step = glm::radians(double(sky.rebuild_sun_deg));
    if (!(step > 0.0)) return elevation;
    return std::clamp(std::round(elevation / step) * step, -0.5 * std::numbers::pi, 0.5 * std::numbers::pi);
}

}  // namespace

// std140 mirror of AtmosphereUniforms in sky/shaders/atmosphere.glsl.
struct SkyAtmosphere::Uniforms {
    glm::vec4 radii, rayleigh, mie, mie_ext, ozone, misc, albedo, solar, sun, horizon, fog, aerial, moon, night;
    glm::vec4 colour[3];
    glm::vec4 celestial[3];
    glm::ivec4 sizes, sizes2;
    glm::vec4 gl[16];
    glm::ivec4 gl_count;
    glm::vec4 sun_depth[SKY_SUNLIGHT_WAVELENGTHS], sun_rgb[SKY_SUNLIGHT_WAVELENGTHS];
};
static_assert(SKY_SUNLIGHT_WAVELENGTHS == kSunlightWavelengths, "sky_bindings.glsl and atmosphere_spectral.h disagree");

glm::dvec3 sunDirection(const SkySettings& sky) {
    if (sky.sun_mode == SunMode::Time) return sunPosition(sky.latitude_deg, sky.day_of_year, sky.time_of_day_h).direction;
    return glm::normalize(directionFromAngles(sky.sun_azimuth_deg, sky.sun_elevation_deg));
}

namespace {

constexpr double kObliquity = 23.44 * std::numbers::pi / 180.0;

// The sun's ecliptic longitude (mean, 0 at the March equinox) and right ascension at a day.
double solarLongitude(double day) { return 2.0 * std::numbers::pi * (day - 80.0) / 365.2422; }
double rightAscension(double longitude) {
    return std::atan2(std::cos(kObliquity) * std::sin(longitude), std::cos(longitude));
}

// Columns: the celestial x (vernal equinox), y and z (pole) axes in vista's world (east +x, up
// +y, north -z) at latitude phi and local sidereal time lst. A direction of hour angle H and
// declination d is cos d (-sin H east + cos H (cos phi up - sin phi north)) + sin d pole.
glm::dmat3 worldFromCelestial(double phi, double lst) {
    const glm::dvec3 east(1.0, 0.0, 0.0), up(0.0, 1.0, 0.0), north(0.0, 0.0, -1.0);
    const glm::dvec3 meridian = std::cos(phi) * up - std::sin(phi) * north, west = -east;
    const glm::dvec3 pole = std::cos(phi) * north + std::sin(phi) * up;
    // H = lst - alpha: cos H and sin H expand into cos/sin alpha terms.
    const glm::dvec3 x = std::cos(lst) * meridian + std::sin(lst) * west;
    const glm::dvec3 y = std::sin(lst) * meridian - std::cos(lst) * west;
    return glm::dmat3(x, y, pole);
}

double localSiderealTime(const SkySettings& sky) {
    if (sky.sun_mode != SunMode::Time) return 0.0;
    const double day = double(sky.day_of_year) + (double(sky.time_of_day_h) - 12.0) / 24.0;
    const double hour_angle = (double(sky.time_of_day_h) - 12.0) * std::numbers::pi / 12.0;
    return hour_angle + rightAscension(solarLongitude(day));
}

}  // namespace

glm::dvec3 moonDirection(const SkySettings& sky) {
    if (sky.sun_mode != SunMode::Time) return glm::normalize(directionFromAngles(sky.moon_azimuth_deg, sky.moon_elevation_deg));
    const double day = double(sky.day_of_year) + (double(sky.time_of_day_h) - 12.0) / 24.0;
    const double longitude = solarLongitude(day) + 2.0 * std::numbers::pi * double(sky.moon_age_days) / kSynodicMonthDays;
    const double decl = std::asin(std::sin(kObliquity) * std::sin(longitude)), ra = rightAscension(longitude);
    const glm::dvec3 c(std::cos(decl) * std::cos(ra), std::cos(decl) * std::sin(ra), std::sin(decl));
    return glm::normalize(worldFromCelestial(glm::radians(double(sky.latitude_deg)), localSiderealTime(sky)) * c);
}

glm::dmat3 celestialFromWorld(const SkySettings& sky) {
    return glm::transpose(worldFromCelestial(glm::radians(double(sky.latitude_deg)), localSiderealTime(sky)));
}

AtmosphereParams atmosphereParams(const SkySettings& s) {
    AtmosphereParams p;
    p.bottom_radius = double(s.planet_radius_km) * 1e3;
    p.top_radius = p.bottom_radius + double(s.atmosphere_height_km) * 1e3;
    p.rayleigh_scattering = glm::dvec3(s.rayleigh_scattering) * 1e-6;
    p.rayleigh_scale_height = double(s.rayleigh_scale_height_km) * 1e3;
    p.mie_scattering = glm::dvec3(double(s.mie_scattering) * 1e-6);
    p.mie_extinction = glm::dvec3((double(s.mie_scattering) + double(s.mie_absorption)) * 1e-6);
    p.mie_scale_height = double(s.mie_scale_height_km) * 1e3;
    p.mie_g = s.mie_g;
    p.mie_phase = s.mie_phase == SkyMiePhase::HenyeyGreenstein ? MiePhase::HenyeyGreenstein : MiePhase::CornetteShanks;
    p.ozone_absorption = glm::dvec3(s.ozone_absorption) * 1e-6;
    p.ozone_center_altitude = double(s.ozone_center_km) * 1e3;
    p.ozone_half_width = double(s.ozone_half_width_km) * 1e3;
    p.ground_albedo = glm::dvec3(s.ground_albedo);
    p.solar_irradiance = glm::dvec3(1.0);
    p.sun_angular_radius = glm::radians(double(s.sun_angular_radius_deg));
    return p;
}

ProgramList skyPrograms() {
    ProgramList list{{"sky/shaders/transmittance_lut.glsl", {}}, {"sky/shaders/multiscatter_lut.glsl", {}},
                     {"sky/shaders/sky_view_lut.glsl", {}},      {"sky/shaders/aerial_volume.glsl", {}},
                     {"sky/shaders/aerial.glsl", {}}, {"sky/shaders/aerial.glsl", {"AERIAL_FROM_SPACE"}}};
    // The sky pass: each combination of what a view shows, for each part of the screen.
    for (int bits = 0; bits < 8; ++bits)
        for (const auto& [ground, clip] : {std::pair{false, 0}, std::pair{true, 0}, std::pair{false, 1}, std::pair{true, -1}})
            list.push_back({"sky/shaders/sky.glsl", skyDefines({(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0}, ground, clip)});
    return list;
}

SkyShows skyShows(const ViewParams& view, const ViewMatrices& m, const SkySettings& sky, const glm::dvec3& sun,
                  const glm::dvec3& moon, double altitude_m) {
    const double aspect = double(std::max(view.width, 1)) / double(std::max(view.height, 1));
    const double tan_half = std::tan(glm::radians(view.fov_deg) * 0.5);
    const double reach = std::atan(tan_half * std::sqrt(1.0 + aspect * aspect)) + glm::radians(1.0);
    auto inView = [&](const glm::dvec3& dir, double radius) {
        return std::acos(std::clamp(glm::dot(dir, m.forward), -1.0, 1.0)) <= reach + radius;
    };
    const double sun_radius = glm::radians(double(sky.sun_angular_radius_deg));
    const double moon_radius = glm::radians(kMoonAngularRadiusDeg);
    SkyShows shows;
    shows.sun_disk = inView(sun, sun_radius);
    shows.moon = sky.moon && inView(moon, moon_radius);
    const bool eclipse = sky.moon && std::acos(std::clamp(glm::dot(sun, moon), -1.0, 1.0)) <
                                         sun_radius + moon_radius + glm::radians(1.0);
    shows.stars = sky.stars && (sun.y < 0.0 || altitude_m > 20000.0 || eclipse);
    return shows;
}

std::vector<std::string> skyDefines(const SkyShows& shows, bool ground, int clip) {
    std::vector<std::string> d;
    if (!ground) d.push_back("SKY_NO_GROUND");
    if (clip != 0) d.push_back("SKY_CLIP=" + std::to_string(clip));
    if (shows.sun_disk) d.push_back("SKY_SUN_DISK");
    if (shows.moon) d.push_back("SKY_MOON");
    if (shows.stars) d.push_back("SKY_STARS");
    return d;
}

SkyAtmosphere::SkyAtmosphere()
    : uniforms_(gl::Buffer::create(sizeof(Uniforms), nullptr, GL_DYNAMIC_STORAGE_BIT, "sky atmosphere uniforms")),
      frame_uniforms_(gl::Buffer::create(sizeof(Uniforms), nullptr, GL_DYNAMIC_STORAGE_BIT, "sky frame uniforms")) {}

SkyAtmosphere::~SkyAtmosphere() = default;

void SkyAtmosphere::bindFrameUniforms() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, SKY_BINDING_ATMOSPHERE, frame_uniforms_.id());
}

void SkyAtmosphere::invalidate() {
    atmosphere_valid_ = false;
    view_valid_ = false;
}

// The camera's radius, altitude and horizon; the horizon in double, as float loses the few metres
// between the camera and the ground.
void SkyAtmosphere::setCamera(Uniforms& u, const AtmosphereParams& p, double altitude_m) {
    const double r = p.bottom_radius + altitude_m;
    const double mu_h = -std::sqrt(altitude_m * (2.0 * p.bottom_radius + altitude_m)) / r;
    u.radii.z = float(r * 1e-3);
    u.radii.w = float(altitude_m * 1e-3);
    u.horizon = glm::vec4(float(mu_h), float(std::sqrt(1.0 - mu_h * mu_h)), float(std::asin(mu_h)), 0.0f);
}

void SkyAtmosphere::upload(const Uniforms& u) {
    static_assert(sizeof(Uniforms) == 624 + 2 * 16 * SKY_SUNLIGHT_WAVELENGTHS, "Uniforms must match the std140 block");
    glNamedBufferSubData(uniforms_.id(), 0, sizeof u, &u);
    glBindBufferBase(GL_UNIFORM_BUFFER, SKY_BINDING_ATMOSPHERE, uniforms_.id());
}

void SkyAtmosphere::addPasses(FrameGraph& graph, const RenderContext& rc, const SkySettings& sky, SceneTargets& targets) {
    addLutPasses(graph, rc, sky);
    addScenePasses(graph, rc, sky, targets);
}

void SkyAtmosphere::addLutPasses(FrameGraph& graph, const RenderContext& rc, const SkySettings& sky) {
    const AtmosphereParams p = atmosphereParams(sky);
    const glm::dvec3 sun = sunDirection(sky);
    const double altitude_m = cameraAltitudeM(rc);
    const bool in_space = p.bottom_radius + altitude_m >= p.top_radius;

    Uniforms u{};
    const float km = 1e-3f, per_km = 1e3f;
    u.radii = glm::vec4(float(p.bottom_radius) * km, float(p.top_radius) * km, 0.0f, 0.0f);
    u.rayleigh = glm::vec4(glm::vec3(p.rayleigh_scattering) * per_km, float(p.rayleigh_scale_height) * km);
    u.mie = glm::vec4(glm::vec3(p.mie_scattering) * per_km, float(p.mie_scale_height) * km);
    u.mie_ext = glm::vec4(glm::vec3(p.mie_extinction) * per_km, float(p.mie_g));
    u.ozone = glm::vec4(glm::vec3(p.ozone_absorption) * per_km, float(p.ozone_center_altitude) * km);
    u.misc = glm::vec4(float(p.ozone_half_width) * km, p.mie_phase == MiePhase::HenyeyGreenstein ? 1.0f : 0.0f,
                       float(p.sun_angular_radius), sky.sun_limb_darkening);
    u.albedo = glm::vec4(glm::vec3(p.ground_albedo), 0.0f);
    u.solar = glm::vec4(glm::vec3(p.solar_irradiance) * sky.sun_illuminance, sky.sun_illuminance);
    u.sun = glm::vec4(glm::vec3(sun), 0.0f);
    setCamera(u, p, altitude_m);
    if (sky.height_fog && sky.fog_density_per_km > 0.0f)
        u.fog = glm::vec4(sky.fog_density_per_km, sky.fog_base_m * km, sky.fog_falloff_m * km, 0.0f);
    u.aerial = glm::vec4(sky.aerial_distance_km, float(sky.aerial_size), float(sky.aerial_slices), float(sky.aerial_steps));
    u.moon = glm::vec4(glm::vec3(moonDirection(sky)), float(glm::radians(kMoonAngularRadiusDeg)));
    // w: the radiance of starlight and airglow, a uniform sky giving kNightFloorLux (E = pi L).
    u.night = glm::vec4(sky.stars ? sky.stars_intensity * sky.sun_illuminance : 0.0f, float(kMoonAlbedo),
                        sky.moon ? 1.0f : 0.0f,
                        float(kNightFloorLux / kSolarIlluminanceLux / std::numbers::pi) * sky.sun_illuminance);
    const glm::dmat3 colour = skyColourMatrix(sun.y) * double(sky.sun_illuminance);
    for (int i = 0; i < 3; ++i) u.colour[i] = glm::vec4(glm::vec3(colour[i]), 0.0f);
    const SunlightConversion sunlight = sunlightConversion(p);
    for (int i = 0; i < kSunlightWavelengths; ++i) {
        u.sun_depth[i] = glm::vec4(glm::vec3(sunlight.depth[std::size_t(i)]), 0.0f);
        u.sun_rgb[i] = glm::vec4(glm::vec3(sunlight.rgb[std::size_t(i)] * double(sky.sun_illuminance)), 0.0f);
    }
    const glm::dmat3 celestial = glm::transpose(celestialFromWorld(sky));  // rows of celestialFromWorld
    for (int i = 0; i < 3; ++i) u.celestial[i] = glm::vec4(glm::vec3(celestial[i]), 0.0f);
    u.sizes = {sky.transmittance_width, sky.transmittance_height, sky.multiscatter_size, sky.sky_view_width};
    u.sizes2 = {sky.sky_view_height, sky.transmittance_steps, sky.multiscatter_steps, sky.sky_view_steps};
    std::vector<double> gx, gw;
    gaussLegendre01(kMsPolarNodes, gx, gw);
    for (int i = 0; i < kMsPolarNodes; ++i) u.gl[i] = glm::vec4(float(gx[std::size_t(i)]), float(gw[std::size_t(i)]), 0, 0);
    u.gl_count = {kMsPolarNodes, kMsAzimuthNodes, 0, 0};

    // What each LUT depends on; a change rebuilds it (and those that read it).
    std::vector<float> atmosphere_key(reinterpret_cast<const float*>(&u.radii), reinterpret_cast<const float*>(&u.radii) + 2);
    for (const glm::vec4* v : {&u.rayleigh, &u.mie, &u.mie_ext, &u.ozone, &u.albedo})
        atmosphere_key.insert(atmosphere_key.end(), {v->x, v->y, v->z, v->w});
    atmosphere_key.insert(atmosphere_key.end(), {u.misc.x, u.misc.y});
    for (int v : {u.sizes.x, u.sizes.y, u.sizes.z, u.sizes2.y, u.sizes2.z}) atmosphere_key.push_back(float(v));
    std::vector<float> view_key = {float(u.sizes.w), float(u.sizes2.x), float(u.sizes2.w), u.fog.x, u.fog.y, u.fog.z};

    bool rebuild_atmosphere = !atmosphere_valid_ || atmosphere_key != atmosphere_key_;
    if (rebuild_atmosphere) {
        if (!transmittance_ || transmittance_.width() != sky.transmittance_width ||
            transmittance_.height() != sky.transmittance_height)
            transmittance_ = makeLut(sky.transmittance_width, sky.transmittance_height, GL_RGBA32F, "sky transmittance LUT");
        if (!multiscatter_ || multiscatter_.width() != sky.multiscatter_size)
            multiscatter_ = makeLut(sky.multiscatter_size, sky.multiscatter_size, GL_RGBA32F, "sky multiscatter LUT");
        atmosphere_key_ = atmosphere_key;
        atmosphere_valid_ = false;
        view_valid_ = false;
    }
    if (!sky_view_ || sky_view_.width() != sky.sky_view_width || sky_view_.height() != sky.sky_view_height) {
        sky_view_ = makeLut(sky.sky_view_width, sky.sky_view_height, GL_RGBA16F, "sky view LUT");
        view_valid_ = false;
    }
    const double lut_sun_elevation = lutSunElevation(sun, sky), lut_altitude_m = lutAltitudeM(altitude_m);
    bool rebuild_view = !in_space && (!view_valid_ || view_key != view_key_ || lut_sun_elevation != view_sun_elevation_ ||
                                      lut_altitude_m != view_altitude_m_);
    // The sky-view LUT only sees the sun's elevation (its azimuth is relative to the sun's).
    Uniforms u_view = u;
    u_view.sun = glm::vec4(float(std::cos(lut_sun_elevation)), float(std::sin(lut_sun_elevation)), 0.0f, 0.0f);
    setCamera(u_view, p, lut_altitude_m);

    TextureHandle transmittance = graph.importTexture(
        "sky.transmittance_lut", {sky.transmittance_width, sky.transmittance_height, PixelFormat::RGBA32F}, transmittance_.id());
    TextureHandle multiscatter = graph.importTexture(
        "sky.multiscatter_lut", {sky.multiscatter_size, sky.multiscatter_size, PixelFormat::RGBA32F}, multiscatter_.id());
    TextureHandle sky_view = graph.importTexture(
        "sky.view_lut", {sky.sky_view_width, sky.sky_view_height, PixelFormat::RGBA16F}, sky_view_.id());

    struct LutData {
        TextureHandle out, in0, in1;
    };
    // One compute pass writing `out` from the LUTs it reads.
    auto lutPass = [&](const char* name, const char* program, const Uniforms& pass_u, TextureHandle out,
                       TextureHandle in0, TextureHandle in1, auto on_done) {
        const LutData& d = graph.addPass<LutData>(name,
            [&](PassBuilder& b, LutData& data) {
                if (in0.valid()) data.in0 = b.read(in0);
                if (in1.valid()) data.in1 = b.read(in1);
                data.out = b.write(out);
            },
            [this, &rc, u = pass_u, program, on_done](const LutData& data, PassContext& ctx) {
                upload(u);
                glUseProgram(rc.shaders.id(program));
                if (data.in0.valid()) glBindTextureUnit(binding::kTex0, ctx.texture(data.in0));
                if (data.in1.valid()) glBindTextureUnit(binding::kTex1, ctx.texture(data.in1));
                const TextureDesc& desc = ctx.desc(data.out);
                glBindImageTexture(binding::kImageOutput, ctx.texture(data.out), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                                   glInternalFormat(desc.format));
                glDispatchCompute(GLuint((desc.width + 7) / 8), GLuint((desc.height + 7) / 8), 1);
                glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
                on_done();
            });
        return d.out;
    };
    if (rebuild_atmosphere || !atmosphere_valid_) {
        transmittance = lutPass("sky.transmittance", "sky/shaders/transmittance_lut.glsl", u, transmittance, {}, {},
                                [this] { ++stats_.transmittance_builds; });
        multiscatter = lutPass("sky.multiscatter", "sky/shaders/multiscatter_lut.glsl", u, multiscatter, transmittance, {},
                               [this] {
                                   ++stats_.multiscatter_builds;
                                   atmosphere_valid_ = true;
                               });
    }
    if (rebuild_view) {
        sky_view = lutPass("sky.view", "sky/shaders/sky_view_lut.glsl", u_view, sky_view, transmittance, multiscatter,
                           [this, lut_sun_elevation, lut_altitude_m, view_key] {
                               ++stats_.sky_view_builds;
                               view_valid_ = true;
                               view_sun_elevation_ = lut_sun_elevation;
                               view_altitude_m_ = lut_altitude_m;
                               view_key_ = view_key;
                           });
    }

    glNamedBufferSubData(frame_uniforms_.id(), 0, sizeof u, &u);
    frame_transmittance_ = transmittance;
    frame_multiscatter_ = multiscatter;
    frame_sky_view_ = sky_view;
    frame_in_space_ = in_space;
    frame_planet_ground_ = sky.planet_ground;
    frame_shows_ = skyShows(rc.view, rc.matrices, sky, sun, moonDirection(sky), altitude_m);
    frame_aerial_ = AerialVolume{};
    if (!frame_u_) frame_u_ = std::make_unique<Uniforms>();
    *frame_u_ = u;
}

void SkyAtmosphere::addScenePasses(FrameGraph& graph, const RenderContext& rc, const SkySettings& sky,
                                   SceneTargets& targets) {
    addSkyPass(graph, rc, targets);
    addAerialPerspective(graph, rc, sky, targets);
}

void SkyAtmosphere::addAerialPerspective(FrameGraph& graph, const RenderContext& rc, const SkySettings& sky,
                                         SceneTargets& targets) {
    if (sky.aerial_perspective && targets.depth.valid())
        addAerialPasses(graph, rc, *frame_u_, frame_in_space_, frame_transmittance_, frame_multiscatter_, targets);
}

void SkyAtmosphere::addSkyPass(FrameGraph& graph, const RenderContext& rc, SceneTargets& targets) {
    const Uniforms& u = *frame_u_;
    const TextureHandle transmittance = frame_transmittance_, multiscatter = frame_multiscatter_,
                        sky_view = frame_sky_view_;
    struct Data {
        TextureHandle hdr, depth, transmittance, multiscatter, sky_view;
    };
    const Data& d = graph.addPass<Data>("sky.atmosphere",
        [&](PassBuilder& b, Data& data) {
            if (targets.depth.valid()) data.depth = b.read(targets.depth);
            data.transmittance = b.read(transmittance);
            data.multiscatter = b.read(multiscatter);
            data.sky_view = b.read(sky_view);
            data.hdr = b.write(targets.hdr);
        },
        [this, &rc, u, ground = frame_planet_ground_, shows = frame_shows_](const Data& data, PassContext& ctx) {
            upload(u);
            const TextureDesc& desc = ctx.desc(data.hdr);
            GLuint depth = data.depth.valid() ? ctx.texture(data.depth) : 0;
            bindTarget(rc.device.framebuffer({ctx.texture(data.hdr)}, depth), desc.width, desc.height);
            glBindTextureUnit(binding::kTex0, ctx.texture(data.transmittance));
            glBindTextureUnit(binding::kTex1, ctx.texture(data.multiscatter));
            glBindTextureUnit(binding::kTex2, ctx.texture(data.sky_view));
            if (depth != 0) {
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_GEQUAL);  // the triangle is at depth 0: passes only where depth is 0
                glDepthMask(GL_FALSE);
            }
            if (ground) {
                // The rays pointing up never meet the ground: that part takes the variant without
                // it, the rays pointing down (drawn second, over the sliver both clips keep) the
                // variant with it; the same sky where both run.
                glEnable(GL_CLIP_DISTANCE0);
                for (int clip : {1, -1}) {
                    glUseProgram(rc.shaders.id("sky/shaders/sky.glsl", skyDefines(shows, clip < 0, clip)));
                    drawFullscreen(rc);
                }
                glDisable(GL_CLIP_DISTANCE0);
            } else {
                glUseProgram(rc.shaders.id("sky/shaders/sky.glsl", skyDefines(shows, false, 0)));
                drawFullscreen(rc);
            }
            glDisable(GL_DEPTH_TEST);
            glDepthMask(GL_TRUE);
        });
    targets.hdr = d.hdr;
}

// "sky.aerial_volume" fills the froxel volume for this frame's view, "sky.aerial" applies it to
// every pixel at finite depth (after the lighting, before the sky fills depth 0). From space
// there is no volume: "sky.aerial" marches each pixel's ray through the atmosphere.
void SkyAtmosphere::addAerialPasses(FrameGraph& graph, const RenderContext& rc, const Uniforms& u, bool in_space,
                                    TextureHandle transmittance, TextureHandle multiscatter, SceneTargets& targets) {
    struct VolumeData {
        TextureHandle transmittance, multiscatter, inscatter, aerial_transmittance;
    };
    TextureHandle inscatter, aerial_transmittance;
    if (!in_space) {
        const int size = int(u.aerial.y), slices = int(u.aerial.z);
        const TextureDesc atlas{size * slices, size, PixelFormat::RGBA16F};
        const VolumeData& v = graph.addPass<VolumeData>("sky.aerial_volume",
            [&](PassBuilder& b, VolumeData& data) {
                data.transmittance = b.read(transmittance);
                data.multiscatter = b.read(multiscatter);
                data.inscatter = b.write(b.create("sky.aerial_inscatter", atlas));
                data.aerial_transmittance = b.write(b.create("sky.aerial_transmittance", atlas));
            },
            [this, &rc, u, size](const VolumeData& data, PassContext& ctx) {
                upload(u);
                glUseProgram(rc.shaders.id("sky/shaders/aerial_volume.glsl"));
                glBindTextureUnit(binding::kTex0, ctx.texture(data.transmittance));
                glBindTextureUnit(binding::kTex1, ctx.texture(data.multiscatter));
                glBindImageTexture(binding::kImageOutput, ctx.texture(data.inscatter), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                                   GL_RGBA16F);
                glBindImageTexture(SKY_IMAGE_AERIAL_TRANSMITTANCE, ctx.texture(data.aerial_transmittance), 0, GL_FALSE,
                                   0, GL_WRITE_ONLY, GL_RGBA16F);
                glDispatchCompute(GLuint((size + 7) / 8), GLuint((size + 7) / 8), 1);
                glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
            });
        inscatter = v.inscatter;
        aerial_transmittance = v.aerial_transmittance;
        frame_aerial_ = AerialVolume{inscatter, aerial_transmittance, glm::vec4(u.aerial.x, u.aerial.y, u.aerial.z, 0.0f)};
    }

    struct Data {
        TextureHandle hdr, depth, inscatter, aerial_transmittance, transmittance, multiscatter;
    };
    const Data& d = graph.addPass<Data>("sky.aerial",
        [&](PassBuilder& b, Data& data) {
            data.depth = b.read(targets.depth);
            if (inscatter.valid()) {
                data.inscatter = b.read(inscatter);
                data.aerial_transmittance = b.read(aerial_transmittance);
            } else {
                data.transmittance = b.read(transmittance);
                data.multiscatter = b.read(multiscatter);
            }
            data.hdr = b.write(targets.hdr);
        },
        [this, &rc, u](const Data& data, PassContext& ctx) {
            upload(u);
            const TextureDesc& desc = ctx.desc(data.hdr);
            bindTarget(rc.device.framebuffer({ctx.texture(data.hdr)}), desc.width, desc.height);
            // From space there is no volume: the variant that marches each pixel's ray.
            glUseProgram(rc.shaders.id("sky/shaders/aerial.glsl", data.inscatter.valid() ? std::vector<std::string>{}
                                                                                          : std::vector<std::string>{"AERIAL_FROM_SPACE"}));
            glBindTextureUnit(binding::kTex0, ctx.texture(data.depth));
            if (data.inscatter.valid()) {
                glBindTextureUnit(binding::kTex1, ctx.texture(data.inscatter));
                glBindTextureUnit(binding::kTex2, ctx.texture(data.aerial_transmittance));
            } else {
                glBindTextureUnit(binding::kTex3, ctx.texture(data.transmittance));
                glBindTextureUnit(binding::kTex4, ctx.texture(data.multiscatter));
            }
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_SRC1_COLOR);  // hdr = in-scattering + hdr * transmittance
            drawFullscreen(rc);
            glDisable(GL_BLEND);
            // Mesa refuses multi-target draws while a dual-source factor is set, blending on or off.
            glBlendFunc(GL_ONE, GL_ZERO);
        });
    targets.hdr = d.hdr;
}

}  // namespace vista
