// Scene files: loading, validation messages, --set overrides, saving and round trips.
#include "config/ini.h"
#include "config_helpers.h"

#include <doctest/doctest.h>

#include <glm/vec3.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <variant>
#include <vector>

using namespace vista;

namespace {

using Value = std::variant<bool, int, float, double, glm::vec3, glm::dvec3, std::string>;

// Every field as "section.key" -> value, and every list as "section.prefix" -> its entries as
// "NAME = TEXT" lines, so whole Settings can be compared exactly.
class Flatten final : public SettingsVisitor {
public:
    std::map<std::string, Value> values;
    std::map<std::string, std::string> lists;
    void section(const char* name, const char*) override { section_ = name; }
    void field(const FieldInfo& i, bool& v) override { add(i, v); }
    void field(const FieldInfo& i, int& v, int, int) override { add(i, v); }
    void field(const FieldInfo& i, float& v, float, float) override { add(i, v); }
    void field(const FieldInfo& i, double& v, double, double) override { add(i, v); }
    void field(const FieldInfo& i, glm::vec3& v, float, float) override { add(i, v); }
    void field(const FieldInfo& i, glm::dvec3& v, double, double) override { add(i, v); }
    void field(const FieldInfo& i, std::string& v) override { add(i, v); }
    void choice(const FieldInfo& i, int& v, std::span<const char* const>) override { add(i, v); }
    void sequence(const FieldInfo& i, std::vector<int>& v, std::span<const char* const>) override {
        std::string text;
        for (int n : v) text += std::to_string(n) + " ";
        add(i, text);
    }
    void list(const FieldInfo& i, ListField& l) override {
        std::string& text = lists[section_ + "." + i.key];
        for (std::size_t e = 0; e < l.size(); ++e) text += l.name(e) + " = " + l.text(e) + "\n";
    }

private:
    void add(const FieldInfo& i, Value v) { values[section_ + "." + i.key] = std::move(v); }
    std::string section_;
};

Flatten flattenAll(Settings s) {
    Flatten f;
    describe(f, s);
    return f;
}

std::map<std::string, Value> flatten(Settings s) { return flattenAll(std::move(s)).values; }

// The keys and lists whose values differ (bit for bit), space-separated; "" when a and b are equal.
std::string differences(const Settings& a, const Settings& b) {
    const Flatten fa = flattenAll(a), fb = flattenAll(b);
    std::string out;
    for (const auto& [key, value] : fa.values)
        if (!(value == fb.values.at(key))) out += key + " ";
    for (const auto& [key, text] : fa.lists)
        if (text != fb.lists.at(key)) out += key + " ";
    return out;
}

// Sets every field to a value that differs from the current one, inside its range.
class Perturb final : public SettingsVisitor {
public:
    void section(const char*, const char*) override {}
    void field(const FieldInfo&, bool& v) override { v = !v; }
    void field(const FieldInfo&, int& v, int lo, int hi) override { v = v == hi ? lo : v + 1; }
    void field(const FieldInfo&, float& v, float lo, float hi) override { v = pick(v, lo, hi, 0.318309886f); }
    void field(const FieldInfo&, double& v, double lo, double hi) override { v = pick(v, lo, hi, 0.318309886); }
    void field(const FieldInfo&, glm::vec3& v, float lo, float hi) override {
        v = {pick(v.x, lo, hi, 0.1234567f), pick(v.y, lo, hi, 0.7654321f), pick(v.z, lo, hi, 0.0271828f)};
    }
    void field(const FieldInfo&, glm::dvec3& v, double lo, double hi) override {
        v = {pick(v.x, lo, hi, 0.1234567), pick(v.y, lo, hi, 0.7654321), pick(v.z, lo, hi, 0.0271828)};
    }
    void field(const FieldInfo& i, std::string& v) override { v = "a dir/\"quoted\" name=" + std::string(i.key); }
    void choice(const FieldInfo&, int& v, std::span<const char* const> names) override {
        v = (v + 1) % int(names.size());
    }
    void sequence(const FieldInfo&, std::vector<int>& v, std::span<const char* const> names) override {
        v.clear();  // every name, in reverse
        for (int n = int(names.size()) - 1; n >= 0; --n) v.push_back(n);
    }
    // Adds an entry and perturbs its values through the panel's view of it.
    void list(const FieldInfo&, ListField& l) override {
        REQUIRE(l.set("perturbed", l.defaultText()) == "");
        l.describeEntry(l.size() - 1, *this);
    }

private:
    template <class T>
    static T pick(T old, T lo, T hi, T fraction) {
        const T v = lo + (hi - lo) * fraction;
        return v == old ? lo : v;
    }
};

using test::contains;
using test::lines;
using test::messages;
using test::oneError;
using test::oneOverrideError;

// A fresh directory under the system temp dir, removed with everything in it.
struct TempDir {
    std::filesystem::path path;
    TempDir() {
        std::string name = (std::filesystem::temp_directory_path() / "vista_config_test_XXXXXX").string();
        REQUIRE(mkdtemp(name.data()) != nullptr);
        path = name;
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

}  // namespace

TEST_CASE("config: a good file changes exactly the fields it sets") {
    Settings s;
    const InputErrors errors = loadIniString(
        "[window]\n"
        "width = 1920\n"
        "fullscreen = yes\n"
        "\n"
        "[camera]\n"
        "position = 1.5, -2 3e3\n"
        "fov_deg = 75.5\n"
        "\n"
        "[capture]\n"
        "path = \"paths/my flight.path\"\n"
        "format = EXR\n"
        "out = renders\n"
        "\n"
        "[sky]\n"
        "zenith_color = 0.1 0.2 0.3\n"
        "\n"
        "[postfx.tonemap]\n"
        "op = reinhard\n"
        "white = +2.5\n",
        "scene.ini", s);
    CHECK(messages(errors) == "");

    Settings expected;
    expected.window.width = 1920;
    expected.window.fullscreen = true;
    expected.camera.position = {1.5, -2.0, 3000.0};
    expected.camera.fov_deg = 75.5f;
    expected.capture.path = "paths/my flight.path";
    expected.capture.format = ImageFormat::Exr;
    expected.capture.out = "renders";
    expected.sky.zenith_color = {0.1f, 0.2f, 0.3f};
    expected.tonemap.op = Tonemapper::Reinhard;
    expected.tonemap.white = 2.5f;
    CHECK(differences(s, expected) == "");
}

TEST_CASE("config: a file that omits sections and keys keeps the current values") {
    Settings s;
    s.camera.fov_deg = 33.0f;  // not a default: loading goes over what is there
    CHECK(messages(loadIniString("[window]\nheight = 600\n", "scene.ini", s)) == "");
    Settings expected;
    expected.camera.fov_deg = 33.0f;
    expected.window.height = 600;
    CHECK(differences(s, expected) == "");

    Settings empty;
    CHECK(loadIniString("", "empty.ini", empty).empty());
    CHECK(loadIniString("; only a comment\n\n# and another\n", "comments.ini", empty).empty());
    CHECK(differences(empty, Settings{}) == "");
}

TEST_CASE("config: comments, blank lines, indentation, CRLF and a BOM are accepted") {
    Settings s;
    const InputErrors errors = loadIniString(
        "\xEF\xBB\xBF; scene\r\n"
        "[window] ; the window\r\n"
        "width = 10 ; px\r\n"
        "  height = 20 # px\r\n"
        "\tvsync = OFF\r\n"
        "[ camera ]\r\n"
        "fov_deg: 90\r\n"
        "[capture]\r\n"
        "out = a;b#c\r\n",
        "scene.ini", s);
    CHECK(messages(errors) == "");
    CHECK(s.window.width == 10);
    CHECK(s.window.height == 20);
    CHECK(s.window.vsync == false);
    CHECK(s.camera.fov_deg == 90.0f);
    CHECK(s.capture.out == "a;b#c");  // ';' and '#' start a comment only after a blank
}

TEST_CASE("config: an unknown key is reported with a suggestion") {
    Settings s;
    CHECK(oneError("[window]\nwidth = 800\nwidht = 900\n", s, 3) ==
          "unknown key [window] widht; did you mean 'width'?");
    CHECK(s.window.width == 800);
    CHECK(oneError("[window]\nWidth = 900\n", s, 2) == "unknown key [window] Width; did you mean 'width'?");
    CHECK(s.window.width == 800);

    // Nothing close: the message lists the section's keys instead.
    CHECK(oneError("[postfx.exposure]\nbrightness = 2\n", s, 2) ==
          "unknown key [postfx.exposure] brightness; accepted: enabled, mode, ev, min_ev, max_ev, night_ev, low_percent, high_percent, "
          "speed_up, speed_down, iso");
}

TEST_CASE("config: an unknown section is reported once with a suggestion and its keys are skipped") {
    Settings s;
    const std::string message = oneError("[window]\nwidth = 800\n\n[postfx.tonemapp]\nop = reinhard\nwhite = 2\n", s, 4);
    CHECK(message == "unknown section [postfx.tonemapp]; did you mean 'postfx.tonemap'?");
    CHECK(s.tonemap.op == Tonemapper::Aces);
    CHECK(s.window.width == 800);

    CHECK(contains(oneError("[render]\n", s, 1), "unknown section [render]; accepted: window, camera,"));
}

TEST_CASE("config: malformed numbers are reported and leave the field unchanged") {
    Settings s;
    CHECK(oneError("[camera]\n\n\n\nfov_deg = abc\n", s, 5) == "[camera] fov_deg = abc is not a number; accepted: 5..120 (deg)");
    CHECK(s.camera.fov_deg == 60.0f);
    for (const char* bad : {"60deg", "nan", "inf", "-inf", "1,5", "0x10", "", "+-60"}) {
        INFO(bad);
        CHECK(contains(oneError("[camera]\nfov_deg = " + std::string(bad) + "\n", s, 2), "is not a number"));
        CHECK(s.camera.fov_deg == 60.0f);
    }
    for (const char* bad : {"2.5", "1e3", "12px", "abc", "99999999999999999999"}) {
        INFO(bad);
        const std::string message = oneError("[window]\nwidth = " + std::string(bad) + "\n", s, 2);
        CHECK((contains(message, "is not a whole number") || contains(message, "is out of range")));
        CHECK(contains(message, "accepted: 1..16384 (px)"));
        CHECK(s.window.width == 1280);
    }
}

TEST_CASE("config: out-of-range values are reported with the accepted range") {
    Settings s;
    CHECK(oneError("[window]\nwidth = 99999\n", s, 2) == "[window] width = 99999 is out of range; accepted: 1..16384 (px)");
    CHECK(oneError("[window]\nheight = 0\n", s, 2) == "[window] height = 0 is out of range; accepted: 1..16384 (px)");
    CHECK(oneError("[camera]\nnear_m = 0.0001\n", s, 2) ==
          "[camera] near_m = 0.0001 is out of range; accepted: 0.001..100 (m)");
    CHECK(oneError("[postfx.tonemap]\nwhite = 1e50\n", s, 2) ==
          "[postfx.tonemap] white = 1e50 is out of range; accepted: 0.01..1000");
    CHECK(s.window.width == 1280);
    CHECK(s.window.height == 720);
    CHECK(s.camera.near_m == 0.1f);
    CHECK(s.tonemap.white == 4.0f);

    // The bounds themselves are accepted.
    CHECK(loadIniString("[window]\nwidth = 16384\nheight = 1\n", "scene.ini", s).empty());
    CHECK(s.window.width == 16384);
    CHECK(s.window.height == 1);
}

TEST_CASE("config: a bad bool lists the accepted spellings") {
    Settings s;
    CHECK(oneError("[window]\nvsync = maybe\n", s, 2) ==
          "[window] vsync = maybe is not accepted; accepted: true/false, yes/no, on/off, 1/0");
    CHECK(s.window.vsync == true);
    CHECK(contains(oneError("[window]\nvsync = 2\n", s, 2), "is not accepted"));
    CHECK(s.window.vsync == true);

    const char* spellings[][2] = {{"true", "1"}, {"FALSE", "0"}, {"Yes", "1"}, {"no", "0"},
                                  {"on", "1"},   {"Off", "0"},   {"1", "1"},   {"0", "0"}};
    for (const auto& [text, value] : spellings) {
        INFO(text);
        CHECK(loadIniString("[window]\nfullscreen = " + std::string(text) + "\n", "scene.ini", s).empty());
        CHECK(s.window.fullscreen == (value[0] == '1'));
    }
}

TEST_CASE("config: a bad choice lists the accepted names") {
    Settings s;
    CHECK(oneError("[postfx.tonemap]\nop = filmic\n", s, 2) ==
          "[postfx.tonemap] op = filmic is not accepted; accepted: reinhard, aces, clamp, agx");
    CHECK(s.tonemap.op == Tonemapper::Aces);
    CHECK(contains(oneError("[capture]\nformat = jpg\n", s, 2), "accepted: png, exr"));
    CHECK(s.capture.format == ImageFormat::Png);
    CHECK(contains(oneError("[debug]\nview = foo\n", s, 2), "[debug] view = foo is not accepted; accepted: final, depth"));
    CHECK(s.debug.view == DebugView::Final);
}

TEST_CASE("config: a bad vec3 is reported and leaves the vector unchanged") {
    Settings s;
    const glm::dvec3 position = s.camera.position;
    const glm::vec3 zenith = s.sky.zenith_color;
    for (const char* bad : {"1 2", "1 2 3 4", "1 two 3", "", "1 2 nan", "(1, 2, 3)"}) {
        INFO(bad);
        CHECK(contains(oneError("[camera]\nposition = " + std::string(bad) + "\n", s, 2), "is not three numbers"));
        CHECK(s.camera.position == position);
    }
    CHECK(oneError("[sky]\nzenith_color = 0.5 0.5 101\n", s, 2) ==
          "[sky] zenith_color = 0.5 0.5 101 is out of range; accepted: three numbers, each 0..100");
    CHECK(s.sky.zenith_color == zenith);

    CHECK(loadIniString("[sky]\nzenith_color = 1,2,3\nhorizon_color = 4 ,5,  6\n", "scene.ini", s).empty());
    CHECK(s.sky.zenith_color == glm::vec3(1, 2, 3));
    CHECK(s.sky.horizon_color == glm::vec3(4, 5, 6));
}

TEST_CASE("config: a key repeated in a section names both lines and keeps the first value") {
    Settings s;
    CHECK(oneError("[window]\nwidth = 800\nheight = 600\nwidth = 1024\n", s, 4) ==
          "[window] width is set twice, on lines 2 and 4; the second is ignored");
    CHECK(s.window.width == 800);

    // The same key in different sections, or the same section twice with different keys, is fine.
    CHECK(loadIniString("[window]\nwidth = 2\n[capture]\nwidth = 3\n[window]\nheight = 4\n", "scene.ini", s).empty());
    CHECK(s.window.width == 2);
    CHECK(s.capture.width == 3);
    CHECK(s.window.height == 4);
}

TEST_CASE("config: lines that are neither key = value nor a section header are reported and parsing goes on") {
    Settings s;
    const InputErrors errors = loadIniString(
        "[window]\n"
        "width 800\n"
        "height = 600\n"
        "[camera\n"
        "fov_deg = 70\n"
        "[camera]\n"
        "fov_deg = 80\n"
        + std::string(300, 'k') + " = 9\n"
        "pitch_deg = 5\n",
        "scene.ini", s);
    INFO(messages(errors));
    CHECK(lines(errors) == std::vector{2, 4, 8});
    REQUIRE(errors.size() == 3);
    CHECK(errors[0].message == "cannot parse \"width 800\"; accepted: key = value, [section] or a ; comment");
    CHECK(contains(errors[1].message, "cannot parse \"[camera\""));
    CHECK(contains(errors[2].message, "line is too long"));
    CHECK(s.window.width == 1280);
    CHECK(s.window.height == 600);
    CHECK(s.camera.fov_deg == 80.0f);  // keys under a broken header are skipped
    CHECK(s.camera.pitch_deg == 5.0f);

    CHECK(oneError("width = 800\n[window]\n", s, 1) == "width = 800 comes before any [section]");
}

TEST_CASE("config: a value longer than inih's line limit is read whole") {
    Settings s;
    const std::string path = "dir/" + std::string(400, 'p') + ".path";
    CHECK(messages(loadIniString("[capture]\npath = " + path + "  ; a comment\nframes = 3\n", "scene.ini", s)) == "");
    CHECK(s.capture.path == path);
    CHECK(s.capture.frames == 3);
    CHECK(oneError("[camera]\nfov_deg = " + std::string(300, '9') + "\n", s, 2) ==
          "[camera] fov_deg = " + std::string(300, '9') + " is out of range; accepted: 5..120 (deg)");
}

TEST_CASE("config: several errors in one file are all reported in line order") {
    Settings s;
    const InputErrors errors = loadIniString(
        "[window]\n"
        "widht = 800\n"           // 2 unknown key
        "height = 99999\n"        // 3 out of range
        "vsync = sure\n"          // 4 bad bool
        "[camera]\n"
        "fov_deg = wide\n"        // 6 malformed
        "position = 1 2\n"        // 7 bad vec3
        "yaw_deg = 10\n"
        "[postfx.tonemapp]\n"     // 9 unknown section
        "op = aces\n"
        "[debug]\n"
        "view = everything\n"     // 12 bad choice
        "grid = off\n"
        "grid = on\n",            // 14 duplicate
        "scene.ini", s);
    INFO(messages(errors));
    CHECK(lines(errors) == std::vector{2, 3, 4, 6, 7, 9, 12, 14});
    CHECK(s.camera.yaw_deg == 10.0f);  // good keys between bad ones still apply
    CHECK(s.debug.grid == false);
    CHECK(s.window.height == 720);
}

TEST_CASE("config: a missing or unreadable file is one error without a line") {
    Settings s;
    TempDir dir;
    const InputErrors missing = loadIniFile(dir.path / "nope.ini", s);
    REQUIRE(missing.size() == 1);
    CHECK(missing[0].line == 0);
    CHECK(missing[0].file == (dir.path / "nope.ini").string());
    CHECK(missing[0].message == "cannot be opened: No such file or directory");
    CHECK(missing[0].str() == (dir.path / "nope.ini").string() + ": cannot be opened: No such file or directory");

    const InputErrors directory = loadIniFile(dir.path, s);
    REQUIRE(directory.size() == 1);
    CHECK(directory[0].line == 0);
    CHECK(contains(directory[0].message, "cannot be opened: "));
    CHECK(differences(s, Settings{}) == "");
}

TEST_CASE("config: errors from a file carry its path and line") {
    TempDir dir;
    const auto file = dir.path / "scene.ini";
    std::ofstream(file) << "[window]\nwidth = 640\n\n[camera]\nfov_deg = abc\n";
    Settings s;
    const InputErrors errors = loadIniFile(file, s);
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].str() == file.string() + ":5: [camera] fov_deg = abc is not a number; accepted: 5..120 (deg)");
    CHECK(s.window.width == 640);
}

