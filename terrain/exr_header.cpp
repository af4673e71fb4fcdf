// OpenEXR header walk (layout from the OpenEXR file format document: magic, version flags,
// then per part a list of attributes "name\0type\0<int32 size><value>" ended by an empty name).
#include "terrain/exr_header.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace vista {
namespace {

constexpr std::uint32_t kTiledFlag = 0x200;      // single-part file of tiles
constexpr std::uint32_t kDeepFlag = 0x800;       // "non-image": deep data
constexpr std::uint32_t kMultipartFlag = 0x1000;
constexpr std::size_t kMaxNameBytes = 256;       // 255 characters with long names, and the terminator

// Scan lines per chunk for each compression (NONE, RLE, ZIPS, ZIP, PIZ, PXR24, B44, B44A, DWAA, DWAB).
constexpr int kLinesPerChunk[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};

struct Part {
    bool has_window = false;
    std::int64_t x_min = 0, y_min = 0, x_max = -1, y_max = -1;
    bool tiled = false, has_tiles = false, deep = false;
    std::uint32_t tile_x = 0, tile_y = 0;
    int level_mode = 0, rounding = 0;
    int compression = 0;
    std::int64_t chunk_count = -1;  // multi-part files store it
};

std::int32_t readInt32(const unsigned char* p) {
    std::uint32_t v = std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
    std::int32_t s;
    std::memcpy(&s, &v, sizeof s);
    return s;
}

std::uint32_t readUint32(const unsigned char* p) { return std::uint32_t(readInt32(p)); }

// A string ended by '\0' within kMaxNameBytes at bytes[pos]; false when there is none.
bool readName(std::span<const unsigned char> bytes, std::size_t& pos, std::string& name) {
    std::size_t limit = std::min(bytes.size(), pos + kMaxNameBytes);
    for (std::size_t i = pos; i < limit; ++i)
        if (bytes[i] == 0) {
            name.assign(reinterpret_cast<const char*>(bytes.data() + pos), i - pos);
            pos = i + 1;
            return true;
        }
    return false;
}

std::string at(std::size_t pos) { return " at byte " + std::to_string(pos); }

// Reads one part's attributes up to its empty name; pos ends after the terminator.
std::string readPart(std::span<const unsigned char> bytes, std::size_t& pos, Part& part) {
    for (;;) {
        const std::size_t start = pos;
        std::string name, type;
        if (!readName(bytes, pos, name)) return "has a header that ends inside an attribute name" + at(start);
        if (name.empty()) return {};
        if (!readName(bytes, pos, type)) return "has attribute '" + name + "' whose type name never ends" + at(start);
        if (bytes.size() - pos < 4) return "has attribute '" + name + "' cut off before its size" + at(start);
        const std::int32_t size = readInt32(bytes.data() + pos);
        pos += 4;
        if (size < 0 || std::uint64_t(size) > bytes.size() - pos)
            return "has attribute '" + name + "' of " + std::to_string(size) + " bytes but " +
                   std::to_string(bytes.size() - pos) + " bytes are left in the file" + at(start);
        const unsigned char* value = bytes.data() + pos;
        if (name == "dataWindow" && type == "box2i" && size == 16) {
            part.has_window = true;
            part.x_min = readInt32(value);
            part.y_min = readInt32(value + 4);
            part.x_max = readInt32(value + 8);
            part.y_max = readInt32(value + 12);
        } else if (name == "tiles" && type == "tiledesc" && size == 9) {
            part.has_tiles = true;
            part.tile_x = readUint32(value);
            part.tile_y = readUint32(value + 4);
            part.level_mode = value[8] & 0x0f;
            part.rounding = value[8] >> 4;
        } else if (name == "compression" && type == "compression" && size == 1) {
            part.compression = value[0];
        } else if (name == "chunkCount" && type == "int" && size == 4) {
            part.chunk_count = readInt32(value);
        } else if (name == "type" && type == "string") {
            std::string kind(reinterpret_cast<const char*>(value), std::size_t(size));
            part.tiled = kind == "tiledimage";
            part.deep = kind.rfind("deep", 0) == 0;
        }
        pos += std::size_t(size);
    }
}

std::uint64_t ceilDiv(std::uint64_t a, std::uint64_t b) { return (a + b - 1) / b; }

// Level sizes rounded up, an upper bound for either rounding mode.
std::uint64_t levelSize(std::uint64_t size, int level) { return std::max<std::uint64_t>(ceilDiv(size, std::uint64_t(1) << level), 1); }

int levelCount(std::uint64_t size) {
    int levels = 1;
    while ((std::uint64_t(1) << (levels - 1)) < size) ++levels;
    return levels;
}

// Chunk offsets OpenEXR allocates for the part (one uint64 each); an upper bound for tiles.
std::uint64_t chunkCount(const Part& part, std::uint64_t width, std::uint64_t height) {
    if (!part.tiled) return ceilDiv(height, std::uint64_t(kLinesPerChunk[part.compression]));
    if (part.level_mode == 0) return ceilDiv(width, part.tile_x) * ceilDiv(height, part.tile_y);
    const int levels_x = levelCount(width), levels_y = levelCount(height);
    if (part.level_mode == 1) {
        std::uint64_t chunks = 0;
        for (int l = 0; l < std::max(levels_x, levels_y); ++l)
            chunks += ceilDiv(levelSize(width, l), part.tile_x) * ceilDiv(levelSize(height, l), part.tile_y);
        return chunks;
    }
    std::uint64_t across = 0, down = 0;
    for (int l = 0; l < levels_x; ++l) across += ceilDiv(levelSize(width, l), part.tile_x);
    for (int l = 0; l < levels_y; ++l) down += ceilDiv(levelSize(height, l), part.tile_y);
    return across * down;
}

// bytes_left: what the file holds after the headers; the part's offset table is taken from it.
std::string checkPart(const Part& part, std::uint64_t max_bytes, std::uint64_t& bytes_left, const std::string& which) {
    if (part.deep) return which + " holds deep data; a heightmap needs one flat image";
    if (!part.has_window) return which + " has no dataWindow (box2i)";
    if (part.x_max < part.x_min || part.y_max < part.y_min)
        return which + " has an empty data window (" + std::to_string(part.x_min) + ", " + std::to_string(part.y_min) +
               ") - (" + std::to_string(part.x_max) + ", " + std::to_string(part.y_max) + ")";
    const std::uint64_t width = std::uint64_t(part.x_max - part.x_min) + 1, height = std::uint64_t(part.y_max - part.y_min) + 1;
    // Both at most 2^32, so the product fits.
    if (width * height > max_bytes / sizeof(float))
        return which + " has a data window of " + std::to_string(width) + "x" + std::to_string(height) +
               " samples, over the limit of " + std::to_string(max_bytes) + " bytes as floats";
    if (part.compression >= int(std::size(kLinesPerChunk)))
        return which + " has compression " + std::to_string(part.compression) + "; OpenEXR knows 0 to 9";
    if (part.tiled) {
        if (!part.has_tiles) return which + " is tiled but has no tiles (tiledesc) attribute";
        if (part.tile_x == 0 || part.tile_y == 0 || part.tile_x > 0x7fffffffu || part.tile_y > 0x7fffffffu)
            return which + " has tiles of " + std::to_string(part.tile_x) + "x" + std::to_string(part.tile_y) +
                   "; tiles need 1 to 2^31-1 samples a side";
        if (part.level_mode > 2 || part.rounding > 1)
            return which + " has tile level mode " + std::to_string(part.level_mode) + " and rounding " +
                   std::to_string(part.rounding) + "; OpenEXR knows modes 0 to 2 and rounding 0 or 1";
    }
    const std::uint64_t chunks = chunkCount(part, width, height);
    if (part.chunk_count >= 0 && std::uint64_t(part.chunk_count) > chunks)
        return which + " declares " + std::to_string(part.chunk_count) + " chunks; its data window needs at most " +
               std::to_string(chunks);
    // The offset table (8 bytes a chunk) is allocated before any chunk is read.
    if (chunks > max_bytes / 8 || chunks > bytes_left / 8)
        return which + " needs an offset table of " + std::to_string(chunks) + " chunks (" + std::to_string(chunks * 8) +
               " bytes), more than the " + std::to_string(bytes_left) + " bytes left in the file or the limit of " +
               std::to_string(max_bytes) + " bytes";
    bytes_left -= chunks * 8;
    return {};
}

}  // namespace

