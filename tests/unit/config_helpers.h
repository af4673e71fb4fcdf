// Helpers shared by the scene-file tests: error messages, and loads expected to fail once.
#pragma once

#include "config/ini.h"

#include <doctest/doctest.h>

#include <string>
#include <string_view>
#include <vector>

namespace vista::test {

inline std::string messages(const InputErrors& errors) {
    std::string out;
    for (const InputError& e : errors) out += e.str() + "\n";
    return out;
}

// The line numbers of errors, in order.
inline std::vector<int> lines(const InputErrors& errors) {
    std::vector<int> out;
    for (const InputError& e : errors) out.push_back(e.line);
    return out;
}

// Loads text into s and expects exactly one error, on line; returns its message.
inline std::string oneError(std::string_view text, Settings& s, int line) {
    const InputErrors errors = loadIniString(text, "scene.ini", s);
    INFO(messages(errors));
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == "scene.ini");
    CHECK(errors[0].line == line);
    return errors[0].message;
}

// Applies one --set assignment and expects exactly one error; returns its message.
inline std::string oneOverrideError(std::string_view assignment, Settings& s) {
    const InputErrors errors = applyOverride(assignment, s);
    INFO(messages(errors));
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].file == "--set");
    CHECK(errors[0].line == 0);
    return errors[0].message;
}

inline bool contains(const std::string& text, std::string_view part) { return text.find(part) != text.npos; }

}  // namespace vista::test
