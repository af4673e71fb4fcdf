// Objects on the GPU (renderer/meshes/objects.h) over a flat test terrain: objects.cull keeps in
// each (model, LOD) list exactly the instances the CPU expects from their distance and the view
// frustum, and in the shadow list those within the shadow distance; the passes run in order; the
// house is drawn (the G-buffer changes), casts a sun shadow, and its windows' emissive adds light.
#include "app/frame.h"
#include "app/scene.h"
#include "config/file_io.h"
#include "renderer/meshes/gen_props.h"
#include "renderer/meshes/impostor.h"
#include "renderer/half.h"
#include "renderer_fixture.h"
#include "terrain/heightmap.h"
#include "terrain/scatter/scatter.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

using namespace vista;

namespace {

FrameRenderer& renderer() { return test::compiledFileRenderer(); }

constexpr float kFlat = 0.3f, kHeightScale = 100.0f;

// The island of `map` with everything but the terrain and the objects switched off.
Settings bareScene(const std::filesystem::path& map) {
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
    return s;
}

Settings objectScene(const std::filesystem::path& map) {
    Settings s = bareScene(map);
    s.objects.impostor_distance_m = 1.0e6f;  // meshes at every distance (impostors: impostor_test.cpp)
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
    std::uint64_t instances = 0, triangles = 0, shadow_triangles = 0;
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
        if (c.name == "objects.shadow_triangles") f.shadow_triangles = c.value;
    }
    if (Objects* o = r.objects()) {
        f.counts.resize(o->models().size() * kObjectGroups);
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
    REQUIRE(on.counts.size() == 5);  // one model: groups LOD 0, 1, 2, shadow and impostor
    CHECK(on.counts[0] == 1);
    CHECK(on.counts[1] == 1);
    CHECK(on.counts[2] == 1);
    CHECK(on.counts[3] == 4);  // near, mid, behind, right
    CHECK(on.counts[4] == 0);  // no impostors
    CHECK(on.instances == 3);
    const Model& house = renderer().objects()->models()[0];
    REQUIRE(house.lods.size() == 3);
    CHECK(on.triangles == house.lods[0].triangles() + house.lods[1].triangles() + house.lods[2].triangles());
    // Shadow-pass triangles: the 4 casters' LOD 1, once per shadow view that drew them (the sun's
    // cascades starting within shadow_distance_m).
    const std::uint64_t per_view = 4 * house.lods[1].triangles();
    const auto views = std::count_if(on.report.executed.begin(), on.report.executed.end(),
                                     [](const std::string& p) { return p.rfind("shadows.cascade", 0) == 0; });
    CHECK(views > 0);
    CHECK(on.shadow_triangles > 0);
    CHECK(on.shadow_triangles % per_view == 0);
    CHECK(on.shadow_triangles <= per_view * std::uint64_t(views));
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

// Octahedral impostors (renderer/meshes/impostor.h) against the mesh they replace: one tree on a
// flat terrain at the switch distance, drawn as the mesh LOD the cull picks there and as its
// impostor. The impostor must cover nearly the same pixels with nearly the same colour (the
// error bound at the switch); in the fade band the instance is in both lists, and the counters
// say what was drawn.
namespace impostor_case {
namespace {

constexpr double kSwitchM = 150.0;  // [objects] impostor_distance_m's default
constexpr int kW = 160, kH = 90;

Settings treeScene(const std::filesystem::path& map) {
    Settings s = bareScene(map);
    s.taa.enabled = false;
    s.shadows.enabled = false;
    ObjectInstanceSpec o;
    o.file = (vistaRoot() / "data/props/tree.glb").string();
    o.position = glm::dvec3(0.0, 0.0, -kSwitchM);
    o.ground_m = 0.0f;
    o.yaw_deg = 30.0f;
    s.objects.objects.push_back({"tree", o});
    return s;
}

struct Frame {
    test::RenderedFrame f;
    std::vector<std::uint32_t> counts;
};

Frame render(const Settings& s, const ViewParams& view) {
    FrameRenderer& r = test::compiledFileRenderer();
    REQUIRE(r.prepare(s).empty());
    FrameRequest request;
    request.count_objects = true;
    Frame out;
    out.f = test::renderFrame(r, s, view, 10.0, request);
    if (Objects* o = r.objects()) {
        out.counts.resize(o->models().size() * kObjectGroups);
        glGetNamedBufferSubData(o->countsBuffer(), 0, GLsizeiptr(out.counts.size() * 4), out.counts.data());
    }
    return out;
}

double luminance(const std::vector<float>& rgba, std::size_t i) {
    return 0.2126 * rgba[i * 4] + 0.7152 * rgba[i * 4 + 1] + 0.0722 * rgba[i * 4 + 2];
}

// Where a frame differs from the empty one: the object's pixels.
std::vector<bool> coverage(const std::vector<float>& with, const std::vector<float>& without) {
    std::vector<bool> mask(with.size() / 4);
    for (std::size_t i = 0; i < mask.size(); ++i) {
        const double a = luminance(with, i), b = luminance(without, i);
        mask[i] = std::abs(a - b) > 0.02 * std::max(b, 1e-3);
    }
    return mask;
}

struct Comparison {
    double iou = 0.0;        // covered pixels: intersection over union
    double mean_error = 0.0; // |mean luminance over the covered pixels| relative difference
};

Comparison compare(const Frame& a, const Frame& b, const Frame& empty) {
    const std::vector<bool> ma = coverage(a.f.rgba, empty.f.rgba), mb = coverage(b.f.rgba, empty.f.rgba);
    std::size_t both = 0, any = 0;
    double la = 0.0, lb = 0.0;
    std::size_t na = 0, nb = 0;
    for (std::size_t i = 0; i < ma.size(); ++i) {
        both += ma[i] && mb[i];
        any += ma[i] || mb[i];
        if (ma[i]) la += luminance(a.f.rgba, i), ++na;
        if (mb[i]) lb += luminance(b.f.rgba, i), ++nb;
    }
    Comparison c;
    c.iou = any ? double(both) / double(any) : 0.0;
    la /= double(std::max<std::size_t>(na, 1));
    lb /= double(std::max<std::size_t>(nb, 1));
    c.mean_error = std::abs(la - lb) / std::max(la, 1e-6);
    MESSAGE("covered px " << na << " vs " << nb << ", IoU " << c.iou << ", mean luminance " << la << " vs " << lb);
    return c;
}

}  // namespace

TEST_CASE("gl: an impostor at the switch distance covers the mesh's pixels with its colour, and the fade band draws both") {
    test::TempDir dir("impostor");
    Heightmap map{65, 65, std::vector<float>(65 * 65, kFlat)};
    const std::filesystem::path file = dir.path / "flat.png";
    REQUIRE(saveHeightmapPng16(file, map).empty());
    Settings s = treeScene(file);
    const double ground = kFlat * kHeightScale;
    // A narrow view, so the tree at 150 m fills a third of the frame's height.
    const ViewParams view{{0.0, ground + 4.0, 0.0}, 0.0, -0.5, 7.0, 0.1f, kW, kH};

    Settings none = s;
    none.objects.enabled = false;
    const Frame empty = render(none, view);

    Settings mesh = s;  // the mesh as the cull draws it at the switch distance (LOD 1 there)
    mesh.objects.impostor_distance_m = 1.0e6f;
    const Frame m = render(mesh, view);
    REQUIRE(m.counts.size() == 5);
    CHECK(m.counts[1] == 1);
    CHECK(m.counts[4] == 0);
    CHECK(m.f.counter("objects.impostors") == 0);

    Settings impostor = s;  // the impostor just past the switch
    impostor.objects.impostor_distance_m = float(kSwitchM) - 5.0f;
    impostor.objects.impostor_fade_m = 0.0f;
    const Frame i = render(impostor, view);
    REQUIRE(test::compiledFileRenderer().objects()->impostorsBaked());
    CHECK(i.counts[1] == 0);
    CHECK(i.counts[4] == 1);
    CHECK(i.f.counter("objects.impostors") == 1);
    CHECK(i.f.counter("objects.triangles") == 2);
    for (float v : i.f.rgba) REQUIRE(std::isfinite(v));

    // The error bound at the switch: the same silhouette (measured 0.80 of the union) and
    // brightness within a few per cent (measured 4 %).
    const Comparison c = compare(m, i, empty);
    CHECK(c.iou > 0.75);
    CHECK(c.mean_error < 0.1);

    // Against the full-detail mesh too (what LOD 0 would show at that distance).
    Settings full = mesh;
    full.objects.lod1_distance_m = 1.0e5f;
    full.objects.lod2_distance_m = 1.0e5f;
    const Comparison f = compare(render(full, view), i, empty);
    CHECK(f.iou > 0.75);  // measured 0.85
    CHECK(f.mean_error < 0.1);  // measured 2 %

    // In the fade band the instance is in the mesh's list and the impostors' and the two draws
    // share the pixels: the silhouette stays the mesh's.
    Settings fade = s;
    fade.objects.impostor_distance_m = float(kSwitchM) + 10.0f;
    fade.objects.impostor_fade_m = 20.0f;
    const Frame b = render(fade, view);
    CHECK(b.counts[1] == 1);
    CHECK(b.counts[4] == 1);
    CHECK(b.f.counter("objects.instances") == 1);
    CHECK(b.f.counter("objects.impostors") == 1);
    const Comparison cb = compare(m, b, empty);
    CHECK(cb.iou > 0.75);  // measured 0.90
    CHECK(cb.mean_error < 0.1);
}

}  // namespace impostor_case

// Sorted transparency (renderer/meshes/objects_forward.cpp): two overlapping half-transparent
// panes, a red one in front of a blue one. Listed in either order in the scene they render the
// same (objects.transparent sorts them back to front); drawn in the listed order instead (the
// sort switched off) the far pane drawn last is hidden behind the near one's depth: the order
// matters, so the sort is what makes the two renders agree. BLEND materials stay out of the
// G-buffer.
namespace transparent_case {
namespace {


// A 2 x 2 m double-sided pane in the model's x-y plane (x -1..1, y 0..2), the given colour,
// BLEND at alpha 0.5 or opaque.
Model pane(glm::vec3 colour, AlphaMode mode = AlphaMode::Blend) {
    return test::paneModel("pane", 2.0f, 2.0f, glm::vec4(colour, mode == AlphaMode::Blend ? 0.5f : 1.0f), 0.8f, mode);
}

Settings paneScene(const std::filesystem::path& map) {
    Settings s = bareScene(map);
    s.taa.enabled = false;
    s.shadows.enabled = false;
    return s;
}

ObjectInstanceSpec at(const std::filesystem::path& file, double x, double z) {
    ObjectInstanceSpec o;
    o.file = file.string();
    o.position = glm::dvec3(x, 0.0, z);
    o.ground_m = 0.5f;
    return o;
}

test::RenderedFrame render(const Settings& s, const ViewParams& view) {
    FrameRenderer& r = test::compiledFileRenderer();
    REQUIRE(r.prepare(s).empty());
    FrameRequest request;
    request.count_objects = true;
    return test::renderFrame(r, s, view, 10.0, request);
}

std::size_t differing(const std::vector<float>& a, const std::vector<float>& b) {
    REQUIRE(a.size() == b.size());
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size(); i += 4)
        n += std::abs(a[i] - b[i]) + std::abs(a[i + 1] - b[i + 1]) + std::abs(a[i + 2] - b[i + 2]) > 1e-4f * (1.0f + a[i] + a[i + 1] + a[i + 2]);
    return n;
}

}  // namespace

TEST_CASE("gl: transparent panes are sorted back to front: either listed order renders the same, unsorted differs") {
    test::TempDir dir("transparent");
    Heightmap map{65, 65, std::vector<float>(65 * 65, kFlat)};
    const std::filesystem::path file = dir.path / "flat.png";
    REQUIRE(saveHeightmapPng16(file, map).empty());
    const std::filesystem::path red = dir.path / "red.glb", blue = dir.path / "blue.glb";
    REQUIRE(writeFileAtomic(red, modelToGlb(pane({0.9f, 0.05f, 0.05f})), true).empty());
    REQUIRE(writeFileAtomic(blue, modelToGlb(pane({0.05f, 0.05f, 0.9f})), true).empty());
    Settings s = paneScene(file);
    const double ground = kFlat * kHeightScale;
    const ViewParams view{{0.0, ground + 1.5, 0.0}, 0.0, 0.0, 40.0, 0.1f, 160, 90};

    Settings front_first = s;  // red (near, offset right) listed first, blue (far) second
    front_first.objects.objects = {{"red", at(red, 0.6, -6.0)}, {"blue", at(blue, -0.6, -9.0)}};
    Settings back_first = s;
    back_first.objects.objects = {{"blue", at(blue, -0.6, -9.0)}, {"red", at(red, 0.6, -6.0)}};
    Settings none = s;
    none.objects.enabled = false;

    const test::RenderedFrame empty = render(none, view);
    const test::RenderedFrame a = render(front_first, view);
    CHECK(std::find(a.report.executed.begin(), a.report.executed.end(), "objects.transparent") != a.report.executed.end());
    CHECK(a.report.counters.at("objects.transparent") == 2.0);
    const test::RenderedFrame b = render(back_first, view);
    for (float v : a.rgba) REQUIRE(std::isfinite(v));
    CHECK(differing(a.rgba, empty.rgba) > 200);  // the panes are drawn
    CHECK(differing(a.rgba, b.rgba) == 0);       // whatever the order they are listed in

    // Without the sort, the listed order is the drawing order: the far pane is lost behind the
    // near one where they overlap.
    Objects* objects = test::compiledFileRenderer().objects();
    REQUIRE(objects != nullptr);
    objects->setSortTransparent(false);
    const test::RenderedFrame unsorted = render(front_first, view);
    test::compiledFileRenderer().objects()->setSortTransparent(true);
    CHECK(differing(a.rgba, unsorted.rgba) > 20);
}

// Compositing with the sea, the fog and the sun's shadows. Every expectation is built from other
// renders of the same pixels, by the linear algebra of the blend:
//  - premultiplied blending: pixel = C + (1 - a) B, C the pane's own light, B what is behind;
//  - the sea, the aerial perspective and the shadows act on what they cover linearly per pixel,
//    pixel = k X + m; two opaque panes of different colours at the same place give k and m.
namespace {

// RGB of the pixel world projects to (rows top first), for each point.
std::vector<glm::vec3> pixelsAt(const test::RenderedFrame& f, const ViewParams& view, const std::vector<glm::dvec3>& points) {
    const ViewMatrices m = viewMatrices(view);
    std::vector<glm::vec3> out;
    for (const glm::dvec3& world : points) {
        const glm::vec4 c = m.view_proj * glm::vec4(glm::vec3(world - view.position), 1.0f);
        const int px = int((c.x / c.w * 0.5f + 0.5f) * float(view.width));
        const int py = view.height - 1 - int((c.y / c.w * 0.5f + 0.5f) * float(view.height));
        REQUIRE(px >= 0);
        REQUIRE(px < view.width);
        REQUIRE(py >= 0);
        REQUIRE(py < view.height);
        const std::size_t i = (std::size_t(py) * std::size_t(view.width) + std::size_t(px)) * 4;
        out.emplace_back(f.rgba[i], f.rgba[i + 1], f.rgba[i + 2]);
    }
    return out;
}

// Points on a pane standing at centre (its bottom middle), scaled, turned by yaw (deg): u across
// (-1..1), v up (0..2) in the model's units, over [u0, u1] x [v0, v1].
std::vector<glm::dvec3> paneGrid(glm::dvec3 centre, double scale, double yaw_deg, double u0, double u1, double v0, double v1) {
    const double c = std::cos(glm::radians(yaw_deg)), sn = std::sin(glm::radians(yaw_deg));
    std::vector<glm::dvec3> points;
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j) {
            const double u = (u0 + (u1 - u0) * i / 4.0) * scale, v = (v0 + (v1 - v0) * j / 4.0) * scale;
            points.push_back(centre + glm::dvec3(c * u, v, -sn * u));
        }
    return points;
}

// sum |a - b| / sum |b| over every channel.
double relativeError(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    REQUIRE(a.size() == b.size());
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            num += std::abs(double(a[i][k]) - double(b[i][k]));
            den += std::abs(double(b[i][k]));
        }
    return num / std::max(den, 1e-12);
}

// k X + m per pixel and channel, with k and m from two opaque references: y_a = k x_a + m and
// y_b = k x_b + m (x without the effect, y with it).
std::vector<glm::vec3> linearPrediction(const std::vector<glm::vec3>& x, const std::vector<glm::vec3>& x_a,
                                        const std::vector<glm::vec3>& x_b, const std::vector<glm::vec3>& y_a,
                                        const std::vector<glm::vec3>& y_b) {
    std::vector<glm::vec3> out(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            REQUIRE(std::abs(x_a[i][k] - x_b[i][k]) > 1e-3f * (std::abs(x_a[i][k]) + 1e-6f));
            const float slope = (y_a[i][k] - y_b[i][k]) / (x_a[i][k] - x_b[i][k]);
            out[i][k] = slope * x[i][k] + (y_a[i][k] - slope * x_a[i][k]);
        }
    return out;
}

ObjectInstanceSpec placed(const std::filesystem::path& file, glm::dvec3 position, float scale, float yaw_deg = 0.0f,
                          float ground_m = -1.0f) {
    ObjectInstanceSpec o;
    o.file = file.string();
    o.position = position;
    o.scale = scale;
    o.yaw_deg = yaw_deg;
    o.ground_m = ground_m;
    return o;
}

struct PaneFiles {
    test::TempDir dir{"pane_compositing"};
    std::filesystem::path flat = dir.path / "flat.png", red = dir.path / "red.glb", light = dir.path / "light.glb",
                          dark = dir.path / "dark.glb", grey = dir.path / "grey.glb";
    PaneFiles() {
        Heightmap map{65, 65, std::vector<float>(65 * 65, kFlat)};
        REQUIRE(saveHeightmapPng16(flat, map).empty());
        REQUIRE(writeFileAtomic(red, modelToGlb(pane({0.9f, 0.05f, 0.05f})), true).empty());
        REQUIRE(writeFileAtomic(light, modelToGlb(pane({0.8f, 0.7f, 0.6f}, AlphaMode::Opaque)), true).empty());
        REQUIRE(writeFileAtomic(dark, modelToGlb(pane({0.1f, 0.15f, 0.2f}, AlphaMode::Opaque)), true).empty());
        REQUIRE(writeFileAtomic(grey, modelToGlb(pane({0.4f, 0.4f, 0.4f}, AlphaMode::Opaque)), true).empty());
    }
};

// The flat island 10 m under a calm sea (no waves, foam or screen-space reflection, so the sea
// acts on each pixel alone).
Settings seaScene(const std::filesystem::path& map) {
    Settings s = paneScene(map);
    s.water.enabled = true;
    s.water.level_m = float(kFlat * kHeightScale) + 10.0f;
    s.water.amplitude_scale = 0.0f;
    s.water.foam_depth_m = 0.0f;
    s.water.whitecaps = 0.0f;
    s.water.reflection = WaterReflection::Sky;
    return s;
}

Settings withObjects(Settings s, std::vector<NamedObject> objects) {
    s.objects.objects = std::move(objects);
    s.objects.enabled = !s.objects.objects.empty();
    return s;
}

}  // namespace

