// Turning a resolved buffer of faces into DRAW_SPAN commands: each row of a window becomes
// runs of equal colour; pixels no face covers are background and send nothing.
#pragma once

#include <cstdint>

#include "host/raster/screen_scene.h"
#include "protocol/command_sink.h"

namespace fb89::host {

// `row` holds, per pixel of row y, the index + 1 of the face that won it in scene.faces
// (0: background). Sends the runs of pixels x0..x1-1 and returns how many spans it sent.
uint64_t emit_row_spans(const ScreenScene& scene, const uint32_t* row, int y, int x0, int x1,
                        protocol::CommandSink& sink);

}  // namespace fb89::host