bool isExr(std::span<const unsigned char> bytes) {
    return bytes.size() >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01;
}

std::string checkExrHeaders(std::span<const unsigned char> bytes, std::uint64_t max_bytes) {
    if (!isExr(bytes)) return "is not an OpenEXR file (its first 4 bytes are not 76 2f 31 01)";
    if (bytes.size() < 8) return "is an OpenEXR file cut off inside its version field";
    const std::uint32_t version = readUint32(bytes.data() + 4);
    if ((version & 0xff) != 2) return "is OpenEXR version " + std::to_string(version & 0xff) + "; only version 2 exists";
    const bool multipart = version & kMultipartFlag;
    std::size_t pos = 8;
    std::vector<Part> parts;
    for (;;) {
        if (multipart && pos < bytes.size() && bytes[pos] == 0) {  // the empty header ends the list
            ++pos;
            break;
        }
        Part part;
        part.tiled = !multipart && (version & kTiledFlag);
        part.deep = !multipart && (version & kDeepFlag);
        if (std::string why = readPart(bytes, pos, part); !why.empty()) return why;
        parts.push_back(part);
        if (!multipart) break;
        if (parts.size() > 4096) return "has more than 4096 parts; a heightmap needs one image";
    }
    if (parts.empty()) return "is a multi-part OpenEXR file with no parts";
    std::uint64_t bytes_left = bytes.size() - pos;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const std::string which = multipart ? "part " + std::to_string(i) : "the image";
        if (std::string why = checkPart(parts[i], max_bytes, bytes_left, which); !why.empty()) return why;
    }
    return {};
}

}  // namespace vista
