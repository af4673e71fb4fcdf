// The text of a list entry (`light.lamp = point 10 42 -5  lumens 800`, `scatter.woods = tree.glb
// density 0.002 ...`): blank-separated tokens, numbers read strictly and checked against a range
// with a message naming the keyword and the token, and numbers written back in their shortest
// exact form. The features' parse/format functions of their list keys share it
// (renderer/lighting/light_settings.cpp, terrain/scatter/object_settings.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace vista::spec {

// The tokens of text, split at spaces and tabs.
std::vector<std::string_view> tokens(std::string_view text);
// The whole token as a finite number (a leading '+' allowed); false otherwise.
bool toDouble(std::string_view t, double& v);
// The shortest text that reads back as v.
std::string str(double v);
std::string str(float v);
// A range bound for people to read, as the ini loader writes ranges: 100000 rather than 1e+05.
std::string bound(double v);

// Reads an entry's tokens in order: words, and the numbers of one keyword group, checking each
// against [lo, hi].
class Reader {
public:
    explicit Reader(std::string_view text) : t_(tokens(text)) {}
    bool done() const { return i_ >= t_.size(); }
    std::string_view word() { return i_ < t_.size() ? t_[i_++] : std::string_view(); }
    std::string_view peek() const { return i_ < t_.size() ? t_[i_] : std::string_view(); }
    // n numbers into out; false with error ("WHAT needs ...", "WHAT: 'x' is not a number", "WHAT:
    // 5 is outside [0, 1]") at the first that is missing or wrong.
    bool numbers(std::string_view what, double* out, int n, double lo, double hi, std::string& error);

private:
    std::vector<std::string_view> t_;
    std::size_t i_ = 0;
};

}  // namespace vista::spec
