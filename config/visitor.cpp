// The settings visitor's helpers that are not templates.
#include "config/visitor.h"

#include <algorithm>

namespace vista {

bool isValidListName(std::string_view name) {
    return !name.empty() && std::ranges::all_of(name, [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    });
}

}  // namespace vista
