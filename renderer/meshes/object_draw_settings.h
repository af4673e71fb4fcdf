// How Objects (renderer/meshes/objects.h) draws its instances: the distances of the LODs, the
// impostors and the shadows, and the emissive scale. The [objects] section's struct
// (terrain/scatter/object_settings.h ObjectsSettings) derives from it and adds the lists of what is
// placed, so the drawing sees only its own part.
#pragma once

namespace vista {

struct ObjectDrawSettings {
    float lod1_distance_m = 60.0f;    //!< m, beyond this the first simplified LOD, 1..1e5
    float lod2_distance_m = 250.0f;   //!< m, beyond this the coarsest LOD, 1..1e5
    float max_distance_m = 2500.0f;   //!< m, instances farther away are not drawn, 1..1e6
    float impostor_distance_m = 150.0f; //!< m, beyond this an octahedral impostor replaces the mesh, 1..1e6
    float impostor_fade_m = 15.0f;    //!< m, dithered cross-fade from mesh to impostor before that distance, 0..1e4
    float shadow_distance_m = 300.0f; //!< m, instances within this cast shadows (coarsest LOD beyond lod1), 0..1e5
    bool cast_shadows = true;
    float emissive_nits = 60.0f;      //!< cd/m^2 of emissive factor 1 (glow maps, windows), 0..1e6
};

}  // namespace vista
