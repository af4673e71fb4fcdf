// Shader loading: include resolution with line mapping, stage splitting, hot reload.
#include "renderer/shader_library.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace vista {
namespace fs = std::filesystem;

namespace {

bool readFile(const fs::path& path, std::string& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream ss;
    ss << in.rdbuf();
    out = ss.str();
    return true;
}

// Parses `#include "x"` (spaces allowed); returns false for other lines.
bool parseInclude(const std::string& line, std::string& target) {
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line.compare(i, 8, "#include") != 0) return false;
    std::size_t open = line.find('"', i + 8), close = open == std::string::npos ? open : line.find('"', open + 1);
    if (close == std::string::npos) return false;
    target = line.substr(open + 1, close - open - 1);
    return true;
}

struct Preprocessor {
    fs::path root;
    ShaderSource out;
    std::set<fs::path> seen;

    void include(const fs::path& path, const fs::path& from, int from_line) {
        fs::path canonical = fs::weakly_canonical(path);
        if (!seen.insert(canonical).second) return;  // each file once: no include guards needed
        std::string text;
        if (!readFile(path, text)) {
            if (out.error.empty())
                out.error = from.empty() ? path.string() + ": cannot read shader file"
                                         : from.string() + ":" + std::to_string(from_line) +
                                               ": cannot open include \"" + path.string() + "\"";
            return;
        }
        int index = int(out.files.size());
        out.files.push_back(path);
        out.text += "#line 1 " + std::to_string(index) + "\n";
        std::istringstream lines(text);
        std::string line, target;
        int number = 0;
        while (std::getline(lines, line)) {
            ++number;
            if (parseInclude(line, target)) {
                fs::path local = path.parent_path() / target;
                include(fs::exists(local) ? local : root / target, path, number);
                out.text += "#line " + std::to_string(number + 1) + " " + std::to_string(index) + "\n";
            } else {
                out.text += line;
                out.text += '\n';
            }
        }
    }
};

}  // namespace

ShaderSource preprocessShader(const fs::path& root, const fs::path& file) {
    Preprocessor pp{root, {}, {}};
    pp.include(file.is_absolute() ? file : root / file, {}, 0);
    return std::move(pp.out);
}

std::string mapShaderLog(const std::string& log, const std::vector<fs::path>& files) {
    static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\): )");
    static const std::regex nvidia(R"(^(\d+)\((\d+)\) : )");
    std::istringstream in(log);
    std::string line, out;
    while (std::getline(in, line)) {
        std::smatch m;
        bool is_mesa = std::regex_search(line, m, mesa);
        if (is_mesa || std::regex_search(line, m, nvidia)) {
            std::size_t index = std::stoul(m[1].str());
            std::string file = index < files.size() ? files[index].string() : "source " + m[1].str();
            line = file + ":" + m[2].str() + ": " + line.substr(std::size_t(m.length(0)));
        }
        out += line + "\n";
    }
    return out;
}

namespace {

struct Stage {
    const char* define;
    GLenum type;
};
constexpr Stage kStages[] = {{"VERTEX_SHADER", GL_VERTEX_SHADER},
                             {"TESS_CONTROL_SHADER", GL_TESS_CONTROL_SHADER},
                             {"TESS_EVALUATION_SHADER", GL_TESS_EVALUATION_SHADER},
                             {"GEOMETRY_SHADER", GL_GEOMETRY_SHADER},
                             {"FRAGMENT_SHADER", GL_FRAGMENT_SHADER},
                             {"COMPUTE_SHADER", GL_COMPUTE_SHADER}};

std::string infoLog(GLuint object, bool program) {
    GLint length = 0;
    program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    program ? glGetProgramInfoLog(object, length, nullptr, log.data())
            : glGetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

}  // namespace

ShaderLibrary::ShaderLibrary(fs::path root) : root_(std::move(root)) {}

bool ShaderLibrary::build(Program& p) {
    ShaderSource src = preprocessShader(root_, p.file);
    if (!src.error.empty()) {
        p.error = src.error;
        return false;
    }
    std::string header = "#version 450 core\n";
    for (const auto& d : p.defines) {
        std::string def = d;
        std::replace(def.begin(), def.end(), '=', ' ');
        header += "#define " + def + "\n";
    }

    std::vector<gl::Shader> shaders;
    std::string errors;
    for (const Stage& stage : kStages) {
        if (src.text.find(stage.define) == std::string::npos) continue;
        std::string text = header + "#define " + stage.define + " 1\n" + src.text;
        gl::Shader shader(glCreateShader(stage.type));
        const char* ptr = text.c_str();
        glShaderSource(shader.id(), 1, &ptr, nullptr);
        glCompileShader(shader.id());
        GLint ok = 0;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok) errors += mapShaderLog(infoLog(shader.id(), false), src.files);
        shaders.push_back(std::move(shader));
    }
    if (shaders.empty()) errors = p.file.string() + ": no #ifdef VERTEX_SHADER, FRAGMENT_SHADER or COMPUTE_SHADER stage\n";
    if (errors.empty()) {
        gl::Program program(glCreateProgram());
        for (const auto& s : shaders) glAttachShader(program.id(), s.id());
        glLinkProgram(program.id());
        GLint ok = 0;
        glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
        if (ok) {
            program.label(p.name);
            p.gl = std::move(program);
        } else {
            errors = p.name + ": link failed:\n" + mapShaderLog(infoLog(program.id(), true), src.files);
        }
    }
    // Track the files even on failure, so fixing any of them triggers another try.
    p.deps.clear();
    for (const auto& f : src.files) {
        std::error_code ec;
        p.deps.emplace_back(f, fs::last_write_time(f, ec));
    }
    p.error = errors;
    return errors.empty();
}

