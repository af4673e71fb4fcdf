// glTF 2.0 through tinygltf: tinygltf parses the JSON (or GLB container), resolves buffers and
// decodes images; everything a renderer would trust from there on (accessor ranges, indices,
// texture references, node indices, cycles) is checked here, so a bad file gives a message,
// never a crash or a read out of bounds (fuzzed by tests/fuzz/fuzz_gltf.cpp).
#include "renderer/meshes/gltf_loader.h"

#include "config/file_io.h"

#include <stb_image.h>
#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

namespace vista {

float Model::radius() const {
    float r = 0.0f;
    for (const MeshVertex& v : vertices) r = std::max(r, glm::length(v.position));
    return r;
}

bool Model::hasBlend() const {
    for (const ModelMaterial& m : materials)
        if (m.alpha_mode == AlphaMode::Blend) return true;
    return false;
}

namespace {

constexpr std::uintmax_t kMaxGltfBytes = std::uintmax_t(1) << 30;
constexpr int kMaxNodeDepth = 64;

struct Context {
    const tinygltf::Model& g;
    Model& out;
    std::string error;
    std::size_t pixels = 0;
    bool fail(std::string what) {
        if (error.empty()) error = std::move(what);
        return false;
    }
};

// Refuses oversized images before stb_image allocates them, then lets tinygltf decode.
bool loadImage(tinygltf::Image* image, const int index, std::string* err, std::string* warn, int req_width,
               int req_height, const unsigned char* bytes, int size, void* user) {
    int w = 0, h = 0, comp = 0;
    if (!stbi_info_from_memory(bytes, size, &w, &h, &comp)) {
        if (err) *err += "image " + std::to_string(index) + ": not a PNG, JPEG or other image stb_image reads\n";
        return false;
    }
    std::size_t& pixels = *static_cast<std::size_t*>(user);
    pixels += std::size_t(w) * std::size_t(h);
    if (w <= 0 || h <= 0 || pixels > kMaxModelImagePixels) {
        if (err) *err += "image " + std::to_string(index) + ": " + std::to_string(w) + " x " + std::to_string(h) +
                         " pixels; a model's images may hold at most " + std::to_string(kMaxModelImagePixels) + " pixels\n";
        return false;
    }
    return tinygltf::LoadImageData(image, index, err, warn, req_width, req_height, bytes, size, nullptr);
}

// Files outside the model's folder are not read (a model cannot name /etc/passwd as a buffer).
struct FsGuard {
    std::filesystem::path base;
};
bool fileExists(const std::string& path, void* user) {
    const FsGuard& g = *static_cast<FsGuard*>(user);
    if (g.base.empty()) return false;
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}
std::string expandPath(const std::string& path, void*) { return path; }
bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    const FsGuard& g = *static_cast<FsGuard*>(user);
    if (g.base.empty()) {
        if (err) *err += path + ": external files are not read here\n";
        return false;
    }
    std::string bytes;
    if (std::string why = readInputFile(path, kMaxGltfBytes, bytes); !why.empty()) {
        if (err) *err += why + "\n";
        return false;
    }
    out->assign(bytes.begin(), bytes.end());
    return true;
}
bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not allowed while loading\n";
    return false;
}

// Element `index` of accessor a as float components (count comps), converting normalised
// integers. The accessor's range was checked by checkAccessor().
struct AccessorView {
    const unsigned char* data = nullptr;
    std::size_t stride = 0, count = 0;
    int component_type = 0, components = 0;
    bool normalized = false;
    float get(std::size_t i, int c) const {
        const unsigned char* p = data + i * stride;
        switch (component_type) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: {
                float v;
                std::memcpy(&v, p + 4 * c, 4);
                return v;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[c] / 255.0f : float(p[c]);
            case TINYGLTF_COMPONENT_TYPE_BYTE: {
                const float v = float(std::int8_t(p[c]));
                return normalized ? std::max(v / 127.0f, -1.0f) : v;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                std::uint16_t v;
                std::memcpy(&v, p + 2 * c, 2);
                return normalized ? v / 65535.0f : float(v);
            }
            case TINYGLTF_COMPONENT_TYPE_SHORT: {
                std::int16_t v;
                std::memcpy(&v, p + 2 * c, 2);
                return normalized ? std::max(v / 32767.0f, -1.0f) : float(v);
            }
        }
        return 0.0f;
    }
    std::uint32_t index(std::size_t i) const {
        const unsigned char* p = data + i * stride;
        if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return p[0];
        if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return v;
        }
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
};

