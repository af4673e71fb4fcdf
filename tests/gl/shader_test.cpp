// Shader library under OSMesa: every program compiles, errors map through includes to
// file:line, hot reload keeps the old program after a broken edit.
#include "app/frame.h"
#include "app/scene.h"
#include "gl_fixture.h"
#include "renderer/shader_library.h"

#include <fstream>
#include <set>
#include <thread>

using namespace vista;

namespace {

void writeText(const std::filesystem::path& file, const std::string& text) {
    std::ofstream(file, std::ios::trunc) << text;
}

// Moves a file's timestamp forward so a reload sees a change even within one clock tick.
void touchLater(const std::filesystem::path& file) {
    std::filesystem::last_write_time(file, std::filesystem::last_write_time(file) + std::chrono::seconds(2));
}

const char* kGood = R"(#include "lib.glsl"
#ifdef FRAGMENT_SHADER
out vec4 o_color;
void main() { o_color = libColor(); }
#endif
#ifdef VERTEX_SHADER
void main() { gl_Position = vec4(0.0); }
#endif
)";

}  // namespace

TEST_CASE("gl: OSMesa gives a 4.5 core context with reversed-Z clip control") {
    test::glContext();
    GLint major = 0, minor = 0, clip = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CLIP_DEPTH_MODE, &clip);
    CHECK(major * 10 + minor >= 45);
    CHECK(clip == GL_ZERO_TO_ONE);
}

TEST_CASE("gl: every program and variant compiles") {
    test::glContext();
    ShaderLibrary shaders(vistaRoot());
    for (const auto& p : allPrograms()) {
        CAPTURE(p.file);
        CHECK_MESSAGE(shaders.get(p.file, p.defines) != nullptr, shaders.lastError());
    }
    // Every shader file with a stage is used by some program (none is left to rot).
    std::set<std::string> used;
    for (const auto& p : allPrograms()) used.insert(p.file);
    // Every folder named shaders under the source folders (tests/ has its own probes).
    int folders = 0;
    for (const char* top : {"renderer", "terrain", "sky", "postfx"}) {
        for (const auto& d : std::filesystem::recursive_directory_iterator(vistaRoot() / top)) {
            if (!d.is_directory() || d.path().filename() != "shaders") continue;
            ++folders;
            for (const auto& e : std::filesystem::directory_iterator(d.path())) {
                ShaderSource src = preprocessShader(vistaRoot(), e.path());
                bool has_main = src.text.find("void main") != std::string::npos;
                std::string rel = std::filesystem::relative(e.path(), vistaRoot()).generic_string();
                if (has_main && rel != "renderer/shaders/fullscreen.glsl") CHECK_MESSAGE(used.count(rel) == 1, rel << " is not in allPrograms()");
            }
        }
    }
    CHECK(folders >= 10);
}

TEST_CASE("gl: a shader error is reported at its file:line through an include") {
    test::glContext();
    test::TempDir dir("shader-error");
    writeText(dir.path / "lib.glsl", "// library\nvec4 libColor() {\n    return vec4(undefined_name);\n}\n");
    writeText(dir.path / "main.glsl", kGood);
    ShaderLibrary shaders(dir.path);
    CHECK(shaders.get("main.glsl") == nullptr);
    std::string error = shaders.lastError();
    CAPTURE(error);
    CHECK(error.find((dir.path / "lib.glsl").string() + ":3:") != std::string::npos);
    CHECK(error.find("undefined_name") != std::string::npos);
}

TEST_CASE("gl: a missing include names the including file and line") {
    test::glContext();
    test::TempDir dir("shader-include");
    writeText(dir.path / "main.glsl", "// a\n#include \"nope.glsl\"\n");
    ShaderLibrary shaders(dir.path);
    CHECK(shaders.get("main.glsl") == nullptr);
    CHECK(shaders.lastError().find("main.glsl:2: cannot open include \"") != std::string::npos);
}

TEST_CASE("gl: hot reload keeps the old program after a broken edit and takes the fix") {
    test::glContext();
    test::TempDir dir("hot-reload");
    writeText(dir.path / "lib.glsl", "vec4 libColor() { return vec4(1.0); }\n");
    writeText(dir.path / "main.glsl", kGood);
    ShaderLibrary shaders(dir.path);
    shaders.poll_interval = std::chrono::milliseconds(0);
    shaders.settle = std::chrono::milliseconds(0);
    ShaderLibrary::Program* program = shaders.get("main.glsl");
    REQUIRE(program != nullptr);
    GLuint first = program->id();

    // Break the included file: the program keeps working, the error is reported.
    writeText(dir.path / "lib.glsl", "vec4 libColor() { return vec4(1.0) }\n");
    touchLater(dir.path / "lib.glsl");
    shaders.poll();  // sees the change
    shaders.poll();  // settled: rebuilds
    CHECK(program->id() == first);
    CHECK(glIsProgram(first));
    REQUIRE(shaders.errors().size() == 1);
    CHECK(shaders.errors()[0].find("lib.glsl:1:") != std::string::npos);

    // Fix it: nothing happens until the file has been quiet for the settle time (an editor
    // may still be writing), then a new program replaces the old one and errors clear.
    shaders.settle = std::chrono::milliseconds(200);
    writeText(dir.path / "lib.glsl", "vec4 libColor() { return vec4(0.5); }\n");
    touchLater(dir.path / "lib.glsl");
    CHECK(shaders.poll() == 0);
    CHECK(program->id() == first);
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    CHECK(shaders.poll() == 1);
    CHECK(program->id() != 0);
    CHECK(program->id() != first);
    CHECK(shaders.errors().empty());
    CHECK(shaders.get("main.glsl") == program);
}
