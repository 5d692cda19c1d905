// The face-id buffer for people (`render --ids-view`, `radiosity --ids-view`): each id a
// distinct, well-separated colour on a black background, where the exact encoding
// (id + 1 as 24-bit RGB, id_pass.h) shows neighbouring ids as nearly the same dark colour.
//
// Colours: hue walks by the golden ratio (consecutive ids half a turn apart, give or take),
// value by a second irrational step (the plastic number's), saturation fixed. Ids 0 ..
// 16383 get distinct colours; every colour is bright enough never to be mistaken for the
// background. The view is for eyes only: exactness checks read the --ids buffer.
#pragma once

#include <cstdint>
#include <string>

#include "controller_sim/framebuffer.h"
#include "protocol/command.h"

namespace fb89::experiments {

// The colour face `id` gets in the view.
protocol::Rgb id_view_colour(uint32_t id);

// The view of a face-id buffer (as id_framebuffer() returns it): the same size, black where
// the buffer is 0 (background), id_view_colour(id) where it holds id + 1.
controller::Framebuffer id_view(const controller::Framebuffer& ids);

// `--ids` and `--ids-view` of one face-id buffer: the exact encoding to `ids_png` and the
// view to `view_png`, each only when its path is not empty (parent folders made).
void write_id_pngs(const controller::Framebuffer& ids, const std::string& ids_png,
                   const std::string& view_png);

}  // namespace fb89::experiments
