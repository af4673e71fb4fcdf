// Procedural props (see gen_props.h) and a minimal glTF writer over tinygltf.
#include "renderer/meshes/gen_props.h"

#include "config/file_io.h"
#include "renderer/random.h"

#include <tiny_gltf.h>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>

namespace vista {
namespace {

// A deterministic stream of numbers in [0, 1).
struct Random {
    std::uint32_t seed, n = 0;
    float next() { return float(hashInts(seed, n++, 0x51ed27u) >> 8) * (1.0f / 16777216.0f); }
    float range(float a, float b) { return a + (b - a) * next(); }
};

// Triangles per material, assembled into a Model by finish().
struct Builder {
    std::vector<MeshVertex> vertices;
    std::vector<std::vector<std::uint32_t>> tris;  // per material
    Model model;
    explicit Builder(std::string name) { model.name = std::move(name); }
    int material(const ModelMaterial& m) {
        model.materials.push_back(m);
        tris.emplace_back();
        return int(model.materials.size()) - 1;
    }
    std::uint32_t vertex(glm::vec3 p, glm::vec3 n, glm::vec2 uv) {
        vertices.push_back(MeshVertex{p, glm::normalize(n), glm::vec4(0.0f), uv});
        return std::uint32_t(vertices.size() - 1);
    }
    void tri(int m, std::uint32_t a, std::uint32_t b, std::uint32_t c) { tris[std::size_t(m)].insert(tris[std::size_t(m)].end(), {a, b, c}); }
    // A flat quad a b c d counter-clockwise seen from its normal side.
    void quad(int m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec2 uv_scale = glm::vec2(1.0f)) {
        const glm::vec3 n = glm::normalize(glm::cross(b - a, d - a));
        const std::uint32_t i0 = vertex(a, n, glm::vec2(0, uv_scale.y)), i1 = vertex(b, n, uv_scale),
                            i2 = vertex(c, n, glm::vec2(uv_scale.x, 0)), i3 = vertex(d, n, glm::vec2(0));
        tri(m, i0, i1, i2);
        tri(m, i0, i2, i3);
    }
    Model finish() {
        model.vertices = vertices;
        ModelLod lod;
        for (std::size_t m = 0; m < tris.size(); ++m) {
            if (tris[m].empty()) continue;
            lod.primitives.push_back({std::uint32_t(model.indices.size()), std::uint32_t(tris[m].size()), int(m)});
            model.indices.insert(model.indices.end(), tris[m].begin(), tris[m].end());
        }
        model.lods = {lod};
        model.bounds_min = glm::vec3(std::numeric_limits<float>::max());
        model.bounds_max = -model.bounds_min;
        for (const MeshVertex& v : model.vertices) {
            model.bounds_min = glm::min(model.bounds_min, v.position);
            model.bounds_max = glm::max(model.bounds_max, v.position);
        }
        return std::move(model);
    }
};

// A tapered tube of `sides` from a (radius ra) to b (radius rb).
void tube(Builder& b, int m, glm::vec3 a, glm::vec3 e, float ra, float rb, int sides) {
    const glm::vec3 axis = glm::normalize(e - a);
    const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 u = glm::normalize(glm::cross(axis, helper)), v = glm::cross(axis, u);
    const std::uint32_t first = std::uint32_t(b.vertices.size());
    for (int s = 0; s <= sides; ++s) {
        const float t = 2.0f * glm::pi<float>() * float(s) / float(sides);
        const glm::vec3 dir = u * std::cos(t) + v * std::sin(t);
        b.vertex(a + dir * ra, dir, glm::vec2(float(s) / float(sides), 0.0f));
        b.vertex(e + dir * rb, dir, glm::vec2(float(s) / float(sides), 1.0f));
    }
    for (int s = 0; s < sides; ++s) {
        const std::uint32_t i = first + std::uint32_t(2 * s);
        b.tri(m, i, i + 2, i + 1);
        b.tri(m, i + 1, i + 2, i + 3);
    }
}

// Rotation taking +y to dir.
glm::quat towards(glm::vec3 dir) {
    dir = glm::normalize(dir);
    const glm::vec3 axis = glm::cross(glm::vec3(0, 1, 0), dir);
    const float s = glm::length(axis);
    if (s < 1e-6f) return dir.y > 0.0f ? glm::quat(1, 0, 0, 0) : glm::angleAxis(glm::pi<float>(), glm::vec3(1, 0, 0));
    return glm::angleAxis(std::atan2(s, dir.y), axis / s);
}

struct TreeState {
    Builder& b;
    int bark, leaves;
    Random rnd;
};

// The L-system A -> F [+A] [-A] [^A], interpreted directly: F is a tube along the turtle's
// heading; each bracket starts a child turned by a random angle about a rolled axis.
void grow(TreeState& st, glm::vec3 base, glm::quat heading, float length, float radius, int generation) {
    const glm::vec3 dir = heading * glm::vec3(0, 1, 0);
    const glm::vec3 tip = base + dir * length;
    tube(st.b, st.bark, base, tip, radius, radius * 0.7f, generation == 0 ? 8 : 6);
    if (generation == 4) {
        // Three crossed leaf cards around the tip, each 2.4 m, facing out at 60 deg steps.
        const float size = 2.4f;
        for (int k = 0; k < 3; ++k) {
            const float a = glm::pi<float>() * float(k) / 3.0f + st.rnd.range(0.0f, 0.5f);
            const glm::vec3 side(std::cos(a) * size * 0.5f, 0.0f, std::sin(a) * size * 0.5f);
            const glm::vec3 c = tip + glm::vec3(0, 0.3f, 0);
            st.b.quad(st.leaves, c - side - glm::vec3(0, size * 0.5f, 0), c + side - glm::vec3(0, size * 0.5f, 0),
                      c + side + glm::vec3(0, size * 0.5f, 0), c - side + glm::vec3(0, size * 0.5f, 0));
        }
        // One horizontal card caps the cluster (seen from above).
        const glm::vec3 c = tip + glm::vec3(0, 0.6f, 0);
        const float h = size * 0.5f;
        st.b.quad(st.leaves, c + glm::vec3(-h, 0, h), c + glm::vec3(h, 0, h), c + glm::vec3(h, 0, -h), c + glm::vec3(-h, 0, -h));
        return;
    }
    const int children = 3;
    for (int k = 0; k < children; ++k) {
        const float roll = 2.0f * glm::pi<float>() * (float(k) + st.rnd.range(-0.2f, 0.2f)) / float(children);
        const float turn = glm::radians(st.rnd.range(25.0f, 45.0f));
        const glm::quat child = heading * glm::angleAxis(roll, glm::vec3(0, 1, 0)) * glm::angleAxis(turn, glm::vec3(1, 0, 0));
        // Branches bend slightly upward (phototropism): blend the heading toward +y.
        glm::vec3 d = child * glm::vec3(0, 1, 0);
        d = glm::normalize(d + glm::vec3(0, 0.25f, 0));
        grow(st, tip, towards(d), length * st.rnd.range(0.65f, 0.8f), radius * 0.62f, generation + 1);
    }
}

// 64 x 64 RGBA leaf cluster: a dozen leaf ellipses with green variation, alpha 0 between them.
ModelImage leafTexture(std::uint32_t seed) {
    ModelImage im;
    im.width = im.height = 64;
    im.rgba.assign(64 * 64 * 4, 0);
    Random rnd{seed ^ 0x1eafu};
    for (int leaf = 0; leaf < 22; ++leaf) {
        const glm::vec2 c(rnd.range(8.0f, 56.0f), rnd.range(8.0f, 56.0f));
        const float a = rnd.range(0.0f, 3.14159f), len = rnd.range(6.0f, 10.0f), wid = len * 0.45f;
        const glm::vec3 col(rnd.range(0.12f, 0.22f), rnd.range(0.30f, 0.45f), rnd.range(0.05f, 0.10f));
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const glm::vec2 d = glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - c;
                const float u = d.x * std::cos(a) + d.y * std::sin(a), v = -d.x * std::sin(a) + d.y * std::cos(a);
                if ((u * u) / (len * len) + (v * v) / (wid * wid) > 1.0f) continue;
                std::uint8_t* p = &im.rgba[std::size_t(y * 64 + x) * 4];
                const float shade = 0.8f + 0.2f * (u / len);  // sRGB-encoded below
                p[0] = std::uint8_t(std::pow(col.r * shade, 1.0f / 2.2f) * 255.0f);
                p[1] = std::uint8_t(std::pow(col.g * shade, 1.0f / 2.2f) * 255.0f);
                p[2] = std::uint8_t(std::pow(col.b * shade, 1.0f / 2.2f) * 255.0f);
                p[3] = 255;
            }
    }
    return im;
}

float valueNoise(glm::vec3 p, std::uint32_t seed) {
    const glm::vec3 i = glm::floor(p), f = p - i, u = f * f * (3.0f - 2.0f * f);
    auto h = [&](int dx, int dy, int dz) {
        return float(hashInts(std::uint32_t(int(i.x) + dx) ^ seed, std::uint32_t(int(i.y) + dy), std::uint32_t(int(i.z) + dz)) >> 8) /
               16777216.0f;
    };
    const float x00 = glm::mix(h(0, 0, 0), h(1, 0, 0), u.x), x10 = glm::mix(h(0, 1, 0), h(1, 1, 0), u.x);
    const float x01 = glm::mix(h(0, 0, 1), h(1, 0, 1), u.x), x11 = glm::mix(h(0, 1, 1), h(1, 1, 1), u.x);
    return glm::mix(glm::mix(x00, x10, u.y), glm::mix(x01, x11, u.y), u.z);
}

}  // namespace

