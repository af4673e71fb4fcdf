// Grass placement and wind maths without GL: the CPU half of the grass shaders
// (terrain/grass/shaders/grass_common.glsl, grass_cull.glsl, grass.glsl) and its mirror for tests.
//
// Placement (after 001's toroidal wrap): a square box of cells x cells placement cells is
// centred ahead of the camera along the view. Slot s of the box (0..cells-1 per axis) shows
// the world cell n = s + cells * ceil((c - s) / cells - 0.5), c = the box's centre cell, i.e.
// the one cell congruent to s (mod cells) inside [min, min + cells); computed exactly in
// integers from the box's min cell. Blade j of world cell n takes its position and looks from
// a hash of (n.x, n.z, j): the same place always shows the same blades.
#pragma once

#include "renderer/random.h"
#include "terrain/grass/grass_settings.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace vista {

// Integer hash shared with grass_common.glsl (grassHash): same bits on CPU and GPU.
inline std::uint32_t grassHash(std::uint32_t x, std::uint32_t y, std::uint32_t z) { return hashInts(x, y, z); }
// Random number k in [0, 1) of a blade whose hash is h (grassRandom in GLSL).
inline float grassRandom(std::uint32_t h, std::uint32_t k) {
    return float(grassHash(h, k, 0x2545f491u) >> 8) * (1.0f / 16777216.0f);
}

struct GrassLayout {
    int cells = 1;            // placement box side, in cells
    int blades_per_cell = 1;  // candidates per cell
    double cell_m = 1.0;
    double shift_m = 0.0;     // box centre ahead of the camera at a level view (m)
    std::int64_t candidates() const { return std::int64_t(cells) * cells * blades_per_cell; }
};
// Box size and blades per cell for the settings: the box (half side 0.8 radius, plus one cell
// for the snapping to whole cells) shifted forward_shift * radius ahead holds every point
// within radius_m of the camera that a 60 deg (vertical) 16:9 view sees (tested).
GrassLayout grassLayout(const GrassSettings& s);

// The box for a camera at eye_xz looking along forward (3D unit vector; the box moves along
// its horizontal heading): its min cell (world cell coordinates).
glm::ivec2 grassBoxMin(const GrassLayout& layout, glm::dvec2 eye_xz, glm::dvec3 forward);
// The world cell slot s shows for a box starting at box_min (integer form, as the shader).
glm::ivec2 grassWrapCell(glm::ivec2 slot, glm::ivec2 box_min, int cells);
// 001's form for one axis: n = ceil((eye - p) / size - 0.5), p' = p + size * n.
double grassWrapSource(double p, double eye, double size);

// What the hash gives a candidate (before terrain and distance decide whether it grows).
struct GrassCandidate {
    glm::dvec2 world_xz{0.0};  // m
    float facing = 0.0f;       // rad, blade plane rotation about y
    float height_factor = 1.0f;
    float thin = 0.0f;         // in [0, 1): gone once the kept share drops below it
    float density = 0.0f;      // in [0, 1): grows where the grass weight exceeds it
    float curvature = 0.0f;    // in [0, 1): share of the maximum rest bend
    float phase = 0.0f;        // rad, sway phase
    int frequency_step = 8;    // sway frequency = base * step / 8 (6..10)
};
GrassCandidate grassCandidate(const GrassLayout& layout, glm::ivec2 cell, int blade, const GrassSettings& s);

// Distance shaping: kept share of blades at distance d, and a blade's height factor there
// (shrinks to 0 as the kept share passes its thin value and toward radius_m).
double grassKeep(const GrassSettings& s, double d);
double grassFade(const GrassSettings& s, double d, double thin);

// Wind for one frame. Time-dependent phases are wrapped here in double precision so the
// shader's floats stay small at any run time: the gust field is periodic (kGustPeriod noise
// cells) and is sampled at camera-relative coordinates plus a wrapped origin; per-blade sway
// frequencies are integer multiples of base / 8, so one phase wrapped mod 2 pi serves all.
constexpr int kGustPeriod = 64;
struct GrassWind {
    glm::vec2 dir{0.0f, -1.0f};   // horizontal unit vector the wind blows toward (x, z)
    glm::vec2 gust_origin{0.0f};  // noise coordinates of the camera, in [0, kGustPeriod)
    float inv_gust_scale = 1.0f;  // noise cells per metre
    float sway_phase = 0.0f;      // rad in [0, 2 pi): 2 pi f t / 8, wrapped
    float strength = 0.0f, gust = 0.0f, sway = 0.0f;  // rad
};
GrassWind grassWind(const GrassSettings& s, glm::dvec2 eye_xz, double time_s);
// Gust noise in [0, 1] at noise coordinates q (periodic).
float grassGustNoise(glm::vec2 q);
// Horizontal tilt (rad, along x and z) the wind gives a blade at camera-relative rel_xz.
glm::vec2 grassWindTilt(const GrassWind& w, glm::vec2 rel_xz, float phase, int frequency_step);

// Point at level k (0..segments) of a blade of the given length whose segments turn toward
// bend_dir (horizontal unit vector) by angles growing to tip_angle: each segment is a rotated
// copy of the rest one, so the length is kept exactly. Relative to the root, y up.
glm::dvec3 grassBladePoint(double length, double tip_angle, glm::dvec2 bend_dir, int segments, int k);

// The blades' mean albedo (linear), for the terrain's far grass colour.
glm::vec3 grassMeanAlbedo(const GrassSettings& s);

}  // namespace vista
