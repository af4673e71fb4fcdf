// "postfx.scotopic": vision below mesopic levels on the linear HDR image (before exposure).
// Per pixel, by its luminance in cd/m^2, the rods' share w rises from 0 at 5 cd/m^2 to 1 at
// 0.005 cd/m^2 (the CIE mesopic range, smooth in log luminance); the result mixes the colour
// with the rods' response, a blue-shifted grey (Krawczyk, Myszkowski & Seidel 2005, after
// Jensen et al. 2000), blurred over a radius that grows to acuity_arcmin with w (rod vision's
// lost acuity). Added only on frames with a pre-exposure above 1 (sky below 400 lx): day
// frames have no such pass.
#pragma once

#include "postfx/scotopic_settings.h"
#include "renderer/render_context.h"

#include <string>
#include <utility>
#include <vector>

namespace vista {

// The rods' scotopic luminance V for linear sRGB rgb, normalised so that V = Y for D65 white
// (Krawczyk 2005: V = Y (1.33 (1 + (Y + Z) / X) - 1.68), 2.569 Y for white). CPU mirror of the shader.
double scotopicLuminance(double r, double g, double b);
// The rods' share at a photopic luminance (cd/m^2): 0 at >= 5, 1 at <= 0.005, smoothstep in log10.
double rodShare(double luminance_cd);

// cd_per_value: cd/m^2 per unit of image (sky/night_light.h luxPerHdrUnit over the pre-exposure).
TextureHandle addScotopicPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                              const ScotopicSettings& s, double cd_per_value);

ProgramList scotopicPrograms();

}  // namespace vista