Model generateTree(std::uint32_t seed) {
    Builder b("tree.glb");
    ModelMaterial bark;
    bark.base_color = glm::vec4(0.09f, 0.065f, 0.045f, 1.0f);
    bark.metallic = 0.0f;
    bark.roughness = 0.9f;
    ModelMaterial leaves;
    leaves.base_color = glm::vec4(1.0f);
    leaves.metallic = 0.0f;
    leaves.roughness = 0.6f;
    leaves.alpha_mode = AlphaMode::Mask;
    leaves.alpha_cutoff = 0.5f;
    leaves.double_sided = true;
    leaves.base_color_texture = 0;
    b.model.images.push_back(leafTexture(seed));
    TreeState st{b, b.material(bark), b.material(leaves), Random{seed}};
    grow(st, glm::vec3(0.0f, -0.3f, 0.0f), glm::quat(1, 0, 0, 0), 3.2f, 0.28f, 0);
    return b.finish();
}

Model generateRock(std::uint32_t seed) {
    Builder b("rock.glb");
    ModelMaterial m;
    m.base_color = glm::vec4(0.28f, 0.27f, 0.25f, 1.0f);
    m.metallic = 0.0f;
    m.roughness = 0.85f;
    const int mat = b.material(m);
    // Icosahedron, subdivided twice (320 faces), projected to the unit sphere.
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    std::vector<std::array<std::uint32_t, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (glm::vec3& p : v) p = glm::normalize(p);
    for (int level = 0; level < 2; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
        auto middle = [&](std::uint32_t a, std::uint32_t c) {
            auto key = std::minmax(a, c);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            v.push_back(glm::normalize(v[a] + v[c]));
            return mid[key] = std::uint32_t(v.size() - 1);
        };
        std::vector<std::array<std::uint32_t, 3>> next;
        for (auto& tri : f) {
            const std::uint32_t a = middle(tri[0], tri[1]), c = middle(tri[1], tri[2]), d = middle(tri[2], tri[0]);
            next.insert(next.end(), {{tri[0], a, d}, {tri[1], c, a}, {tri[2], d, c}, {a, c, d}});
        }
        f = std::move(next);
    }
    // Displace: three octaves of value noise, radius 0.7..1.3 m, flattened to 0.6 in y and sunk 0.25 m.
    for (glm::vec3& p : v) {
        float n = 0.0f, amp = 0.5f, freq = 1.5f;
        for (int o = 0; o < 3; ++o, amp *= 0.5f, freq *= 2.1f) n += amp * (valueNoise(p * freq + 10.0f, seed) * 2.0f - 1.0f);
        p *= 1.0f + 0.6f * n;
        p.y = p.y * 0.6f - 0.25f;
    }
    // Flat-shaded faces (a rock's facets catch the light).
    for (auto& tri : f) {
        const glm::vec3 n = glm::normalize(glm::cross(v[tri[1]] - v[tri[0]], v[tri[2]] - v[tri[0]]));
        const std::uint32_t a = b.vertex(v[tri[0]], n, glm::vec2(0)), c = b.vertex(v[tri[1]], n, glm::vec2(1, 0)),
                            d = b.vertex(v[tri[2]], n, glm::vec2(0, 1));
        b.tri(mat, a, c, d);
    }
    return b.finish();
}

