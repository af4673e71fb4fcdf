// Move-only RAII owners of GL objects (GL 4.5 DSA). A default-constructed object is
// "not created" (id 0) and costs nothing; moving leaves the source empty. Feature code
// never holds a bare GLuint it owns.
#pragma once

#include <glad/gl.h>

#include <cstddef>
#include <string_view>
#include <utility>

namespace vista::gl {

template <class Traits>
class Object {
public:
    Object() = default;
    explicit Object(GLuint id) : id_(id) {}
    ~Object() { reset(); }
    Object(Object&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Object& operator=(Object&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_ != 0) Traits::destroy(id_);
        id_ = 0;
    }
    // Names the object in debuggers and KHR_debug messages.
    void label(std::string_view name) const {
        if (id_ != 0) glObjectLabel(Traits::kLabelType, id_, GLsizei(name.size()), name.data());
    }

private:
    GLuint id_ = 0;
};

struct BufferTraits {
    static constexpr GLenum kLabelType = GL_BUFFER;
    static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct TextureTraits {
    static constexpr GLenum kLabelType = GL_TEXTURE;
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct FramebufferTraits {
    static constexpr GLenum kLabelType = GL_FRAMEBUFFER;
    static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct VertexArrayTraits {
    static constexpr GLenum kLabelType = GL_VERTEX_ARRAY;
    static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct ProgramTraits {
    static constexpr GLenum kLabelType = GL_PROGRAM;
    static void destroy(GLuint id) { glDeleteProgram(id); }
};
struct ShaderTraits {
    static constexpr GLenum kLabelType = GL_SHADER;
    static void destroy(GLuint id) { glDeleteShader(id); }
};
struct QueryTraits {
    static constexpr GLenum kLabelType = GL_QUERY;
    static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};
struct SamplerTraits {
    static constexpr GLenum kLabelType = GL_SAMPLER;
    static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};

using Framebuffer = Object<FramebufferTraits>;
using VertexArray = Object<VertexArrayTraits>;
using Program = Object<ProgramTraits>;
using Shader = Object<ShaderTraits>;
using Query = Object<QueryTraits>;
using Sampler = Object<SamplerTraits>;

class Buffer : public Object<BufferTraits> {
public:
    Buffer() = default;
    // Immutable storage (glNamedBufferStorage); data may be null.
    static Buffer create(GLsizeiptr bytes, const void* data, GLbitfield flags, std::string_view name);
    GLsizeiptr size() const { return size_; }

private:
    Buffer(GLuint id, GLsizeiptr size) : Object(id), size_(size) {}
    GLsizeiptr size_ = 0;
};

class Texture : public Object<TextureTraits> {
public:
    Texture() = default;
    static Texture create2D(GLsizei width, GLsizei height, GLenum internal_format, GLsizei levels,
                            std::string_view name);
    // Takes ownership of a texture made elsewhere (arrays, 3D); its storage must exist.
    static Texture adopt(GLuint id, GLsizei width, GLsizei height, GLenum internal_format) {
        return Texture(id, width, height, internal_format);
    }
    GLsizei width() const { return width_; }
    GLsizei height() const { return height_; }
    GLenum format() const { return format_; }
    // Bytes of its storage (every level and layer), as GL describes it when it is made or adopted.
    std::size_t bytes() const { return id() != 0 ? bytes_ : 0; }

private:
    Texture(GLuint id, GLsizei width, GLsizei height, GLenum format)
        : Object(id), width_(width), height_(height), format_(format), bytes_(storageBytes(id)) {}
    static std::size_t storageBytes(GLuint id);
    GLsizei width_ = 0, height_ = 0;
    GLenum format_ = 0;
    std::size_t bytes_ = 0;
};

Framebuffer createFramebuffer(std::string_view name);
VertexArray createVertexArray(std::string_view name);
Query createQuery(GLenum target);
Sampler createSampler(GLenum min_filter, GLenum mag_filter, GLenum wrap, std::string_view name);
// A bilinear, edge-clamped depth sampler that compares the reference with `func` (shadow lookups).
Sampler createCompareSampler(GLenum func, std::string_view name);

}  // namespace vista::gl
