// Shader library under OSMesa: every program compiles, errors map through includes to
// file:line, hot reload keeps the old program after a broken edit.
#include "app/frame.h"
#include "app/scene.h"
#include "gl_fixture.h"
#include "renderer/lighting/light_variants.h"
#include "renderer/lighting/sun_variant.h"
#include "renderer/shader_library.h"
#include "terrain/water/water.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>
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
    const ProgramList programs = allPrograms();
    std::set<std::string> keys;
    for (const ProgramKey& p : programs) {
        CAPTURE(p.text());
        CHECK_MESSAGE(keys.insert(p.text()).second, "listed twice");
        CHECK_MESSAGE(shaders.get(p) != nullptr, shaders.lastError());
    }
    MESSAGE(programs.size() << " program variants");
    // Every shader file with a stage is used by some program (none is left to rot).
    std::set<std::string> used;
    for (const ProgramKey& p : programs) used.insert(p.file);
    // Every folder named shaders anywhere in the sources (tests/ has its own probes, build
    // folders hold copies).
    int folders = 0;
    std::set<std::string> tops;
    for (const auto& top : std::filesystem::directory_iterator(vistaRoot())) {
        const std::string name = top.path().filename().string();
        if (!top.is_directory() || name == "tests" || name.starts_with(".") || name.starts_with("build")) continue;
        for (const auto& d : std::filesystem::recursive_directory_iterator(top.path())) {
            if (!d.is_directory() || d.path().filename() != "shaders") continue;
            ++folders;
            tops.insert(name);
            for (const auto& e : std::filesystem::directory_iterator(d.path())) {
                ShaderSource src = preprocessShader(vistaRoot(), e.path());
                bool has_main = src.text.find("void main") != std::string::npos;
                std::string rel = std::filesystem::relative(e.path(), vistaRoot()).generic_string();
                if (has_main && rel != "renderer/shaders/fullscreen.glsl") CHECK_MESSAGE(used.count(rel) == 1, rel << " is not in allPrograms()");
            }
        }
    }
    CHECK(folders >= 11);  // nested ones too: renderer/lighting/shaders, sky/clouds/shaders, ...
    CHECK(tops.size() >= 4);
}

TEST_CASE("gl: a variant outside allPrograms() fails the test, and a failed compile gives no null program") {
    test::glContext();  // strict mode from here on (gl_fixture.h)
    FrameRenderer renderer(vistaRoot());
    ShaderLibrary& shaders = renderer.shaders();
    CHECK(shaders.listed({"renderer/shaders/copy.glsl", {}}));
    CHECK(shaders.id("renderer/shaders/copy.glsl") != 0);
    CHECK_FALSE(shaders.listed({"renderer/shaders/copy.glsl", {"NOT_A_VARIANT"}}));
    CHECK_THROWS_AS(shaders.id("renderer/shaders/copy.glsl", {"NOT_A_VARIANT"}), std::logic_error);
    // The same defines in another order is another program: also refused.
    CHECK(shaders.listed(SunVariant{true, true, true, SunVariant::Debug::None}.key()));
    CHECK_THROWS_AS(shaders.id(SunVariant::kFile, {"HAS_SUN_SHADOW", "HAS_AO"}), std::logic_error);
    CHECK(shaders.unlistedRequests().empty());

    // Production: the unlisted variant compiles, reported once; a failed compile is id 0 (its
    // pass draws nothing) instead of a null dereference, and its error is kept.
    test::TempDir dir("shader-strict");
    writeText(dir.path / "lib.glsl", "vec4 libColor() { return vec4(1.0) }\n");  // missing ';'
    writeText(dir.path / "main.glsl", kGood);
    ShaderLibrary lenient(dir.path);
    lenient.unlisted = UnlistedProgram::Log;
    lenient.setListed({{"main.glsl", {}}});
    CHECK(lenient.id("main.glsl") == 0);
    REQUIRE(lenient.errors().size() == 1);
    CHECK(lenient.errors()[0].find("lib.glsl:1:") != std::string::npos);
    writeText(dir.path / "lib.glsl", "vec4 libColor() { return vec4(1.0); }\n");
    CHECK(lenient.id("main.glsl", {"EXTRA"}) != 0);
    CHECK(lenient.unlistedRequests() == std::set<std::string>{"main.glsl -DEXTRA"});
    CHECK(lenient.compiled() == 2);
    // Under the tests' strict mode the failed compile throws with its error.
    ShaderLibrary strict(dir.path);
    writeText(dir.path / "lib.glsl", "vec4 libColor() { return vec4(1.0) }\n");
    CHECK_THROWS_AS(strict.id("main.glsl"), std::runtime_error);
}

TEST_CASE("gl: the variant structs enumerate exactly the valid combinations of their fields") {
    // lighting.sun: 2 x 2 x 2 fields x 3 debug outputs, less the cascade view without cascades;
    // with cascades also without the PCSS search (SHADOW_NO_PCSS).
    const std::vector<SunVariant> sun = SunVariant::all();
    CHECK(sun.size() == 2 * 2 * (2 + 3 * 2));
    std::set<std::vector<std::string>> distinct;
    for (const SunVariant& v : sun) {
        CHECK(v.valid());
        distinct.insert(v.defines());
    }
    CHECK(distinct.size() == sun.size());
    CHECK_FALSE((SunVariant{false, false, false, SunVariant::Debug::Cascades}.valid()));
    CHECK_FALSE((SunVariant{false, false, false, SunVariant::Debug::None, false}.valid()));  // a filter needs cascades
    // The combinations that used to compile lazily, untested, are listed now.
    const ProgramList listed = allPrograms();
    auto isListed = [&](const ProgramKey& k) { return std::find(listed.begin(), listed.end(), k) != listed.end(); };
    CHECK(isListed(SunVariant{false, true, true, SunVariant::Debug::None}.key()));  // SSAO off, cloud and sun shadows
    CHECK(isListed(LightShadeVariant{LightCulling::Tiled, true, false, false, false}.key()));  // counters without heat
    // lights.shade: every method with 2^4 switches; lights.cull: tiled and clustered, forward or not.
    CHECK(LightShadeVariant::all().size() == 4 * 16);
    CHECK(LightCullVariant::all().size() == 2 * 2);
    for (const LightCullVariant& v : LightCullVariant::all()) CHECK(screenCulled(v.method));
    // water.surface: unlit or each method, with or without the sun's shadows, each method's further
    // chunks (no sun), the three debug views alone, and the surface's motion (water.velocity); the
    // five with the sun's shadows also without the PCSS search.
    CHECK(WaterSurfaceVariant::all().size() == 2 + 4 * 3 + 3 + 1 + 5);
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
