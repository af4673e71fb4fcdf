// A program variant: one shader file and the #defines pushed before it. Each feature lists
// the variants it can request (a variant struct beside the feature, e.g.
// renderer/lighting/sun_variant.h, whose defines() the pass uses and whose all() enumerates
// them); FrameRenderer's allPrograms() is the concatenation of those lists, and the shader
// library refuses (tests) or reports (production) a request outside it.
#pragma once

#include <string>
#include <vector>

namespace vista {

struct ProgramKey {
    std::string file;                  // relative to the vista root
    std::vector<std::string> defines;  // "NAME" or "NAME=VALUE", in the order the pass pushes them

    // "file -DNAME -DNAME=VALUE": the shader library's key and the name in messages.
    std::string text() const {
        std::string out = file;
        for (const auto& d : defines) out += " -D" + d;
        return out;
    }
    bool operator==(const ProgramKey&) const = default;
};

using ProgramList = std::vector<ProgramKey>;

// Appends `more` to `list` (allPrograms() concatenates the features' lists).
inline void appendPrograms(ProgramList& list, const ProgramList& more) { list.insert(list.end(), more.begin(), more.end()); }

// The keys of a variant struct's enumeration: V::all() with each V::key().
template <class V>
ProgramList variantPrograms() {
    ProgramList out;
    for (const V& v : V::all()) out.push_back(v.key());
    return out;
}

}  // namespace vista
