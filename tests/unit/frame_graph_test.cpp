// Frame-graph culling, lifetimes and transient pooling against a null device (no GL).
#include "renderer/frame_graph.h"
#include "renderer/transient_pool.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <stdexcept>

using namespace vista;

namespace {

// Hands out fake ids and counts what is alive.
struct NullDevice final : ResourceDevice {
    std::uint32_t next = 1;
    std::map<std::uint32_t, std::string> alive;
    std::uint32_t createTexture(const TextureDesc&, const std::string& name) override {
        alive[next] = name;
        return next++;
    }
    void destroyTexture(std::uint32_t id) override { REQUIRE(alive.erase(id) == 1); }
    std::uint32_t createBuffer(const BufferDesc&, const std::string& name) override {
        alive[next] = name;
        return next++;
    }
    void destroyBuffer(std::uint32_t id) override { REQUIRE(alive.erase(id) == 1); }
};

struct Recorder final : PassObserver {
    std::vector<std::string> order;
    void beginPass(const std::string& name) override { order.push_back(name); }
    void endPass(const std::string&) override {}
};

bool contains(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

const TextureDesc kHdr{64, 32, PixelFormat::RGBA16F};
const TextureDesc kLdr{64, 32, PixelFormat::RGBA8};
const TextureDesc kDepth{64, 32, PixelFormat::Depth32F};

struct Chain {
    TextureHandle shadow, hdr, depth, ldr, debug;
};

// shadow -> lighting -> tonemap -> present; "debug.view" reads depth and writes a target
// that nobody reads; "ssao" reads depth and writes an occlusion target only debug reads.
Chain buildChain(FrameGraph& g, int& runs, bool present_ldr, bool capture_hdr) {
    Chain c;
    struct Out { TextureHandle t; };
    c.shadow = g.addPass<Out>("shadows.cascade0",
        [&](PassBuilder& b, Out& d) { d.t = b.write(b.create("shadow.map", kDepth)); },
        [&](const Out&, PassContext&) { ++runs; }).t;
    struct Gbuf { TextureHandle hdr, depth; };
    const Gbuf& gb = g.addPass<Gbuf>("terrain.gbuffer",
        [&](PassBuilder& b, Gbuf& d) {
            d.hdr = b.write(b.create("hdr", kHdr));
            d.depth = b.write(b.create("depth", kDepth));
        },
        [&](const Gbuf& d, PassContext& ctx) {
            CHECK(ctx.firstWrite(d.hdr));
            CHECK(ctx.texture(d.hdr) != 0);
            ++runs;
        });
    c.hdr = gb.hdr;
    c.depth = gb.depth;
    g.addPass<Out>("lighting.sun",
        [&](PassBuilder& b, Out& d) {
            b.read(c.shadow);
            b.read(c.depth);
            d.t = b.write(c.hdr);
        },
        [&](const Out& d, PassContext& ctx) {
            CHECK_FALSE(ctx.firstWrite(d.t));
            ++runs;
        });
    TextureHandle ao = g.addPass<Out>("postfx.ssao",
        [&](PassBuilder& b, Out& d) {
            b.read(c.depth);
            d.t = b.write(b.create("ao", TextureDesc{32, 16, PixelFormat::R16F}));
        },
        [&](const Out&, PassContext&) { ++runs; }).t;
    c.debug = g.addPass<Out>("debug.view",
        [&](PassBuilder& b, Out& d) {
            b.read(ao);
            d.t = b.write(b.create("debug", kLdr));
        },
        [&](const Out&, PassContext&) { ++runs; }).t;
    c.ldr = g.addPass<Out>("postfx.tonemap",
        [&](PassBuilder& b, Out& d) {
            b.read(c.hdr);
            d.t = b.write(b.create("ldr", kLdr));
        },
        [&](const Out&, PassContext&) { ++runs; }).t;
    if (present_ldr) g.present(c.ldr);
    if (capture_hdr)
        g.addPass<Out>("capture.readback",
            [&](PassBuilder& b, Out&) {
                b.read(c.hdr);
                b.sideEffect();
            },
            [&](const Out&, PassContext&) { ++runs; });
    return c;
}

}  // namespace

TEST_CASE("frame graph: an unread pass is culled together with its inputs' writers") {
    NullDevice device;
    TransientPool pool(device);
    FrameGraph g;
    int runs = 0;
    buildChain(g, runs, /*present_ldr=*/true, /*capture_hdr=*/false);
    g.compile();
    auto culled = g.culledPasses();
    CHECK(culled == std::vector<std::string>{"postfx.ssao", "debug.view"});
    Recorder rec;
    g.execute(pool, &rec);
    CHECK(rec.order == std::vector<std::string>{"shadows.cascade0", "terrain.gbuffer", "lighting.sun", "postfx.tonemap"});
    CHECK(runs == 4);
    // Culled passes allocate nothing: shadow map, hdr, depth and ldr only.
    for (auto& [id, name] : device.alive) CHECK_MESSAGE(name != "ao", "culled pass allocated");
    CHECK(pool.createdCount() == 4);
}

TEST_CASE("frame graph: present and capture roots are kept") {
    NullDevice device;
    TransientPool pool(device);
    SUBCASE("nothing presented: everything is culled") {
        FrameGraph g;
        int runs = 0;
        buildChain(g, runs, false, false);
        g.compile();
        CHECK(g.executedPasses().empty());
        g.execute(pool, nullptr);
        CHECK(runs == 0);
        CHECK(pool.createdCount() == 0);
    }
    SUBCASE("capture of the HDR target only: tone mapping is culled") {
        FrameGraph g;
        int runs = 0;
        buildChain(g, runs, false, true);
        g.compile();
        auto executed = g.executedPasses();
        CHECK(executed == std::vector<std::string>{"shadows.cascade0", "terrain.gbuffer", "lighting.sun", "capture.readback"});
        CHECK(contains(g.culledPasses(), "postfx.tonemap"));
    }
    SUBCASE("a pass that writes nothing and has no side effect is culled") {
        FrameGraph g;
        struct Empty {};
        g.addPass<Empty>("orphan", [](PassBuilder&, Empty&) {}, [](const Empty&, PassContext&) { FAIL("ran"); });
        g.compile();
        CHECK(g.culledPasses() == std::vector<std::string>{"orphan"});
        g.execute(pool, nullptr);
    }
}

TEST_CASE("frame graph: transient targets are reused within and across frames") {
    NullDevice device;
    TransientPool pool(device);
    // a -> b -> c -> d, each writes a new RGBA16F target and reads the previous one: at most
    // two are alive at once, so the pool needs two textures, not four.
    auto build = [](FrameGraph& g) {
        struct Out { TextureHandle t; };
        TextureHandle prev = g.addPass<Out>("a", [](PassBuilder& b, Out& d) { d.t = b.write(b.create("t0", kHdr)); },
                                            [](const Out&, PassContext&) {}).t;
        for (const char* name : {"b", "c", "d"}) {
            prev = g.addPass<Out>(name,
                [&](PassBuilder& b, Out& d) {
                    b.read(prev);
                    d.t = b.write(b.create(std::string("t_") + name, kHdr));
                },
                [](const Out&, PassContext&) {}).t;
        }
        g.present(prev);
    };
    for (int frame = 0; frame < 5; ++frame) {
        FrameGraph g;
        build(g);
        g.execute(pool, nullptr);
        pool.endFrame();
    }
    CHECK(pool.createdCount() == 2);
    CHECK(device.alive.size() == 2);

    // A different size (a resize): new targets; the old ones go after kKeepFrames frames.
    for (std::uint64_t frame = 0; frame <= TransientPool::kKeepFrames + 1; ++frame) {
        FrameGraph g;
        struct Out { TextureHandle t; };
        auto t = g.addPass<Out>("resized", [](PassBuilder& b, Out& d) { d.t = b.write(b.create("big", TextureDesc{128, 64, PixelFormat::RGBA16F})); },
                                [](const Out&, PassContext&) {}).t;
        g.present(t);
        g.execute(pool, nullptr);
        pool.endFrame();
    }
    CHECK(device.alive.size() == 1);
    pool.clear();
    CHECK(device.alive.empty());
}

TEST_CASE("frame graph: reading what no kept pass writes names the pass and resource") {
    FrameGraph g;
    struct Out { TextureHandle t; };
    TextureHandle orphan;
    g.addPass<Out>("producer", [&](PassBuilder& b, Out&) { orphan = b.create("never.written", kHdr); },
                   [](const Out&, PassContext&) {});
    auto t = g.addPass<Out>("consumer",
        [&](PassBuilder& b, Out& d) {
            b.read(orphan);
            d.t = b.write(b.create("out", kHdr));
        },
        [](const Out&, PassContext&) {}).t;
    g.present(t);
    try {
        g.compile();
        FAIL("compile accepted an unwritten read");
    } catch (const std::logic_error& e) {
        std::string what = e.what();
        CHECK(what.find("consumer") != std::string::npos);
        CHECK(what.find("never.written") != std::string::npos);
    }
}

TEST_CASE("frame graph: imported resources are never pooled and keep their id") {
    NullDevice device;
    TransientPool pool(device);
    FrameGraph g;
    TextureHandle persistent = g.importTexture("heightmap", kHdr, 777);
    struct Out { TextureHandle t; };
    auto t = g.addPass<Out>("terrain.gbuffer",
        [&](PassBuilder& b, Out& d) {
            b.read(persistent);
            d.t = b.write(b.create("hdr", kHdr));
        },
        [&](const Out&, PassContext& ctx) { CHECK(ctx.texture(persistent) == 777); }).t;
    g.present(t);
    g.execute(pool, nullptr);
    CHECK(pool.createdCount() == 1);
    CHECK(g.dot().find("heightmap") != std::string::npos);
}

TEST_CASE("frame graph: texture bytes count every mip level, the pool reports what it holds") {
    CHECK(textureBytes({64, 32, PixelFormat::RGBA16F, 1}) == 64u * 32u * 8u);
    // 64x32, 32x16, 16x8 levels of 4-byte texels.
    CHECK(textureBytes({64, 32, PixelFormat::Depth32F, 3}) == (64u * 32u + 32u * 16u + 16u * 8u) * 4u);
    // Levels past 1x1 stay 1x1 (GL clamps each dimension at 1).
    CHECK(textureBytes({4, 1, PixelFormat::R16F, 4}) == (4u + 2u + 1u + 1u) * 2u);
    CHECK(textureBytes({1, 1, PixelFormat::RGBA32F, 1}) == 16u);
    NullDevice device;
    TransientPool pool(device);
    CHECK(pool.bytes() == 0);
    const std::uint32_t t = pool.acquireTexture({64, 32, PixelFormat::RGBA16F, 1}, "t");
    const std::uint32_t b = pool.acquireBuffer({100}, "b");
    CHECK(pool.bytes() == 64u * 32u * 8u + 100u);
    pool.releaseTexture({64, 32, PixelFormat::RGBA16F, 1}, t);
    pool.releaseBuffer({100}, b);
    CHECK(pool.bytes() == 64u * 32u * 8u + 100u);  // free objects are still held
    pool.clear();
    CHECK(pool.bytes() == 0);
}