TEST_CASE("gl: a transparent pane in front of the sea blends over the sea surface") {
    PaneFiles files;
    const Settings sea = seaScene(files.flat);
    Settings dry = sea;
    dry.water.enabled = false;
    const double level = double(sea.water.level_m);
    const glm::dvec3 base(0.0, level + 1.0, -8.0);  // floating 1 m above the water, 8 m ahead
    const ViewParams view{{0.0, level + 4.0, 0.0}, 0.0, -14.0, 40.0, 0.1f, 160, 90};
    const NamedObject pane{"pane", placed(files.red, base, 1.0f)};
    const auto points = paneGrid(base, 1.0, 0.0, -0.7, 0.7, 0.3, 1.7);

    const auto sea_empty = pixelsAt(render(withObjects(sea, {}), view), view, points);
    const test::RenderedFrame sea_frame = render(withObjects(sea, {pane}), view);
    const auto sea_pane = pixelsAt(sea_frame, view, points);
    const auto dry_empty = pixelsAt(render(withObjects(dry, {}), view), view, points);
    const auto dry_pane = pixelsAt(render(withObjects(dry, {pane}), view), view, points);
    CHECK(sea_frame.report.counters.at("objects.transparent") == 1.0);
    CHECK(sea_frame.report.counters.at("objects.transparent_beyond_water") == 0.0);  // all above the water
    CHECK(relativeError(sea_empty, dry_empty) > 0.2);  // the sea is not the ground under it
    CHECK(relativeError(dry_pane, dry_empty) > 0.2);   // the pane shows

    // The pane's own light C = dry_pane - (1 - a) dry_empty; over the sea: C + (1 - a) sea.
    std::vector<glm::vec3> expected(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) expected[i] = dry_pane[i] - 0.5f * dry_empty[i] + 0.5f * sea_empty[i];
    const double error = relativeError(sea_pane, expected);
    INFO("relative error " << error);
    CHECK(error < 0.02);
}

