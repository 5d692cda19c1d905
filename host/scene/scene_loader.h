// Loading scenes from files: JSON scene files (DESIGN.md "Scene model"; comments allowed),
// `.tri` screen-space triangle sets (the conformance fixtures' format) and bare `.obj`
// models, framed by an automatic camera (host/scene/auto_camera.h).
#pragma once

#include <filesystem>
#include <string_view>

#include "host/scene/scene.h"

namespace fb89::host {

// Chooses the format by extension (.json, .obj, .tri). Throws SceneError on any problem.
// A bare OBJ model's notes say how it was framed, and warn of a missing material library.
Scene load_scene(const std::filesystem::path& file);

// The same from text already in memory; `name` stands for the file in messages and
// `base_dir` resolves relative mesh paths.
Scene parse_scene_json(std::string_view text, const std::string& name,
                       const std::filesystem::path& base_dir);
Scene parse_tri(std::string_view text, const std::string& name);

}  // namespace fb89::host
