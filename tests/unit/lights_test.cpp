// Local lights: the windowed falloff and spot cone the shaders mirror, spot bounding spheres,
// deterministic generation volumes, animation, and the [lights] ini format.
#include "renderer/lighting/light_settings.h"
#include "renderer/lights.h"
#include "renderer/random.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <set>
#include <string>

using namespace vista;

TEST_CASE("lights: splitmix64 gives the published sequence, so generation is the same everywhere") {
    std::uint64_t state = 0;
    CHECK(splitmix64(state) == 0xE220A8397B1DCDAFull);
    CHECK(splitmix64(state) == 0x6E789E6AA1B965F4ull);
    Rng a(42), b(42);
    for (int i = 0; i < 100; ++i) {
        double u = a.uniform();
        CHECK(u == b.uniform());
        CHECK(u >= 0.0);
        CHECK(u < 1.0);
    }
}

TEST_CASE("lights: falloff is exactly 0 from the radius on, finite at 0 and non-increasing") {
    for (float r : {0.01f, 1.0f, 15.0f, 1000.0f}) {
        CHECK(falloff(r * r, r) == 0.0f);
        CHECK(falloff(r * r * 1.0001f, r) == 0.0f);
        CHECK(falloff(4.0f * r * r, r) == 0.0f);
        CHECK(falloffD(double(r) * r, r) == 0.0);
        float at0 = falloff(0.0f, r);
        CHECK(std::isfinite(at0));
        CHECK(at0 == doctest::Approx(1.0f / kFalloffEpsM2));
        float prev = at0;
        for (int i = 1; i <= 1000; ++i) {
            float d = r * float(i) / 800.0f;
            float f = falloff(d * d, r);
            CHECK(std::isfinite(f));
            CHECK(f >= 0.0f);
            CHECK(f <= prev);
            prev = f;
        }
    }
    // Inverse square well inside the radius (the window is ~1 there).
    CHECK(falloffD(1.0, 1000.0) == doctest::Approx(1.0 / (1.0 + kFalloffEpsM2)).epsilon(1e-6));
    CHECK(falloffD(100.0, 1000.0) == doctest::Approx(1.0 / (100.0 + kFalloffEpsM2)).epsilon(1e-6));
    // Zero and negative radii reach nothing, even at distance 0.
    CHECK(falloff(0.0f, 0.0f) == 0.0f);
    CHECK(falloff(1.0f, -1.0f) == 0.0f);
    Light zero;
    zero.radius_m = 0.0f;
    CHECK(!reaches(zero, zero.position));
    CHECK(attenuation(zero, zero.position) == 0.0);
}

TEST_CASE("lights: the spot cone is a smoothstep from the outer to the inner cosine") {
    SpotCone c = spotCone(20.0f, 30.0f);
    auto at = [&](double deg) { return spotFactor(c, float(std::cos(deg * 3.14159265358979 / 180.0))); };
    CHECK(at(0.0) == 1.0f);
    CHECK(at(19.9) == 1.0f);
    CHECK(at(30.0) == doctest::Approx(0.0f).epsilon(1e-4));
    CHECK(at(31.0) == 0.0f);
    CHECK(at(90.0) == 0.0f);
    CHECK(at(180.0) == 0.0f);
    double prev = 1.0;
    for (double a = 20.0; a <= 30.0; a += 0.25) {
        CHECK(at(a) <= prev + 1e-6);
        prev = at(a);
    }
    CHECK(at(25.0) > 0.2f);
    CHECK(at(25.0) < 0.8f);
    // Equal angles: a hard edge at the outer angle, no division by zero.
    SpotCone hard = spotCone(25.0f, 25.0f);
    CHECK(std::isfinite(hard.scale));
    CHECK(spotFactor(hard, float(std::cos(24.0 * 3.14159265358979 / 180.0))) == 1.0f);
    CHECK(spotFactor(hard, float(std::cos(26.0 * 3.14159265358979 / 180.0))) == 0.0f);
    // Point lights have no cone.
    CHECK(spotFactor(spotCone(Light{}), -1.0f) == 1.0f);

    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.0, 10.0, 0.0};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.radius_m = 20.0f;
    CHECK(reaches(spot, {0.0, 0.0, 0.0}));
    CHECK(!reaches(spot, {0.0, 20.0, 0.0}));  // behind
    CHECK(!reaches(spot, {10.0, 9.0, 0.0}));  // outside the cone
    CHECK(reaches(spot, spot.position));      // at the apex: on the axis
}

