// `vista gen-props`: the default scene's procedural props, written as binary glTF (.glb) into a
// folder (data/props/ by default), so the scene needs no third-party assets:
//   tree.glb   a broadleaf tree grown by a stochastic bracketed L-system (Lindenmayer 1968;
//              Prusinkiewicz and Lindenmayer, "The Algorithmic Beauty of Plants", ch. 1-2):
//              axiom A, rule A -> F [+A] [-A] [^A] with per-branch random turn, roll and length
//              (ratio 0.72 per generation, 4 generations), branches as tapered 6-sided tubes and
//              every terminal branch crowned by three crossed leaf cards with an alpha-masked
//              (MASK, cutoff 0.5), double-sided leaf texture;
//   rock.glb   a twice-subdivided icosahedron displaced by three octaves of hashed value noise
//              and squashed vertically;
//   house.glb  walls, a gable roof, a door, and windows with an emissive material (warm
//              light) that glows into the HDR target at night;
//   lantern.glb a lamp post with a glass lantern: four sides and a floor of faintly amber glass
//              (BLEND, alpha 0.2, double-sided, a faint emissive glow) under an iron cap, for
//              the village's door lamps (the point light sits inside the glass).
// Deterministic: the same seed writes the same bytes. Each file is written atomically.
#pragma once

#include "renderer/meshes/model.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace vista {

// The props as models (what the files hold), for tests.
Model generateTree(std::uint32_t seed);
Model generateRock(std::uint32_t seed);
Model generateHouse();
Model generateLantern();

// A model as binary glTF bytes (one buffer, one mesh with a primitive per material, images
// embedded as PNG).
std::string modelToGlb(const Model& model);

// Writes tree.glb, rock.glb, house.glb and lantern.glb into dir. Prints what was written and returns 0;
// 2 (with "vista: reason" on stderr) when dir is not a writable folder or a file exists
// without force.
int runGenProps(const std::filesystem::path& dir, std::uint32_t seed, bool force);

}  // namespace vista
