// Shader programs from one file each: stages are split by #ifdef VERTEX_SHADER /
// FRAGMENT_SHADER / COMPUTE_SHADER, variants are #defines pushed from C++, shared code
// comes in by #include "path" (resolved relative to the including file, then the vista
// root; each file is included once). Compile errors are reported as file:line through
// includes. Hot reload: every file a program used is tracked; poll() checks a few
// timestamps, waits until an editor has finished writing, rebuilds only the affected
// programs and keeps the old program when the new one fails.
// Listed variants: once given the list of every variant the renderer may request
// (FrameRenderer: allPrograms()), a request outside it is reported once (production) or
// throws (the GL tests set UnlistedProgram::Fail: tests/gl/gl_fixture.h), so a reachable variant
// cannot go untested by the shader test, which compiles the whole list.
#pragma once

#include "renderer/gl/objects.h"
#include "renderer/program_key.h"

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace vista {

// GLSL source after #include resolution, with #line directives mapping back to files.
struct ShaderSource {
    std::string text;                           // without #version
    std::vector<std::filesystem::path> files;   // index = GLSL source-string number in #line
    std::string error;                          // non-empty when a file could not be read
};

// Resolves includes of file (a path relative to root, or absolute).
ShaderSource preprocessShader(const std::filesystem::path& root, const std::filesystem::path& file);

// Rewrites "0:12(5): error: ..." (Mesa) and "0(12) : error ..." (NVIDIA) references to
// "file:line: ..." using the source's file table.
std::string mapShaderLog(const std::string& log, const std::vector<std::filesystem::path>& files);

// What a request for a variant outside the library's list does.
enum class UnlistedProgram {
    Log,   // compile it, and say so once on stderr (production)
    Fail,  // throw std::logic_error naming the variant, and id() throws on a failed compile (the tests)
};

class ShaderLibrary {
public:
    struct Program {
        gl::Program gl;         // empty until the first successful compile
        std::string error;      // last compile error, "" when the current program is current
        std::string name;       // file plus defines, for messages
        std::filesystem::path file;
        std::vector<std::string> defines;
        std::vector<std::pair<std::filesystem::path, std::filesystem::file_time_type>> deps;
        GLuint id() const { return gl.id(); }
    };

    explicit ShaderLibrary(std::filesystem::path root);

    // The program for file with the given defines ("NAME" or "NAME VALUE"), compiled on
    // first use. The pointer stays valid for the library's lifetime and follows reloads.
    // Returns nullptr when the first compile fails; the error is in lastError().
    Program* get(const std::filesystem::path& file, const std::vector<std::string>& defines = {});
    Program* get(const ProgramKey& key) { return get(key.file, key.defines); }

    // The GL name of the program a pass draws with: get(), compiled on first use, but never a
    // null dereference: a failed compile gives 0 (nothing drawn) with its error printed once on
    // stderr and kept in errors(); under UnlistedProgram::Fail it throws std::runtime_error.
    GLuint id(const std::filesystem::path& file, const std::vector<std::string>& defines = {});
    GLuint id(const ProgramKey& key) { return id(key.file, key.defines); }

    // Checks, once per linked program, that its uniform block `block` is `bytes` long as GL
    // lays it out: the C++ mirror of a PASS_BLOCK (renderer/shaders/pass_block.glsl) and the
    // GLSL block then agree. A program that does not use the block passes. A mismatch throws
    // std::logic_error under UnlistedProgram::Fail (the tests), else is printed once.
    void checkBlock(GLuint program, const char* block, std::size_t bytes);

    // The variants the renderer may request. Until a list is set, any is allowed.
    void setListed(const ProgramList& keys);
    // One more allowed variant (the GL tests' probe programs, drawn with a renderer's library).
    void addListed(const ProgramKey& key);
    bool listed(const ProgramKey& key) const;
    // Requests outside the list so far, each once ("file -DA -DB").
    const std::set<std::string>& unlistedRequests() const { return unlisted_seen_; }
    // Programs built so far, failed ones too (each variant once; reloads not counted).
    int compiled() const { return compiled_; }
    UnlistedProgram unlisted = unlisted_default;
    // Every new library's `unlisted`: Log, or Fail once the GL tests' context exists (tests/gl/gl_fixture.h).
    static inline UnlistedProgram unlisted_default = UnlistedProgram::Log;

    // Checks tracked files at most every poll_interval; recompiles programs whose files
    // changed and stayed unchanged for settle time. Returns the programs rebuilt.
    int poll();
    // Recompiles every program now (the R key). Returns how many failed.
    int reloadAll();

    // Compile errors of the programs that currently fail, one per program.
    std::vector<std::string> errors() const;
    const std::string& lastError() const { return last_error_; }
    std::size_t size() const { return programs_.size(); }
    // The name (file plus defines) of every program asked for so far: what the frames used.
    std::vector<std::string> names() const;
    const std::filesystem::path& root() const { return root_; }

    std::chrono::milliseconds poll_interval{250};
    std::chrono::milliseconds settle{100};

private:
    bool build(Program& p);  // false keeps the old program and sets p.error

    std::filesystem::path root_;
    std::map<std::string, std::unique_ptr<Program>> programs_;
    std::string last_error_;
    bool restricted_ = false;             // a list was set
    std::set<std::string> listed_;        // ProgramKey::text() of every listed variant
    std::set<std::string> unlisted_seen_;
    std::set<std::string> failures_reported_;  // id() prints each failed program once
    std::set<std::pair<GLuint, std::string>> blocks_checked_;  // (program, block) seen by checkBlock
    int compiled_ = 0;
    std::chrono::steady_clock::time_point last_poll_{};
    // Programs whose files changed, with when the change was first seen.
    std::map<Program*, std::chrono::steady_clock::time_point> pending_;
};

}  // namespace vista