TEST_CASE("lights: a spot's bounding sphere holds everything it lights and is no larger than its radius") {
    Rng rng(7);
    for (int i = 0; i < 200; ++i) {
        Light l;
        l.type = LightType::Spot;
        l.position = {rng.uniform(-100, 100), rng.uniform(-100, 100), rng.uniform(-100, 100)};
        l.direction = glm::vec3(float(rng.uniform(-1, 1)), float(rng.uniform(-1, 1)), float(rng.uniform(-1, 1)) + 0.01f);
        l.radius_m = float(rng.uniform(0.5, 50));
        l.outer_deg = float(rng.uniform(1, 179));
        l.inner_deg = float(rng.uniform(0, l.outer_deg));
        Sphere s = boundingSphere(l);
        CHECK(s.radius <= double(l.radius_m) * (1.0 + 1e-12));
        for (int j = 0; j < 200; ++j) {
            glm::dvec3 p = l.position + glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * double(l.radius_m);
            if (reaches(l, p)) CHECK(glm::length(p - s.center) <= s.radius * (1.0 + 1e-9) + 1e-9);
        }
    }
}

TEST_CASE("lights: generation volumes are deterministic, counted and inside their box") {
    LightVolume v;
    v.min_m = {-100.0, 5.0, -50.0};
    v.max_m = {100.0, 15.0, 50.0};
    v.count = {10, 2, 5};
    v.radius_m = 12.0f;
    v.saturation = 0.6f;
    v.value = 0.9f;
    v.jitter = 0.5f;
    v.seed = 23;
    std::vector<Light> a, b;
    generateLights(v, a);
    generateLights(v, b);
    REQUIRE(a.size() == 100);
    CHECK(lightCount(v) == 100);
    std::set<float> hues;
    for (std::size_t i = 0; i < a.size(); ++i) {
        CHECK(a[i].position == b[i].position);
        CHECK(a[i].color == b[i].color);
        CHECK(a[i].radius_m == 12.0f);
        for (int k = 0; k < 3; ++k) {
            CHECK(a[i].position[k] >= v.min_m[k]);
            CHECK(a[i].position[k] <= v.max_m[k]);
        }
        float hi = std::max({a[i].color.r, a[i].color.g, a[i].color.b});
        float lo = std::min({a[i].color.r, a[i].color.g, a[i].color.b});
        CHECK(hi == doctest::Approx(0.9f));
        CHECK(lo == doctest::Approx(0.9f * 0.4f));
        hues.insert(a[i].color.r * 7.0f + a[i].color.g * 3.0f + a[i].color.b);
    }
    CHECK(hues.size() > 90);  // random hues, not one colour
    // Without jitter the lights sit on the cell centres, x fastest.
    v.jitter = 0.0f;
    std::vector<Light> grid;
    generateLights(v, grid);
    CHECK(grid[0].position.x == doctest::Approx(-90.0));
    CHECK(grid[1].position.x == doctest::Approx(-70.0));
    CHECK(grid[10].position.y == doctest::Approx(12.5));
    CHECK(grid[0].color == a[0].color);  // the hue does not depend on the jitter
    // Another seed, other colours; an empty count, no lights.
    v.seed = 24;
    std::vector<Light> other;
    generateLights(v, other);
    CHECK(other[0].color != a[0].color);
    v.count = {0, 3, 3};
    CHECK(lightCount(v) == 0);
    std::vector<Light> none;
    generateLights(v, none);
    CHECK(none.empty());
    std::vector<Light> explicit_lights(3);
    CHECK(collectLights(explicit_lights, std::vector<LightVolume>{LightVolume{}, LightVolume{}}).size() == 3 + 16 + 16);
}

