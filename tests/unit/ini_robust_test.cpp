// Scene files against hostile contents (issue 19): NUL bytes, floods of problems, huge
// values, many list entries.
#include "config/ini.h"
#include "config/settings.h"

#include <doctest/doctest.h>

#include <string>

using namespace vista;

TEST_CASE("ini: a NUL byte inside a value is an error, not a silently shorter value") {
    Settings s;
    const std::string text = std::string("[terrain]\nheightmap = data/a") + '\0' + "b.png\n";
    InputErrors errors = loadIniString(text, "nul.ini", s);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].line == 2);
    CHECK(errors[0].message.find("NUL") != std::string::npos);
    CHECK(s.terrain.heightmap == Settings{}.terrain.heightmap);
}

TEST_CASE("ini: problems are capped with a count of the rest, and long values are cut in messages") {
    std::string text = "[window]\n";
    for (int i = 0; i < 5000; ++i) text += "unknown_" + std::to_string(i) + " = 1\n";
    Settings s;
    InputErrors errors = loadIniString(text, "flood.ini", s);
    REQUIRE(errors.size() == 101);
    CHECK(errors[0].line == 2);
    CHECK(errors.back().message.find("and 4900 more problem(s) not listed") != std::string::npos);

    const std::string huge(1 << 20, '7');
    errors = loadIniString("[window]\nwidth = " + huge + "\n", "huge.ini", s);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].message.size() < 400);
    CHECK(errors[0].message.find("1048576 characters") != std::string::npos);
}

TEST_CASE("ini: many list entries load in order, a later file replacing an entry of an earlier one") {
    std::string text = "[lights]\n";
    for (int i = 0; i < 20000; ++i) text += "light.l" + std::to_string(i) + " = point " + std::to_string(i % 100) + " 1 0\n";
    Settings s;
    CHECK(loadIniString(text, "many.ini", s).empty());
    REQUIRE(s.lights.lights.size() == 20000);
    CHECK(s.lights.lights[19999].name == "l19999");
    // A second file layered over the first replaces l5 rather than appending a second l5.
    CHECK(loadIniString("[lights]\nlight.l5 = point 9 9 9\n", "over.ini", s).empty());
    CHECK(s.lights.lights.size() == 20000);
    CHECK(s.lights.lights[5].light.position.x == doctest::Approx(9.0));
}

TEST_CASE("ini: --set suggests a key of the section it names, never one of another section") {
    // Every key of every section, misspelt by dropping one letter: a suggestion, when one comes,
    // names the same section (it suggested e.g. another section's key with a similar full name).
    Settings defaults;
    const std::string text = saveIniString(defaults);
    std::string section;
    int checked = 0;
    for (std::size_t at = 0; at < text.size();) {
        std::size_t end = text.find('\n', at);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(at, end - at);
        at = end + 1;
        if (line.size() > 2 && line.front() == '[') section = line.substr(1, line.find(']') - 1);
        const std::size_t eq = line.find(" = ");
        if (line.empty() || line.front() == '[' || line.front() == ';' || line.front() == '#' || eq == std::string::npos)
            continue;
        const std::string key = line.substr(0, eq);
        if (key.find('.') != std::string::npos || key.size() < 4) continue;  // list entries, tiny keys
        for (std::size_t drop = 1; drop < key.size(); drop += 2) {
            const std::string misspelt = key.substr(0, drop) + key.substr(drop + 1);
            Settings s;
            const InputErrors errors = applyOverride(section + "." + misspelt + "=1", s);
            if (errors.empty()) continue;  // another key of the section
            const std::string& m = errors[0].message;
            const std::size_t guess = m.find("did you mean '");
            CAPTURE(m);
            if (guess != std::string::npos) CHECK(m.compare(guess + 14, section.size() + 1, section + ".") == 0);
            ++checked;
        }
    }
    CHECK(checked > 50);
}

TEST_CASE("ini: --set postfx.bloom_intensity does not suggest [postfx.bloom] intensity") {
    Settings s;
    const InputErrors errors = applyOverride("postfx.bloom_intensity=1", s);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].message.find("unknown key [postfx] bloom_intensity") == 0);
    CHECK(errors[0].message.find("postfx.bloom.intensity") == std::string::npos);  // was its did-you-mean
}
