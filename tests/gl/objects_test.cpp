// Objects on the GPU (renderer/meshes/objects.h) over a flat test terrain: objects.cull keeps in
// each (model, LOD) list exactly the instances the CPU expects from their distance and the view
// frustum, and in the shadow list those within the shadow distance; the passes run in order; the
// house is drawn (the G-buffer changes), casts a sun shadow, and its windows' emissive adds light.
#include "app/frame.h"
#include "app/scene.h"
#include "renderer/half.h"
#include "renderer_fixture.h"
#include "terrain/heightmap.h"

#include <algorithm>
#include <cmath>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::compiledFileRenderer(); }

constexpr float kFlat = 0.3f, kHeightScale = 100.0f;

Settings objectScene(const std::filesystem::path& map) {
    Settings s;
    s.terrain.heightmap = map.string();
    s.terrain.size_m = 8192.0f;
    s.terrain.height_scale_m = kHeightScale;
    s.sky.enabled = false;
    s.debug.grid = false;
    s.lights.enabled = false;
    s.grass.enabled = false;
    s.water.enabled = false;
    s.ssao.enabled = false;
    const std::string house = (vistaRoot() / "data/props/house.glb").string();
    auto add = [&](const char* name, double x, double z) {
        ObjectInstanceSpec o;
        o.file = house;
        o.position = glm::dvec3(x, 0.0, z);
        o.ground_m = 0.0f;
        s.objects.objects.push_back({name, o});
    };
    add("near", 0, -30);        // in view, LOD 0
    add("mid", 0, -150);        // in view, LOD 1
    add("far", 5, -400);        // in view, LOD 2
    add("behind", 0, 40);       // behind the camera: shadow caster only
    add("right", 200, -10);     // outside the view to the right: shadow caster only
    add("away", 0, -3000);      // beyond max_distance_m and the shadow distance: nothing
    return s;
}

struct Frame {
    FrameReport report;
    std::vector<std::uint16_t> hdr;
    std::vector<std::uint32_t> counts;
    std::uint64_t instances = 0, triangles = 0;
};

Frame render(const Settings& s, const ViewParams& view) {
    FrameRenderer& r = renderer();
    REQUIRE(r.prepare(s).empty());
    r.counters().collect(true);
    Frame f;
    FrameRequest request;
    request.capture_hdr = &f.hdr;
    request.count_objects = true;
    f.report = r.render(s, view, 10.0, request);
    for (const auto& c : r.counters().collect(true)) {
        if (c.name == "objects.instances") f.instances = c.value;
        if (c.name == "objects.triangles") f.triangles = c.value;
    }
    if (Objects* o = r.objects()) {
        f.counts.resize(o->models().size() * 4);
        glGetNamedBufferSubData(o->countsBuffer(), 0, GLsizeiptr(f.counts.size() * 4), f.counts.data());
    }
    return f;
}

double luminance(const std::vector<std::uint16_t>& hdr) {
    double sum = 0.0;
    for (std::size_t i = 0; i + 3 < hdr.size(); i += 4) sum += halfToFloat(hdr[i]) + halfToFloat(hdr[i + 1]) + halfToFloat(hdr[i + 2]);
    return sum;
}

}  // namespace

TEST_CASE("gl: objects are culled on the GPU into the LOD and shadow lists the CPU expects, drawn, shadowed and glowing") {
    test::TempDir dir("objects");
    Heightmap map{65, 65, std::vector<float>(65 * 65, kFlat)};
    const std::filesystem::path file = dir.path / "flat.png";
    REQUIRE(saveHeightmapPng16(file, map).empty());
    Settings s = objectScene(file);
    const double ground = kFlat * kHeightScale;
    const ViewParams view{{0.0, ground + 2.5, 0.0}, 0.0, -2.0, 60.0, 0.1f, 160, 90};
    Frame on = render(s, view);
    REQUIRE(renderer().objects() != nullptr);
    REQUIRE(on.counts.size() == 4);  // one model: groups LOD 0, 1, 2 and shadow
    CHECK(on.counts[0] == 1);
    CHECK(on.counts[1] == 1);
    CHECK(on.counts[2] == 1);
    CHECK(on.counts[3] == 4);  // near, mid, behind, right
    CHECK(on.instances == 3);
    const Model& house = renderer().objects()->models()[0];
    REQUIRE(house.lods.size() == 3);
    CHECK(on.triangles == house.lods[0].triangles() + house.lods[1].triangles() + house.lods[2].triangles());
    CHECK(on.report.counters.at("objects.placed") == 6.0);
    const auto& ex = on.report.executed;
    auto at = [&](const char* name) { return std::find(ex.begin(), ex.end(), name) - ex.begin(); };
    REQUIRE(at("objects.cull") < std::ptrdiff_t(ex.size()));
    REQUIRE(at("objects.gbuffer") < std::ptrdiff_t(ex.size()));
    CHECK(at("terrain.gbuffer") < at("objects.gbuffer"));
    CHECK(at("objects.gbuffer") < at("lighting.sun"));
    if (at("shadows.cascade0") < std::ptrdiff_t(ex.size())) CHECK(at("objects.cull") < at("shadows.cascade0"));
    for (std::uint16_t h : on.hdr) CHECK(std::isfinite(halfToFloat(h)));

    // Without objects the image differs (the house is drawn) and nothing of them runs.
    Settings none = s;
    none.objects.enabled = false;
    const Frame off = render(none, view);
    CHECK(renderer().objects() == nullptr);
    CHECK(std::none_of(off.report.executed.begin(), off.report.executed.end(),
                       [](const std::string& p) { return p.rfind("objects.", 0) == 0; }));
    std::size_t changed = 0;
    for (std::size_t i = 0; i < on.hdr.size(); ++i) changed += on.hdr[i] != off.hdr[i];
    CHECK(changed > 100);

    // A low sun behind the near house: its shadow falls toward the camera (less light reaches it).
    Settings lit = s;
    lit.sky.sun_azimuth_deg = 0.0f;
    lit.sky.sun_elevation_deg = 15.0f;
    Settings unshadowed = lit;
    unshadowed.objects.cast_shadows = false;
    const double with_shadow = luminance(render(lit, view).hdr), without = luminance(render(unshadowed, view).hdr);
    CHECK(with_shadow < without * 0.999);

    // Emissive windows add light in proportion to emissive_nits.
    Settings bright = s;
    bright.objects.emissive_nits = 1.0e4f;
    Settings dark = s;
    dark.objects.emissive_nits = 0.0f;
    CHECK(luminance(render(bright, view).hdr) > luminance(render(dark, view).hdr) * 1.001);
}
