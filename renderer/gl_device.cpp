// GL resources for the frame graph.
#include "renderer/gl_device.h"

#include <algorithm>
#include <stdexcept>

namespace vista {

GLenum glInternalFormat(PixelFormat format) {
    switch (format) {
        case PixelFormat::RGBA8: return GL_RGBA8;
        case PixelFormat::RGB10A2: return GL_RGB10_A2;
        case PixelFormat::RGBA16F: return GL_RGBA16F;
        case PixelFormat::RGBA32F: return GL_RGBA32F;
        case PixelFormat::RG16F: return GL_RG16F;
        case PixelFormat::R16F: return GL_R16F;
        case PixelFormat::R32F: return GL_R32F;
        case PixelFormat::R32UI: return GL_R32UI;
        case PixelFormat::Depth32F: return GL_DEPTH_COMPONENT32F;
    }
    throw std::logic_error("glInternalFormat: unknown pixel format");
}

std::uint32_t GlDevice::createTexture(const TextureDesc& desc, const std::string& name) {
    gl::Texture t = gl::Texture::create2D(desc.width, desc.height, glInternalFormat(desc.format), desc.levels, name);
    if (desc.format == PixelFormat::R32UI || desc.format == PixelFormat::Depth32F || desc.format == PixelFormat::RGB10A2) {
        glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    std::uint32_t id = t.id();
    textures_.emplace(id, std::move(t));
    return id;
}

void GlDevice::destroyTexture(std::uint32_t id) {
    std::erase_if(framebuffers_, [id](const auto& entry) {
        return std::find(entry.first.begin(), entry.first.end(), id) != entry.first.end();
    });
    textures_.erase(id);
}

std::uint32_t GlDevice::createBuffer(const BufferDesc& desc, const std::string& name) {
    gl::Buffer b = gl::Buffer::create(GLsizeiptr(desc.bytes), nullptr, GL_DYNAMIC_STORAGE_BIT, name);
    std::uint32_t id = b.id();
    buffers_.emplace(id, std::move(b));
    return id;
}

void GlDevice::destroyBuffer(std::uint32_t id) { buffers_.erase(id); }

GLuint GlDevice::framebuffer(std::initializer_list<GLuint> colors, GLuint depth) {
    return framebuffer(std::vector<GLuint>(colors), depth);
}

GLuint GlDevice::framebuffer(const std::vector<GLuint>& colors, GLuint depth) {
    std::vector<GLuint> key(colors);
    key.push_back(depth);
    auto it = framebuffers_.find(key);
    if (it != framebuffers_.end()) return it->second.id();
    gl::Framebuffer fb = gl::createFramebuffer("graph target");
    std::vector<GLenum> draw;
    for (GLuint c : colors) {
        GLenum attachment = GL_COLOR_ATTACHMENT0 + GLenum(draw.size());
        glNamedFramebufferTexture(fb.id(), attachment, c, 0);
        draw.push_back(attachment);
    }
    if (depth != 0) glNamedFramebufferTexture(fb.id(), GL_DEPTH_ATTACHMENT, depth, 0);
    if (draw.empty())
        glNamedFramebufferDrawBuffer(fb.id(), GL_NONE);
    else
        glNamedFramebufferDrawBuffers(fb.id(), GLsizei(draw.size()), draw.data());
    GLenum status = glCheckNamedFramebufferStatus(fb.id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::logic_error("GlDevice::framebuffer: incomplete framebuffer, status " + std::to_string(status));
    GLuint id = fb.id();
    framebuffers_.emplace(std::move(key), std::move(fb));
    return id;
}

void GlDevice::bindUniforms(int binding, const void* data, std::size_t bytes) {
    constexpr std::size_t kRingBytes = std::size_t(1) << 18;
    if (bytes > kRingBytes) throw std::logic_error("GlDevice::bindUniforms: a uniform block of " + std::to_string(bytes) + " bytes");
    if (uniform_ring_.id() == 0) {
        GLint alignment = 256;
        glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &alignment);
        ring_alignment_ = std::size_t(std::max(alignment, 1));
        uniform_ring_ = gl::Buffer::create(GLsizeiptr(kRingBytes), nullptr, GL_DYNAMIC_STORAGE_BIT, "pass uniform blocks");
    }
    if (ring_offset_ + bytes > kRingBytes) ring_offset_ = 0;
    glNamedBufferSubData(uniform_ring_.id(), GLintptr(ring_offset_), GLsizeiptr(bytes), data);
    glBindBufferRange(GL_UNIFORM_BUFFER, GLuint(binding), uniform_ring_.id(), GLintptr(ring_offset_), GLsizeiptr(bytes));
    ring_offset_ += (bytes + ring_alignment_ - 1) / ring_alignment_ * ring_alignment_;
}

void bindTarget(GLuint fb, int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glViewport(0, 0, width, height);
}

}  // namespace vista
