// Scene files: inih splits the text into [section] and key = value lines; everything that
// knows about keys, types and ranges goes through describe() with three visitors: one
// collects the names, one applies a value, one writes the file.
#include "config/ini.h"
#include "config/file_io.h"

#include <ini.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <unordered_set>
#include <limits>
#include <map>
#include <optional>
#include <type_traits>
#include <vector>

namespace vista {
namespace {

using Names = std::span<const char* const>;

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

bool iequals(std::string_view a, std::string_view b) {
    return std::ranges::equal(a, b, {}, lower, lower);
}

constexpr std::size_t kMaxListedProblems = 100;

// A value quoted in a message: one over 1 KiB (a 10 MB value) is cut, saying how long it was.
std::string clipValue(std::string_view text) {
    if (text.size() <= 1024) return std::string(text);
    return std::string(text.substr(0, 100)) + "... (" + std::to_string(text.size()) + " characters)";
}

std::string_view trim(std::string_view t) {
    const auto begin = t.find_first_not_of(" \t\r\n");
    return begin == t.npos ? std::string_view{} : t.substr(begin, t.find_last_not_of(" \t\r\n") - begin + 1);
}

template <class Range>
std::string join(const Range& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + std::string(n);
    return out;
}

// Shortest text that reads back as exactly v, so saved files round-trip.
template <class T>
std::string exact(T v) {
    char buf[64];
    return {buf, std::to_chars(buf, buf + sizeof buf, v).ptr};
}

// Ranges are for people to read: 1e+05 is clearer as 100000, and 0.01f as 0.01.
template <class T>
std::string range(T lo, T hi) {
    char buf[64];
    std::snprintf(buf, sizeof buf, std::is_integral_v<T> ? "%.0f..%.0f" : "%g..%g", double(lo), double(hi));
    return buf;
}

// parse() reads text into v and returns why it is not accepted, or "". v is written only
// on success, so a bad value leaves the field as it was.
std::string parse(std::string_view t, bool& v) {
    static constexpr const char* words[] = {"false", "true", "no", "yes", "off", "on", "0", "1"};
    const auto it = std::ranges::find_if(words, [&](const char* w) { return iequals(t, w); });
    if (it == std::end(words)) return "is not accepted";
    v = (it - std::begin(words)) % 2 == 1;  // words alternate false, true
    return "";
}

template <class T>
    requires std::is_arithmetic_v<T>
std::string parse(std::string_view t, T& v, T lo, T hi) {
    if (t.starts_with('+') && !t.starts_with("+-")) t.remove_prefix(1);
    T x{};
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
    if (ec == std::errc::result_out_of_range) return "is out of range";
    if (ec != std::errc{} || end != t.data() + t.size() || !std::isfinite(double(x)))
        return std::is_integral_v<T> ? "is not a whole number" : "is not a number";
    if (x < lo || x > hi) return "is out of range";
    v = x;
    return "";
}

template <class T, glm::qualifier Q>
std::string parse(std::string_view t, glm::vec<3, T, Q>& v, T lo, T hi) {
    glm::vec<3, T, Q> x{};
    int n = 0;
    for (auto pos = t.find_first_not_of(" \t,"); pos != t.npos; pos = t.find_first_not_of(" \t,", pos)) {
        const auto end = t.find_first_of(" \t,", pos);
        const auto word = t.substr(pos, end - pos);
        if (n == 3 || !parse(word, x[n++], std::numeric_limits<T>::lowest(), std::numeric_limits<T>::max()).empty())
            return "is not three numbers";
        pos = end;
    }
    if (n != 3) return "is not three numbers";
    for (int i = 0; i < 3; ++i)
        if (x[i] < lo || x[i] > hi) return "is out of range";
    v = x;
    return "";
}

std::string parse(std::string_view t, std::string& v) {
    if (t.size() >= 2 && t.front() == '"' && t.back() == '"') t = t.substr(1, t.size() - 2);
    v = t;
    return "";
}

std::string parse(std::string_view t, int& v, Names names) {
    const auto it = std::ranges::find_if(names, [&](const char* n) { return iequals(t, n); });
    if (it == names.end()) return "is not accepted";
    v = int(it - names.begin());
    return "";
}

// An ordered list of distinct names, separated by blanks or commas; empty is allowed.
using Sequence = std::vector<int>;
std::string parse(std::string_view t, Sequence& v, Names names) {
    Sequence x;
    for (auto pos = t.find_first_not_of(" \t,"); pos != t.npos; pos = t.find_first_not_of(" \t,", pos)) {
        const auto end = t.find_first_of(" \t,", pos);
        const auto word = t.substr(pos, end - pos);
        const auto it = std::ranges::find_if(names, [&](const char* n) { return iequals(word, n); });
        if (it == names.end()) return "is not accepted ('" + std::string(word) + "')";
        if (std::ranges::find(x, int(it - names.begin())) != x.end())
            return "is not accepted ('" + std::string(word) + "' twice)";
        x.push_back(int(it - names.begin()));
        pos = end;
    }
    v = std::move(x);
    return "";
}

// The value as it is written to a file.
std::string format(bool v) { return v ? "true" : "false"; }
template <class T>
    requires std::is_arithmetic_v<T>
std::string format(T v, T, T) { return exact(v); }
template <class T, glm::qualifier Q>
std::string format(const glm::vec<3, T, Q>& v, T, T) { return exact(v.x) + " " + exact(v.y) + " " + exact(v.z); }
std::string format(const std::string& v) { return '"' + v + '"'; }  // quoted: leading spaces survive
std::string format(int v, Names names) { return v >= 0 && size_t(v) < names.size() ? names[v] : std::to_string(v); }
std::string format(const Sequence& v, Names names) {
    std::string out;
    for (int i : v) out += (out.empty() ? "" : " ") + format(i, names);
    return out;
}

// What a field accepts, without its unit.
std::string accepted(bool) { return "true/false, yes/no, on/off, 1/0"; }
template <class T>
    requires std::is_arithmetic_v<T>
std::string accepted(T, T lo, T hi) { return range(lo, hi); }
template <class T, glm::qualifier Q>
std::string accepted(const glm::vec<3, T, Q>&, T lo, T hi) { return "three numbers, each " + range(lo, hi); }
std::string accepted(const std::string&) { return ""; }
std::string accepted(int, Names names) { return join(names); }
std::string accepted(const Sequence&, Names names) { return "names from " + join(names) + ", each at most once"; }

// Routes the nine field kinds to one Derived::visit(info, value, limits...), so each
// visitor below is a single generic function, plus Derived::visitList() for list keys.
template <class Derived>
class Visitor : public SettingsVisitor {
public:
    void field(const FieldInfo& i, bool& v) override { self().visit(i, v); }
    void field(const FieldInfo& i, int& v, int lo, int hi) override { self().visit(i, v, lo, hi); }
    void field(const FieldInfo& i, float& v, float lo, float hi) override { self().visit(i, v, lo, hi); }
    void field(const FieldInfo& i, double& v, double lo, double hi) override { self().visit(i, v, lo, hi); }
    void field(const FieldInfo& i, glm::vec3& v, float lo, float hi) override { self().visit(i, v, lo, hi); }
    void field(const FieldInfo& i, glm::dvec3& v, double lo, double hi) override { self().visit(i, v, lo, hi); }
    void field(const FieldInfo& i, std::string& v) override { self().visit(i, v); }
    void choice(const FieldInfo& i, int& v, Names names) override { self().visit(i, v, names); }
    void list(const FieldInfo& i, ListField& l) override { self().visitList(i, l); }
    void sequence(const FieldInfo& i, Sequence& v, Names names) override { self().visit(i, v, names); }

private:
    Derived& self() { return static_cast<Derived&>(*this); }
};

struct Section {
    std::string name;
    std::vector<std::string> keys;
    std::vector<std::string> lists;  // PREFIX of the PREFIX.NAME list keys
};

// "light" of the list key "light.lantern"; "" for a plain key.
std::string_view listPrefix(std::string_view key) {
    const auto dot = key.find('.');
    return dot == key.npos ? std::string_view{} : key.substr(0, dot);
}

bool isListKey(const Section& section, std::string_view key) {
    const std::string_view prefix = listPrefix(key);
    return !prefix.empty() && std::ranges::find(section.lists, prefix) != section.lists.end();
}

bool hasKey(const Section& section, std::string_view key) {
    return std::ranges::find(section.keys, key) != section.keys.end() || isListKey(section, key);
}

// The keys an error lists as accepted: the plain keys, then PREFIX.NAME for each list.
std::vector<std::string> acceptedKeys(const Section& section) {
    std::vector<std::string> out = section.keys;
    for (const std::string& prefix : section.lists) out.push_back(prefix + ".NAME");
    return out;
}

class NameCollector final : public Visitor<NameCollector> {
public:
    std::vector<Section> sections;
    void section(const char* name, const char*) override { sections.push_back({name, {}, {}}); }
    template <class T, class... L>
    void visit(const FieldInfo& i, T&, const L&...) { sections.back().keys.push_back(i.key); }
    void visitList(const FieldInfo& i, ListField&) { sections.back().lists.push_back(i.key); }
};

// Sets the one field [section] key from text, or says why not.
class Applier final : public Visitor<Applier> {
public:
    // known_new: the caller knows a list entry of this name does not exist yet (append).
    Applier(std::string_view section, std::string_view key, std::string_view text, bool known_new = false)
        : section_(section), key_(key), text_(text), knownNew_(known_new) {}
    std::string error;

