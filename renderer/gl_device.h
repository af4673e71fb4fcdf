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
    GLuint framebuffer(const std::vector<GLuint>& colors, GLuint depth = 0);

    // Copies a pass's uniform block into a ring buffer and binds that range at uniform
    // block binding `binding` (renderer/pass_kit.h: bindPassBlock). Later draws read the
    // copy made for them: GL orders the buffer update after the draws already issued.
    void bindUniforms(int binding, const void* data, std::size_t bytes);

private:
    std::unordered_map<std::uint32_t, gl::Texture> textures_;
    std::unordered_map<std::uint32_t, gl::Buffer> buffers_;
    std::map<std::vector<GLuint>, gl::Framebuffer> framebuffers_;  // key: colors..., depth
    gl::Buffer uniform_ring_;        // made on first use
    std::size_t ring_offset_ = 0;    // next free byte
    std::size_t ring_alignment_ = 256;  // GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT
};

// Binds fb, sets the viewport to width x height and the draw buffers to its colours.
void bindTarget(GLuint fb, int width, int height);

}  // namespace vista