Model generateHouse() {
    Builder b("house.glb");
    ModelMaterial wall, roof, door, window;
    wall.base_color = glm::vec4(0.62f, 0.55f, 0.45f, 1.0f);
    wall.metallic = 0.0f;
    wall.roughness = 0.9f;
    roof.base_color = glm::vec4(0.35f, 0.1f, 0.06f, 1.0f);
    roof.metallic = 0.0f;
    roof.roughness = 0.7f;
    door.base_color = glm::vec4(0.15f, 0.08f, 0.04f, 1.0f);
    door.metallic = 0.0f;
    door.roughness = 0.8f;
    window.base_color = glm::vec4(0.05f, 0.05f, 0.05f, 1.0f);
    window.metallic = 0.0f;
    window.roughness = 0.1f;
    window.emissive = glm::vec3(1.0f, 0.62f, 0.3f);  // warm lamp light; scaled by [objects] emissive_nits
    const int w = b.material(wall), r = b.material(roof), d = b.material(door), win = b.material(window);
    const float hx = 4.0f, hz = 3.0f, h = 3.2f, ridge = 5.6f, below = 1.5f;  // walls reach 1.5 m into the ground
    // Walls (counter-clockwise seen from outside).
    b.quad(w, {-hx, -below, hz}, {hx, -below, hz}, {hx, h, hz}, {-hx, h, hz}, {2, 1});
    b.quad(w, {hx, -below, -hz}, {-hx, -below, -hz}, {-hx, h, -hz}, {hx, h, -hz}, {2, 1});
    b.quad(w, {hx, -below, hz}, {hx, -below, -hz}, {hx, h, -hz}, {hx, h, hz}, {2, 1});
    b.quad(w, {-hx, -below, -hz}, {-hx, -below, hz}, {-hx, h, hz}, {-hx, h, -hz}, {2, 1});
    // Gables.
    auto gable = [&](float z, bool front) {
        const glm::vec3 a(-hx, h, z), c(hx, h, z), top(0, ridge, z);
        const glm::vec3 n(0, 0, front ? 1.0f : -1.0f);
        const std::uint32_t i0 = b.vertex(a, n, {0, 0}), i1 = b.vertex(c, n, {1, 0}), i2 = b.vertex(top, n, {0.5f, 1});
        if (front) b.tri(w, i0, i1, i2);
        else b.tri(w, i1, i0, i2);
    };
    gable(hz, true);
    gable(-hz, false);
    // Roof planes with 0.4 m eaves.
    const float e = 0.4f;
    b.quad(r, {-hx - e, h - 0.3f, hz + e}, {hx + e, h - 0.3f, hz + e}, {hx + e, ridge, 0}, {-hx - e, ridge, 0});
    b.quad(r, {hx + e, h - 0.3f, -hz - e}, {-hx - e, h - 0.3f, -hz - e}, {-hx - e, ridge, 0}, {hx + e, ridge, 0});
    // Door and windows, 2 cm proud of the walls.
    const float o = 0.02f;
    b.quad(d, {-0.5f, 0, hz + o}, {0.5f, 0, hz + o}, {0.5f, 2.1f, hz + o}, {-0.5f, 2.1f, hz + o});
    for (float x : {-2.6f, 2.0f}) b.quad(win, {x, 1.0f, hz + o}, {x + 1.0f, 1.0f, hz + o}, {x + 1.0f, 2.2f, hz + o}, {x, 2.2f, hz + o});
    for (float x : {-2.6f, -0.5f, 1.6f}) b.quad(win, {x + 1.0f, 1.0f, -hz - o}, {x, 1.0f, -hz - o}, {x, 2.2f, -hz - o}, {x + 1.0f, 2.2f, -hz - o});
    for (float sgn : {-1.0f, 1.0f}) {
        const float x = sgn * (hx + o);
        const glm::vec3 a(x, 1.0f, sgn * 0.6f), c(x, 1.0f, -sgn * 0.6f);
        b.quad(win, a, c, c + glm::vec3(0, 1.2f, 0), a + glm::vec3(0, 1.2f, 0));
    }
    return b.finish();
}

