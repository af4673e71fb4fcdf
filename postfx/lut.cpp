// .cube parsing: keywords and data lines may come in any order the format allows (keywords
// first); comments (#) and blank lines are skipped; 1D LUTs are refused with a message.
#include "postfx/lut.h"
#include "config/file_io.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace vista {

namespace {

bool parseFloats(std::string_view rest, float* out, int count) {
    std::istringstream in{std::string(rest)};
    for (int i = 0; i < count; ++i)
        if (!(in >> out[i]) || !std::isfinite(out[i])) return false;
    std::string extra;
    return !(in >> extra);
}

}  // namespace

std::optional<CubeLut> parseCube(std::string_view text, const std::string& file, InputErrors& errors) {
    CubeLut lut;
    const std::size_t before = errors.size();
    int line_no = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        ++line_no;
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
        while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
        if (line.empty()) {
            if (end == text.size()) break;
            continue;
        }
        const auto error = [&](const std::string& message) { errors.push_back({file, line_no, message}); };
        const std::size_t space = line.find_first_of(" \t");
        const std::string_view word = line.substr(0, space);
        const std::string_view rest = space == std::string_view::npos ? std::string_view{} : line.substr(space + 1);
        if (word == "TITLE") continue;
        if (word == "LUT_3D_SIZE") {
            int n = 0;
            const auto r = std::from_chars(rest.data(), rest.data() + rest.size(), n);
            if (r.ec != std::errc{} || r.ptr != rest.data() + rest.size() || n < 2 || n > 256 || lut.size != 0)
                error("LUT_3D_SIZE " + std::string(rest) + " is not accepted; expected one integer 2..256, once, before the data");
            else
                lut.size = n;
        } else if (word == "LUT_1D_SIZE") {
            error("1D LUTs are not supported; expected LUT_3D_SIZE");
        } else if (word == "DOMAIN_MIN" || word == "DOMAIN_MAX") {
            float v[3];
            if (!parseFloats(rest, v, 3)) error(std::string(word) + " expects three finite numbers");
            else (word == "DOMAIN_MIN" ? lut.domain_min : lut.domain_max) = {v[0], v[1], v[2]};
        } else {
            float v[3];
            if (!parseFloats(line, v, 3)) {
                error("'" + std::string(line) + "' is not a keyword (TITLE, LUT_3D_SIZE, DOMAIN_MIN, DOMAIN_MAX) or three numbers");
            } else if (lut.size == 0) {
                error("data before LUT_3D_SIZE");
            } else if (lut.table.size() >= std::size_t(lut.size) * std::size_t(lut.size) * std::size_t(lut.size)) {
                error("more than LUT_3D_SIZE^3 = " + std::to_string(lut.size * lut.size * lut.size) + " entries");
            } else {
                lut.table.push_back({v[0], v[1], v[2]});
            }
        }
        if (end == text.size()) break;
    }
    const std::size_t want = std::size_t(lut.size) * std::size_t(lut.size) * std::size_t(lut.size);
    if (errors.size() == before && lut.size == 0) errors.push_back({file, 0, "no LUT_3D_SIZE line"});
    else if (errors.size() == before && lut.table.size() != want)
        errors.push_back({file, line_no, std::to_string(lut.table.size()) + " entries; LUT_3D_SIZE " +
                                             std::to_string(lut.size) + " needs " + std::to_string(want)});
    if (errors.size() == before && !(lut.domain_min.x < lut.domain_max.x && lut.domain_min.y < lut.domain_max.y &&
                                     lut.domain_min.z < lut.domain_max.z))
        errors.push_back({file, 0, "DOMAIN_MIN must be below DOMAIN_MAX in every channel"});
    if (errors.size() != before) return std::nullopt;
    return lut;
}

std::optional<CubeLut> loadCube(const std::filesystem::path& path, InputErrors& errors) {
    // Regular files under the text limit only: /dev/zero or a FIFO is refused, not read forever.
    std::string text;
    if (std::string why = inputFileProblem(path, kMaxTextInputBytes); !why.empty()) {
        errors.push_back({path.string(), 0, why + " ([postfx.grade] lut)"});
        return std::nullopt;
    }
    if (std::string why = readInputFile(path, kMaxTextInputBytes, text); !why.empty()) {
        errors.push_back({path.string(), 0, "cannot read the LUT file ([postfx.grade] lut)"});
        return std::nullopt;
    }
    return parseCube(text, path.string(), errors);
}

gl::Texture uploadCube(const CubeLut& lut, std::string_view name) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &id);
    glTextureStorage3D(id, 1, GL_RGB32F, lut.size, lut.size, lut.size);
    glTextureSubImage3D(id, 0, 0, 0, 0, lut.size, lut.size, lut.size, GL_RGB, GL_FLOAT, lut.table.data());
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) glTextureParameteri(id, wrap, GL_CLAMP_TO_EDGE);
    glObjectLabel(GL_TEXTURE, id, GLsizei(name.size()), name.data());
    return gl::Texture::adopt(id, lut.size, lut.size, GL_RGB32F);
}

}  // namespace vista
