// libFuzzer target: scene files and --set overrides. Any text must load without crashing,
// hanging or undefined behaviour, every error must say something, and a file the loader
// accepts must survive a save and reload unchanged.
#include "config/ini.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    vista::Settings s;
    const vista::InputErrors errors = vista::loadIniString(text, "fuzz.ini", s);
    for (const vista::InputError& e : errors)
        if (e.message.empty() || e.line < 0) std::abort();
    // The first line as one --set override (section.key=value).
    vista::Settings o;
    (void)vista::applyOverride(text.substr(0, text.find('\n')), o);
    // An accepted file writes out as a file that reads back to the same settings. (Only then:
    // the full saved scene costs a thousand times the fuzzed text to load.)
    if (!errors.empty()) return 0;
    const std::string saved = vista::saveIniString(s);
    vista::Settings again;
    if (!vista::loadIniString(saved, "saved.ini", again).empty()) {
        std::fprintf(stderr, "a saved scene does not load back:\n%s\n", saved.c_str());
        std::abort();
    }
    if (vista::saveIniString(again) != saved) std::abort();
    return 0;
}
