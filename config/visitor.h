// One description of every setting: a settings struct lists its fields once through a
// SettingsVisitor, and the ini loader, the ini writer, the --set overrides, `vista check`
// and the ImGui panel are all visitors. Adding a field to a describe() function is all it
// takes for it to be loadable, savable, checked and editable.
#pragma once

#include <glm/vec3.hpp>

#include <span>
#include <string>

namespace vista {

// Metadata shown in error messages, saved ini comments and panel tooltips.
struct FieldInfo {
    const char* key;
    const char* unit;  // "m", "deg", "px", "" ...
    const char* help;  // one line
};

class SettingsVisitor {
public:
    virtual ~SettingsVisitor() = default;
    // Called before the fields of each section, e.g. "window" or "postfx.tonemap".
    virtual void section(const char* name, const char* help) = 0;

    virtual void field(const FieldInfo& info, bool& value) = 0;
    virtual void field(const FieldInfo& info, int& value, int min, int max) = 0;
    virtual void field(const FieldInfo& info, float& value, float min, float max) = 0;
    virtual void field(const FieldInfo& info, double& value, double min, double max) = 0;
    // A colour or direction; each component in [min, max].
    virtual void field(const FieldInfo& info, glm::vec3& value, float min, float max) = 0;
    // A position that may be far from the origin; each component in [min, max].
    virtual void field(const FieldInfo& info, glm::dvec3& value, double min, double max) = 0;
    // Free text (file paths). Empty is allowed.
    virtual void field(const FieldInfo& info, std::string& value) = 0;
    // One of a fixed list of names; value is the index into names.
    virtual void choice(const FieldInfo& info, int& value, std::span<const char* const> names) = 0;

    // Enum-typed convenience over choice(): the enum's values must be 0..names.size()-1.
    template <class Enum>
    void choice(const FieldInfo& info, Enum& value, std::span<const char* const> names) {
        static_assert(sizeof(Enum) == sizeof(int));
        int index = static_cast<int>(value);
        choice(info, index, names);
        value = static_cast<Enum>(index);
    }
};

}  // namespace vista