    void section(const char* name, const char*) override { inSection_ = section_ == name; }
    template <class T, class... L>
    void visit(const FieldInfo& i, T& v, const L&... limits) {
        if (!inSection_ || key_ != i.key) return;
        if (const std::string why = parse(text_, v, limits...); !why.empty()) {
            const std::string unit = *i.unit ? std::string(" (") + i.unit + ")" : "";
            error = "[" + std::string(section_) + "] " + i.key + " = " + clipValue(text_) + " " + why +
                    "; accepted: " + accepted(v, limits...) + unit;
        }
    }
    // key_ is PREFIX.NAME: sets (replaces or appends) the entry NAME.
    void visitList(const FieldInfo& i, ListField& list) {
        if (!inSection_ || listPrefix(key_) != i.key) return;
        const std::string_view name = key_.substr(listPrefix(key_).size() + 1);
        const std::string key = "[" + std::string(section_) + "] " + std::string(key_);
        if (!isValidListName(name))
            error = key + ": the name '" + std::string(name) + "' is not accepted; accepted: " + i.key +
                    ".NAME with NAME made of letters, digits and _";
        else if (const std::string why = knownNew_ ? list.append(name, text_) : list.set(name, text_); !why.empty())
            error = key + " = " + clipValue(text_) + " is not accepted: " + why;
    }

private:
    std::string_view section_, key_, text_;
    bool knownNew_ = false;
    bool inSection_ = false;
};

// The names of the list entries settings already hold ("section\nprefix.name"), so a load
// knows which of its entries are new without searching the lists.
class ListNames final : public Visitor<ListNames> {
public:
    std::unordered_set<std::string> names;
    void section(const char* name, const char*) override { section_ = name; }
    template <class T, class... L>
    void visit(const FieldInfo&, T&, const L&...) {}
    void visitList(const FieldInfo& i, ListField& list) {
        for (std::size_t e = 0; e < list.size(); ++e) names.insert(section_ + "\n" + i.key + "." + list.name(e));
    }

private:
    std::string section_;
};

class Writer final : public Visitor<Writer> {
public:
    std::string out;
    void section(const char* name, const char* help) override {
        out += (out.empty() ? "[" : "\n[") + std::string(name) + "]\n; " + help + "\n";
    }
    template <class T, class... L>
    void visit(const FieldInfo& i, T& v, const L&... limits) {
        std::string hint = accepted(v, limits...);
        if constexpr (std::is_same_v<T, bool>) hint = "true or false";  // the other spellings are for typing
        if constexpr ((std::is_same_v<L, Names> || ...) && !std::is_same_v<T, Sequence>) hint = "one of: " + hint;
        if (*i.unit) hint = hint.empty() ? i.unit : i.unit + (", " + hint);
        out += "; " + std::string(i.help) + (hint.empty() ? "" : " (" + hint + ")") + "\n";
        out += i.key + (" = " + format(v, limits...)) + "\n";
    }
    void visitList(const FieldInfo& i, ListField& list) {
        out += "; " + std::string(i.help) + " (one " + i.key + ".NAME key per entry, NAME: letters, digits, _)\n";
        for (std::size_t e = 0; e < list.size(); ++e) out += i.key + ("." + list.name(e)) + " = " + list.text(e) + "\n";
    }
};

// The scene-file reference (docs/scene-file.md): a Markdown table per section with each key's
// default, unit, what it accepts and its help, all from describe().
class Reference final : public Visitor<Reference> {
public:
    std::string out;
    void section(const char* name, const char* help) override {
        out += "\n## [" + std::string(name) + "]\n\n" + cell(help) + "\n\n| key | default | unit | accepts | meaning |\n|---|---|---|---|---|\n";
    }
    template <class T, class... L>
    void visit(const FieldInfo& i, T& v, const L&... limits) {
        std::string value = format(v, limits...);  // exact for files; shortest readable here
        if constexpr (std::is_floating_point_v<T>) value = number(v);
        if constexpr (std::is_same_v<T, glm::vec3> || std::is_same_v<T, glm::dvec3>)
            value = number(v.x) + " " + number(v.y) + " " + number(v.z);
        std::string hint = accepted(v, limits...);
        if constexpr (std::is_same_v<T, bool>) hint = "true, false";
        if constexpr (std::is_same_v<T, std::string>) value = v.empty() ? "" : '`' + v + '`';
        row("`" + std::string(i.key) + "`", value, i.unit, hint, i.help);
    }
    void visitList(const FieldInfo& i, ListField& list) {
        row("`" + std::string(i.key) + ".NAME`", list.size() ? std::to_string(list.size()) + " entries" : "none", "",
            "one key per entry, NAME: letters, digits, _; the value: `" + list.defaultText() + "` (defaults)", i.help);
    }

private:
    static std::string number(double x) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", x);
        return buf;
    }
    // Markdown table cells: '|' would end the cell.
    static std::string cell(std::string_view text) {
        std::string s;
        for (char c : text) s += c == '|' ? std::string("\\|") : std::string(1, c);
        return s;
    }
    void row(const std::string& key, const std::string& value, const std::string& unit, const std::string& hint,
             const std::string& help) {
        out += "| " + cell(key) + " | " + cell(value) + " | " + cell(unit) + " | " + cell(hint) + " | " + cell(help) + " |\n";
    }
};

std::vector<Section> collectNames(Settings& s) {
    NameCollector names;
    describe(names, s);
    return names.sections;
}

const Section* find(const std::vector<Section>& sections, std::string_view name) {
    const auto it = std::ranges::find(sections, name, &Section::name);
    return it == sections.end() ? nullptr : &*it;
}

std::vector<std::string> sectionNames(const std::vector<Section>& sections) {
    std::vector<std::string> out;
    for (const Section& s : sections) out.push_back(s.name);
    out.push_back("terrain.material.NAME");  // the named family (addNamedSection)
    return out;
}

std::string unknown(const std::string& what, const std::string& guess, const std::vector<std::string>& accepted) {
    return what + (guess.empty() ? "; accepted: " + join(accepted) : "; did you mean '" + guess + "'?");
}

// Optimal string alignment distance (a swap of neighbours counts as one edit), ignoring case.
size_t distance(std::string_view a, std::string_view b) {
    const size_t w = b.size() + 1;
    std::vector<size_t> d((a.size() + 1) * w);
    for (size_t i = 0; i <= a.size(); ++i) {
        for (size_t j = 0; j <= b.size(); ++j) {
            size_t& x = d[i * w + j];
            if (i == 0 || j == 0) {
                x = i + j;
                continue;
            }
            x = std::min({d[(i - 1) * w + j] + 1, d[i * w + j - 1] + 1,
                          d[(i - 1) * w + j - 1] + (lower(a[i - 1]) != lower(b[j - 1]))});
            if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
                x = std::min(x, d[(i - 2) * w + j - 2] + 1);
        }
    }
    return d.back();
}

// One load: the state shared by the line reader and the key handler that inih calls.
class Loader {
public:
    Loader(std::string_view text, const std::string& file, Settings& s)
        : text_(text), file_(file), settings_(s), sections_(collectNames(s)) {
        if (text_.starts_with("\xEF\xBB\xBF")) text_.remove_prefix(3);
        ListNames existing;
        describe(existing, settings_);
        existing_ = std::move(existing.names);
    }

