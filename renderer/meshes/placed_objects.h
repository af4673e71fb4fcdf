// What Objects (renderer/meshes/objects.h) draws: instances of glTF models, as the placement
// (terrain/scatter/scatter.h placeObjects: [objects]' lists over the terrain) gives them.
#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace vista {

struct PlacedObject {
    glm::dvec3 position{0.0};  // world, m (on the ground)
    float yaw_rad = 0.0f;
    float scale = 1.0f;
    int file = 0;  // index into its placement's files
    bool operator==(const PlacedObject&) const = default;
};

// The instances of one list entry (object.NAME, scatter.NAME): each is a model of files[file].
struct ObjectPlacement {
    std::string entry;               // "object.mill": names the entry in problems with its files
    std::vector<std::string> files;  // glTF/GLB paths as the scene gives them
    std::vector<PlacedObject> instances;
};

}  // namespace vista
