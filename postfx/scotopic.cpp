// The scotopic pass (postfx/scotopic.h): its CPU mirrors and its one full-screen pass.
#include "postfx/scotopic.h"

#include "renderer/pass_kit.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace vista {

namespace {

#include "postfx/shaders/scotopic_block.glsl"

// Linear sRGB to CIE XYZ (D65).
void toXyz(double r, double g, double b, double& x, double& y, double& z) {
    x = 0.4124 * r + 0.3576 * g + 0.1805 * b;
    y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    z = 0.0193 * r + 0.1192 * g + 0.9505 * b;
}

// V / Y of D65 white (X, Y, Z = 0.9505, 1, 1.089): V is divided by it so white keeps its brightness.
constexpr double kWhiteScotopic = 2.5694;

}  // namespace

double scotopicLuminance(double r, double g, double b) {
    double x, y, z;
    toXyz(r, g, b, x, y, z);
    if (!(x > 0.0)) return 0.0;
    return std::max(y * (1.33 * (1.0 + (y + z) / x) - 1.68), 0.0) / kWhiteScotopic;
}

double rodShare(double luminance_cd) {
    if (!(luminance_cd > 0.0)) return 1.0;
    const double t = std::clamp((std::log10(5.0) - std::log10(luminance_cd)) / 3.0, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

TextureHandle addScotopicPass(FrameGraph& graph, const RenderContext& rc, TextureHandle image,
                              const ScotopicSettings& s, double cd_per_value) {
    // The blur radius at w = 1 in pixels: acuity_arcmin over the view's angle per pixel.
    const double px_per_rad = 0.5 * double(rc.view.height) / std::tan(glm::radians(rc.view.fov_deg) * 0.5);
    const float radius_px = float(glm::radians(double(s.acuity_arcmin) / 60.0) * px_per_rad);
    std::vector<std::string> defines;
    if (s.show_rod_share) defines.push_back("ROD_SHARE_VIEW");
    return addFullscreenPass(graph, rc,
                             FullscreenPass("postfx.scotopic", {"postfx/shaders/scotopic.glsl", defines}, {image}, "scotopic"),
                             ScotopicBlock{float(cd_per_value), radius_px, s.blue_shift, 0.0f});
}

ProgramList scotopicPrograms() {
    return {{"postfx/shaders/scotopic.glsl", {}}, {"postfx/shaders/scotopic.glsl", {"ROD_SHARE_VIEW"}}};
}

}  // namespace vista
