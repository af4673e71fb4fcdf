// Creation helpers for the RAII GL objects.
#include "renderer/gl/objects.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace vista::gl {

Buffer Buffer::create(GLsizeiptr bytes, const void* data, GLbitfield flags, std::string_view name) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    glNamedBufferStorage(id, bytes, data, flags);
    // Out of memory leaves the buffer without storage; drawing with it crashed llvmpipe. Asking
    // the object (not glGetError) leaves other pending errors to whoever checks them.
    GLint immutable = GL_TRUE;
    if (bytes > 0) glGetNamedBufferParameteriv(id, GL_BUFFER_IMMUTABLE_STORAGE, &immutable);
    if (immutable != GL_TRUE) {
        glDeleteBuffers(1, &id);
        throw std::runtime_error("the GL could not allocate buffer '" + std::string(name) + "' of " + std::to_string(bytes) +
                                 " bytes (out of memory?)");
    }
    Buffer buffer(id, bytes);
    buffer.label(name);
    return buffer;
}

Texture Texture::create2D(GLsizei width, GLsizei height, GLenum internal_format, GLsizei levels,
                          std::string_view name) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    glTextureStorage2D(id, levels, internal_format, width, height);
    GLint immutable = GL_FALSE;  // as for buffers: no storage after an out-of-memory
    glGetTextureParameteriv(id, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
    if (immutable != GL_TRUE) {
        glDeleteTextures(1, &id);
        throw std::runtime_error("the GL could not allocate texture '" + std::string(name) + "' of " + std::to_string(width) +
                                 "x" + std::to_string(height) + " (out of memory, or larger than the GL allows?)");
    }
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    Texture texture(id, width, height, internal_format);
    texture.label(name);
    return texture;
}

// Sums each level's texels times the bits of its components, so every uncompressed format,
// array layer and 3D slice is counted without a table of formats.
std::size_t Texture::storageBytes(GLuint id) {
    if (id == 0) return 0;
    GLint levels = 0;
    glGetTextureParameteriv(id, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    std::size_t bytes = 0;
    for (GLint level = 0; level < std::max(levels, 1); ++level) {
        GLint w = 0, h = 0, d = 0, bits = 0;
        glGetTextureLevelParameteriv(id, level, GL_TEXTURE_WIDTH, &w);
        glGetTextureLevelParameteriv(id, level, GL_TEXTURE_HEIGHT, &h);
        glGetTextureLevelParameteriv(id, level, GL_TEXTURE_DEPTH, &d);
        for (GLenum component : {GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE,
                                 GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_STENCIL_SIZE}) {
            GLint b = 0;
            glGetTextureLevelParameteriv(id, level, component, &b);
            bits += b;
        }
        bytes += std::size_t(w) * std::size_t(h) * std::size_t(std::max(d, 1)) * std::size_t(bits) / 8;
    }
    return bytes;
}

Framebuffer createFramebuffer(std::string_view name) {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    Framebuffer fb(id);
    fb.label(name);
    return fb;
}

VertexArray createVertexArray(std::string_view name) {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    VertexArray vao(id);
    vao.label(name);
    return vao;
}

Query createQuery(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    return Query(id);
}

Sampler createSampler(GLenum min_filter, GLenum mag_filter, GLenum wrap, std::string_view name) {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GLint(min_filter));
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, GLint(mag_filter));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GLint(wrap));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GLint(wrap));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_R, GLint(wrap));
    Sampler sampler(id);
    sampler.label(name);
    return sampler;
}

Sampler createCompareSampler(GLenum func, std::string_view name) {
    Sampler sampler = createSampler(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, name);
    glSamplerParameteri(sampler.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(sampler.id(), GL_TEXTURE_COMPARE_FUNC, GLint(func));
    return sampler;
}

}  // namespace vista::gl