TEST_CASE("config: --set overrides a field, with dots in the section name") {
    Settings s;
    CHECK(applyOverride("window.width=1920", s).empty());
    CHECK(applyOverride("postfx.tonemap.op=reinhard", s).empty());
    CHECK(applyOverride(" postfx.exposure.ev = -1.5 ", s).empty());
    CHECK(applyOverride("postfx.enabled=off", s).empty());
    CHECK(applyOverride("camera.position=1,2,3", s).empty());
    CHECK(applyOverride("capture.path=a=b.path", s).empty());  // the first '=' splits
    Settings expected;
    expected.window.width = 1920;
    expected.tonemap.op = Tonemapper::Reinhard;
    expected.exposure.ev = -1.5f;
    expected.postfx.enabled = false;
    expected.camera.position = {1, 2, 3};
    expected.capture.path = "a=b.path";
    CHECK(differences(s, expected) == "");
}

TEST_CASE("config: --set with bad syntax explains the syntax") {
    Settings s;
    for (const char* bad : {"window.width", "width=3", "=3", ".width=3", "window.=3", ""}) {
        INFO(bad);
        CHECK(contains(oneOverrideError(bad, s), "accepted: --set section.key=value"));
    }
    CHECK(differences(s, Settings{}) == "");
}

TEST_CASE("config: --set with an unknown section or key suggests the full name") {
    Settings s;
    CHECK(oneOverrideError("window.widht=3", s) == "unknown key [window] widht; did you mean 'window.width'?");
    CHECK(oneOverrideError("postfx.tonemapp.op=aces", s) ==
          "unknown section [postfx.tonemapp]; did you mean 'postfx.tonemap.op'?");
    CHECK(contains(oneOverrideError("render.quality=3", s), "unknown section [render]; accepted: window, camera,"));
    CHECK(differences(s, Settings{}) == "");
}