    InputErrors run() && {
        const int first = ini_parse_stream(&Loader::readLine, this, &Loader::onKey, this);
        checkHandled();
        // inih reports only its first error; the checks above should have found it already.
        if (first > 0 && std::ranges::none_of(errors_, [&](const InputError& e) { return e.line == first; }))
            error(first, "cannot be parsed");
        std::ranges::stable_sort(errors_, {}, &InputError::line);
        if (unlisted_ > 0)
            errors_.push_back({file_, 0, "and " + std::to_string(unlisted_) + " more problem(s) not listed (the first " +
                                             std::to_string(kMaxListedProblems) + " are)"});
        return std::move(errors_);
    }

private:
    // inih calls this once per line. Each line is handed over without leading blanks (an
    // indented line would otherwise continue the previous value) or inline comments (";"
    // and "#" after a blank, whichever inih was built with).
    static char* readLine(char* buf, int size, void* self) {
        auto& l = *static_cast<Loader*>(self);
        l.checkHandled();
        if (l.text_.empty()) return nullptr;
        const auto end = l.text_.find('\n');
        std::string_view line = l.text_.substr(0, end);
        l.text_.remove_prefix(end == l.text_.npos ? l.text_.size() : end + 1);
        ++l.line_;
        for (size_t c = line.find_first_of(";#"); c != line.npos; c = line.find_first_of(";#", c + 1)) {
            if (c == 0 || line[c - 1] == ' ' || line[c - 1] == '\t') {
                line = line.substr(0, c);
                break;
            }
        }
        line = trim(line);
        l.longValue_.reset();
        if (line.find('\0') != line.npos) {
            // inih reads C strings: a NUL would cut the value short without a word.
            l.error(l.line_, "contains a NUL byte; accepted: text without NUL bytes");
            line = {};
        }
        if (line.size() + 2 > size_t(size) && !line.starts_with('[')) {
            // inih takes at most size - 2 characters a line, but values (a list entry far from the
            // origin, a long path) may be longer: inih gets "key =" and onKey the value kept here.
            const auto delimiter = line.find_first_of("=:");  // inih's delimiters
            if (delimiter != line.npos && delimiter + 3 <= size_t(size)) {
                l.longValue_ = std::string(trim(line.substr(delimiter + 1)));
                l.pending_ = l.line_;
                l.pendingText_ = line;
                line = line.substr(0, delimiter + 1);
            }
        }
        if (line.size() + 2 > size_t(size)) {
            l.error(l.line_, "line is too long; accepted: a section or key of up to " + std::to_string(size - 3) +
                                 " characters");
            line = {};
        } else if (line.starts_with('[')) {
            l.header(line);
        } else if (!line.empty()) {
            l.pending_ = l.line_;
            l.pendingText_ = line;
        }
        line.copy(buf, line.size());
        buf[line.size()] = '\n';
        buf[line.size() + 1] = '\0';
        return buf;
    }

