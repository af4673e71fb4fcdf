// Creation helpers for the RAII GL objects.
#include "renderer/gl/objects.h"

namespace vista::gl {

Buffer Buffer::create(GLsizeiptr bytes, const void* data, GLbitfield flags, std::string_view name) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    glNamedBufferStorage(id, bytes, data, flags);
    Buffer buffer(id, bytes);
    buffer.label(name);
    return buffer;
}

Texture Texture::create2D(GLsizei width, GLsizei height, GLenum internal_format, GLsizei levels,
                          std::string_view name) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    glTextureStorage2D(id, levels, internal_format, width, height);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    Texture texture(id, width, height, internal_format);
    texture.label(name);
    return texture;
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

}  // namespace vista::gl
