// Rain and snow maths without GL: the CPU half of sky/weather/shaders/weather_rain.glsl,
// weather_splash.glsl and rain_ripples.glsl, and their mirror for the tests.
//
// Drops: a static lattice of cubic cells in a "fall frame" that moves with the wind and the
// fall speed, so a world point p shows the field point q = p - offset(t), offset(t) = (wind
// offset x, -speed t, wind offset z). The cube of cells x cells x cells field cells centred on
// the camera's cell (001's placement box; a cell is addressed by its offset o from the box's
// min cell, as no per-slot state outlives a frame) covers every point within radius_m; drop j
// of field cell n takes its place and looks from a hash of (n, j): the same field cell always
// holds the same drops. Drop j is drawn while j + random_j < intensity x drops_per_cell, so a
// rising intensity adds drops and keeps the others. offset(t) and the camera's cell are
// computed here in double and 64-bit integers, so the GPU only sees small camera-relative
// floats and 32-bit wrapped cell ids (for the hash): a camera 10,000 km out at t = 1e7 s rains
// as at the origin at t = 0. The CPU lists the cells that can show a drop in the view
// (visibleDropCells); the GPU draws ceil(intensity x drops_per_cell) quads per listed cell.
//
// Splashes: a square of ground cells around the camera; slot j of ground cell m makes one
// splash per period at a place hashed from (m, j, cycle k), k = floor(t / period + phase_j).
// The cycle count and phase are split in double here (integer part, fraction).
#pragma once

#include "sky/clouds/cloud_settings.h"
#include "sky/weather/weather_settings.h"
#include "terrain/cdlod.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace vista {

inline constexpr int kMaxDropsPerCell = 256;
inline constexpr int kMaxSplashSlots = 64;
inline constexpr double kSplashCellM = 1.0;     // ground cell side of the splash lattice
inline constexpr double kSnowSwayM = 0.25;      // snow: amplitude of the flakes' sideways sway
inline constexpr double kSnowSwayHz = 0.35;     // snow: sway frequency

// The hash of the drop and splash shaders (sky/weather/shaders/weather_common.glsl weatherHash): the
// clouds' integer avalanche (cloudHash) folded over four words.
std::uint32_t weatherHash(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d);
// Random number k in [0, 1) of a drop or splash whose hash is h (weatherRandom in GLSL).
float weatherRandom(std::uint32_t h, std::uint32_t k);

struct DropLayout {
    int half = 1;             // cells from the camera's cell to the box edge, per axis
    int cells = 3;            // box side in cells: 2 half + 1
    int drops_per_cell = 1;
    double cell_m = 2.0;
    std::int64_t candidates() const { return std::int64_t(cells) * cells * cells * drops_per_cell; }
};
// The box holds every point within radius_m of the camera.
DropLayout dropLayout(const WeatherSettings& s);

// Horizontal wind (m/s, world x and z) at time t, and how far it has carried the drops (m).
glm::dvec2 weatherWindVelocity(const WeatherSettings& s, const CloudsSettings& clouds, double t);
glm::dvec2 weatherWindOffset(const WeatherSettings& s, const CloudsSettings& clouds, double t);
// The fall frame's offset at t (m, world): q = p - offset.
glm::dvec3 dropFieldOffset(const WeatherSettings& s, const CloudsSettings& clouds, double t);

// What the rain shader needs for one frame.
struct DropFrame {
    glm::ivec3 box_min{0};  // the box's min field cell, wrapped to 32 bits (hash input only)
    glm::vec3 frac{0.0f};   // the camera's field position inside its cell, in [0, 1)
    float sway_phase = 0.0f;  // snow: 2 pi kSnowSwayHz t mod 2 pi
};
DropFrame dropFrame(const DropLayout& layout, const glm::dvec3& eye, const glm::dvec3& field_offset, double t);

