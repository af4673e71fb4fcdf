// A per-frame graph of render passes. Each pass declares in its setup which transient
// textures and buffers it reads and writes; compile() culls every pass whose outputs
// nobody reads (roots: presented resources and side-effect passes such as readbacks),
// and execute() runs the rest in declaration order, acquiring each transient resource
// just before its first user and releasing it after its last (after Filament's FrameGraph).
// The graph itself makes no GL calls: resources come from a ResourceAllocator and timers
// from a PassObserver, so culling and pooling are tested against a null device.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace vista {

enum class PixelFormat : std::uint8_t { RGBA8, RGB10A2, RGBA16F, RGBA32F, RG16F, R16F, R32F, R32UI, Depth32F };

struct TextureDesc {
    int width = 1;
    int height = 1;
    PixelFormat format = PixelFormat::RGBA8;
    int levels = 1;
    bool operator==(const TextureDesc&) const = default;
};

// Bytes of a texture with this description, every mip level included.
std::size_t textureBytes(const TextureDesc& desc);

struct BufferDesc {
    std::size_t bytes = 0;
    bool operator==(const BufferDesc&) const = default;
};

template <class Tag>
struct GraphHandle {
    std::uint32_t index = std::numeric_limits<std::uint32_t>::max();
    bool valid() const { return index != std::numeric_limits<std::uint32_t>::max(); }
    bool operator==(const GraphHandle&) const = default;
};
using TextureHandle = GraphHandle<struct TextureTag>;
using BufferHandle = GraphHandle<struct BufferTag>;

// Supplies physical resources (GL names, or fake ids in tests).
class ResourceAllocator {
public:
    virtual ~ResourceAllocator() = default;
    virtual std::uint32_t acquireTexture(const TextureDesc& desc, const std::string& name) = 0;
    virtual void releaseTexture(const TextureDesc& desc, std::uint32_t id) = 0;
    virtual std::uint32_t acquireBuffer(const BufferDesc& desc, const std::string& name) = 0;
    virtual void releaseBuffer(const BufferDesc& desc, std::uint32_t id) = 0;
};

// Sees each executed pass: debug groups, GPU and CPU timers.
class PassObserver {
public:
    virtual ~PassObserver() = default;
    virtual void beginPass(const std::string& name) = 0;
    virtual void endPass(const std::string& name) = 0;
};

class FrameGraph;

// Declares a pass's resources during setup.
class PassBuilder {
public:
    TextureHandle create(std::string name, const TextureDesc& desc);
    BufferHandle create(std::string name, const BufferDesc& desc);
    TextureHandle read(TextureHandle h);
    TextureHandle write(TextureHandle h);
    BufferHandle read(BufferHandle h);
    BufferHandle write(BufferHandle h);
    // The pass has an effect outside the graph (readback, present): never culled.
    void sideEffect();
    // Description of an existing texture (to size new targets after it).
    const TextureDesc& desc(TextureHandle h) const;

private:
    friend class FrameGraph;
    PassBuilder(FrameGraph& graph, std::uint32_t pass) : graph_(graph), pass_(pass) {}
    void declare(std::uint32_t resource, bool texture, bool write);
    FrameGraph& graph_;
    std::uint32_t pass_;
};

// What a pass sees while it executes.
class PassContext {
public:
    std::uint32_t texture(TextureHandle h) const;
    const TextureDesc& desc(TextureHandle h) const;
    std::uint32_t buffer(BufferHandle h) const;
    const BufferDesc& desc(BufferHandle h) const;
    // True when this pass is the first executed writer of h this frame: it should clear.
    bool firstWrite(TextureHandle h) const;

private:
    friend class FrameGraph;
    PassContext(const FrameGraph& graph, std::uint32_t pass) : graph_(graph), pass_(pass) {}
    const FrameGraph& graph_;
    std::uint32_t pass_;
};

class FrameGraph {
public:
    FrameGraph() = default;
    FrameGraph(const FrameGraph&) = delete;
    FrameGraph& operator=(const FrameGraph&) = delete;
    ~FrameGraph();

    // Adds a pass. setup(PassBuilder&, Data&) runs now and fills Data with handles;
    // execute(const Data&, PassContext&) runs in execute() unless the pass is culled.
    template <class Data, class Setup, class Execute>
    const Data& addPass(std::string name, Setup&& setup, Execute&& execute) {
        auto pass = std::make_unique<PassImpl<Data, std::decay_t<Execute>>>(std::forward<Execute>(execute));
        Data& data = pass->data;
        std::uint32_t index = addPassNode(std::move(name), std::move(pass));
        PassBuilder builder(*this, index);
        setup(builder, data);
        return data;
    }

    // Resources owned outside the graph (persistent textures, history buffers): never
    // acquired or released by the graph, never culled for lack of a writer.
    TextureHandle importTexture(std::string name, const TextureDesc& desc, std::uint32_t id);
    BufferHandle importBuffer(std::string name, const BufferDesc& desc, std::uint32_t id);

    // Marks h as a root: its writers (and theirs) are kept.
    void present(TextureHandle h);

    // Culls, computes lifetimes. Throws std::logic_error naming the pass and resource when
    // a kept pass reads a resource that no kept pass writes.
    void compile();
    // Runs the kept passes in declaration order. observer may be null.
    void execute(ResourceAllocator& allocator, PassObserver* observer);

    std::vector<std::string> executedPasses() const;
    std::vector<std::string> culledPasses() const;
    // Graphviz DOT of passes and resources; culled ones dashed.
    std::string dot() const;

private:
    friend class PassBuilder;
    friend class PassContext;

    struct PassBase {
        virtual ~PassBase() = default;
        virtual void run(PassContext& ctx) = 0;
    };
    template <class Data, class Execute>
    struct PassImpl final : PassBase {
        explicit PassImpl(Execute e) : execute(std::move(e)) {}
        void run(PassContext& ctx) override { execute(static_cast<const Data&>(data), ctx); }
        Data data{};
        Execute execute;
    };

    struct PassNode {
        std::string name;
        std::unique_ptr<PassBase> impl;
        std::vector<std::uint32_t> reads, writes;  // resource indices
        bool side_effect = false;
        int ref_count = 0;
        bool culled = false;
    };
    struct ResourceNode {
        std::string name;
        bool is_texture = true;
        TextureDesc texture;
        BufferDesc buffer;
        bool imported = false;
        bool presented = false;
        std::uint32_t id = 0;  // physical name while alive
        std::vector<std::uint32_t> writers, readers;
        int ref_count = 0;
        static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
        std::uint32_t first_pass = kNone, last_pass = kNone, first_writer = kNone;
    };

    std::uint32_t addPassNode(std::string name, std::unique_ptr<PassBase> pass);
    std::uint32_t addResource(ResourceNode node);
    const ResourceNode& resource(std::uint32_t index, bool texture, const char* what) const;

    std::vector<PassNode> passes_;
    std::vector<ResourceNode> resources_;
    bool compiled_ = false;
};

}  // namespace vista