    static int onKey(void* self, const char*, const char* key, const char* value) {
        auto& l = *static_cast<Loader*>(self);
        l.pending_ = 0;
        l.key(key, l.longValue_ ? std::string_view(*l.longValue_) : std::string_view(value));
        return 1;
    }

    // A line that is neither blank nor a header and did not reach onKey is not key = value.
    void checkHandled() {
        if (pending_)
            error(pending_, "cannot parse \"" + pendingText_ + "\"; accepted: key = value, [section] or a ; comment");
        pending_ = 0;
    }

    void header(std::string_view line) {
        section_ = "";  // keys under a broken or unknown header are skipped quietly
        if (!line.ends_with(']')) {
            error(line_, "cannot parse \"" + std::string(line) + "\"; accepted: [section]");
            return;
        }
        section_ = std::string(trim(line.substr(1, line.size() - 2)));
        // A section of a named family ([terrain.material.NAME]) makes its entry on first sight.
        if (!find(sections_, *section_) && addNamedSection(settings_, *section_)) sections_ = collectNames(settings_);
        if (!find(sections_, *section_)) {
            const std::vector<std::string> names = sectionNames(sections_);
            error(line_, unknown("unknown section [" + *section_ + "]", didYouMean(*section_, names), names));
        }
    }

    void key(const std::string& key, std::string_view value) {
        if (!section_) return error(line_, key + " = " + std::string(value) + " comes before any [section]");
        const Section* section = find(sections_, *section_);
        if (!section) return;
        const std::string name = "[" + section->name + "] " + key;
        if (!hasKey(*section, key)) return error(line_, unknownKey(*section, key));
        if (const auto [it, fresh] = seen_.try_emplace(section->name + "\n" + key, line_); !fresh)
            return error(line_, name + " is set twice, on lines " + std::to_string(it->second) + " and " +
                                    std::to_string(line_) + "; the second is ignored");
        // Fresh in this file (seen_ above) and not held before it: a list entry can be appended.
        const bool known_new = !listPrefix(key).empty() && !existing_.contains(section->name + "\n" + key);
        Applier apply(section->name, key, value, known_new);
        describe(apply, settings_);
        if (!apply.error.empty()) error(line_, apply.error);
    }

