// Reuse of transient frame-graph resources across passes and frames.
#include "renderer/transient_pool.h"

#include <algorithm>
#include <stdexcept>

namespace vista {

TransientPool::~TransientPool() { clear(); }

std::uint32_t TransientPool::acquireTexture(const TextureDesc& desc, const std::string& name) {
    for (auto& e : entries_)
        if (e.is_texture && !e.in_use && e.texture == desc) {
            e.in_use = true;
            e.last_used = frame_;
            return e.id;
        }
    entries_.push_back({true, desc, {}, device_.createTexture(desc, name), true, frame_});
    ++created_;
    return entries_.back().id;
}

std::uint32_t TransientPool::acquireBuffer(const BufferDesc& desc, const std::string& name) {
    for (auto& e : entries_)
        if (!e.is_texture && !e.in_use && e.buffer == desc) {
            e.in_use = true;
            e.last_used = frame_;
            return e.id;
        }
    entries_.push_back({false, {}, desc, device_.createBuffer(desc, name), true, frame_});
    ++created_;
    return entries_.back().id;
}

void TransientPool::releaseTexture(const TextureDesc&, std::uint32_t id) {
    for (auto& e : entries_)
        if (e.is_texture && e.id == id && e.in_use) {
            e.in_use = false;
            return;
        }
    throw std::logic_error("transient pool: released texture " + std::to_string(id) + " is not in use");
}

void TransientPool::releaseBuffer(const BufferDesc&, std::uint32_t id) {
    for (auto& e : entries_)
        if (!e.is_texture && e.id == id && e.in_use) {
            e.in_use = false;
            return;
        }
    throw std::logic_error("transient pool: released buffer " + std::to_string(id) + " is not in use");
}

void TransientPool::destroy(const Entry& e) {
    if (e.is_texture)
        device_.destroyTexture(e.id);
    else
        device_.destroyBuffer(e.id);
}

void TransientPool::endFrame() {
    ++frame_;
    std::erase_if(entries_, [&](const Entry& e) {
        bool stale = !e.in_use && frame_ - e.last_used > kKeepFrames;
        if (stale) destroy(e);
        return stale;
    });
}

std::size_t TransientPool::bytes() const {
    std::size_t total = 0;
    for (const Entry& e : entries_) total += e.is_texture ? textureBytes(e.texture) : e.buffer.bytes;
    return total;
}

void TransientPool::clear() {
    std::erase_if(entries_, [&](const Entry& e) {
        if (!e.in_use) destroy(e);
        return !e.in_use;
    });
}

}  // namespace vista
