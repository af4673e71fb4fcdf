// A pass's own uniform block, declared once in a file that both C++ and GLSL include
// (e.g. postfx/shaders/grade_block.glsl):
//     PASS_BLOCK(GradeBlock)
//         vec3 lift; float saturation;
//     PASS_BLOCK_END
// GLSL sees a std140 uniform block at BINDING_PASS_BLOCK; C++ sees a struct of the same
// members (glm types) that renderer/pass_kit.h uploads there before the pass draws.
// Keep members in whole 16-byte rows (a vec4; a vec3 and a float; two vec2; four floats or
// ints; a mat4): then std140 and C++ place every member at the same offset. A row broken
// anyway makes the GLSL block longer than the struct, and ShaderLibrary::checkBlock (run the
// first time a program gets its block; a throw in the GL tests) names it.
// Only #defines and // comments, so C++ can include it (after renderer/pass_kit.h, for glm).
#define BINDING_PASS_BLOCK 8
#ifdef __cplusplus
#define PASS_BLOCK(NAME)                                 \
    struct NAME {                                        \
        using vec2 = glm::vec2;                          \
        using vec3 = glm::vec3;                          \
        using vec4 = glm::vec4;                          \
        using ivec2 = glm::ivec2;                        \
        using ivec4 = glm::ivec4;                        \
        using uvec2 = glm::uvec2;                        \
        using uvec4 = glm::uvec4;                        \
        using mat4 = glm::mat4;                          \
        using uint = std::uint32_t;                      \
        static constexpr const char* kBlockName = #NAME;
#define PASS_BLOCK_END };
#else
#define PASS_BLOCK(NAME) layout(std140, binding = BINDING_PASS_BLOCK) uniform NAME {
#define PASS_BLOCK_END };
#endif
