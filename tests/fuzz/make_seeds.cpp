// Writes the generated seed corpora: stream_reader (streams from the project's StreamWriter,
// whole, cut and corrupted: version 1 under the seeds' first names, version 4 -- checksummed
// batches, send times, depth commands -- as *_v4) and controller (command lists in
// controller_fuzz.cpp's tiny encoding). Run from the source tree after changing the stream format
// or that encoding:
//   cmake --build build --target fb89_fuzz_make_seeds
//   build/tests/fuzz/fb89_fuzz_make_seeds tests/fuzz/corpus
// The other corpora (scene, obj, call_set) are hand-written files.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "protocol/stream_writer.h"
#include "tests/protocol/sample_streams.h"

namespace {

namespace fs = std::filesystem;
using namespace fb89::protocol;

void save(const fs::path& dir, const std::string& name, const std::vector<uint8_t>& bytes) {
    fs::create_directories(dir);
    std::ofstream out(dir / name, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
}

std::vector<uint8_t> encode(const std::vector<Command>& commands, const Properties& props,
                            bool close, Checksums checksums = Checksums::Off) {
    StreamWriter w(props, Timing::Untimed, Commands::Tiling, checksums);
    for (const Command& c : commands)
        w.submit(c);
    if (close) w.close();
    return w.take_bytes();
}

std::vector<uint8_t> cut(const std::vector<uint8_t>& bytes, std::size_t size) {
    return std::vector<uint8_t>(bytes.begin(), bytes.begin() + static_cast<long>(size));
}

void stream_seeds(const fs::path& dir) {
    const Properties props = testing::sample_properties();
    // version 1
    const auto two = encode(testing::two_frames(), props, true);
    save(dir, "two_frames.stream", two);
    save(dir, "two_frames_no_index.stream", encode(testing::two_frames(), props, false));
    save(dir, "every_opcode.stream", encode(testing::every_opcode(), {}, true));
    save(dir, "header_only.stream", encode({}, props, true));
    // cut inside a record, inside the index, inside the footer
    save(dir, "two_frames_cut_record.stream", cut(two, two.size() / 2));
    save(dir, "two_frames_cut_footer.stream", cut(two, two.size() - 7));
    // corruption: an unknown opcode after the header, a wrong index entry
    auto bad_op = two;
    bad_op[encode({}, props, false).size()] = 0x7f;
    save(dir, "two_frames_bad_opcode.stream", bad_op);
    auto bad_index = two;
    bad_index[bad_index.size() - 30] ^= 0x55;
    save(dir, "two_frames_bad_index.stream", bad_index);

    // version 4: batches with their checksums, a timed stream with depth commands
    const auto two4 = encode(testing::two_frames(), props, true, Checksums::On);
    save(dir, "two_frames_v4.stream", two4);
    save(dir, "two_frames_no_index_v4.stream",
         encode(testing::two_frames(), props, false, Checksums::On));
    save(dir, "every_opcode_v4.stream", encode(testing::every_opcode(), {}, true, Checksums::On));
    save(dir, "header_only_v4.stream", encode({}, props, true, Checksums::On));
    const auto mixed = testing::mixed_stream(Checksums::On, 300).bytes;
    save(dir, "timed_depth_v4.stream", mixed);
    save(dir, "timed_depth_cut_batch_v4.stream", cut(mixed, mixed.size() / 2));
    save(dir, "two_frames_cut_footer_v4.stream", cut(two4, two4.size() - 7));
    // damage: a flipped bit in a command, in a BATCH record's length, in the frame index, in
    // the header
    const std::size_t header = encode({}, props, false, Checksums::On).size();
    auto flipped = two4;
    flipped[header + kBatchRecordSize + 20] ^= 0x04;
    save(dir, "two_frames_flipped_command_v4.stream", flipped);
    auto length = two4;
    length[header + 25] ^= 0x10;
    save(dir, "two_frames_flipped_length_v4.stream", length);
    auto index = two4;
    index[index.size() - 30] ^= 0x01;
    save(dir, "two_frames_flipped_index_v4.stream", index);
    auto head = two4;
    head[16] ^= 0x20;  // a letter of the first key: the header fails its checksum
    save(dir, "two_frames_flipped_header_v4.stream", head);
}

void put32(std::vector<uint8_t>& out, uint32_t v) {
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

// controller_fuzz.cpp's encoding: flags byte, then opcode byte % 6 and 32-bit fields.
void controller_seeds(const fs::path& dir) {
    const auto frame = [](std::vector<uint8_t>& o, uint32_t w, uint32_t h) {
        o.push_back(0);
        put32(o, 7);
        put32(o, w);
        put32(o, h);
        o.insert(o.end(), {10, 20, 30});
    };
    const auto fill = [](std::vector<uint8_t>& o, int32_t x, int32_t y, uint32_t w, uint32_t h) {
        o.push_back(1);
        put32(o, static_cast<uint32_t>(x));
        put32(o, static_cast<uint32_t>(y));
        put32(o, w);
        put32(o, h);
        o.insert(o.end(), {255, 0, 0});
    };
    const auto span = [](std::vector<uint8_t>& o, int32_t y, int32_t x0, int32_t x1) {
        o.push_back(2);
        put32(o, static_cast<uint32_t>(y));
        put32(o, static_cast<uint32_t>(x0));
        put32(o, static_cast<uint32_t>(x1));
        o.insert(o.end(), {0, 255, 0});
    };
    std::vector<uint8_t> small = {0};
    frame(small, 16, 12);
    fill(small, 2, 2, 4, 4);
    span(small, 5, 1, 14);
    small.insert(small.end(), {3, 5, 'h', 'e', 'l', 'l', 'o'});
    small.push_back(4);
    save(dir, "small_frame", small);

    std::vector<uint8_t> edges = {1};
    frame(edges, 1024, 780);
    fill(edges, -5, -5, 20, 20);
    fill(edges, INT32_MIN, INT32_MAX, UINT32_MAX, UINT32_MAX);
    fill(edges, 1000, 770, UINT32_MAX, 100);
    span(edges, 779, INT32_MIN, INT32_MAX);
    span(edges, -1, 0, 10);
    span(edges, 3, 10, 2);
    edges.push_back(4);
    save(dir, "large_frame_edges", edges);

    std::vector<uint8_t> unframed = {2};
    fill(unframed, 0, 0, 4, 4);
    span(unframed, 0, 0, 4);
    unframed.push_back(4);
    frame(unframed, 0, 0);
    fill(unframed, 0, 0, 4, 4);
    frame(unframed, 8, 8);  // closes the empty frame as incomplete
    unframed.push_back(5);  // raw-size FRAME_BEGIN, refused
    put32(unframed, 1);
    put32(unframed, 16385);
    put32(unframed, UINT32_MAX);
    unframed.insert(unframed.end(), {0, 0, 0});
    save(dir, "unframed_and_refused", unframed);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s CORPUS_DIR\n", argv[0]);
        return 2;
    }
    const fs::path root = argv[1];
    stream_seeds(root / "stream_reader");
    controller_seeds(root / "controller");
    std::printf("seeds written under %s\n", root.c_str());
    return 0;
}