TEST_CASE("lights: animation runs closed loops, moves only the chosen share and stays finite") {
    LightAnimation anim;
    anim.motion = LightMotion::Circle;
    anim.amplitude_m = 3.0f;
    anim.period_s = 8.0f;
    anim.fraction = 0.5f;
    int moving = 0;
    for (std::uint64_t i = 0; i < 1000; ++i) {
        glm::dvec3 base(double(i), 10.0, -5.0);
        glm::dvec3 p0 = animatedPosition(base, anim, 1.25, i);
        if (!isAnimated(anim, i)) {
            CHECK(p0 == base);
            continue;
        }
        ++moving;
        CHECK(glm::length(p0 - base) == doctest::Approx(3.0));
        CHECK(p0.y == base.y);
        glm::dvec3 p1 = animatedPosition(base, anim, 1.25 + 8.0, i);
        CHECK(glm::length(p1 - p0) < 1e-9);
        glm::dvec3 late = animatedPosition(base, anim, 1e9, i);
        CHECK(std::isfinite(late.x));
        CHECK(glm::length(late - base) == doctest::Approx(3.0));
    }
    CHECK(moving > 400);
    CHECK(moving < 600);
    anim.motion = LightMotion::Bob;
    anim.fraction = 1.0f;
    glm::dvec3 base(1.0, 2.0, 3.0);
    for (double t = 0.0; t < 16.0; t += 0.5) {
        glm::dvec3 p = animatedPosition(base, anim, t, 7);
        CHECK(p.x == base.x);
        CHECK(p.z == base.z);
        CHECK(std::abs(p.y - base.y) <= 3.0 + 1e-12);
    }
    std::vector<Light> lights(5), out;
    animateLights(lights, anim, 2.0, out);
    CHECK(out.size() == 5);
    anim.motion = LightMotion::None;
    CHECK(animatedPosition(base, anim, 3.0, 1) == base);
}

TEST_CASE("lights: light and volume specs round-trip and bad ones name the problem") {
    Light l;
    REQUIRE(parseLightSpec("spot 10.5 42 -5  radius 12  color 1 0.7 0.4  intensity 30 direction 0 -1 0.25 cone 20 35", l).empty());
    CHECK(l.type == LightType::Spot);
    CHECK(l.position == glm::dvec3(10.5, 42.0, -5.0));
    CHECK(l.radius_m == 12.0f);
    CHECK(l.color == glm::vec3(1.0f, 0.7f, 0.4f));
    CHECK(l.intensity == 30.0f);
    CHECK(l.direction == glm::vec3(0.0f, -1.0f, 0.25f));
    CHECK(l.outer_deg == 35.0f);
    Light back;
    REQUIRE(parseLightSpec(formatLightSpec(l), back).empty());
    CHECK(formatLightSpec(back) == formatLightSpec(l));
    CHECK(back.position == l.position);
    CHECK(back.color == l.color);

    Light p;
    REQUIRE(parseLightSpec("point 0.1 +2 3e2", p).empty());  // omitted groups keep the defaults
    CHECK(p.type == LightType::Point);
    CHECK(p.position.z == 300.0);
    CHECK(p.radius_m == Light{}.radius_m);

    LightVolume v;
    REQUIRE(parseVolumeSpec("box -200 30 -150  200 40 150  count 16 1 12  radius 18  intensity 40 saturation 0.5 value 1 jitter 0.3 seed 99", v).empty());
    CHECK(v.count == glm::ivec3(16, 1, 12));
    CHECK(v.seed == 99u);
    CHECK(v.jitter == 0.3f);
    LightVolume vb;
    REQUIRE(parseVolumeSpec(formatVolumeSpec(v), vb).empty());
    CHECK(formatVolumeSpec(vb) == formatVolumeSpec(v));
    CHECK(vb.min_m == v.min_m);

    Light bad;
    CHECK(parseLightSpec("lamp 0 0 0", bad).find("point") != std::string::npos);
    CHECK(parseLightSpec("point 0 0", bad).find("3 numbers") != std::string::npos);
    CHECK(parseLightSpec("point 0 0 x", bad).find("'x'") != std::string::npos);
    CHECK(parseLightSpec("point 0 0 0 radius -1", bad).find("outside") != std::string::npos);
    CHECK(parseLightSpec("point 0 0 0 radius 1 glow 2", bad).find("glow") != std::string::npos);
    CHECK(parseLightSpec("spot 0 0 0 cone 40 30", bad).find("wider") != std::string::npos);
    CHECK(parseLightSpec("spot 0 0 0 direction 0 0 0", bad).find("direction") != std::string::npos);
    LightVolume badv;
    CHECK(parseVolumeSpec("box 0 0 0 1 1", badv).find("6 numbers") != std::string::npos);
    CHECK(parseVolumeSpec("box 0 0 0 1 1 1 count 1.5 1 1", badv).find("whole") != std::string::npos);
    CHECK(parseVolumeSpec("box 0 0 0 1 1 1 count 10000 10000 10000", badv).find("more than") != std::string::npos);
    CHECK(isValidListName("village_2"));
    CHECK(!isValidListName(""));
    CHECK(!isValidListName("a.b"));
}

