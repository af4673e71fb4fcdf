// How the sun, spot and point shadow inputs bind for their readers: the uniform block, and the
// one depth texture twice, through the comparing sampler (filtered lookups) and the raw depth
// sampler (PCSS blocker search, debug views).
#pragma once

#include "renderer/bindings.h"
#include "renderer/gl/objects.h"

#include <glad/gl.h>

#include <cstddef>
#include <string>

namespace vista {

struct ShadowBindingPoints {
    GLuint uniforms;  // uniform buffer binding
    GLuint map;       // texture unit read through the comparing sampler
    GLuint depth;     // texture unit read through the raw depth sampler
};

constexpr ShadowBindingPoints kSunShadowBindings{binding::kShadowUniforms, binding::kShadowMap, binding::kShadowDepth};
constexpr ShadowBindingPoints kSpotShadowBindings{binding::kSpotShadowUniforms, binding::kSpotShadowMap,
                                                  binding::kSpotShadowDepth};
constexpr ShadowBindingPoints kPointShadowBindings{binding::kPointShadowUniforms, binding::kPointShadowMap,
                                                   binding::kPointShadowDepth};

inline void bindShadowInput(ShadowBindingPoints at, GLuint uniforms, GLuint texture, GLuint compare_sampler,
                            GLuint depth_sampler) {
    glBindBufferBase(GL_UNIFORM_BUFFER, at.uniforms, uniforms);
    glBindTextureUnit(at.map, texture);
    glBindSampler(at.map, compare_sampler);
    glBindTextureUnit(at.depth, texture);
    glBindSampler(at.depth, depth_sampler);
}

inline void unbindShadowInput(ShadowBindingPoints at) {
    glBindSampler(at.map, 0);
    glBindSampler(at.depth, 0);
}

// The objects a shadow kind's readers go through besides its depth texture: the uniform block
// and the two samplers. Created once, on the kind's first allocation.
struct ShadowReadObjects {
    gl::Buffer uniforms;
    gl::Sampler compare, depth;

    // compare_func: GL_LEQUAL for the sun's forward-Z maps, GL_GEQUAL for reversed-Z (nearer is larger).
    void create(std::size_t uniform_bytes, GLenum compare_func, const std::string& name) {
        if (uniforms) return;
        uniforms = gl::Buffer::create(GLsizeiptr(uniform_bytes), nullptr, GL_DYNAMIC_STORAGE_BIT, name + " uniforms");
        compare = gl::createCompareSampler(compare_func, name + " compare");
        depth = gl::createSampler(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, name + " depth");
    }
    std::size_t bytes() const { return std::size_t(uniforms.size()); }
};

}  // namespace vista
