// One description of every setting: a settings struct lists its fields once through a
// SettingsVisitor, and the ini loader, the ini writer, the --set overrides, `vista check`
// and the ImGui panel are all visitors. Adding a field to a describe() function is all it
// takes for it to be loadable, savable, checked and editable; list keys (light.NAME = ...)
// go through one ListField per list.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vista {

// Metadata shown in error messages, saved ini comments and panel tooltips.
struct FieldInfo {
    const char* key;
    const char* unit;  // "m", "deg", "px", "" ...
    const char* help;  // one line
};

class SettingsVisitor;

// Whether name can be the NAME of a list key PREFIX.NAME: letters, digits and '_', not empty.
bool isValidListName(std::string_view name);

// The entries of a list key: lines `PREFIX.NAME = TEXT` of one section (`light.lantern = point
// 10 42 -5` in [lights]), each NAME unique in the section, kept in file order. Visitors see an
// entry as its name and its canonical text; the panel can also edit an entry's values one by one
// through describeEntry(). NamedList below implements it over a std::vector.
class ListField {
public:
    virtual ~ListField() = default;
    virtual std::size_t size() const = 0;
    virtual const std::string& name(std::size_t i) const = 0;
    // Canonical text of entry i: set(name(i), text(i)) reproduces the entry exactly.
    virtual std::string text(std::size_t i) const = 0;
    // Parses text into the entry called name: replaces it where there is one, else appends one.
    // Empty on success, otherwise why text is not accepted (the bad token and what is accepted);
    // the list is then unchanged. The caller checks the name with isValidListName().
    virtual std::string set(std::string_view name, std::string_view text) = 0;
    // set() for a name the caller knows is not in the list: appends without searching, so a
    // file of n entries loads in O(n), not O(n^2) (300,000 lights took minutes).
    virtual std::string append(std::string_view name, std::string_view text) { return set(name, text); }
    virtual void erase(std::size_t i) = 0;
    // Text of an entry with every value at its default (what an editor adds).
    virtual std::string defaultText() const = 0;
    // Lists entry i's values as fields of v (keys are the text's keywords). An edit that leaves
    // the entry invalid (one its text would not parse back) is undone.
    virtual void describeEntry(std::size_t i, SettingsVisitor& v) = 0;
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
    // A list key: info.key is the PREFIX of the section's PREFIX.NAME keys, info.help says the
    // format of their values.
    virtual void list(const FieldInfo& info, ListField& entries) = 0;
    // An ordered list of distinct names from names (the post chain's order), as indices into
    // names. Visitors that have no use for it may ignore it.
    virtual void sequence(const FieldInfo&, std::vector<int>&, std::span<const char* const>) {}

    // Enum-typed convenience over choice(): the enum's values must be 0..names.size()-1.
    template <class Enum>
    void choice(const FieldInfo& info, Enum& value, std::span<const char* const> names) {
        static_assert(sizeof(Enum) == sizeof(int));
        int index = static_cast<int>(value);
        choice(info, index, names);
        value = static_cast<Enum>(index);
    }
    // Enum-typed convenience over sequence().
    template <class Enum>
    void sequence(const FieldInfo& info, std::vector<Enum>& value, std::span<const char* const> names) {
        static_assert(sizeof(Enum) == sizeof(int));
        std::vector<int> indices;
        for (Enum e : value) indices.push_back(static_cast<int>(e));
        sequence(info, indices, names);
        value.clear();
        for (int i : indices) value.push_back(static_cast<Enum>(i));
    }
};

// ListField over std::vector<Entry>, each Entry a `std::string name` and a Value member, with
// the value's text format (parse: "" or why not; format: text that parses back exactly) and its
// fields for the panel.
template <class Entry, class Value>
class NamedList final : public ListField {
public:
    using Parse = std::string (*)(std::string_view, Value&);
    using Format = std::string (*)(const Value&);
    using Describe = void (*)(SettingsVisitor&, Value&);

    NamedList(std::vector<Entry>& entries, Value Entry::*value, Parse parse, Format format, Describe describe)
        : entries_(entries), value_(value), parse_(parse), format_(format), describe_(describe) {}

    std::size_t size() const override { return entries_.size(); }
    const std::string& name(std::size_t i) const override { return entries_[i].name; }
    std::string text(std::size_t i) const override { return format_(entries_[i].*value_); }
    std::string set(std::string_view name, std::string_view text) override { return put(name, text, true); }
    std::string append(std::string_view name, std::string_view text) override { return put(name, text, false); }
    std::string put(std::string_view name, std::string_view text, bool search) {
        Value v{};  // groups the text omits take the defaults, not the old entry's values
        if (std::string why = parse_(text, v); !why.empty()) return why;
        for (Entry& e : entries_) {
            if (!search) break;
            if (e.name == name) {
                e.*value_ = std::move(v);
                return {};
            }
        }
        Entry e{};
        e.name = std::string(name);
        e.*value_ = std::move(v);
        entries_.push_back(std::move(e));
        return {};
    }
    void erase(std::size_t i) override { entries_.erase(entries_.begin() + std::ptrdiff_t(i)); }
    std::string defaultText() const override { return format_(Value{}); }
    void describeEntry(std::size_t i, SettingsVisitor& v) override {
        Value& value = entries_[i].*value_;
        const Value before = value;
        describe_(v, value);
        Value check{};
        if (!parse_(format_(value), check).empty()) value = before;
    }

private:
    std::vector<Entry>& entries_;
    Value Entry::*value_;
    Parse parse_;
    Format format_;
    Describe describe_;
};

}  // namespace vista