int componentBytes(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    }
    return 0;
}

// Checks accessor `index` (what: "POSITION of mesh 2 primitive 0") and returns a view of it.
// allowed: component types accepted; components: VEC size wanted.
bool viewAccessor(Context& c, int index, const std::string& what, std::initializer_list<int> allowed, int components,
                  AccessorView& v) {
    const auto& g = c.g;
    const std::string name = "accessor " + std::to_string(index) + " (" + what + ")";
    if (index < 0 || std::size_t(index) >= g.accessors.size()) return c.fail(name + ": no such accessor");
    const tinygltf::Accessor& a = g.accessors[std::size_t(index)];
    if (a.sparse.isSparse) return c.fail(name + ": sparse accessors are not supported");
    if (std::find(allowed.begin(), allowed.end(), a.componentType) == allowed.end())
        return c.fail(name + ": component type " + std::to_string(a.componentType) + " is not accepted here");
    if (tinygltf::GetNumComponentsInType(std::uint32_t(a.type)) != components)
        return c.fail(name + ": has " + std::to_string(tinygltf::GetNumComponentsInType(std::uint32_t(a.type))) +
                      " components, " + std::to_string(components) + " expected");
    if (a.bufferView < 0 || std::size_t(a.bufferView) >= g.bufferViews.size())
        return c.fail(name + ": bufferView " + std::to_string(a.bufferView) + " does not exist");
    const tinygltf::BufferView& bv = g.bufferViews[std::size_t(a.bufferView)];
    if (bv.buffer < 0 || std::size_t(bv.buffer) >= g.buffers.size())
        return c.fail(name + ": buffer " + std::to_string(bv.buffer) + " does not exist (missing buffer)");
    const tinygltf::Buffer& buf = g.buffers[std::size_t(bv.buffer)];
    const std::size_t elem = std::size_t(componentBytes(a.componentType)) * std::size_t(components);
    const std::size_t stride = bv.byteStride ? bv.byteStride : elem;
    if (stride < elem) return c.fail(name + ": byteStride " + std::to_string(bv.byteStride) + " is below the element size");
    if (bv.byteOffset > buf.data.size() || bv.byteLength > buf.data.size() - bv.byteOffset)
        return c.fail(name + ": bufferView " + std::to_string(a.bufferView) + " reaches past the end of buffer " +
                      std::to_string(bv.buffer) + " (" + std::to_string(buf.data.size()) + " bytes; missing buffer?)");
    if (a.count > kMaxModelVertices * 4) return c.fail(name + ": count " + std::to_string(a.count) + " is too large");
    if (a.count > 0) {
        const std::size_t need = a.byteOffset + (a.count - 1) * stride + elem;
        if (a.byteOffset > bv.byteLength || need > bv.byteLength)
            return c.fail(name + ": " + std::to_string(a.count) + " elements from byte " + std::to_string(a.byteOffset) +
                          " reach past its bufferView's " + std::to_string(bv.byteLength) + " bytes");
    }
    v.data = buf.data.data() + bv.byteOffset + a.byteOffset;
    v.stride = stride;
    v.count = a.count;
    v.component_type = a.componentType;
    v.components = components;
    v.normalized = a.normalized;
    return true;
}

bool textureImage(Context& c, int texture, const std::string& what, int& image) {
    image = -1;
    if (texture < 0) return true;
    if (std::size_t(texture) >= c.g.textures.size()) return c.fail(what + ": texture " + std::to_string(texture) + " does not exist");
    const int source = c.g.textures[std::size_t(texture)].source;
    if (source < 0 || std::size_t(source) >= c.g.images.size())
        return c.fail(what + ": texture " + std::to_string(texture) + " has no image (source " + std::to_string(source) + ")");
    image = source;
    return true;
}

