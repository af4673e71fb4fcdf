// List entry text: tokens, strict numbers and their shortest text (see spec_text.h).
#include "config/spec_text.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace vista::spec {

std::vector<std::string_view> tokens(std::string_view text) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
        std::size_t j = i;
        while (j < text.size() && text[j] != ' ' && text[j] != '\t') ++j;
        if (j > i) out.push_back(text.substr(i, j - i));
        i = j;
    }
    return out;
}

bool toDouble(std::string_view t, double& v) {
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);  // from_chars rejects a leading '+'
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    return ec == std::errc() && end == t.data() + t.size() && std::isfinite(v);
}

std::string str(double v) {
    char buf[32];
    return {buf, std::to_chars(buf, buf + sizeof buf, v).ptr};
}

std::string str(float v) {
    char buf[32];
    return {buf, std::to_chars(buf, buf + sizeof buf, v).ptr};
}

std::string bound(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

bool Reader::numbers(std::string_view what, double* out, int n, double lo, double hi, std::string& error) {
    for (int k = 0; k < n; ++k) {
        if (i_ >= t_.size()) {
            error = std::string(what) + " needs " + std::to_string(n) + " number" + (n > 1 ? "s" : "");
            return false;
        }
        std::string_view tok = t_[i_++];
        if (!toDouble(tok, out[k])) {
            error = std::string(what) + ": '" + std::string(tok) + "' is not a number";
            return false;
        }
        if (out[k] < lo || out[k] > hi) {
            error = std::string(what) + ": " + std::string(tok) + " is outside [" + bound(lo) + ", " + bound(hi) + "]";
            return false;
        }
    }
    return true;
}

}  // namespace vista::spec
