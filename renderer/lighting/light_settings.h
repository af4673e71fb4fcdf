// The [lights] section of a scene file (Settings::lights): culling method and its parameters,
// explicit lights, generation volumes and animation. describe() lists the plain keys and the two
// list keys below for a SettingsVisitor; the parse/format functions are the lists' text format.
//
// List keys (the ini format for explicit lights and generation volumes). Each entry is one key
// `light.NAME` or `volume.NAME`, NAME made of letters, digits and '_' and unique in the
// section; entries keep file order. The value is a type word and a position, then keyword groups
// in any order; omitted groups keep the defaults of Light / LightVolume (renderer/lights.h):
//
//   light.lantern = point 10 42 -5  color 1 0.7 0.4  candela 100            (radius auto)
//   light.beam    = spot 0 50 0  radius 40  color 1 1 1  lumens 2000  direction 0 -1 0  cone 20 30
//   light.old     = point 0 9 0  radius 12  intensity 30                      (HDR units, as before)
//   volume.village = box -200 30 -150  200 40 150  count 16 1 12  radius 18  intensity 40
//                    saturation 0.5  value 1  jitter 0.3  seed 23        (one line in the file)
//
//   point|spot X Y Z        m, world position (|X|,|Y|,|Z| <= 1e8)
//   radius R | auto         m, [0, 1e5]; 0 reaches nothing; auto (radius_m -1): from the intensity
//                           and cutoff_lux (lights.h autoRadiusM), the default with candela or lumens
//   color R G B             linear RGB, each [0, 1e3]; filters candela and lumens
//   candela C               cd, [0, 1e9], luminous intensity (a spot: on its axis)      unit Candela
//   lumens L                lm, [0, 1e9], flux over the cone's solid angle (lightSolidAngleSr) unit Lumen
//   intensity I             HDR irradiance at 1 m, [0, 1e7] (the old unit; scenes before issue 23) unit Hdr
//   direction X Y Z         spot axis, not all zero (normalised on use)
//   cone INNER OUTER        deg, spot half-angles, 0 <= INNER <= OUTER <= 180
//   shadow on|off           spot lights: may take a tile of the spot shadow atlas; point lights a
//                           depth cube with [shadows] point_enabled (default on)
//   ground H                m, [0, 1e4]: the light stands H above the terrain at its x, z (y ignored)
//   box X0 Y0 Z0 X1 Y1 Z1   m, world, two opposite corners
//   count NX NY NZ          lights per axis, each [1, 10000], product <= kMaxVolumeLights
//   saturation S, value V   HSV of the random hue, [0, 1]
//   jitter J                fraction of a grid cell, [0, 1]
//   seed N                  integer [0, 2^32 - 1]
//
// Wiring: describe() hands each list to SettingsVisitor::list() as a NamedList (config/visitor.h)
// over parseLightSpec / formatLightSpec and parseVolumeSpec / formatVolumeSpec, so the ini loader,
// --set lights.light.NAME=..., the writer, `vista check` and the panel all handle them. A scene
// without light.* / volume.* keys has empty lists. This file and light_settings.cpp use only
// headers from config/ and renderer/lights.h (no lights.cpp): they are part of vista_config.
#pragma once

#include "config/visitor.h"
#include "renderer/lights.h"

#include <string>
#include <string_view>
#include <vector>

namespace vista {

inline constexpr std::uint64_t kMaxVolumeLights = 1000000;  // lights one volume may make

enum class LightCulling : int { Naive, Tiled, Clustered, Hashed };
// 8 and 64 came after 16 and 32 (002's sweep); appended so saved scenes keep their values.
enum class LightTileSize : int { Px16, Px32, Px8, Px64 };
inline int tilePixels(LightTileSize s) {
    switch (s) {
        case LightTileSize::Px16: return 16;
        case LightTileSize::Px32: return 32;
        case LightTileSize::Px8: return 8;
        case LightTileSize::Px64: return 64;
    }
    return 16;
}

struct NamedLight {
    std::string name;
    Light light;
    bool operator==(const NamedLight&) const = default;
};
struct NamedLightVolume {
    std::string name;
    LightVolume volume;
    bool operator==(const NamedLightVolume&) const = default;
};

struct LightsSettings {
    bool enabled = true;                               //!< local lights (point, spot); off: no culling pass, no buffers
    LightCulling culling = LightCulling::Clustered;    //!< naive | tiled | clustered | hashed
    LightTileSize tile_size = LightTileSize::Px16;     //!< px, screen tile of tiled and clustered: 16 | 32 | 8 | 64
    int cluster_slices = 0;         //!< depth slices, 0..256; 0 = 002's cubic clusters (ratio 1 + 2 tan(fov/2) / tiles_y), at most kMaxAutoSlices
    float cluster_near_m = 0.0f;    //!< m, near_0 of near_k = near_0 * ratio^k, 0..1e4; 0 = the camera's near plane
    float cluster_far_m = 4000.0f;  //!< m, depth the bounded slices reach; the last slice also takes all beyond, 1..1e7
    int max_lights_per_cell = 1024; //!< list capacity per tile or cluster, 1..4096; overflow is counted and warned
    float min_screen_px = 0.0f;     //!< px, tiled/clustered: lights whose sphere's screen radius is below this are skipped, 0..64 (0: none; above 0 the methods may differ)
    float hash_node_m = 0.0f;       //!< m, leaf node size of the hashed light octree, 0..1e5; 0 = half the mean light radius
    float hash_memory_mb = 256.0f;  //!< MiB of GPU tables + index list, 1..65536; beyond it the node size doubles until it fits
    float hash_slack = 0.25f;       //!< extra hash-table room kept for incremental updates, fraction 0..4
    bool glow = true;               //!< glow around lights in fog (single scattering, renderer/lighting/lamp_glow.h); only where the medium is dense enough
    int glow_max_lights = 32;       //!< lights that glow at most, the brightest on screen, 0..1024
    float cutoff_lux = 0.05f;       //!< lx, illuminance where a light of `radius auto` ends (lights.h autoRadiusM), 1e-6..1e3
    LightAnimation animation;       //!< animation = none|circle|bob, animation_amplitude_m, animation_period_s, animation_fraction, animation_seed
    std::vector<NamedLight> lights;          //!< light.NAME keys
    std::vector<NamedLightVolume> volumes;   //!< volume.NAME keys
};

inline constexpr int kMaxAutoSlices = 64;  // slices of cluster_slices = 0 at most

// Lists the keys of [lights] with units and ranges: the plain keys, then the lists `light`
// (lights) and `volume` (volumes).
void describe(SettingsVisitor& v, LightsSettings& s);

// Parses the value of a light.NAME key (format above) into out. Empty on success, otherwise a
// message naming the bad token and what is accepted; out is then unspecified.
std::string parseLightSpec(std::string_view text, Light& out);
std::string parseVolumeSpec(std::string_view text, LightVolume& out);
// Canonical text of a light / volume; parse(format(x)) reproduces x exactly (floats round-trip).
std::string formatLightSpec(const Light& light);
std::string formatVolumeSpec(const LightVolume& volume);
// Whether a NAME of light.NAME / volume.NAME is valid: isValidListName() (config/visitor.h).
// The scene's lights before animation are collectLights(lights, volumes) (renderer/lights.h).

}  // namespace vista
