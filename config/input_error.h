// A problem with user input (scene file, --set override, camera path, image), located
// precisely enough for the user to fix it: "file:line: message".
#pragma once

#include <string>
#include <vector>

namespace vista {

struct InputError {
    std::string file;     // path as the user gave it, or "--set"
    int line = 0;         // 1-based; 0 when the problem has no line (missing file)
    std::string message;  // names the key and what is accepted

    std::string str() const {
        return line > 0 ? file + ":" + std::to_string(line) + ": " + message : file + ": " + message;
    }
};

using InputErrors = std::vector<InputError>;

}  // namespace vista
