// Octahedral impostors (Ryan Brucks' "octahedral impostors", Fortnite 2018): a model rendered at
// bake time from kImpostorFrames x kImpostorFrames directions over the upper hemisphere, laid out
// by the hemi-octahedral map, into an atlas of the G-buffer's own encodings (emissive, albedo and
// roughness, normal and F0; coverage in the normal's w). A distant instance is then one quad
// showing the frame nearest its view direction, written into the G-buffer and lit like the mesh.
// The maps here are the CPU side of object_common.glsl's hemiOctEncode / hemiOctDecode /
// impostorBasis (tests/unit/impostor_test.cpp holds them to each other).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace vista {

constexpr int kImpostorFrames = 8;      // frames per side of the grid (directions on its edge: the horizon)
constexpr int kImpostorFramePx = 64;    // texels per frame side (a tree fills ~30 px at 150 m, 640x360)
constexpr int kImpostorMipLevels = 4;   // 64 .. 8 texels a frame: coarser levels would mix frames

// Upper hemisphere <-> [-1, 1]^2 (directions below the horizon are folded onto it).
glm::vec2 hemiOctEncode(glm::vec3 d);
glm::vec3 hemiOctDecode(glm::vec2 e);
// The unit direction (toward the viewer, model space) that frame (i, j) of the grid shows.
glm::vec3 impostorFrameDirection(int i, int j);
// The frame whose direction is nearest the grid's rounding of d.
glm::ivec2 impostorFrameOf(glm::vec3 d);
// The card's right and up axes seen from unit direction d.
void impostorBasis(glm::vec3 d, glm::vec3& right, glm::vec3& up);
// Model space -> clip for baking frame direction d: orthographic, the sphere (centre, radius)
// filling the frame, depth 1 nearest the viewer (reversed-Z, [0, 1] clip depth).
glm::mat4 impostorBakeMatrix(glm::vec3 d, glm::vec3 centre, float radius);

}  // namespace vista
