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


// A 2 x 2 m double-sided pane in the model's x-y plane, BLEND, the given colour at alpha 0.5.
Model pane(glm::vec3 colour) {
    Model m;
    m.name = "pane";
    for (int c = 0; c < 4; ++c) {
        MeshVertex v;
        v.uv = glm::vec2(float(c == 1 || c == 2), float(c >= 2));
        v.position = glm::vec3(v.uv.x * 2.0f - 1.0f, v.uv.y * 2.0f, 0.0f);
        v.normal = glm::vec3(0.0f, 0.0f, 1.0f);
        m.vertices.push_back(v);
    }
    m.indices = {0, 1, 2, 0, 2, 3};
    ModelMaterial mat;
    mat.base_color = glm::vec4(colour, 0.5f);
    mat.metallic = 0.0f;
    mat.roughness = 0.8f;
    mat.alpha_mode = AlphaMode::Blend;
    mat.double_sided = true;
    m.materials = {mat};
    m.lods = {ModelLod{{ModelPrimitive{0, 6, 0}}}};
    m.bounds_min = glm::vec3(-1.0f, 0.0f, 0.0f);
    m.bounds_max = glm::vec3(1.0f, 2.0f, 0.0f);
    return m;
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

}  // namespace transparent_case
