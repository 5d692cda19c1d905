// The shared coverage rule, as the host's raster methods name it. The rule itself is
// protocol/coverage.h: the controller's FACE command covers pixels by it too, so it sits
// below both sides (docs/ARCHITECTURE.md, "The shared raster rule").
#pragma once

#include "host/raster/screen_scene.h"
#include "protocol/coverage.h"

namespace fb89::host {

using protocol::covers;
using protocol::row_span;
using protocol::setup_edges;

}  // namespace fb89::host