TEST_CASE("gl: a transparent pane partly under the sea is seen through the water as an opaque pane there would be") {
    PaneFiles files;
    const Settings sea = seaScene(files.flat);
    Settings dry = sea;
    dry.water.enabled = false;
    const double level = double(sea.water.level_m);
    const glm::dvec3 base(0.0, level - 2.0, -10.0);  // 4 m tall: half under the water
    const ViewParams view{{0.0, level + 4.0, 0.0}, 0.0, -21.8, 50.0, 0.1f, 160, 90};
    auto with = [&](const Settings& s, const std::filesystem::path& file) {
        return withObjects(s, {{"pane", placed(file, base, 2.0f)}});
    };
    const auto under = paneGrid(base, 2.0, 0.0, -0.8, 0.8, 0.15, 0.75);  // 0.5 to 1.7 m under the water

    const test::RenderedFrame wet_frame = render(with(sea, files.red), view);
    CHECK(wet_frame.report.counters.at("objects.transparent_beyond_water") == 1.0);
    CHECK(std::find(wet_frame.report.executed.begin(), wet_frame.report.executed.end(), "objects.transparent_beyond_water") !=
          wet_frame.report.executed.end());
    const auto wet = pixelsAt(wet_frame, view, under);
    const auto wet_a = pixelsAt(render(with(sea, files.light), view), view, under);
    const auto wet_b = pixelsAt(render(with(sea, files.dark), view), view, under);
    const auto x = pixelsAt(render(with(dry, files.red), view), view, under);
    const auto x_a = pixelsAt(render(with(dry, files.light), view), view, under);
    const auto x_b = pixelsAt(render(with(dry, files.dark), view), view, under);
    CHECK(relativeError(wet_a, x_a) > 0.2);  // the water changes what is under it
    // The sea maps what it covers at each pixel linearly (refraction, absorption over the water
    // to the pane, scattering): the two opaque panes give that map, the glass must follow it.
    const double error = relativeError(wet, linearPrediction(x, x_a, x_b, wet_a, wet_b));
    INFO("relative error " << error);
    CHECK(error < 0.03);
}

