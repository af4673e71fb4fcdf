// Shared draw helpers.
#include "renderer/render_context.h"

namespace vista {

void drawFullscreen(const RenderContext& rc) {
    glBindVertexArray(rc.empty_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace vista