TEST_CASE("config: --set with a bad value leaves the field unchanged") {
    Settings s;
    CHECK(oneOverrideError("window.width=0", s) == "[window] width = 0 is out of range; accepted: 1..16384 (px)");
    CHECK(oneOverrideError("postfx.tonemap.op=filmic", s) ==
          "[postfx.tonemap] op = filmic is not accepted; accepted: reinhard, aces, clamp, agx");
    CHECK(contains(oneOverrideError("camera.fov_deg=", s), "is not a number"));
    CHECK(differences(s, Settings{}) == "");
}

TEST_CASE("config: saved text has every section, help comments and ranges") {
    Settings s;
    const std::string text = saveIniString(s);
    CHECK(text.starts_with("[window]\n; window and GL context\n; window width (px, 1..16384)\nwidth = 1280\n"));
    CHECK(contains(text, "\n[postfx.tonemap]\n; tone mapping from HDR to display\n"));
    CHECK(contains(text, "; operator: extended Reinhard on luminance, ACES fit (Narkowicz), clamp, AgX (Sobotka) "
                         "(one of: reinhard, aces, clamp, agx)\nop = aces\n"));
    CHECK(contains(text, "; wait for vertical sync (true or false)\nvsync = true\n"));
    CHECK(contains(text, "; near plane (the far plane is at infinity) (m, 0.001..100)\nnear_m = 0.1\n"));
    CHECK(contains(text, "\nposition = 0 60 0\n"));
    CHECK(contains(text, "\npath = \"data/paths/default.path\"\n"));
    for (const auto& [key, value] : flatten(s)) {
        const std::string name = key.substr(key.rfind('.') + 1);
        INFO(key);
        CHECK(contains(text, "\n" + name + " = "));
    }
}

