// The Z-buffer's span emission: the same spans, in the same order, as emit_row_spans()
// (span_emission.h), on rows of short and long runs, background gaps and adjacent faces of
// one colour; the row zeroed and nothing outside it touched.
#include "host/raster/band_spans.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "host/raster/span_emission.h"
#include "protocol/memory_buffer.h"

namespace fb89::host {
namespace {

// Faces whose colours repeat, so that adjacent faces often share one.
ScreenScene faces_of_few_colors(uint32_t count, uint32_t colors) {
    ScreenScene scene;
    scene.faces.resize(count);
    for (uint32_t i = 0; i < count; ++i)
        scene.faces[i].color = {static_cast<uint8_t>(i % colors), 0x40, 0x80};
    return scene;
}

std::vector<uint32_t> color_table(const ScreenScene& scene) {
    std::vector<uint32_t> table;
    for (const ScreenFace& f : scene.faces)
        table.push_back(packed_color(f.color));
    return table;
}

// A row of runs of random length (1 to max_run entries), a third of them background.
std::vector<uint32_t> random_row(std::mt19937& rng, int width, int max_run, uint32_t faces) {
    std::vector<uint32_t> row;
    while (static_cast<int>(row.size()) < width) {
        const auto face = static_cast<uint32_t>(rng() % 3 == 0 ? 0 : 1 + rng() % faces);
        row.insert(row.end(), 1 + rng() % static_cast<uint32_t>(max_run), face);
    }
    row.resize(static_cast<size_t>(width));
    return row;
}

TEST(BandSpans, SendsTheSpansOfEmitRowSpansInTheSameOrder) {
    const ScreenScene scene = faces_of_few_colors(12, 4);
    const std::vector<uint32_t> colors = color_table(scene);
    std::mt19937 rng(7);
    for (int trial = 0; trial < 400; ++trial) {
        const int width = 1 + trial % 45;
        const int max_run = trial % 3 == 0 ? 2 : trial % 3 == 1 ? 6 : 30;
        std::vector<uint32_t> row = random_row(rng, width, max_run, 12);
        const int x0 = trial % 5 == 0 ? 0 : static_cast<int>(rng() % static_cast<uint32_t>(width));
        const int x1 = x0 + static_cast<int>(rng() % static_cast<uint32_t>(width - x0 + 1));
        protocol::MemoryBuffer expected, got;
        const uint64_t expected_spans = emit_row_spans(scene, row.data(), 3, x0, x1, expected);
        row.push_back(0xDEAD);  // the entry after the row, which is read and not changed
        const uint64_t spans = emit_band_row(row.data(), 3, x0, x1, colors.data(), got);
        ASSERT_EQ(spans, expected_spans) << "trial " << trial;
        ASSERT_EQ(got.commands(), expected.commands()) << "trial " << trial;
        for (int x = x0; x < x1; ++x)
            ASSERT_EQ(row[static_cast<size_t>(x)], 0u) << "trial " << trial << " x " << x;
        EXPECT_EQ(row.back(), 0xDEADu);
    }
}

TEST(BandSpans, LeavesEntriesOutsideTheWindowAlone) {
    const ScreenScene scene = faces_of_few_colors(3, 3);
    const std::vector<uint32_t> colors = color_table(scene);
    std::vector<uint32_t> row = {1, 1, 2, 2, 2, 2, 2, 2, 2, 2, 2, 3, 3, 0, 1, 1, 2, 2};
    protocol::MemoryBuffer got;
    // x 2..14: face 2 for 9 pixels, face 3 for 2, a background gap, then face 1
    EXPECT_EQ(emit_band_row(row.data(), 0, 2, 15, colors.data(), got), 3u);
    const std::vector<uint32_t> left = {1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 2};
    EXPECT_EQ(row, left);
    ASSERT_EQ(got.size(), 3u);
    EXPECT_EQ(std::get<protocol::DrawSpan>(got.commands()[0]).x0, 2);
    EXPECT_EQ(std::get<protocol::DrawSpan>(got.commands()[0]).x1, 10);
    EXPECT_EQ(std::get<protocol::DrawSpan>(got.commands()[2]).x0, 14);
    EXPECT_EQ(std::get<protocol::DrawSpan>(got.commands()[2]).x1, 14);
}

}  // namespace
}  // namespace fb89::host