// Glass within a wave's height of the level (docs/objects.md, the wave band): the split between
// the glass drawn before the sea and after it is the band's far edge, so a pane dipping into the
// band but not below it is drawn whole after the sea (depth-tested against the moving surface);
// on a calm sea the same pane is split at the still level.
TEST_CASE("gl: glass within the waves' reach of the level is drawn after the sea, glass below every trough before it") {
    PaneFiles files;
    Settings calm = seaScene(files.flat);
    Settings waves = calm;
    waves.water.amplitude_scale = 1.0f;
    const double level = double(calm.water.level_m);
    const ViewParams view{{0.0, level + 4.0, 0.0}, 0.0, -14.0, 40.0, 0.1f, 160, 90};
    auto frame = [&](const Settings& s, double bottom) {
        return render(withObjects(s, {{"pane", placed(files.red, glm::dvec3(0.0, bottom, -8.0), 1.0f)}}), view);
    };
    const test::RenderedFrame probe = frame(waves, level);
    REQUIRE(test::compiledFileRenderer().water() != nullptr);
    const double reach = test::compiledFileRenderer().water()->waves().max_height;
    INFO("waves reach " << reach << " m");
    REQUIRE(reach > 0.2);
    const double dip = 0.5 * reach;  // the pane's bottom this far under the level: inside the band
    CHECK(frame(calm, level - dip).report.counters.at("objects.transparent_beyond_water") == 1.0);
    const test::RenderedFrame within = frame(waves, level - dip);
    CHECK(within.report.counters.at("objects.transparent_beyond_water") == 0.0);
    CHECK(within.report.counters.at("objects.transparent") == 1.0);
    const test::RenderedFrame deeper = frame(waves, level - 2.0 * reach);  // reaches below every trough
    CHECK(deeper.report.counters.at("objects.transparent_beyond_water") == 1.0);
    for (float v : within.rgba) REQUIRE(std::isfinite(v));
}