TEST_CASE("config: save then load reproduces every field exactly") {
    Settings s;
    Perturb perturb;
    describe(perturb, s);
    s.camera.slow_multiplier = 0.1f;
    s.camera.zoom_sensitivity = 1e-7f;
    s.camera.position = {1.0e7 + 0.123, -0.1, 1e-300};
    s.sky.horizon_color = {0.1f, 1.0f / 3.0f, 16777217.0f / 1e6f};
    s.capture.out = "";
    s.capture.path = " leading and trailing blanks ";

    const auto before = flatten(s), defaults = flatten(Settings{});
    for (const auto& [key, value] : before) {
        INFO(key);
        CHECK(!(value == defaults.at(key)));  // so the round trip below really tests every field
    }
    for (const auto& [key, text] : flattenAll(s).lists) {
        INFO(key);
        CHECK(contains(text, "perturbed = "));
    }

    const std::string text = saveIniString(s);
    CHECK(contains(text, "\nslow_multiplier = 0.1\n"));
    CHECK(contains(text, "\nzoom_sensitivity = 1e-07\n"));
    CHECK(contains(text, "\nposition = 10000000.123 -0.1 1e-300\n"));

    Settings loaded;
    INFO(text);
    CHECK(messages(loadIniString(text, "saved.ini", loaded)) == "");
    CHECK(differences(loaded, s) == "");
    CHECK(saveIniString(loaded) == text);
}