    // "unknown key [section] key" with a suggestion: a list key's prefix is matched against the
    // section's lists, and one that belongs to another section says which.
    std::string unknownKey(const Section& section, const std::string& key) const {
        const std::string what = "unknown key [" + section.name + "] " + key;
        const std::string_view prefix = listPrefix(key);
        if (prefix.empty()) return unknown(what, didYouMean(key, section.keys), acceptedKeys(section));
        for (const Section& other : sections_)
            if (&other != &section && isListKey(other, key))
                return what + "; " + std::string(prefix) + ".NAME keys belong in [" + other.name + "]";
        const std::string guess = didYouMean(prefix, section.lists);
        return unknown(what, guess.empty() ? "" : guess + key.substr(prefix.size()), acceptedKeys(section));
    }

    // At most kMaxListedProblems are kept (2,000,000 unknown keys printed 2 M lines and took
    // 1 GB); the rest are counted and reported as one line at the end.
    void error(int line, std::string message) {
        if (errors_.size() >= kMaxListedProblems) {
            ++unlisted_;
            return;
        }
        errors_.push_back({file_, line, std::move(message)});
    }

    std::string_view text_;  // not read yet
    const std::string& file_;
    Settings& settings_;
    std::vector<Section> sections_;  // grows when a named section ([terrain.material.NAME]) appears
    InputErrors errors_;
    int line_ = 0;
    int pending_ = 0;  // line handed to inih as key = value that has not reached onKey yet
    std::string pendingText_;
    std::optional<std::string> longValue_;  // value of the current line when inih gets only its key
    std::optional<std::string> section_;  // none before the first header
    std::map<std::string, int> seen_;     // "section\nkey" -> line
    std::unordered_set<std::string> existing_;  // list entries held before this file
    std::size_t unlisted_ = 0;                  // problems beyond kMaxListedProblems
};

}  // namespace

