// Loading scenes from files: JSON scene files (DESIGN.md "Scene model"; comments allowed)
// and `.tri` screen-space triangle sets (the conformance fixtures' format).
#pragma once

#include <filesystem>
#include <string_view>

#include "host/scene/scene.h"

namespace fb89::host {

// Chooses the format by extension (.json, .tri). Throws SceneError on any problem.
Scene load_scene(const std::filesystem::path& file);

// The same from text already in memory; `name` stands for the file in messages and
// `base_dir` resolves relative mesh paths.
Scene parse_scene_json(std::string_view text, const std::string& name,
                       const std::filesystem::path& base_dir);
Scene parse_tri(std::string_view text, const std::string& name);

}  // namespace fb89::host
