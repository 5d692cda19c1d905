// The paper's Figs. 4.7 and 4.10: a beam-ray hybrid's frame with every pixel the ray
// tracer decided blacked out, so the regions beams rendered stand out.
#pragma once

#include <cstdint>
#include <vector>

#include "controller_sim/framebuffer.h"

namespace fb89::experiments {

// `by_beam` holds one entry per pixel, row by row: 1 where a beam decided it.
controller::Framebuffer masked_by_beams(const controller::Framebuffer& frame,
                                        const std::vector<uint8_t>& by_beam);

}  // namespace fb89::experiments
