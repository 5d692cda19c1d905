// The keys a scene file may hold, section by section. The loader accepts exactly these (every
// JsonFields::only_keys call names a section here) and scenes/README.md documents each section
// in a table marked `<!-- keys SECTION -->`; a test holds the two to each other.
#pragma once

#include <string_view>
#include <vector>

namespace fb89::host {

struct KeySection {
    std::string_view name;  // "camera", "generator box", ...
    std::vector<std::string_view> keys;
};

const std::vector<KeySection>& scene_key_sections();

// The keys of one section; an unknown name is a programming error (std::logic_error).
const std::vector<std::string_view>& scene_keys(std::string_view section);

}  // namespace fb89::host