InputErrors loadIniString(std::string_view text, const std::string& name, Settings& s) {
    return Loader(text, name, s).run();
}

InputErrors loadIniFile(const std::filesystem::path& file, Settings& s) {
    // Regular files under a size limit only: a FIFO or /dev/zero is refused, not read forever.
    std::string text;
    std::string problem = readInputFile(file, kMaxTextInputBytes, text);
    if (!problem.empty()) return {{file.string(), 0, problem.substr(std::min(problem.size(), file.string().size() + 2))}};
    return loadIniString(text, file.string(), s);
}

InputErrors applyOverride(std::string_view assignment, Settings& s) {
    const auto fail = [](std::string message) { return InputErrors{{"--set", 0, std::move(message)}}; };
    const auto eq = assignment.find('=');
    const std::string name(trim(assignment.substr(0, eq)));
    const auto dot = name.rfind('.');
    if (eq == assignment.npos || dot == name.npos || dot == 0 || dot + 1 == name.size())
        return fail("cannot parse \"" + std::string(assignment) +
                    "\"; accepted: --set section.key=value, e.g. --set window.width=1920");
    std::vector<Section> sections = collectNames(s);
    // A key of a named section that is not there yet ([terrain.material.NAME]) makes the entry;
    // it is taken out again when the key is refused.
    bool added = false;
    if (const auto last = name.rfind('.'); !find(sections, std::string_view(name).substr(0, last))) {
        const std::size_t before = s.terrain.materials.size();
        if (addNamedSection(s, std::string_view(name).substr(0, last))) {
            added = s.terrain.materials.size() > before;
            sections = collectNames(s);
        }
    }
    const auto undo = [&](InputErrors errors) {
        if (added && !errors.empty()) s.terrain.materials.pop_back();
        return errors;
    };
    // The last dot splits section and key, except in a list key: lights.light.lantern is
    // [lights] light.lantern.
    std::string section = name.substr(0, dot), key = name.substr(dot + 1);
    for (auto d = dot; d != 0 && d != name.npos; d = name.rfind('.', d - 1)) {
        const Section* candidate = find(sections, std::string_view(name).substr(0, d));
        if (candidate && isListKey(*candidate, std::string_view(name).substr(d + 1))) {
            section = name.substr(0, d), key = name.substr(d + 1);
            break;
        }
    }
    std::vector<std::string> all;  // suggestions name the whole section.key
    for (const Section& sec : sections) {
        for (const std::string& k : sec.keys) all.push_back(sec.name + "." + k);
        for (const std::string& prefix : sec.lists) all.push_back(sec.name + "." + prefix + name.substr(dot));
    }
    const Section* found = find(sections, section);
    if (!found) return fail(unknown("unknown section [" + section + "]", didYouMean(name, all), sectionNames(sections)));
    if (!hasKey(*found, key)) {
        if (added) s.terrain.materials.pop_back();
        // The section is known: suggest only its own keys (a key of another section with a
        // similar name would be refused there too, or set something else).
        std::vector<std::string> own;
        for (const std::string& k : found->keys) own.push_back(found->name + "." + k);
        for (const std::string& prefix : found->lists) own.push_back(found->name + "." + prefix + name.substr(dot));
        return fail(unknown("unknown key [" + section + "] " + key, didYouMean(name, own), acceptedKeys(*found)));
    }
    Applier apply(section, key, trim(assignment.substr(eq + 1)));
    describe(apply, s);
    return undo(apply.error.empty() ? InputErrors{} : fail(apply.error));
}