ShaderLibrary::Program* ShaderLibrary::get(const fs::path& file, const std::vector<std::string>& defines) {
    const std::string key = ProgramKey{file.generic_string(), defines}.text();
    auto it = programs_.find(key);
    if (it != programs_.end()) return it->second->gl ? it->second.get() : nullptr;

    if (restricted_ && !listed_.count(key)) {
        const std::string message = "program variant " + key +
                                    " is not listed: add it to its feature's variant list (the enumeration "
                                    "allPrograms() concatenates), which the shader test compiles";
        if (unlisted == UnlistedProgram::Fail) throw std::logic_error(message);
        if (unlisted_seen_.insert(key).second) std::fprintf(stderr, "vista: %s\n", message.c_str());
    }
    auto program = std::make_unique<Program>();
    program->name = key;
    program->file = file;
    program->defines = defines;
    Program* p = program.get();
    programs_.emplace(key, std::move(program));
    ++compiled_;
    if (!build(*p)) {
        last_error_ = p->error;
        return nullptr;
    }
    return p;
}

GLuint ShaderLibrary::id(const fs::path& file, const std::vector<std::string>& defines) {
    if (Program* p = get(file, defines)) return p->id();
    const std::string key = ProgramKey{file.generic_string(), defines}.text();
    const auto it = programs_.find(key);
    const std::string error = it != programs_.end() ? it->second->error : last_error_;
    if (unlisted == UnlistedProgram::Fail) throw std::runtime_error(key + " failed to compile:\n" + error);
    if (failures_reported_.insert(key).second)
        std::fprintf(stderr, "vista: %s failed to compile; its passes draw nothing:\n%s", key.c_str(), error.c_str());
    return 0;
}

void ShaderLibrary::checkBlock(GLuint program, const char* block, std::size_t bytes) {
    if (program == 0 || !blocks_checked_.emplace(program, block).second) return;
    const GLuint index = glGetUniformBlockIndex(program, block);
    if (index == GL_INVALID_INDEX) return;
    GLint size = 0;
    glGetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    if (std::size_t(size) == bytes) return;
    std::string name = "program " + std::to_string(program);
    for (const auto& [key, p] : programs_)
        if (p->id() == program) name = key;
    const std::string message = name + ": uniform block " + block + " is " + std::to_string(size) +
                                " bytes in GLSL (std140) and " + std::to_string(bytes) +
                                " in C++; keep its members in whole 16-byte rows (renderer/shaders/pass_block.glsl)";
    if (unlisted == UnlistedProgram::Fail) throw std::logic_error(message);
    std::fprintf(stderr, "vista: %s\n", message.c_str());
}

void ShaderLibrary::setListed(const ProgramList& keys) {
    restricted_ = true;
    listed_.clear();
    for (const ProgramKey& k : keys) addListed(k);
}

void ShaderLibrary::addListed(const ProgramKey& key) { listed_.insert(key.text()); }

bool ShaderLibrary::listed(const ProgramKey& key) const { return !restricted_ || listed_.count(key.text()) > 0; }

std::vector<std::string> ShaderLibrary::names() const {
    std::vector<std::string> out;
    for (const auto& [key, p] : programs_) out.push_back(key);
    return out;
}

int ShaderLibrary::poll() {
    auto now = std::chrono::steady_clock::now();
    if (now - last_poll_ < poll_interval) return 0;
    last_poll_ = now;

    std::map<fs::path, fs::file_time_type> stamps;  // each file stat'ed once per poll
    for (auto& [key, p] : programs_) {
        if (pending_.count(p.get())) continue;
        for (const auto& [file, time] : p->deps) {
            auto [it, fresh] = stamps.try_emplace(file);
            if (fresh) {
                std::error_code ec;
                it->second = fs::last_write_time(file, ec);
            }
            if (it->second != time) {
                pending_.emplace(p.get(), now);
                break;
            }
        }
    }
    int rebuilt = 0;
    for (auto it = pending_.begin(); it != pending_.end();) {
        if (now - it->second < settle) {  // an editor may still be writing
            ++it;
            continue;
        }
        Program& p = *it->first;
        if (build(p)) {
            ++rebuilt;
            std::fprintf(stderr, "vista: reloaded %s\n", p.name.c_str());
        } else {
            std::fprintf(stderr, "vista: reload of %s failed, keeping the previous program:\n%s", p.name.c_str(),
                         p.error.c_str());
        }
        it = pending_.erase(it);
    }
    return rebuilt;
}

int ShaderLibrary::reloadAll() {
    int failed = 0;
    pending_.clear();
    for (auto& [key, p] : programs_) {
        if (!build(*p)) {
            ++failed;
            std::fprintf(stderr, "vista: %s failed, keeping the previous program:\n%s", p->name.c_str(), p->error.c_str());
        }
    }
    return failed;
}

std::vector<std::string> ShaderLibrary::errors() const {
    std::vector<std::string> out;
    for (const auto& [key, p] : programs_)
        if (!p->error.empty()) out.push_back(p->error);
    return out;
}

}  // namespace vista
