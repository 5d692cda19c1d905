// Whether a text holds a part: what many tests ask of a message or an output.
#pragma once

#include <string>

namespace fb89::testing {

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace fb89::testing
