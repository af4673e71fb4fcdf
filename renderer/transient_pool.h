// Transient textures and buffers for the frame graph, kept in free lists keyed by
// description (size, format) and reused across frames; whatever has not been used for a
// few frames (after a resize, or when a feature is switched off) is destroyed.
#pragma once

#include "renderer/frame_graph.h"

#include <cstdint>
#include <string>
#include <vector>

namespace vista {

// Creates and destroys the physical objects (GL, or fake ids in tests).
class ResourceDevice {
public:
    virtual ~ResourceDevice() = default;
    virtual std::uint32_t createTexture(const TextureDesc& desc, const std::string& name) = 0;
    virtual void destroyTexture(std::uint32_t id) = 0;
    virtual std::uint32_t createBuffer(const BufferDesc& desc, const std::string& name) = 0;
    virtual void destroyBuffer(std::uint32_t id) = 0;
};

class TransientPool final : public ResourceAllocator {
public:
    // Frames an unused object survives before it is destroyed.
    static constexpr std::uint64_t kKeepFrames = 4;

    explicit TransientPool(ResourceDevice& device) : device_(device) {}
    ~TransientPool() override;
    TransientPool(const TransientPool&) = delete;
    TransientPool& operator=(const TransientPool&) = delete;

    std::uint32_t acquireTexture(const TextureDesc& desc, const std::string& name) override;
    void releaseTexture(const TextureDesc& desc, std::uint32_t id) override;
    std::uint32_t acquireBuffer(const BufferDesc& desc, const std::string& name) override;
    void releaseBuffer(const BufferDesc& desc, std::uint32_t id) override;

    // Ends a frame: destroys free objects unused for more than kKeepFrames frames.
    void endFrame();
    // Destroys everything that is not in use.
    void clear();

    std::size_t liveCount() const { return entries_.size(); }
    // Bytes of every texture and buffer the pool holds, in use or free.
    std::size_t bytes() const;
    std::uint64_t createdCount() const { return created_; }

private:
    struct Entry {
        bool is_texture;
        TextureDesc texture;
        BufferDesc buffer;
        std::uint32_t id;
        bool in_use;
        std::uint64_t last_used;
    };
    void destroy(const Entry& e);

    ResourceDevice& device_;
    std::vector<Entry> entries_;
    std::uint64_t frame_ = 0;
    std::uint64_t created_ = 0;
};

}  // namespace vista
