// User materials and splat maps (user_materials.h): every image is opened only by the reader its
// extension names (as heightmaps are), after the file is known to be a regular file under the
// binary input limit; channels and size are checked before a pixel is read.
#include "terrain/user_materials.h"

#include "config/file_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace vista {
namespace usermat {

constexpr const char* kGeneratedNames[int(MaterialLayer::Count)] = {"sand", "grass", "rock", "snow", "dirt"};
constexpr const char* kFormats = ".png .jpg .jpeg .tga .tif .tiff .bmp";

struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<std::uint8_t> pixels;  // width x height x channels, top row first
};

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

std::string channelNames(const std::vector<int>& accepted) {
    std::string out;
    for (std::size_t i = 0; i < accepted.size(); ++i) {
        const int c = accepted[i];
        out += (i == 0 ? "" : i + 1 == accepted.size() ? " or " : ", ") + std::to_string(c) +
               (c == 1 ? " (grey)" : c == 3 ? " (RGB)" : c == 4 ? " (RGBA)" : "");
    }
    return out;
}

// Reads file as 8-bit samples; "" or why not (without the file's name: the caller's error has it).
std::string readImage8(const std::string& file, const std::vector<int>& channels, Image& out) {
    if (std::string why = inputFileProblem(file, kMaxBinaryInputBytes); !why.empty()) return why;
    const std::string extension = lower(std::filesystem::path(file).extension().string());
    if (const std::vector<std::string> formats = words(kFormats); std::ranges::find(formats, extension) == formats.end())
        return "is not an image format vista reads for materials (extension '" + extension + "'); accepted: " + kFormats;
    auto in = OIIO::ImageInput::create(extension.substr(1));
    if (!in) return "cannot be read: OpenImageIO has no reader for '" + extension + "' (" + OIIO::geterror() + ")";
    OIIO::ImageSpec config, spec;
    config.attribute("oiio:UnassociatedAlpha", 1);  // stored values, not premultiplied ones
    if (!in->open(file, spec, config)) {
        const std::string error = in->geterror();
        return "cannot be read as " + std::string(in->format_name()) + " (" + (error.empty() ? "not a valid file" : error) +
               "); accepted: an image in one of " + kFormats;
    }
    if (std::ranges::find(channels, spec.nchannels) == channels.end())
        return "has " + std::to_string(spec.nchannels) + " channels; accepted: " + channelNames(channels);
    if (spec.depth > 1) return "is a volume of " + std::to_string(spec.depth) + " slices; accepted: one 2D image";
    if (spec.width < 1 || spec.height < 1 || std::uint64_t(spec.width) * std::uint64_t(spec.height) > (std::uint64_t(1) << 30))
        return "is " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " pixels; accepted: 1 to 2^30 pixels";
    out.width = spec.width;
    out.height = spec.height;
    out.channels = spec.nchannels;
    out.pixels.resize(std::size_t(out.width) * std::size_t(out.height) * std::size_t(out.channels));
    // has_error: some readers fill a truncated file's missing rows and still return true.
    if (!in->read_image(0, 0, 0, out.channels, OIIO::TypeDesc::UINT8, out.pixels.data()) || in->has_error()) {
        const std::string error = in->geterror();
        return "cannot be read (" + (error.empty() ? std::string("the file is truncated or damaged") : error) + ")";
    }
    in->close();
    return {};
}

bool isPowerOfTwo(int v) { return v > 0 && (v & (v - 1)) == 0; }

// Channel c of texel (x, y) of image, enlarged by an integer factor with bilinear filtering that
// wraps around (the images repeat on the ground): texel centres of the small image land on
// texel centres of the large one's.
float sampleRepeat(const Image& image, int factor, int x, int y, int c) {
    const int n = image.width;
    const float u = (float(x) + 0.5f) / float(factor) - 0.5f, v = (float(y) + 0.5f) / float(factor) - 0.5f;
    const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
    const float fx = u - float(x0), fy = v - float(y0);
    auto at = [&](int xx, int yy) {
        xx = ((xx % n) + n) % n, yy = ((yy % n) + n) % n;
        return float(image.pixels[(std::size_t(yy) * std::size_t(n) + std::size_t(xx)) * std::size_t(image.channels) + std::size_t(c)]);
    };
    const float top = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * fx;
    const float bottom = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * fx;
    return top + (bottom - top) * fy;
}

std::uint8_t byte(float v) { return std::uint8_t(std::clamp(v, 0.0f, 255.0f) + 0.5f); }

struct UserImages {
    Image albedo, normal, height, roughness;  // empty images: not given
};

}  // namespace usermat