namespace {
// Collects the keys describe() lists.
struct KeyLister : SettingsVisitor {
    std::vector<std::string> keys;
    std::string section_name;
    void section(const char* name, const char*) override { section_name = name; }
    void field(const FieldInfo& i, bool&) override { keys.push_back(i.key); }
    void field(const FieldInfo& i, int&, int, int) override { keys.push_back(i.key); }
    void field(const FieldInfo& i, float&, float, float) override { keys.push_back(i.key); }
    void field(const FieldInfo& i, double&, double, double) override { keys.push_back(i.key); }
    void field(const FieldInfo& i, glm::vec3&, float, float) override { keys.push_back(i.key); }
    void field(const FieldInfo& i, glm::dvec3&, double, double) override { keys.push_back(i.key); }
    void field(const FieldInfo& i, std::string&) override { keys.push_back(i.key); }
    void choice(const FieldInfo& i, int& value, std::span<const char* const> names) override {
        keys.push_back(i.key);
        CHECK(value >= 0);
        CHECK(value < int(names.size()));
    }
    void list(const FieldInfo& i, ListField&) override { keys.push_back(i.key); }
};
}  // namespace

TEST_CASE("lights: [lights] lists each plain key once with in-range defaults") {
    LightsSettings s;
    KeyLister v;
    describe(v, s);
    CHECK(v.section_name == "lights");
    std::set<std::string> unique(v.keys.begin(), v.keys.end());
    CHECK(unique.size() == v.keys.size());
    for (const char* key : {"enabled", "culling", "tile_size", "cluster_slices", "max_lights_per_cell", "hash_node_m",
                            "hash_memory_mb", "animation", "animation_period_s"})
        CHECK(unique.count(key) == 1);
    CHECK(tilePixels(s.tile_size) == 16);
    CHECK(tilePixels(LightTileSize::Px32) == 32);
}