Model generateLantern() {
    Builder b("lantern.glb");
    ModelMaterial iron, glass;
    iron.base_color = glm::vec4(0.04f, 0.04f, 0.045f, 1.0f);
    iron.metallic = 0.8f;
    iron.roughness = 0.5f;
    glass.base_color = glm::vec4(0.9f, 0.8f, 0.6f, 0.2f);  // faintly amber, mostly clear
    glass.metallic = 0.0f;
    glass.roughness = 0.05f;
    glass.emissive = glm::vec3(0.25f, 0.15f, 0.07f);  // the flame's glow in the glass; x [objects] emissive_nits
    glass.alpha_mode = AlphaMode::Blend;
    glass.double_sided = true;
    const int i = b.material(iron), g = b.material(glass);
    // The post up to the glass box, which holds the lamp at 2.5 m (light.lampN ground 2.5): the
    // box is glass all round, which casts no shadow, so the lamp's light leaves it unshadowed
    // except under the post and above the cap.
    const float post = 2.1f, top = 2.85f, half = 0.17f;
    tube(b, i, {0, -0.5f, 0}, {0, post, 0}, 0.06f, 0.04f, 8);
    const glm::vec3 p00(-half, post, -half), p10(half, post, -half), p11(half, post, half), p01(-half, post, half);
    const glm::vec3 up(0, top - post, 0);
    b.quad(g, p01, p11, p11 + up, p01 + up);  // +z
    b.quad(g, p10, p00, p00 + up, p10 + up);  // -z
    b.quad(g, p11, p10, p10 + up, p11 + up);  // +x
    b.quad(g, p00, p01, p01 + up, p00 + up);  // -x
    b.quad(g, p00, p10, p11, p01);            // bottom
    // An iron pyramid cap with a 3 cm overhang.
    const float e = half + 0.03f, apex = top + 0.22f;
    const glm::vec3 c00(-e, top, -e), c10(e, top, -e), c11(e, top, e), c01(-e, top, e), tip(0, apex, 0);
    for (auto [a, c] : {std::pair{c01, c11}, std::pair{c11, c10}, std::pair{c10, c00}, std::pair{c00, c01}}) {
        const glm::vec3 n = glm::normalize(glm::cross(c - a, tip - a));
        b.tri(i, b.vertex(a, n, {0, 0}), b.vertex(c, n, {1, 0}), b.vertex(tip, n, {0.5f, 1}));
    }
    b.quad(i, c00, c01, c11, c10);  // underside
    return b.finish();
}