// Drop j of the box cell at offset o (0..cells-1 per axis) from box_min (CPU mirror of the
// rain vertex shader's placement).
struct Drop {
    glm::ivec3 cell{0};     // field cell (32-bit wrapped)
    glm::dvec3 rel{0.0};    // camera-relative position (m), without the snow sway
    float keep = 0.0f;      // in [0, 1): drawn while j + keep < intensity x drops_per_cell
    float size = 1.0f;      // width factor, 0.6..1.4
    float phase = 0.0f;     // rad, snow sway phase
};
Drop dropAt(const DropLayout& layout, const DropFrame& frame, glm::ivec3 o, int j);
// Drops per cell the GPU draws at an intensity (the others can never be kept).
int dropsDrawnPerCell(const DropLayout& layout, float intensity);
// Offset o packed as the shader unpacks it: o.x + cells (o.y + cells o.z).
inline std::uint32_t packDropCell(glm::ivec3 o, int cells) {
    return std::uint32_t(o.x + cells * (o.y + cells * o.z));
}
// The packed cells of the box that may show a drop: those with a point within radius_m of the
// camera and not wholly outside the view frustum (camera-relative planes), each widened by
// reach_m (the streak's length, the snow sway) first.
void visibleDropCells(const DropLayout& layout, const DropFrame& frame, const Frustum& planes, double radius_m,
                      double reach_m, std::vector<std::uint32_t>& out);

struct SplashLayout {
    int half = 1, cells = 3;  // ground cells per side: 2 half + 1
    int slots = 1;            // splash slots per cell
    double period_s = 0.5;    // each slot splashes once per period (life = a quarter of it)
    std::int64_t candidates() const { return std::int64_t(cells) * cells * slots; }
};
// period = 4 splash_life_s; enough slots per cell for splash_rate splashes per m^2 per s at
// intensity 1 (at most kMaxSplashSlots: faster rates are capped there).
SplashLayout splashLayout(const WeatherSettings& s);
// Share of a cell's slots that splash at intensity 1.
double splashFill(const SplashLayout& layout, const WeatherSettings& s);

struct SplashFrame {
    glm::ivec2 box_min{0};   // the box's min ground cell (wrapped to 32 bits)
    glm::vec2 frac{0.0f};    // the camera inside its ground cell, in [0, 1)
    std::uint32_t cycle = 0; // floor(t / period), low 32 bits
    float cycle_frac = 0.0f; // t / period - floor(t / period), in [0, 1)
};
SplashFrame splashFrame(const SplashLayout& layout, const glm::dvec2& eye_xz, double t);

struct Splash {
    glm::dvec2 rel_xz{0.0};  // camera-relative (m)
    float age = 0.0f;        // share of the period since it started, in [0, 1): visible below 0.25
    float keep = 0.0f;       // in [0, 1): splashes this cycle while j + keep < splashesKept()
    std::uint32_t cycle = 0;
};
// Slot j of the ground cell at offset o (0..cells-1 per axis) from box_min.
Splash splashAt(const SplashLayout& layout, const SplashFrame& frame, glm::ivec2 o, int j);
// intensity x splashFill x slots: slot j splashes in a cycle while j + keep < this.
double splashesKept(const SplashLayout& layout, const WeatherSettings& s);

// How wet the terrain is (0 dry .. 1 soaked): wetness * min(1, 2 intensity) while it rains.
float weatherWetness(const WeatherSettings& s);

// Rain ripples for water surfaces (sky/weather/shaders/rain_ripples.glsl rainRippleNormal, mirrored
// here in double): expanding rings in 0.5 m cells, periodic over kRippleWrapM in x and z and
// kRippleWrapS in time, so callers wrap world x/z and time in double first (rainRippleWrap).
inline constexpr double kRippleWrapM = 32.0;
inline constexpr double kRippleWrapS = 8.0;
struct RippleInput {
    glm::vec2 xz{0.0f};  // in [0, kRippleWrapM)
    float time = 0.0f;   // in [0, kRippleWrapS)
};
RippleInput rainRippleWrap(const glm::dvec2& world_xz, double time_s);
// Unit normal (y up) of the rippled surface at wrapped xz and time; (0, 1, 0) at intensity 0.
glm::dvec3 rainRippleNormal(glm::dvec2 xz, double time, double intensity);

}  // namespace vista