TEST_CASE("lights: candela and lumens become HDR units through lux per HDR unit, and the auto radius is exact") {
    // Candela: I cd give I lux at 1 m, I / luxPerHdrUnit HDR units; Hdr lights keep their value.
    Light cd;
    cd.unit = LightUnit::Candela;
    cd.intensity = 1000.0f;
    cd.radius_m = 7.0f;
    const Light r = resolveUnits(cd, 250.0, 0.05);
    CHECK(r.unit == LightUnit::Hdr);
    CHECK(r.intensity == 4.0f);  // 1000 / 250
    CHECK(r.radius_m == 7.0f);   // explicit radius kept
    Light old;  // the old unit: unchanged, so scenes from before render as they did
    old.intensity = 30.0f;
    old.radius_m = 12.0f;
    CHECK(resolveUnits(old, 250.0, 0.05) == old);
    CHECK(candela(old, 250.0) == 7500.0);

    // Lumens over the cone's solid angle: 4 pi for a point light; a spot 2 pi (1 - (cos i + cos o) / 2).
    Light lm;
    lm.unit = LightUnit::Lumen;
    lm.intensity = 1200.0f;
    CHECK(candela(lm, 1.0) == doctest::Approx(1200.0 / (4.0 * std::numbers::pi)).epsilon(1e-12));
    lm.type = LightType::Spot;
    lm.inner_deg = lm.outer_deg = 60.0f;  // hard edge: the cap's 2 pi (1 - cos 60) = pi
    CHECK(lightSolidAngleSr(lm) == doctest::Approx(std::numbers::pi).epsilon(1e-12));
    CHECK(candela(lm, 1.0) == doctest::Approx(1200.0 / std::numbers::pi).epsilon(1e-12));
    lm.inner_deg = 0.0f;
    lm.outer_deg = 90.0f;  // 2 pi (1 - (1 + 0) / 2) = pi
    CHECK(lightSolidAngleSr(lm) == doctest::Approx(std::numbers::pi).epsilon(1e-12));
    // ... and that is the shader's cone (spotFactor) integrated over the sphere (midpoint rule in cos a).
    for (auto [inner, outer] : {std::pair{20.0f, 50.0f}, std::pair{45.0f, 65.0f}, std::pair{0.0f, 180.0f}}) {
        lm.inner_deg = inner;
        lm.outer_deg = outer;
        const SpotCone cone = spotCone(lm);
        const int n = 200000;
        double sum = 0.0;
        for (int k = 0; k < n; ++k) sum += double(spotFactor(cone, float(-1.0 + (k + 0.5) * 2.0 / n)));
        CHECK(2.0 * std::numbers::pi * sum * 2.0 / n == doctest::Approx(lightSolidAngleSr(lm)).epsilon(1e-4));
    }

    // Auto radius: where I * max(colour) / (d^2 + eps) falls to cutoff_lux.
    CHECK(autoRadiusM(100.0, 1.0, 0.05) == doctest::Approx(std::sqrt(2000.0 - 0.01)).epsilon(1e-12));  // 44.72 m
    CHECK(autoRadiusM(300.0, 1.0, 0.05) == doctest::Approx(std::sqrt(6000.0 - 0.01)).epsilon(1e-12));  // 77.46 m
    CHECK(autoRadiusM(1e-4, 1.0, 0.05) == 0.0);        // below eps * cutoff: reaches nothing
    CHECK(autoRadiusM(1e12, 1.0, 1e-6) == kMaxLightRadiusM);
    Light a;
    a.unit = LightUnit::Candela;
    a.intensity = 400.0f;
    a.color = {0.5f, 0.25f, 0.1f};
    a.radius_m = -1.0f;
    const Light ra = resolveUnits(a, 100.0, 0.02);
    const double rr = double(ra.radius_m);
    CHECK(rr == doctest::Approx(std::sqrt(400.0 * 0.5 / 0.02 - 0.01)).epsilon(1e-6));  // 100.0 m
    CHECK(400.0 * 0.5 / (rr * rr + double(kFalloffEpsM2)) == doctest::Approx(0.02).epsilon(1e-5));
    CHECK(ra.intensity == 4.0f);
    CHECK(falloff(float(rr * rr) * 1.0001f, ra.radius_m) == 0.0f);  // and the window ends it there

    // The text format: candela / lumens set the unit and, without a radius, radius auto.
    Light p;
    REQUIRE(parseLightSpec("point 1 2 3  candela 300  color 1 0.72 0.42", p).empty());
    CHECK(p.unit == LightUnit::Candela);
    CHECK(p.intensity == 300.0f);
    CHECK(p.radius_m == -1.0f);
    CHECK(formatLightSpec(p) == "point 1 2 3  radius auto  color 1 0.72 0.42  candela 300");
    REQUIRE(parseLightSpec("spot 0 9 0  radius 20  lumens 5000  cone 30 40", p).empty());
    CHECK(p.unit == LightUnit::Lumen);
    CHECK(p.radius_m == 20.0f);
    Light back;
    REQUIRE(parseLightSpec(formatLightSpec(p), back).empty());
    CHECK(back == p);
    REQUIRE(parseLightSpec("point 0 0 0  radius auto  intensity 3", p).empty());
    CHECK(p.unit == LightUnit::Hdr);
    CHECK(p.radius_m == -1.0f);
    CHECK(parseLightSpec("point 0 0 0  candela -5", p).find("candela") != std::string::npos);
    CHECK(parseLightSpec("point 0 0 0  radius far", p).find("auto") != std::string::npos);
    LightVolume v;
    REQUIRE(parseVolumeSpec("box 0 0 0 10 0 10  count 2 1 2  candela 100", v).empty());
    CHECK(v.unit == LightUnit::Candela);
    CHECK(v.radius_m == -1.0f);
    std::vector<Light> lights;
    generateLights(v, lights);
    REQUIRE(lights.size() == 4);
    for (const Light& l : lights) {
        CHECK(l.unit == LightUnit::Candela);
        CHECK(l.radius_m == -1.0f);
    }
    LightVolume vb;
    REQUIRE(parseVolumeSpec(formatVolumeSpec(v), vb).empty());
    CHECK(vb == v);
}
