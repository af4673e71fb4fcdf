// The GL side of the frame graph: creates the textures and buffers the transient pool
// asks for, and caches framebuffers by attachment set.
#pragma once

#include "renderer/gl/objects.h"
#include "renderer/transient_pool.h"

#include <initializer_list>
#include <map>
#include <unordered_map>
#include <vector>

namespace vista {

GLenum glInternalFormat(PixelFormat format);

class GlDevice final : public ResourceDevice {
public:
    std::uint32_t createTexture(const TextureDesc& desc, const std::string& name) override;
    void destroyTexture(std::uint32_t id) override;
    std::uint32_t createBuffer(const BufferDesc& desc, const std::string& name) override;
    void destroyBuffer(std::uint32_t id) override;

    // A framebuffer with these colour attachments (in order) and depth (0: none), made
    // once and reused; dropped when one of its textures is destroyed.
    GLuint framebuffer(std::initializer_list<GLuint> colors, GLuint depth = 0);

private:
    std::unordered_map<std::uint32_t, gl::Texture> textures_;
    std::unordered_map<std::uint32_t, gl::Buffer> buffers_;
    std::map<std::vector<GLuint>, gl::Framebuffer> framebuffers_;  // key: colors..., depth
};

// Binds fb, sets the viewport to width x height and the draw buffers to its colours.
void bindTarget(GLuint fb, int width, int height);

}  // namespace vista