bool readMaterials(Context& c) {
    for (std::size_t i = 0; i < c.g.materials.size(); ++i) {
        const tinygltf::Material& m = c.g.materials[i];
        const std::string what = "material " + std::to_string(i);
        ModelMaterial out;
        const auto& pbr = m.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() == 4)
            out.base_color = glm::vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                                       float(pbr.baseColorFactor[2]), float(pbr.baseColorFactor[3]));
        out.metallic = float(pbr.metallicFactor);
        out.roughness = float(pbr.roughnessFactor);
        if (m.emissiveFactor.size() == 3)
            out.emissive = glm::vec3(float(m.emissiveFactor[0]), float(m.emissiveFactor[1]), float(m.emissiveFactor[2]));
        out.normal_scale = float(m.normalTexture.scale);
        out.occlusion_strength = float(m.occlusionTexture.strength);
        if (m.alphaMode == "MASK") out.alpha_mode = AlphaMode::Mask;
        else if (m.alphaMode == "BLEND") out.alpha_mode = AlphaMode::Blend;
        else if (m.alphaMode != "OPAQUE" && !m.alphaMode.empty())
            return c.fail(what + ": alphaMode '" + m.alphaMode + "'; accepted OPAQUE, MASK, BLEND");
        out.alpha_cutoff = float(m.alphaCutoff);
        out.double_sided = m.doubleSided;
        const float values[] = {out.base_color.r, out.base_color.g, out.base_color.b, out.base_color.a, out.metallic,
                                out.roughness, out.emissive.r, out.emissive.g, out.emissive.b, out.normal_scale,
                                out.occlusion_strength, out.alpha_cutoff};
        for (float v : values)
            if (!std::isfinite(v)) return c.fail(what + ": a factor is not a finite number");
        out.base_color = glm::clamp(out.base_color, 0.0f, 1.0f);
        out.metallic = std::clamp(out.metallic, 0.0f, 1.0f);
        out.roughness = std::clamp(out.roughness, 0.0f, 1.0f);
        out.emissive = glm::max(out.emissive, 0.0f);
        if (!textureImage(c, pbr.baseColorTexture.index, what + " baseColorTexture", out.base_color_texture) ||
            !textureImage(c, pbr.metallicRoughnessTexture.index, what + " metallicRoughnessTexture",
                          out.metallic_roughness_texture) ||
            !textureImage(c, m.normalTexture.index, what + " normalTexture", out.normal_texture) ||
            !textureImage(c, m.occlusionTexture.index, what + " occlusionTexture", out.occlusion_texture) ||
            !textureImage(c, m.emissiveTexture.index, what + " emissiveTexture", out.emissive_texture))
            return false;
        c.out.materials.push_back(out);
    }
    if (c.out.materials.empty()) c.out.materials.push_back(ModelMaterial{});  // glTF's default material
    return true;
}

bool readImages(Context& c) {
    for (std::size_t i = 0; i < c.g.images.size(); ++i) {
        const tinygltf::Image& im = c.g.images[i];
        const std::string what = "image " + std::to_string(i);
        if (im.width <= 0 || im.height <= 0 || im.image.empty()) return c.fail(what + ": not decoded (missing or unreadable)");
        const int bytes = im.bits == 16 ? 2 : 1;
        const std::size_t n = std::size_t(im.width) * std::size_t(im.height);
        if (im.component < 1 || im.component > 4 || (im.bits != 8 && im.bits != 16) ||
            im.image.size() < n * std::size_t(im.component * bytes))
            return c.fail(what + ": " + std::to_string(im.component) + " channels of " + std::to_string(im.bits) +
                          " bits; accepted 1..4 channels of 8 or 16 bits");
        ModelImage out;
        out.width = im.width;
        out.height = im.height;
        out.rgba.resize(n * 4);
        for (std::size_t p = 0; p < n; ++p) {
            std::uint8_t px[4] = {0, 0, 0, 255};
            for (int k = 0; k < im.component; ++k) {
                const std::size_t at = (p * std::size_t(im.component) + std::size_t(k)) * std::size_t(bytes);
                px[k] = bytes == 2 ? im.image[at + 1] : im.image[at];  // little-endian: high byte second
            }
            if (im.component == 1) px[1] = px[2] = px[0];
            if (im.component == 2) {  // grey + alpha
                px[3] = px[1];
                px[1] = px[2] = px[0];
            }
            std::memcpy(&out.rgba[p * 4], px, 4);
        }
        c.out.images.push_back(std::move(out));
    }
    return true;
}

glm::mat4 nodeMatrix(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) {
        glm::dmat4 m;
        for (int k = 0; k < 16; ++k) m[k / 4][k % 4] = n.matrix[std::size_t(k)];
        return glm::mat4(m);
    }
    glm::dmat4 m(1.0);
    if (n.translation.size() == 3) m = glm::translate(m, glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
    if (n.rotation.size() == 4)
        m *= glm::mat4_cast(glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]));
    if (n.scale.size() == 3) m = glm::scale(m, glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
    return glm::mat4(m);
}