// Whether the glass goes over the clouds or under them: over them when no cloud can be between
// the eye and the glass (both below the lowest layer's base), so the clouds behind a pane are
// seen through it; under them when the eye is above the base.
TEST_CASE("gl: glass is drawn after the clouds from below their base and before them from above it") {
    PaneFiles files;
    Settings s = paneScene(files.flat);
    s.sky.enabled = true;
    s.clouds.enabled = true;
    s.objects.max_distance_m = 10000.0f;
    const double ground = kFlat * kHeightScale;
    const Settings scene = withObjects(s, {{"pane", placed(files.red, glm::dvec3(0.0, ground, -2000.0), 100.0f)}});
    auto order = [&](double eye_y) {
        const ViewParams view{{0.0, eye_y, 0.0}, 0.0, -2.0, 40.0, 0.1f, 96, 54};
        const test::RenderedFrame f = render(scene, view);
        const auto& p = f.report.executed;
        const auto glass = std::find(p.begin(), p.end(), "objects.transparent"), shell = std::find(p.begin(), p.end(), "clouds.shell");
        REQUIRE(glass != p.end());
        REQUIRE(shell != p.end());
        CHECK(f.report.counters.at("objects.transparent_fogged") == 1.0);
        return glass < shell ? -1 : 1;
    };
    CHECK(order(ground + 50.0) == 1);                       // below the base (1500 m): the clouds first
    CHECK(order(double(s.clouds.low.base_m) + 300.0) == -1);  // above it: the glass first
}

TEST_CASE("gl: a distant transparent pane is fogged like an opaque pane at the same distance") {
    PaneFiles files;
    Settings fog = paneScene(files.flat);
    fog.sky.enabled = true;
    fog.clouds.enabled = false;
    fog.sky.height_fog = true;
    fog.sky.fog_density_per_km = 4.0f;  // about 0.3 transmittance over 300 m
    Settings clear = fog;
    clear.sky.aerial_perspective = false;
    const double ground = kFlat * kHeightScale;
    const glm::dvec3 base(0.0, ground, -300.0);
    // A grey wall 2 m behind the panes: what is seen through the glass is at the glass's distance
    // too, so the expectation holds whether the blend fogs the background at its own distance or
    // at the glass's.
    const NamedObject wall{"wall", placed(files.grey, base + glm::dvec3(0, 0, -2), 30.0f)};
    auto with = [&](const Settings& s) { return withObjects(s, {{"pane", placed(files.red, base, 20.0f)}, wall}); };
    auto opaque = [&](const Settings& s, const std::filesystem::path& file) {
        return withObjects(s, {{"pane", placed(file, base, 20.0f)}, wall});
    };
    const ViewParams view{{0.0, ground + 20.0, 0.0}, 0.0, 0.0, 20.0, 0.1f, 160, 90};
    const auto points = paneGrid(base, 20.0, 0.0, -0.7, 0.7, 0.3, 1.7);

    const auto y = pixelsAt(render(with(fog), view), view, points);
    const auto y_a = pixelsAt(render(opaque(fog, files.light), view), view, points);
    const auto y_b = pixelsAt(render(opaque(fog, files.dark), view), view, points);
    const auto x = pixelsAt(render(with(clear), view), view, points);
    const auto x_a = pixelsAt(render(opaque(clear, files.light), view), view, points);
    const auto x_b = pixelsAt(render(opaque(clear, files.dark), view), view, points);
    // The fog is strong there: the opaque panes' difference keeps under 0.8 of itself.
    double kept = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) kept += double(y_a[i].g - y_b[i].g) / double(x_a[i].g - x_b[i].g);
    kept /= double(points.size());
    INFO("transmittance " << kept);
    CHECK(kept < 0.8);
    CHECK(kept > 0.05);
    const double error = relativeError(y, linearPrediction(x, x_a, x_b, y_a, y_b));
    INFO("relative error " << error);
    CHECK(error < 0.03);
}