std::string modelToGlb(const Model& model) {
    tinygltf::Model g;
    g.asset.version = "2.0";
    g.asset.generator = "vista gen-props";
    tinygltf::Buffer buffer;
    auto append = [&](const void* data, std::size_t bytes) {
        while (buffer.data.size() % 4) buffer.data.push_back(0);
        const std::size_t at = buffer.data.size();
        buffer.data.resize(at + bytes);
        std::memcpy(buffer.data.data() + at, data, bytes);
        return at;
    };
    auto view = [&](std::size_t offset, std::size_t bytes, int target, int stride) {
        tinygltf::BufferView bv;
        bv.buffer = 0;
        bv.byteOffset = offset;
        bv.byteLength = bytes;
        bv.byteStride = std::size_t(stride);
        bv.target = target;
        g.bufferViews.push_back(bv);
        return int(g.bufferViews.size() - 1);
    };
    const std::size_t vbytes = model.vertices.size() * sizeof(MeshVertex);
    const int vview = view(append(model.vertices.data(), vbytes), vbytes, TINYGLTF_TARGET_ARRAY_BUFFER, int(sizeof(MeshVertex)));
    auto accessor = [&](int bv, std::size_t offset, int type, int comp, std::size_t count) {
        tinygltf::Accessor a;
        a.bufferView = bv;
        a.byteOffset = offset;
        a.componentType = comp;
        a.type = type;
        a.count = count;
        g.accessors.push_back(a);
        return int(g.accessors.size() - 1);
    };
    const int pos = accessor(vview, offsetof(MeshVertex, position), TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT,
                             model.vertices.size());
    g.accessors[std::size_t(pos)].minValues = {model.bounds_min.x, model.bounds_min.y, model.bounds_min.z};
    g.accessors[std::size_t(pos)].maxValues = {model.bounds_max.x, model.bounds_max.y, model.bounds_max.z};
    const int nrm = accessor(vview, offsetof(MeshVertex, normal), TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT,
                             model.vertices.size());
    const int uv = accessor(vview, offsetof(MeshVertex, uv), TINYGLTF_TYPE_VEC2, TINYGLTF_COMPONENT_TYPE_FLOAT, model.vertices.size());
    tinygltf::Mesh mesh;
    for (const ModelPrimitive& p : model.lods.front().primitives) {
        const std::size_t at = append(model.indices.data() + p.first_index, p.index_count * 4);
        const int iv = view(at, p.index_count * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, 0);
        tinygltf::Primitive prim;
        prim.attributes = {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}};
        prim.indices = accessor(iv, 0, TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, p.index_count);
        prim.material = p.material;
        prim.mode = TINYGLTF_MODE_TRIANGLES;
        mesh.primitives.push_back(prim);
    }
    for (const ModelImage& im : model.images) {
        tinygltf::Image out;
        out.width = im.width;
        out.height = im.height;
        out.component = 4;
        out.bits = 8;
        out.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
        out.image = im.rgba;
        out.mimeType = "image/png";
        g.images.push_back(out);
        tinygltf::Texture tex;
        tex.source = int(g.images.size() - 1);
        g.textures.push_back(tex);
    }
    for (const ModelMaterial& m : model.materials) {
        tinygltf::Material out;
        out.pbrMetallicRoughness.baseColorFactor = {m.base_color.r, m.base_color.g, m.base_color.b, m.base_color.a};
        out.pbrMetallicRoughness.metallicFactor = m.metallic;
        out.pbrMetallicRoughness.roughnessFactor = m.roughness;
        out.pbrMetallicRoughness.baseColorTexture.index = m.base_color_texture;
        out.emissiveFactor = {m.emissive.r, m.emissive.g, m.emissive.b};
        out.alphaMode = m.alpha_mode == AlphaMode::Mask ? "MASK" : m.alpha_mode == AlphaMode::Blend ? "BLEND" : "OPAQUE";
        out.alphaCutoff = m.alpha_cutoff;
        out.doubleSided = m.double_sided;
        g.materials.push_back(out);
    }
    g.buffers.push_back(buffer);
    g.meshes.push_back(mesh);
    tinygltf::Node node;
    node.mesh = 0;
    g.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes = {0};
    g.scenes.push_back(scene);
    g.defaultScene = 0;
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    writer.WriteGltfSceneToStream(&g, out, false, true);
    return out.str();
}

int runGenProps(const std::filesystem::path& dir, std::uint32_t seed, bool force) {
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) {
        std::fprintf(stderr, "vista: --out: '%s' is not a folder (create it first)\n", dir.string().c_str());
        return 2;
    }
    const std::pair<const char*, Model> props[] = {
        {"tree.glb", generateTree(seed)}, {"rock.glb", generateRock(seed)}, {"house.glb", generateHouse()},
        {"lantern.glb", generateLantern()}};
    for (const auto& [name, model] : props)
        if (std::string why = checkOutputFile(dir / name, force, "--out"); !why.empty()) {
            std::fprintf(stderr, "vista: %s\n", why.c_str());
            return 2;
        }
    for (const auto& [name, model] : props) {
        if (std::string why = writeFileAtomic(dir / name, modelToGlb(model), force); !why.empty()) {
            std::fprintf(stderr, "vista: %s\n", why.c_str());
            return 2;
        }
        std::printf("wrote %s: %zu vertices, %zu triangles, %zu materials\n", (dir / name).string().c_str(),
                    model.vertices.size(), model.indices.size() / 3, model.materials.size());
    }
    return 0;
}

}  // namespace vista