// Per-vertex tangents from the UVs (Lengyel's method), for normal maps on meshes without TANGENT.
void deriveTangents(std::vector<MeshVertex>& v, const std::vector<std::uint32_t>& idx, std::size_t first_vertex,
                    std::size_t first_index) {
    std::vector<glm::vec3> t(v.size() - first_vertex, glm::vec3(0.0f)), b(t.size(), glm::vec3(0.0f));
    for (std::size_t i = first_index; i + 2 < idx.size(); i += 3) {
        const MeshVertex &a = v[idx[i]], &c1 = v[idx[i + 1]], &c2 = v[idx[i + 2]];
        const glm::vec3 e1 = c1.position - a.position, e2 = c2.position - a.position;
        const glm::vec2 d1 = c1.uv - a.uv, d2 = c2.uv - a.uv;
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(det) < 1e-12f) continue;
        const float r = 1.0f / det;
        const glm::vec3 sdir = (e1 * d2.y - e2 * d1.y) * r, tdir = (e2 * d1.x - e1 * d2.x) * r;
        for (int k = 0; k < 3; ++k) {
            t[idx[i + std::size_t(k)] - first_vertex] += sdir;
            b[idx[i + std::size_t(k)] - first_vertex] += tdir;
        }
    }
    for (std::size_t i = 0; i < t.size(); ++i) {
        MeshVertex& m = v[first_vertex + i];
        glm::vec3 tt = t[i] - m.normal * glm::dot(m.normal, t[i]);
        const float len = glm::length(tt);
        if (!(len > 1e-12f)) continue;  // w stays 0: the shader derives a frame
        tt /= len;
        m.tangent = glm::vec4(tt, glm::dot(glm::cross(m.normal, tt), b[i]) < 0.0f ? -1.0f : 1.0f);
    }
}