// The glass fogs itself (object.glsl AERIAL_FOG, drawn after sky.aerial): a pane 2.5 km away,
// seen from 270 m up against the ground (1.5 km behind it, to the island's edge) and the sky
// beyond. From first principles, the pixel is what reaches the eye from the pane's place,
// dimmed and added to by the air in front: T (C + (1 - a) B_g) + L, where B_g is the light
// reaching the pane from behind; the fogged frame without the pane holds B = T B_g + L, so the
// pixel is T C + a L + (1 - a) B. C (the pane's own light) comes from the frame without aerial
// perspective, C = P - (1 - a) B_clear; T and L from two opaque panes at the same place with and
// without it (y = T x + L per channel). The old order (the glass before sky.aerial, fogged as an
// opaque surface at its depth) gives T (C + (1 - a) B_clear) + L instead: the background seen
// through the pane gets the pane's fog over (or instead of) its own.
TEST_CASE("gl: a far transparent pane fogs itself at its own distance over a background fogged to its own") {
    PaneFiles files;
    Settings fog = paneScene(files.flat);
    fog.sky.enabled = true;
    fog.clouds.enabled = false;
    fog.sky.height_fog = true;
    fog.sky.fog_density_per_km = 2.0f;  // falling off over 200 m: dense under the camera, thin above it
    fog.objects.max_distance_m = 10000.0f;
    fog.objects.impostor_distance_m = fog.objects.max_distance_m;  // meshes, no impostors
    Settings clear = fog;
    clear.sky.aerial_perspective = false;
    const double ground = kFlat * kHeightScale;
    const glm::dvec3 base(0.0, ground, -2500.0);
    const ViewParams view{{0.0, ground + 270.0, 0.0}, 0.0, -4.5, 20.0, 0.1f, 160, 90};
    auto with = [&](const Settings& s, const std::filesystem::path& file) {
        return withObjects(s, {{"pane", placed(file, base, 100.0f)}});
    };
    const auto points = paneGrid(base, 100.0, 0.0, -0.7, 0.7, 0.2, 1.8);

    const test::RenderedFrame frame = render(with(fog, files.red), view);
    CHECK(frame.report.counters.at("objects.transparent_fogged") == 1.0);
    const auto& passes = frame.report.executed;
    const auto order = [&](const char* name) { return std::find(passes.begin(), passes.end(), name) - passes.begin(); };
    CHECK(order("sky.aerial") < order("objects.transparent"));
    const auto p = pixelsAt(frame, view, points);
    const auto b = pixelsAt(render(withObjects(fog, {}), view), view, points);
    const auto p_clear = pixelsAt(render(with(clear, files.red), view), view, points);
    const auto b_clear = pixelsAt(render(withObjects(clear, {}), view), view, points);
    const auto y_a = pixelsAt(render(with(fog, files.light), view), view, points);
    const auto y_b = pixelsAt(render(with(fog, files.dark), view), view, points);
    const auto x_a = pixelsAt(render(with(clear, files.light), view), view, points);
    const auto x_b = pixelsAt(render(with(clear, files.dark), view), view, points);
    const float a = 0.5f;
    std::vector<glm::vec3> expected(points.size()), old_order(points.size());
    double kept = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::vec3 t = (y_a[i] - y_b[i]) / (x_a[i] - x_b[i]), l = y_a[i] - t * x_a[i];
        const glm::vec3 c = p_clear[i] - (1.0f - a) * b_clear[i];
        expected[i] = t * c + a * l + (1.0f - a) * b[i];
        old_order[i] = t * (c + (1.0f - a) * b_clear[i]) + l;
        kept += double(t.g) / double(points.size());
    }
    INFO("transmittance to the pane " << kept);
    CHECK(kept > 0.05);  // the fog is strong there (measured 0.17), but the pane shows through it
    CHECK(kept < 0.5);
    const double error = relativeError(p, expected), old_error = relativeError(old_order, expected);
    INFO("relative error " << error << ", the old order's " << old_error);
    CHECK(error < 0.01);       // measured 0.0002
    CHECK(old_error > 0.04);  // the test tells the orders apart (measured 0.069)
}

