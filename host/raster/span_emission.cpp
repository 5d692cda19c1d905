#include "host/raster/span_emission.h"

namespace fb89::host {

namespace {
uint32_t packed(protocol::Rgb c) { return (uint32_t{c.r} << 16) | (uint32_t{c.g} << 8) | c.b; }
}  // namespace

uint64_t emit_row_spans(const ScreenScene& scene, const uint32_t* row, int y, int x0, int x1,
                        protocol::CommandSink& sink) {
    uint64_t spans = 0;
    int x = x0;
    while (x < x1) {
        // skip background
        while (x < x1 && row[x] == 0) ++x;
        if (x == x1) break;
        // extend the run while the colour stays the same (faces may share a colour)
        uint32_t face = row[x];
        const protocol::Rgb color = scene.faces[face - 1].color;
        const uint32_t key = packed(color);
        int start = x;
        while (x < x1 && row[x] != 0 &&
               (row[x] == face || packed(scene.faces[row[x] - 1].color) == key)) {
            ++x;
        }
        sink.draw_span({y, start, x - 1, color});
        ++spans;
    }
    return spans;
}

}  // namespace fb89::host
