#include "experiments/beam_mask.h"

#include <stdexcept>

namespace fb89::experiments {

controller::Framebuffer masked_by_beams(const controller::Framebuffer& frame,
                                        const std::vector<uint8_t>& by_beam) {
    if (by_beam.size() != uint64_t{frame.width()} * frame.height())
        throw std::logic_error("the beam mask does not match the frame's size");
    controller::Framebuffer out = frame;
    for (uint32_t y = 0; y < frame.height(); ++y)
        for (uint32_t x = 0; x < frame.width(); ++x)
            if (!by_beam[static_cast<size_t>(y) * frame.width() + x])
                out.set_pixel(x, y, {0, 0, 0});
    return out;
}

}  // namespace fb89::experiments