namespace {

// How much of a light the glass keeps where a shadow falls on it, against an opaque pane. The
// pane (red glass, or the light opaque one) stands at `base` turned by yaw; `shadowed` and
// `unshadowed` are the same scene with the light's shadows on and off. The glass's own light is
// C = P - (1 - a) B (B: the same view without the pane), summed over each area.
struct ShadowShare {
    double glass = 0.0;       // red: C in the shaded area with shadows over C without them
    double opaque = 0.0;      // red: the same for the opaque pane's pixels
    double lit_change = 0.0;  // red: C in the lit area with shadows over C without them
};
ShadowShare shadowShare(const PaneFiles& files, const Settings& shadowed, const Settings& unshadowed, glm::dvec3 base,
                        double scale, double yaw_deg, const ViewParams& view, const std::vector<glm::dvec3>& shaded,
                        const std::vector<glm::dvec3>& lit) {
    auto with = [&](const Settings& settings, const std::filesystem::path& file) {
        return withObjects(settings, {{"pane", placed(file, base, float(scale), float(yaw_deg), 0.5f)}});
    };
    auto own = [&](const Settings& settings, const std::vector<glm::dvec3>& points) {
        const test::RenderedFrame p = render(with(settings, files.red), view), b = render(withObjects(settings, {}), view);
        const auto pp = pixelsAt(p, view, points), bb = pixelsAt(b, view, points);
        glm::dvec3 sum(0.0);
        for (std::size_t i = 0; i < pp.size(); ++i) sum += glm::dvec3(pp[i] - 0.5f * bb[i]);
        return sum;
    };
    auto opaque = [&](const Settings& settings, const std::vector<glm::dvec3>& points) {
        const auto pp = pixelsAt(render(with(settings, files.light), view), view, points);
        glm::dvec3 sum(0.0);
        for (const glm::vec3& v : pp) sum += glm::dvec3(v);
        return sum;
    };
    ShadowShare share;
    share.glass = own(shadowed, shaded).r / own(unshadowed, shaded).r;
    share.opaque = opaque(shadowed, shaded).r / opaque(unshadowed, shaded).r;
    share.lit_change = own(shadowed, lit).r / own(unshadowed, lit).r;
    return share;
}

}  // namespace

TEST_CASE("gl: a transparent pane half in a pillar's sun shadow is darker there by the share the sun gives an opaque pane") {
    PaneFiles files;
    Settings s = paneScene(test::pillarHeightmap("pane_shadow"));
    s.terrain.size_m = 256.0f;
    s.terrain.height_scale_m = 40.0f;
    s.sky.enabled = true;
    s.sky.aerial_perspective = false;  // the shadow alone acts on the glass
    s.clouds.enabled = false;
    s.sky.sun_azimuth_deg = 90.0f;  // east: the pillar's shadow falls towards -x over |z| < 4 m
    s.sky.sun_elevation_deg = 45.0f;
    s.shadows.enabled = true;
    Settings unshadowed = s;
    unshadowed.shadows.enabled = false;
    // Turned 45 degrees towards the sun; across it from z = -2.7 (in the shadow) to -8.3 m (lit),
    // seen from 11 m along its normal.
    const glm::dvec3 base(-15.0, 0.0, -5.5);
    const ViewParams view{{-7.0, 4.5, 2.5}, -45.0, 0.0, 40.0, 0.1f, 160, 90};
    const glm::dvec3 standing = base + glm::dvec3(0.0, 0.5, 0.0);
    const ShadowShare share = shadowShare(files, s, unshadowed, base, 4.0, 45.0, view,
                                          paneGrid(standing, 4.0, 45.0, -0.9, -0.6, 0.3, 1.3),
                                          paneGrid(standing, 4.0, 45.0, 0.6, 0.9, 0.3, 1.3));
    INFO("glass in the shadow keeps " << share.glass << ", an opaque pane " << share.opaque);
    CHECK(share.lit_change == doctest::Approx(1.0).epsilon(0.03));  // the lit half is as without shadows
    CHECK(share.opaque < 0.7);                                      // the shadow is there
    CHECK(share.glass == doctest::Approx(share.opaque).epsilon(0.08));
}

// The local lights' shadows reach the glass (object.glsl FORWARD + HAS_SPOT_SHADOWS /
// HAS_POINT_SHADOWS): at night, a lamp 20 m east of the pillar (11.4 m wide at the lamp's height)
// throws its shadow west; at x = -15 its edge is near z = -11.5. A pane there facing the lamp, from
// z = -6 (shadowed) to -17 m (lit), is darker in the shadow by the share an opaque pane loses, and
// as bright as without shadows in the light. A spot aimed at the pane, then a point light.
TEST_CASE("gl: a transparent pane half in a pillar's spot or point-light shadow is darker there like an opaque pane") {
    PaneFiles files;
    Settings s = paneScene(test::pillarHeightmap("pane_shadow"));
    s.terrain.size_m = 256.0f;
    s.terrain.height_scale_m = 40.0f;
    s.sky.enabled = true;
    s.sky.aerial_perspective = false;  // the shadow alone acts on the glass
    s.clouds.enabled = false;
    s.sky.sun_elevation_deg = -30.0f;  // night: the lamp is the light
    s.shadows.enabled = true;
    s.lights.enabled = true;
    Light lamp;
    lamp.position = glm::dvec3(20.0, 6.0, -1.7);
    lamp.radius_m = 80.0f;
    lamp.intensity = 2000.0f;
    const glm::dvec3 base(-15.0, 0.0, -11.5);
    const ViewParams view{{5.0, 6.0, -11.5}, -90.0, -5.0, 50.0, 0.1f, 160, 90};  // looking west
    const glm::dvec3 standing = base + glm::dvec3(0.0, 0.5, 0.0);
    // yaw 90: the pane's normal is +x (towards the lamp), its u axis -z.
    const auto shaded = paneGrid(standing, 5.5, 90.0, -0.85, -0.55, 0.3, 1.3);  // z -6.8 .. -8.5
    const auto lit = paneGrid(standing, 5.5, 90.0, 0.55, 0.85, 0.3, 1.3);       // z -14.5 .. -16.2
    for (const LightType type : {LightType::Spot, LightType::Point}) {
        Light l = lamp;
        l.type = type;
        l.direction = glm::normalize(glm::vec3(-35.0f, -3.0f, -9.8f));  // spot: towards the pane's middle
        l.inner_deg = 40.0f;
        l.outer_deg = 60.0f;
        Settings shadowed = s;
        shadowed.lights.lights = {{"lamp", l}};
        shadowed.shadows.spot_enabled = type == LightType::Spot;
        shadowed.shadows.point_enabled = type == LightType::Point;
        shadowed.shadows.point_resolution = 512;
        Settings unshadowed = shadowed;
        unshadowed.shadows.spot_enabled = unshadowed.shadows.point_enabled = false;
        const test::RenderedFrame frame = render(withObjects(shadowed, {{"pane", placed(files.red, base, 5.5f, 90.0f, 0.5f)}}), view);
        const char* counter = type == LightType::Spot ? "shadows.spot_shadowed" : "shadows.point_shadowed";
        CHECK(frame.report.counters.at(counter) == 1.0);
        const ShadowShare share = shadowShare(files, shadowed, unshadowed, base, 5.5, 90.0, view, shaded, lit);
        INFO(std::string(type == LightType::Spot ? "spot" : "point") << ": glass in the shadow keeps " << share.glass
             << ", an opaque pane " << share.opaque << ", the lit part " << share.lit_change);
        CHECK(share.lit_change == doctest::Approx(1.0).epsilon(0.05));
        CHECK(share.opaque < 0.5);  // measured 1e-7: the lamp is the only light, the pillar hides it
        CHECK(std::abs(share.glass - share.opaque) < 0.05);  // unshadowed glass kept 1.0
    }
}

}  // namespace transparent_case