bool readPrimitive(Context& c, const tinygltf::Primitive& p, const std::string& what, const glm::mat4& world,
                   std::vector<std::vector<std::uint32_t>>& per_material) {
    if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1)
        return c.fail(what + ": mode " + std::to_string(p.mode) + " is not supported; accepted triangles (4)");
    auto pos = p.attributes.find("POSITION");
    if (pos == p.attributes.end()) return c.fail(what + ": no POSITION attribute");
    AccessorView vp;
    if (!viewAccessor(c, pos->second, "POSITION of " + what, {TINYGLTF_COMPONENT_TYPE_FLOAT}, 3, vp)) return false;
    const std::size_t count = vp.count;
    if (c.out.vertices.size() + count > kMaxModelVertices)
        return c.fail(what + ": the model has more than " + std::to_string(kMaxModelVertices) + " vertices");
    AccessorView vn, vt, vuv;
    bool has_n = false, has_t = false, has_uv = false;
    auto attr = [&](const char* key, AccessorView& v, bool& has, std::initializer_list<int> types, int comps) {
        auto it = p.attributes.find(key);
        if (it == p.attributes.end()) return true;
        if (!viewAccessor(c, it->second, std::string(key) + " of " + what, types, comps, v)) return false;
        if (v.count != count)
            return c.fail(what + ": " + key + " has " + std::to_string(v.count) + " elements, POSITION " + std::to_string(count));
        has = true;
        return true;
    };
    if (!attr("NORMAL", vn, has_n, {TINYGLTF_COMPONENT_TYPE_FLOAT}, 3) ||
        !attr("TANGENT", vt, has_t, {TINYGLTF_COMPONENT_TYPE_FLOAT}, 4) ||
        !attr("TEXCOORD_0", vuv, has_uv,
              {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}, 2))
        return false;
    const int material = p.material < 0 ? int(c.g.materials.size() == 0 ? 0 : 0) : p.material;
    if (p.material >= 0 && std::size_t(p.material) >= c.out.materials.size())
        return c.fail(what + ": material " + std::to_string(p.material) + " does not exist");
    // Primitives without a material use glTF's default material: appended once, at the end.
    int mat = material;
    if (p.material < 0) {
        if (!c.g.materials.empty()) {
            if (c.out.materials.size() == c.g.materials.size()) c.out.materials.push_back(ModelMaterial{});
            mat = int(c.out.materials.size()) - 1;
        }
    }
    const glm::mat3 normal_m = glm::transpose(glm::inverse(glm::mat3(world)));
    const bool mirrored = glm::determinant(glm::mat3(world)) < 0.0f;
    const std::size_t base = c.out.vertices.size();
    for (std::size_t i = 0; i < count; ++i) {
        MeshVertex v;
        v.position = glm::vec3(world * glm::vec4(vp.get(i, 0), vp.get(i, 1), vp.get(i, 2), 1.0f));
        if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) || !std::isfinite(v.position.z) ||
            glm::length(v.position) > 1e6f)
            return c.fail("POSITION of " + what + ": vertex " + std::to_string(i) + " is not finite or beyond 1e6 m");
        if (has_n) {
            glm::vec3 n = normal_m * glm::vec3(vn.get(i, 0), vn.get(i, 1), vn.get(i, 2));
            const float len = glm::length(n);
            v.normal = len > 1e-12f && std::isfinite(len) ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
        }
        if (has_t) {
            glm::vec3 t = glm::mat3(world) * glm::vec3(vt.get(i, 0), vt.get(i, 1), vt.get(i, 2));
            const float len = glm::length(t);
            if (len > 1e-12f && std::isfinite(len))
                v.tangent = glm::vec4(t / len, (vt.get(i, 3) < 0.0f) != mirrored ? -1.0f : 1.0f);
        }
        if (has_uv) {
            v.uv = glm::vec2(vuv.get(i, 0), vuv.get(i, 1));
            if (!std::isfinite(v.uv.x) || !std::isfinite(v.uv.y)) v.uv = glm::vec2(0.0f);
        }
        c.out.vertices.push_back(v);
    }
    std::vector<std::uint32_t> idx;
    if (p.indices >= 0) {
        AccessorView vi;
        if (!viewAccessor(c, p.indices, "indices of " + what,
                          {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}, 1, vi))
            return false;
        idx.reserve(vi.count);
        for (std::size_t i = 0; i < vi.count; ++i) {
            const std::uint32_t k = vi.index(i);
            if (k >= count)
                return c.fail("indices of " + what + ": index " + std::to_string(k) + " at " + std::to_string(i) +
                              " is past the " + std::to_string(count) + " vertices");
            idx.push_back(std::uint32_t(base) + k);
        }
    } else {
        for (std::size_t i = 0; i < count; ++i) idx.push_back(std::uint32_t(base + i));
    }
    idx.resize(idx.size() / 3 * 3);
    if (mirrored)
        for (std::size_t i = 0; i < idx.size(); i += 3) std::swap(idx[i + 1], idx[i + 2]);
    if (!has_n) {  // flat-ish normals: area-weighted face normals summed per vertex
        for (std::size_t i = base; i < c.out.vertices.size(); ++i) c.out.vertices[i].normal = glm::vec3(0.0f);
        for (std::size_t i = 0; i < idx.size(); i += 3) {
            MeshVertex &a = c.out.vertices[idx[i]], &b = c.out.vertices[idx[i + 1]], &d = c.out.vertices[idx[i + 2]];
            const glm::vec3 n = glm::cross(b.position - a.position, d.position - a.position);
            a.normal += n, b.normal += n, d.normal += n;
        }
        for (std::size_t i = base; i < c.out.vertices.size(); ++i) {
            glm::vec3& n = c.out.vertices[i].normal;
            const float len = glm::length(n);
            n = len > 1e-20f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
        }
    }
    if (!has_t && has_uv && c.out.materials[std::size_t(mat)].normal_texture >= 0)
        deriveTangents(c.out.vertices, idx, base, 0);
    if (per_material.size() < c.out.materials.size()) per_material.resize(c.out.materials.size());
    auto& list = per_material[std::size_t(mat)];
    list.insert(list.end(), idx.begin(), idx.end());
    return true;
}

