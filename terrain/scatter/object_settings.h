// The [objects] section of a scene file (Settings::objects): glTF models placed one by one
// (object.NAME) and scattered by rules over the terrain (scatter.NAME), and how they are drawn.
// Built into vista_scene (no GL), like [lights]' light_settings.
//
// List keys (one line each in the file; keyword groups after the first words in any order):
//
//   object.mill   = data/props/house.glb  -2690 0 2745  ground 0  yaw 90  scale 1.2
//   scatter.woods = data/props/tree.glb data/props/tree.glb  density 0.002  height 2 200  slope 0.8
//                   grass 0.3  scale 0.7 1.3  cell 64  seed 3
//
//   object:  FILE X Y Z        glTF/GLB path (relative to the vista root) and world position (m)
//            ground H          m, [0, 1e4]: stand H above the terrain at X, Z (Y ignored)
//            yaw DEG           deg about +y, [-360, 360]
//            scale S           uniform, [0.001, 1000]
//   scatter: FILE...           one or more glTF/GLB paths (each candidate picks one at random)
//            density D         instances per m^2 before the limits, [0, 1]
//            height MIN MAX    m, world heights of the ground where instances may stand
//            slope MAX         largest ground slope (rise over run), [0, 100]
//            grass W           the terrain's grass weight must reach W, [0, 1] (0: any material)
//            scale MIN MAX     uniform scale range, each [0.001, 1000]
//            cell C            m, placement cell side, [4, 4096]
//            seed N            integer [0, 2^32 - 1]
#pragma once

#include "config/visitor.h"
#include "renderer/meshes/object_draw_settings.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vista {

struct ObjectInstanceSpec {
    std::string file = "data/props/house.glb";  // a default that parses (what an editor adds)
    glm::dvec3 position{0.0};
    float ground_m = -1.0f;  // >= 0: stand this high above the terrain (y ignored)
    float yaw_deg = 0.0f;
    float scale = 1.0f;
    bool operator==(const ObjectInstanceSpec&) const = default;
};

struct ScatterRule {
    std::vector<std::string> files{"data/props/tree.glb"};
    double density = 0.001;  // per m^2
    float height_min_m = -1.0e4f, height_max_m = 1.0e4f;
    float slope_max = 100.0f;
    float grass_min = 0.0f;
    float scale_min = 1.0f, scale_max = 1.0f;
    float cell_m = 64.0f;
    std::uint32_t seed = 1;
    bool operator==(const ScatterRule&) const = default;
};

struct NamedObject {
    std::string name;
    ObjectInstanceSpec object;
    bool operator==(const NamedObject&) const = default;
};
struct NamedScatter {
    std::string name;
    ScatterRule rule;
    bool operator==(const NamedScatter&) const = default;
};

//! Objects (renderer/meshes/objects.h): glTF models instanced into the G-buffer with GPU culling
//! and LODs, casting into the sun cascades and the spot atlas. No entries: no pass, no memory.
//! How they are drawn is ObjectDrawSettings' part (renderer/meshes/object_draw_settings.h); what
//! is placed where, the lists, is placed by terrain/scatter/scatter.h placeObjects().
struct ObjectsSettings : ObjectDrawSettings {
    bool enabled = true;
    std::vector<NamedObject> objects;    //!< object.NAME keys
    std::vector<NamedScatter> scatters;  //!< scatter.NAME keys
};

void describe(SettingsVisitor& v, ObjectsSettings& s);

// Text format of object.NAME / scatter.NAME (above). "" on success, else the bad token and
// what is accepted.
std::string parseObjectSpec(std::string_view text, ObjectInstanceSpec& out);
std::string parseScatterSpec(std::string_view text, ScatterRule& out);
std::string formatObjectSpec(const ObjectInstanceSpec& o);
std::string formatScatterSpec(const ScatterRule& r);

// Whether the section places anything (the objects feature exists only then).
inline bool objectsWanted(const ObjectsSettings& s) { return s.enabled && (!s.objects.empty() || !s.scatters.empty()); }

}  // namespace vista