TEST_CASE("gl: scatter rules too dense for the whole terrain are placed around the camera, and again as it moves") {
    test::TempDir dir("objects-local");
    const Heightmap map{65, 65, std::vector<float>(65 * 65, kFlat)};
    const std::filesystem::path file = dir.path / "flat.png";
    REQUIRE(saveHeightmapPng16(file, map).empty());
    Settings s = bareScene(file);
    s.terrain.size_m = 400000.0f;  // 160 M candidates over the whole terrain: more than kMaxScatterCandidates
    s.objects.max_distance_m = 500.0f;
    ScatterRule rule;
    rule.files = {(vistaRoot() / "data/props/tree.glb").string()};
    s.objects.scatters.push_back({"trees", rule});
    s.camera.position = {0.0, 50.0, 0.0};
    REQUIRE_FALSE(scatterBudgetProblem(s.objects, ScatterArea{{-2.0e5, -2.0e5}, {2.0e5, 2.0e5}}).empty());

    // The x, z of the placed instances, against every candidate of the camera-local area's cells
    // (the flat ground keeps them all).
    auto placed = [&] {
        std::vector<std::pair<double, double>> xz;
        for (const auto& list : renderer().objects()->placed())
            for (const PlacedObject& p : list) xz.emplace_back(p.position.x, p.position.z);
        std::sort(xz.begin(), xz.end());
        return xz;
    };
    auto expected = [&](glm::dvec2 centre) {
        const ScatterArea area = localScatterArea(centre, s.objects.max_distance_m);
        const GroundFunction flat = [](double, double) { return GroundSample{true, 0.0, 0.0, 1.0}; };
        std::vector<std::pair<double, double>> xz;
        for (const PlacedObject& p : scatterRegion(rule, scatterCellOf(rule, area.min), scatterCellOf(rule, area.max), flat))
            xz.emplace_back(p.position.x, p.position.z);
        std::sort(xz.begin(), xz.end());
        return xz;
    };
    auto at = [](double x, double z) { return ViewParams{{x, 50.0, z}, 0.0, -10.0, 60.0, 0.5, 64, 36}; };

    const Frame start = render(s, at(0.0, 0.0));
    CHECK(start.report.counters.at("objects.local") == 1.0);
    CHECK(start.report.counters.at("objects.replaced") == 0.0);  // placed around [camera] position by prepare
    const auto first = placed();
    CHECK(first.size() > 1000);  // 1500 m square at 0.001 per m^2: about 2250
    CHECK(first == expected({0.0, 0.0}));
    // Within (1.5 - 1) x max_distance_m of the centre: kept.
    CHECK(render(s, at(200.0, -200.0)).report.counters.at("objects.replaced") == 0.0);
    CHECK(placed() == first);
    // Beyond it: placed around the camera.
    CHECK(render(s, at(3000.0, 0.0)).report.counters.at("objects.replaced") == 1.0);
    CHECK(placed() == expected({3000.0, 0.0}));
    // Back: the same instances as at the start (a cell always holds the same ones).
    CHECK(render(s, at(0.0, 0.0)).report.counters.at("objects.replaced") == 1.0);
    CHECK(placed() == first);
    // Half way to the margin: the next placement is made on another thread and swapped in by a
    // later frame, without the frame waiting for it.
    CHECK(render(s, at(150.0, 0.0)).report.counters.at("objects.replaced") == 0.0);
    CHECK(placed() == first);
    bool swapped = false;
    for (int i = 0; i < 200 && !swapped; ++i) swapped = render(s, at(150.0, 0.0)).report.counters.at("objects.replaced") == 1.0;
    CHECK(swapped);
    CHECK(placed() == expected({150.0, 0.0}));
    // Over the whole terrain when it fits: the island, not the camera's surroundings.
    s.terrain.size_m = 8192.0f;
    CHECK(render(s, at(0.0, 0.0)).report.counters.at("objects.local") == 0.0);
}