std::string saveIniString(Settings& s) {
    Writer writer;
    describe(writer, s);
    return writer.out;
}

std::string sceneFileReference() {
    Settings defaults;
    addNamedSection(defaults, "terrain.material.NAME");  // documents the family's keys (none by default)
    Reference reference;
    describe(reference, defaults);
    return "# Scene file reference\n\n"
           "Generated from the settings' describe() functions by `vista check --reference > docs/scene-file.md`\n"
           "(a unit test fails when this file is not current). Every key is optional; a missing section keeps\n"
           "its defaults (the built-in ones below; `config/default.ini` sets some differently). An unknown key\n"
           "(with a did-you-mean suggestion), a malformed value or one out of range is an error naming\n"
           "`file:line`; `vista check` lists them all. `--set section.key=value` overrides any key, and `-c`\n"
           "may repeat (later files override earlier ones). Flags accept true/false, yes/no, on/off, 1/0.\n" +
           reference.out;
}

std::string saveIniFile(const std::filesystem::path& file, Settings& s) {
    // The panel's "save" replaces the scene on purpose; writeFileAtomic checks every write.
    return writeFileAtomic(file, saveIniString(s), /*force=*/true);
}

std::string didYouMean(std::string_view word, std::span<const std::string> candidates) {
    std::string best;
    size_t bestDistance = std::max<size_t>(1, word.size() / 3) + 1;
    for (const std::string& c : candidates) {
        if (const size_t d = distance(word, c); d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    return best;
}

}  // namespace vista