std::vector<std::string> splatFiles(const TerrainSettings& s) { return usermat::words(s.splat_map); }

TerrainSettings resolveMaterialPaths(TerrainSettings s, const std::function<std::filesystem::path(const std::filesystem::path&)>& resolve) {
    auto fix = [&](std::string& file) {
        if (!file.empty()) file = resolve(file).string();
    };
    for (TerrainMaterialSettings& m : s.materials)
        for (std::string* file : {&m.albedo, &m.normal, &m.height, &m.roughness}) fix(*file);
    std::vector<std::string> splat = splatFiles(s);
    s.splat_map.clear();
    for (std::string& file : splat) {
        fix(file);
        s.splat_map += (s.splat_map.empty() ? "" : " ") + file;
    }
    return s;
}

MaterialSet loadMaterialSet(const TerrainSettings& s, int map_width, int map_height, InputErrors& errors) {
    using namespace usermat;
    MaterialSet set;
    const std::size_t errors_before = errors.size();
    auto fail = [&](const std::string& file, const std::string& message) { errors.push_back({file, 0, message}); };

    // The user's images, each checked on its own, then their sizes against each other.
    std::vector<UserImages> user(s.materials.size());
    int size = 0;
    std::string size_file;
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
        const TerrainMaterialSettings& m = s.materials[i];
        const std::string section = "[" + m.section + "] ";
        if (m.albedo.empty()) fail(section + "albedo", "no albedo image; accepted: an RGB or RGBA image file (" + std::string(kFormats) + ")");
        struct Slot {
            const std::string& file;
            const char* key;
            std::vector<int> channels;
            Image& image;
        };
        for (const Slot& slot : {Slot{m.albedo, "albedo", {3, 4}, user[i].albedo}, Slot{m.normal, "normal", {3, 4}, user[i].normal},
                                 Slot{m.height, "height", {1}, user[i].height}, Slot{m.roughness, "roughness", {1}, user[i].roughness}}) {
            if (slot.file.empty()) continue;
            if (std::string why = readImage8(slot.file, slot.channels, slot.image); !why.empty()) {
                fail(slot.file, section + slot.key + ": " + why);
                continue;
            }
            const Image& image = slot.image;
            if (image.width != image.height || !isPowerOfTwo(image.width) || image.width < kMinMaterialImage ||
                image.width > kMaxMaterialImage) {
                fail(slot.file, section + slot.key + ": is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                    "; accepted: square, a power of two from " + std::to_string(kMinMaterialImage) + " to " +
                                    std::to_string(kMaxMaterialImage));
            } else if (size == 0) {
                size = image.width, size_file = slot.file;
            } else if (image.width != size) {
                fail(slot.file, section + slot.key + ": is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                    "; accepted: the size of every other material image, " + std::to_string(size) + "x" +
                                    std::to_string(size) + " (as " + size_file + ")");
            }
        }
    }

    // Layers: the generated ones, a user material of a generated name in its place, others after them.
    std::vector<int> layer_of(s.materials.size(), -1);
    for (const char* name : kGeneratedNames) set.names.push_back(name);
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
        const auto it = std::ranges::find(set.names, s.materials[i].name);
        if (it != set.names.end() && it - set.names.begin() < int(MaterialLayer::Count)) {
            layer_of[i] = int(it - set.names.begin());
            continue;
        }
        if (int(set.names.size()) >= kMaxMaterialLayers) {
            fail("[" + s.materials[i].section + "]", "one added material too many; accepted: at most " +
                                                         std::to_string(kMaxMaterialLayers - int(MaterialLayer::Count)) +
                                                         " besides those named sand, grass, rock, snow or dirt (which replace them)");
            continue;
        }
        layer_of[i] = int(set.names.size());
        set.names.push_back(s.materials[i].name);
    }

    // Splat maps: RGB(A) weights, one texel per heightmap sample.
    const std::vector<std::string> splat = splatFiles(s);
    if (splat.size() > std::size_t(kMaxSplatImages))
        fail("[terrain] splat_map", std::to_string(splat.size()) + " files; accepted: 1 or " + std::to_string(kMaxSplatImages) +
                                        " images separated by a space");
    if (!splat.empty() && splat.size() <= std::size_t(kMaxSplatImages)) {
        set.splat_images = int(splat.size());
        set.splat_width = map_width, set.splat_height = map_height;
        const std::size_t texels = std::size_t(map_width) * std::size_t(map_height);
        set.splat.assign(texels * 4 * splat.size(), 0);
        for (std::size_t k = 0; k < splat.size(); ++k) {
            Image image;
            if (std::string why = readImage8(splat[k], {3, 4}, image); !why.empty()) {
                fail(splat[k], "[terrain] splat_map: " + why);
                continue;
            }
            if (image.width != map_width || image.height != map_height) {
                fail(splat[k], "[terrain] splat_map: is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                   "; accepted: one texel per heightmap sample, " + std::to_string(map_width) + "x" +
                                   std::to_string(map_height));
                continue;
            }
            for (std::size_t t = 0; t < texels; ++t)
                for (int c = 0; c < 4; ++c)  // RGB: no fourth weight
                    set.splat[(k * texels + t) * 4 + std::size_t(c)] = c < image.channels ? image.pixels[t * std::size_t(image.channels) + std::size_t(c)] : 0;
        }
        std::vector<std::string> names = words(s.splat_layers);
        if (names.empty())
            for (const TerrainMaterialSettings& m : s.materials) names.push_back(m.name);
        std::string accepted;
        for (const std::string& n : set.names) accepted += (accepted.empty() ? "" : " ") + n;
        if (names.empty())
            fail("[terrain] splat_layers", "is empty and there is no [terrain.material.NAME]; accepted: the layer of each splat "
                                           "channel by name, from: " + accepted);
        if (names.size() > std::size_t(4 * set.splat_images))
            fail("[terrain] splat_layers", std::to_string(names.size()) + " layers for " + std::to_string(4 * set.splat_images) +
                                               " splat channels; accepted: at most one name per channel");
        set.splat_layers.assign(std::size_t(4 * set.splat_images), -1);
        for (std::size_t c = 0; c < names.size() && c < set.splat_layers.size(); ++c) {
            const auto it = std::ranges::find(set.names, names[c]);
            if (it == set.names.end())
                fail("[terrain] splat_layers", "'" + names[c] + "' is no layer; accepted: " + accepted);
            else
                set.splat_layers[c] = int(it - set.names.begin());
        }
    }
    for (std::size_t i = 0; i < s.materials.size(); ++i)
        if (layer_of[i] >= int(MaterialLayer::Count) && std::ranges::find(set.splat_layers, layer_of[i]) == set.splat_layers.end())
            fail("[" + s.materials[i].section + "]", "is placed by nothing; accepted: a splat_map with the material in [terrain] "
                                                     "splat_layers, or the name of a layer it replaces (sand, grass, rock, snow, dirt)");
    if (errors.size() > errors_before) return {};

    // The arrays: the generated layers at the common size, the user's in their places.
    const int array_size = std::max(size, kGeneratedMaterialSize);
    MaterialImages generated = generateMaterialImages(array_size);
    const std::size_t texels = std::size_t(array_size) * std::size_t(array_size);
    set.images.size = array_size;
    set.images.layers = int(set.names.size());
    set.images.albedo.assign(texels * 4 * set.names.size(), 0);
    set.images.normal.assign(texels * 4 * set.names.size(), 0);
    std::copy(generated.albedo.begin(), generated.albedo.end(), set.images.albedo.begin());
    std::copy(generated.normal.begin(), generated.normal.end(), set.images.normal.begin());
    set.repeat_m.assign(set.names.size(), 0.0f);
    set.user.assign(set.names.size(), false);
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
        const TerrainMaterialSettings& m = s.materials[i];
        const UserImages& images = user[i];
        const std::size_t layer = std::size_t(layer_of[i]);
        set.repeat_m[layer] = m.tiling_m;
        set.user[layer] = true;
        const int factor = array_size / size;
        for (int y = 0; y < array_size; ++y)
            for (int x = 0; x < array_size; ++x) {
                const std::size_t o = (layer * texels + std::size_t(y) * std::size_t(array_size) + std::size_t(x)) * 4;
                auto at = [&](const Image& image, int c, float fallback) {
                    return image.pixels.empty() ? fallback : sampleRepeat(image, factor, x, y, c);
                };
                for (int c = 0; c < 3; ++c) set.images.albedo[o + std::size_t(c)] = byte(at(images.albedo, c, 0.0f));
                set.images.albedo[o + 3] = byte(at(images.roughness, 0, m.roughness_value * 255.0f));
                for (int c = 0; c < 3; ++c) set.images.normal[o + std::size_t(c)] = byte(at(images.normal, c, c == 2 ? 255.0f : 127.5f));
                set.images.normal[o + 3] = byte(at(images.height, 0, 255.0f));  // flat: at the drawn surface
            }
    }
    return set;
}

}  // namespace vista
