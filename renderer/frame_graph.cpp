// Frame graph bookkeeping: declared reads and writes, reference-count culling, lifetimes.
#include "renderer/frame_graph.h"

#include <algorithm>
#include <stdexcept>

namespace vista {

std::size_t textureBytes(const TextureDesc& desc) {
    std::size_t texel = 4;
    switch (desc.format) {
        case PixelFormat::RGBA8: case PixelFormat::RGB10A2: case PixelFormat::RG16F: case PixelFormat::R32F:
        case PixelFormat::R32UI: case PixelFormat::Depth32F: texel = 4; break;
        case PixelFormat::RGBA16F: texel = 8; break;
        case PixelFormat::RGBA32F: texel = 16; break;
        case PixelFormat::R16F: texel = 2; break;
    }
    std::size_t bytes = 0;
    for (int level = 0, w = desc.width, h = desc.height; level < std::max(desc.levels, 1); ++level) {
        bytes += std::size_t(std::max(w, 1)) * std::size_t(std::max(h, 1)) * texel;
        w /= 2;
        h /= 2;
    }
    return bytes;
}

FrameGraph::~FrameGraph() = default;

std::uint32_t FrameGraph::addPassNode(std::string name, std::unique_ptr<PassBase> pass) {
    PassNode node;
    node.name = std::move(name);
    node.impl = std::move(pass);
    passes_.push_back(std::move(node));
    compiled_ = false;
    return std::uint32_t(passes_.size() - 1);
}

std::uint32_t FrameGraph::addResource(ResourceNode node) {
    resources_.push_back(std::move(node));
    return std::uint32_t(resources_.size() - 1);
}

const FrameGraph::ResourceNode& FrameGraph::resource(std::uint32_t index, bool texture,
                                                     const char* what) const {
    if (index >= resources_.size() || resources_[index].is_texture != texture)
        throw std::logic_error(std::string("frame graph: invalid ") + (texture ? "texture" : "buffer") +
                               " handle passed to " + what);
    return resources_[index];
}

TextureHandle PassBuilder::create(std::string name, const TextureDesc& desc) {
    FrameGraph::ResourceNode node;
    node.name = std::move(name);
    node.texture = desc;
    return {graph_.addResource(std::move(node))};
}

BufferHandle PassBuilder::create(std::string name, const BufferDesc& desc) {
    FrameGraph::ResourceNode node;
    node.name = std::move(name);
    node.is_texture = false;
    node.buffer = desc;
    return {graph_.addResource(std::move(node))};
}

namespace {
void addUnique(std::vector<std::uint32_t>& list, std::uint32_t value) {
    if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
}
}  // namespace

void PassBuilder::declare(std::uint32_t resource, bool texture, bool write) {
    graph_.resource(resource, texture, graph_.passes_[pass_].name.c_str());
    FrameGraph::PassNode& pass = graph_.passes_[pass_];
    FrameGraph::ResourceNode& res = graph_.resources_[resource];
    addUnique(write ? pass.writes : pass.reads, resource);
    addUnique(write ? res.writers : res.readers, pass_);
}

TextureHandle PassBuilder::read(TextureHandle h) { return declare(h.index, true, false), h; }
TextureHandle PassBuilder::write(TextureHandle h) { return declare(h.index, true, true), h; }
BufferHandle PassBuilder::read(BufferHandle h) { return declare(h.index, false, false), h; }
BufferHandle PassBuilder::write(BufferHandle h) { return declare(h.index, false, true), h; }

void PassBuilder::sideEffect() { graph_.passes_[pass_].side_effect = true; }

const TextureDesc& PassBuilder::desc(TextureHandle h) const {
    return graph_.resource(h.index, true, graph_.passes_[pass_].name.c_str()).texture;
}

std::uint32_t PassContext::texture(TextureHandle h) const {
    return graph_.resource(h.index, true, graph_.passes_[pass_].name.c_str()).id;
}
const TextureDesc& PassContext::desc(TextureHandle h) const {
    return graph_.resource(h.index, true, graph_.passes_[pass_].name.c_str()).texture;
}
std::uint32_t PassContext::buffer(BufferHandle h) const {
    return graph_.resource(h.index, false, graph_.passes_[pass_].name.c_str()).id;
}
const BufferDesc& PassContext::desc(BufferHandle h) const {
    return graph_.resource(h.index, false, graph_.passes_[pass_].name.c_str()).buffer;
}
bool PassContext::firstWrite(TextureHandle h) const {
    return graph_.resource(h.index, true, graph_.passes_[pass_].name.c_str()).first_writer == pass_;
}

TextureHandle FrameGraph::importTexture(std::string name, const TextureDesc& desc, std::uint32_t id) {
    ResourceNode node;
    node.name = std::move(name);
    node.texture = desc;
    node.imported = true;
    node.id = id;
    return {addResource(std::move(node))};
}

BufferHandle FrameGraph::importBuffer(std::string name, const BufferDesc& desc, std::uint32_t id) {
    ResourceNode node;
    node.name = std::move(name);
    node.is_texture = false;
    node.buffer = desc;
    node.imported = true;
    node.id = id;
    return {addResource(std::move(node))};
}

void FrameGraph::present(TextureHandle h) {
    resource(h.index, true, "present()");
    resources_[h.index].presented = true;
    compiled_ = false;
}

void FrameGraph::compile() {
    // Reference counts: a resource is needed by its readers (and by present), a pass by
    // the resources it writes (and by its side effect). Whatever drops to zero is culled,
    // which in turn releases what it read.
    for (auto& r : resources_) {
        r.ref_count = int(r.readers.size()) + (r.presented ? 1 : 0);
        r.first_pass = r.last_pass = r.first_writer = ResourceNode::kNone;
    }
    std::vector<std::uint32_t> unreferenced;
    auto cull = [&](PassNode& pass) {
        pass.culled = true;
        for (std::uint32_t r : pass.reads)
            if (--resources_[r].ref_count == 0) unreferenced.push_back(r);
    };
    for (auto& pass : passes_) {
        pass.ref_count = int(pass.writes.size()) + (pass.side_effect ? 1 : 0);
        pass.culled = false;
    }
    for (auto& pass : passes_)
        if (pass.ref_count == 0) cull(pass);
    for (std::uint32_t r = 0; r < resources_.size(); ++r)
        if (resources_[r].ref_count == 0) unreferenced.push_back(r);
    while (!unreferenced.empty()) {
        std::uint32_t r = unreferenced.back();
        unreferenced.pop_back();
        for (std::uint32_t w : resources_[r].writers) {
            PassNode& writer = passes_[w];
            if (!writer.culled && --writer.ref_count == 0) cull(writer);
        }
    }

    // Lifetimes over the kept passes, and a check that everything read is produced.
    for (std::uint32_t p = 0; p < passes_.size(); ++p) {
        const PassNode& pass = passes_[p];
        if (pass.culled) continue;
        for (std::uint32_t r : pass.reads) {
            ResourceNode& res = resources_[r];
            if (!res.imported && res.first_writer == ResourceNode::kNone)
                throw std::logic_error("frame graph: pass '" + pass.name + "' reads '" + res.name +
                                       "' before any kept pass writes it");
        }
        for (std::uint32_t r : pass.writes)
            if (resources_[r].first_writer == ResourceNode::kNone) resources_[r].first_writer = p;
        auto touch = [&](std::uint32_t r) {
            ResourceNode& res = resources_[r];
            if (res.first_pass == ResourceNode::kNone) res.first_pass = p;
            res.last_pass = p;
        };
        for (std::uint32_t r : pass.reads) touch(r);
        for (std::uint32_t r : pass.writes) touch(r);
    }
    compiled_ = true;
}

void FrameGraph::execute(ResourceAllocator& allocator, PassObserver* observer) {
    if (!compiled_) compile();
    for (std::uint32_t p = 0; p < passes_.size(); ++p) {
        PassNode& pass = passes_[p];
        if (pass.culled) continue;
        for (auto& res : resources_) {
            if (res.imported || res.first_pass != p) continue;
            res.id = res.is_texture ? allocator.acquireTexture(res.texture, res.name)
                                    : allocator.acquireBuffer(res.buffer, res.name);
        }
        if (observer) observer->beginPass(pass.name);
        PassContext ctx(*this, p);
        pass.impl->run(ctx);
        if (observer) observer->endPass(pass.name);
        for (auto& res : resources_) {
            if (res.imported || res.last_pass != p) continue;
            if (res.is_texture)
                allocator.releaseTexture(res.texture, res.id);
            else
                allocator.releaseBuffer(res.buffer, res.id);
        }
    }
}

std::vector<std::string> FrameGraph::executedPasses() const {
    std::vector<std::string> names;
    for (const auto& pass : passes_)
        if (!pass.culled) names.push_back(pass.name);
    return names;
}

std::vector<std::string> FrameGraph::culledPasses() const {
    std::vector<std::string> names;
    for (const auto& pass : passes_)
        if (pass.culled) names.push_back(pass.name);
    return names;
}

std::string FrameGraph::dot() const {
    std::string out = "digraph frame {\n  rankdir=LR;\n";
    for (std::uint32_t p = 0; p < passes_.size(); ++p)
        out += "  p" + std::to_string(p) + " [shape=box,label=\"" + passes_[p].name + "\"" +
               (passes_[p].culled ? ",style=dashed" : "") + "];\n";
    for (std::uint32_t r = 0; r < resources_.size(); ++r) {
        const ResourceNode& res = resources_[r];
        out += "  r" + std::to_string(r) + " [shape=ellipse,label=\"" + res.name + "\"" +
               (res.first_pass == ResourceNode::kNone ? ",style=dashed" : "") + "];\n";
        for (std::uint32_t w : res.writers) out += "  p" + std::to_string(w) + " -> r" + std::to_string(r) + ";\n";
        for (std::uint32_t rd : res.readers) out += "  r" + std::to_string(r) + " -> p" + std::to_string(rd) + ";\n";
    }
    return out + "}\n";
}

}  // namespace vista