TEST_CASE("config: saveIniFile writes a file that loadIniFile accepts") {
    TempDir dir;
    const auto file = dir.path / "scene.ini";
    Settings s;
    s.window.width = 1111;
    s.tonemap.white = 0.3f;
    CHECK(saveIniFile(file, s) == "");
    CHECK(!std::filesystem::exists(dir.path / "scene.ini.tmp"));

    s.window.width = 2222;  // overwrites an existing file
    CHECK(saveIniFile(file, s) == "");

    Settings loaded;
    const InputErrors errors = loadIniFile(file, loaded);
    CHECK(messages(errors) == "");
    CHECK(differences(loaded, s) == "");

    const auto nowhere = dir.path / "missing-dir" / "scene.ini";
    const std::string error = saveIniFile(nowhere, s);
    CHECK(contains(error, nowhere.string()));
    CHECK(contains(error, "No such file or directory"));
}

TEST_CASE("config: didYouMean finds close names and ignores far ones") {
    const std::vector<std::string> keys{"width", "height", "fullscreen", "vsync", "gl_debug"};
    CHECK(didYouMean("widht", keys) == "width");     // swapped letters
    CHECK(didYouMean("WIDTH", keys) == "width");     // case
    CHECK(didYouMean("heigth", keys) == "height");
    CHECK(didYouMean("fulscreen", keys) == "fullscreen");
    CHECK(didYouMean("vsinc", keys) == "vsync");
    CHECK(didYouMean("depth", keys) == "");
    CHECK(didYouMean("x", keys) == "");
    CHECK(didYouMean("", keys) == "");
    CHECK(didYouMean("width", {}) == "");
    const std::vector<std::string> sections{"postfx", "postfx.exposure", "postfx.tonemap"};
    CHECK(didYouMean("postfx.tonemapp", sections) == "postfx.tonemap");
    CHECK(didYouMean("postfx.tone", sections) == "postfx.tonemap");
    CHECK(didYouMean("postfx.exposur", sections) == "postfx.exposure");
}
