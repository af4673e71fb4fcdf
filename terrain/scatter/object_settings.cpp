// [objects] keys and the object.NAME / scatter.NAME text format (see object_settings.h). Strict
// like the light lists: every token checked, so a typo is an error, not a missing forest.
#include "terrain/scatter/object_settings.h"

#include "config/spec_text.h"

#include <cmath>

namespace vista {
namespace {

using spec::Reader;
using spec::str;

bool isNumber(std::string_view t) {
    double v;
    return spec::toDouble(t, v);
}
bool isModelFile(std::string_view t) {
    return t.size() > 5 && (t.ends_with(".glb") || t.ends_with(".gltf") || t.ends_with(".GLB") || t.ends_with(".GLTF"));
}

void describeObject(SettingsVisitor& v, ObjectInstanceSpec& o) {
    v.field({"file", "", "glTF/GLB model (.gltf or .glb)"}, o.file);
    v.field({"position", "m", "world position"}, o.position, -1.0e8, 1.0e8);
    v.field({"ground", "m", "height above the terrain; -1 = the position's y"}, o.ground_m, -1.0f, 1.0e4f);
    v.field({"yaw", "deg", "turn about +y"}, o.yaw_deg, -360.0f, 360.0f);
    v.field({"scale", "", "uniform scale"}, o.scale, 0.001f, 1000.0f);
}

void describeScatter(SettingsVisitor& v, ScatterRule& r) {
    v.field({"density", "1/m^2", "instances per square metre before the limits"}, r.density, 0.0, 1.0);
    v.field({"height_min", "m", "lowest ground"}, r.height_min_m, -1.0e4f, 1.0e4f);
    v.field({"height_max", "m", "highest ground"}, r.height_max_m, -1.0e4f, 1.0e4f);
    v.field({"slope", "", "steepest ground (rise over run)"}, r.slope_max, 0.0f, 100.0f);
    v.field({"grass", "", "least grass weight of the terrain material"}, r.grass_min, 0.0f, 1.0f);
    v.field({"scale_min", "", "smallest scale"}, r.scale_min, 0.001f, 1000.0f);
    v.field({"scale_max", "", "largest scale"}, r.scale_max, 0.001f, 1000.0f);
    v.field({"cell", "m", "placement cell side"}, r.cell_m, 4.0f, 4096.0f);
    int seed = int(r.seed & 0x7FFFFFFFu);
    v.field({"seed", "", "random seed"}, seed, 0, 0x7FFFFFFF);
    r.seed = std::uint32_t(seed);
}

}  // namespace

void describe(SettingsVisitor& v, ObjectsSettings& s) {
    v.section("objects", "glTF models placed one by one and scattered over the terrain (renderer/meshes/objects.h)");
    v.field({"enabled", "", "draw the objects; off (or no entries): no pass, no buffers"}, s.enabled);
    v.field({"lod1_distance_m", "m", "the first simplified LOD beyond this distance"}, s.lod1_distance_m, 1.0f, 1.0e5f);
    v.field({"lod2_distance_m", "m", "the coarsest LOD beyond this distance"}, s.lod2_distance_m, 1.0f, 1.0e5f);
    v.field({"max_distance_m", "m", "instances farther from the camera are not drawn"}, s.max_distance_m, 1.0f, 1.0e6f);
    v.field({"impostor_distance_m", "m", "an octahedral impostor (one textured quad, baked at load) replaces the mesh beyond this distance"},
            s.impostor_distance_m, 1.0f, 1.0e6f);
    v.field({"impostor_fade_m", "m", "the mesh dithers into the impostor over this band before impostor_distance_m"},
            s.impostor_fade_m, 0.0f, 1.0e4f);
    v.field({"shadow_distance_m", "m", "instances within this distance cast shadows"}, s.shadow_distance_m, 0.0f, 1.0e5f);
    v.field({"cast_shadows", "", "objects cast into the sun cascades and the spot atlas"}, s.cast_shadows);
    v.field({"emissive_nits", "cd/m^2", "luminance of emissive factor 1 (glowing windows)"}, s.emissive_nits, 0.0f, 1.0e6f);
    NamedList objects(s.objects, &NamedObject::object, parseObjectSpec, formatObjectSpec, describeObject);
    v.list({"object", "", "one model: FILE X Y Z (m), then any of ground H (m above the terrain), yaw DEG, scale S"}, objects);
    NamedList scatters(s.scatters, &NamedScatter::rule, parseScatterSpec, formatScatterSpec, describeScatter);
    v.list({"scatter", "", "a scatter rule: FILE... then any of density D (1/m^2), height MIN MAX (m), slope MAX, "
                           "grass W, scale MIN MAX, cell C (m), seed N"},
           scatters);
}

std::string parseObjectSpec(std::string_view text, ObjectInstanceSpec& out) {
    Reader r(text);
    std::string_view file = r.word();
    if (!isModelFile(file)) return "expected a model file (.gltf or .glb) first, got '" + std::string(file) + "'";
    out.file = std::string(file);
    std::string error;
    double v[3];
    if (!r.numbers("position", v, 3, -1e8, 1e8, error)) return error;
    out.position = glm::dvec3(v[0], v[1], v[2]);
    while (!r.done()) {
        std::string_view key = r.word();
        if (key == "ground") {
            if (!r.numbers(key, v, 1, 0.0, 1e4, error)) return error;
            out.ground_m = float(v[0]);
        } else if (key == "yaw") {
            if (!r.numbers(key, v, 1, -360.0, 360.0, error)) return error;
            out.yaw_deg = float(v[0]);
        } else if (key == "scale") {
            if (!r.numbers(key, v, 1, 0.001, 1000.0, error)) return error;
            out.scale = float(v[0]);
        } else {
            return "unknown word '" + std::string(key) + "' (expected ground, yaw or scale)";
        }
    }
    return "";
}

std::string parseScatterSpec(std::string_view text, ScatterRule& out) {
    Reader r(text);
    out.files.clear();
    while (!r.done() && !isNumber(r.peek()) && isModelFile(r.peek())) out.files.emplace_back(r.word());
    if (out.files.empty()) return "expected one or more model files (.gltf or .glb) first, got '" + std::string(r.peek()) + "'";
    std::string error;
    double v[2];
    while (!r.done()) {
        std::string_view key = r.word();
        if (key == "density") {
            if (!r.numbers(key, v, 1, 0.0, 1.0, error)) return error;
            out.density = v[0];
        } else if (key == "height") {
            if (!r.numbers(key, v, 2, -1e4, 1e4, error)) return error;
            if (v[0] > v[1]) return "height: MIN " + str(v[0]) + " is above MAX " + str(v[1]);
            out.height_min_m = float(v[0]);
            out.height_max_m = float(v[1]);
        } else if (key == "slope") {
            if (!r.numbers(key, v, 1, 0.0, 100.0, error)) return error;
            out.slope_max = float(v[0]);
        } else if (key == "grass") {
            if (!r.numbers(key, v, 1, 0.0, 1.0, error)) return error;
            out.grass_min = float(v[0]);
        } else if (key == "scale") {
            if (!r.numbers(key, v, 2, 0.001, 1000.0, error)) return error;
            if (v[0] > v[1]) return "scale: MIN " + str(v[0]) + " is above MAX " + str(v[1]);
            out.scale_min = float(v[0]);
            out.scale_max = float(v[1]);
        } else if (key == "cell") {
            if (!r.numbers(key, v, 1, 4.0, 4096.0, error)) return error;
            out.cell_m = float(v[0]);
        } else if (key == "seed") {
            if (!r.numbers(key, v, 1, 0.0, 4294967295.0, error)) return error;
            if (v[0] != std::floor(v[0])) return "seed: " + str(v[0]) + " is not a whole number";
            out.seed = std::uint32_t(v[0]);
        } else {
            return "unknown word '" + std::string(key) + "' (expected density, height, slope, grass, scale, cell or seed)";
        }
    }
    return "";
}

std::string formatObjectSpec(const ObjectInstanceSpec& o) {
    std::string s = o.file + " " + str(o.position.x) + " " + str(o.position.y) + " " + str(o.position.z);
    if (o.ground_m >= 0.0f) s += "  ground " + str(o.ground_m);
    if (o.yaw_deg != 0.0f) s += "  yaw " + str(o.yaw_deg);
    if (o.scale != 1.0f) s += "  scale " + str(o.scale);
    return s;
}

std::string formatScatterSpec(const ScatterRule& r) {
    std::string s;
    for (const std::string& f : r.files) s += (s.empty() ? "" : " ") + f;
    s += "  density " + str(r.density) + "  height " + str(r.height_min_m) + " " + str(r.height_max_m) + "  slope " +
         str(r.slope_max) + "  grass " + str(r.grass_min) + "  scale " + str(r.scale_min) + " " + str(r.scale_max) +
         "  cell " + str(r.cell_m) + "  seed " + std::to_string(r.seed);
    return s;
}

}  // namespace vista