bool readNode(Context& c, int index, const glm::mat4& parent, int depth, std::set<int>& path,
              std::vector<std::vector<std::uint32_t>>& per_material) {
    if (index < 0 || std::size_t(index) >= c.g.nodes.size()) return c.fail("node " + std::to_string(index) + " does not exist");
    if (depth > kMaxNodeDepth || !path.insert(index).second)
        return c.fail("node " + std::to_string(index) + ": the node hierarchy has a cycle or is deeper than " +
                      std::to_string(kMaxNodeDepth));
    const tinygltf::Node& n = c.g.nodes[std::size_t(index)];
    const glm::mat4 world = parent * nodeMatrix(n);
    for (int k = 0; k < 16; ++k)
        if (!std::isfinite(world[k / 4][k % 4])) return c.fail("node " + std::to_string(index) + ": transform is not finite");
    if (n.mesh >= 0) {
        if (std::size_t(n.mesh) >= c.g.meshes.size())
            return c.fail("node " + std::to_string(index) + ": mesh " + std::to_string(n.mesh) + " does not exist");
        const tinygltf::Mesh& mesh = c.g.meshes[std::size_t(n.mesh)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
            if (!readPrimitive(c, mesh.primitives[p], "mesh " + std::to_string(n.mesh) + " primitive " + std::to_string(p), world,
                               per_material))
                return false;
    }
    for (int child : n.children)
        if (!readNode(c, child, world, depth + 1, path, per_material)) return false;
    path.erase(index);
    return true;
}

std::string convert(const tinygltf::Model& g, const std::string& name, Model& out) {
    out = Model{};
    out.name = name;
    Context c{g, out, {}, 0};
    for (const std::string& ext : g.extensionsRequired)
        return name + ": requires extension " + ext + ", which vista does not support (none is required-supported)";
    std::vector<std::vector<std::uint32_t>> per_material;
    if (readImages(c) && readMaterials(c)) {
        std::vector<int> roots;
        if (!g.scenes.empty()) {
            const int scene = g.defaultScene >= 0 && std::size_t(g.defaultScene) < g.scenes.size() ? g.defaultScene : 0;
            roots = g.scenes[std::size_t(scene)].nodes;
        } else {  // no scene: every node that is nobody's child
            std::vector<bool> child(g.nodes.size(), false);
            for (const auto& n : g.nodes)
                for (int k : n.children)
                    if (k >= 0 && std::size_t(k) < child.size()) child[std::size_t(k)] = true;
            for (std::size_t i = 0; i < g.nodes.size(); ++i)
                if (!child[i]) roots.push_back(int(i));
        }
        std::set<int> path;
        for (int r : roots)
            if (!readNode(c, r, glm::mat4(1.0f), 0, path, per_material)) break;
    }
    if (!c.error.empty()) return name + ": " + c.error;
    ModelLod lod0;
    for (std::size_t m = 0; m < per_material.size(); ++m) {
        if (per_material[m].empty()) continue;
        lod0.primitives.push_back({std::uint32_t(out.indices.size()), std::uint32_t(per_material[m].size()), int(m)});
        out.indices.insert(out.indices.end(), per_material[m].begin(), per_material[m].end());
    }
    if (lod0.primitives.empty()) return name + ": no triangles in the scene's meshes";
    out.lods.push_back(std::move(lod0));
    out.bounds_min = glm::vec3(std::numeric_limits<float>::max());
    out.bounds_max = glm::vec3(-std::numeric_limits<float>::max());
    for (const MeshVertex& v : out.vertices) {
        out.bounds_min = glm::min(out.bounds_min, v.position);
        out.bounds_max = glm::max(out.bounds_max, v.position);
    }
    return "";
}

}  // namespace

std::string loadGltfFromMemory(std::string_view bytes, const std::filesystem::path& base_dir, const std::string& name,
                               Model& out) {
    tinygltf::TinyGLTF loader;
    std::size_t pixels = 0;
    loader.SetImageLoader(loadImage, &pixels);
    FsGuard guard{base_dir};
    loader.SetFsCallbacks({fileExists, expandPath, readWholeFile, writeWholeFile, &guard});
    tinygltf::Model g;
    std::string err, warn;
    const bool glb = bytes.size() >= 4 && bytes.substr(0, 4) == "glTF";
    if (bytes.size() > std::size_t(std::numeric_limits<unsigned int>::max())) return name + ": file too large";
    const std::string base = base_dir.empty() ? std::string() : base_dir.string();
    const bool ok = glb ? loader.LoadBinaryFromMemory(&g, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                      static_cast<unsigned int>(bytes.size()), base)
                        : loader.LoadASCIIFromString(&g, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()), base);
    if (!ok) {
        while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
        for (char& ch : err)
            if (ch == '\n') ch = ';';
        return name + ": not a valid glTF 2.0 file: " + (err.empty() ? std::string("unreadable") : err);
    }
    return convert(g, name, out);
}

std::string loadGltf(const std::filesystem::path& path, Model& out) {
    std::string bytes;
    if (std::string why = readInputFile(path, kMaxGltfBytes, bytes); !why.empty()) return why;
    std::filesystem::path base = path.parent_path();
    if (base.empty()) base = ".";
    return loadGltfFromMemory(bytes, base, path.string(), out);
}

}  // namespace vista
