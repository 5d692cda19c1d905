// The checkout's scenes/ folder, as the test executable is told it (FB89_SCENES_DIR).
#pragma once

#include <string>

namespace fb89::testing {

inline const std::string kScenes = FB89_SCENES_DIR;

}  // namespace fb89::testing
