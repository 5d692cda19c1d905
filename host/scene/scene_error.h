// The one error type of scene loading: every message names the file, the field or line,
// and what was expected.
#pragma once

#include <stdexcept>
#include <string>

namespace fb89::host {

class SceneError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace fb89::host
