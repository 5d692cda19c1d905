// Fuzz target: controller::Controller executing decoded commands. The bytes are a tiny
// encoding of our own (not the stream format, so every byte string is a command list):
//   byte 0: bit 0 picks the framebuffer range (0: sides up to 64, 1: up to 1024), bits 1..
//           pick a built-in cost profile;
//   then per command an opcode byte (its value % 6) and little-endian 32-bit fields, missing
//   bytes reading as 0: 0 FRAME_BEGIN frame w h rgb, 1 FILL_RECT x y w h rgb,
//   2 DRAW_SPAN y x0 x1 rgb, 3 MARKER (length byte, text), 4 FRAME_END, 5 FRAME_BEGIN with
//   w and h exactly as read (mostly beyond kMaxFrameSide: must throw std::invalid_argument).
// Positions, spans and rectangle sizes are taken as read, huge and negative included;
// FRAME_BEGIN sides are folded into the chosen range so that one input stays fast. At most
// kMaxCommands commands per input. Nothing may write outside the framebuffer (ASan), and
// the counters must stay consistent with the framebuffer's size.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "controller_sim/controller.h"
#include "controller_sim/profile.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using fb89::fuzz::finding;
namespace protocol = fb89::protocol;
namespace controller = fb89::controller;

constexpr int kMaxCommands = 256;

class Bytes {
  public:
    Bytes(const uint8_t* data, size_t size) : m_data(data), m_size(size) {}
    bool done() const { return m_pos >= m_size; }
    uint8_t u8() { return m_pos < m_size ? m_data[m_pos++] : 0; }
    uint32_t u32() {
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i)
            v |= uint32_t{u8()} << (8 * i);
        return v;
    }
    int32_t i32() {
        const uint32_t u = u32();
        int32_t v;
        std::memcpy(&v, &u, sizeof v);
        return v;
    }
    protocol::Rgb rgb() { return {u8(), u8(), u8()}; }

  private:
    const uint8_t* m_data;
    size_t m_size;
    size_t m_pos = 0;
};

protocol::Command decode(Bytes& in, uint32_t max_side, bool& raw_size) {
    raw_size = false;
    switch (in.u8() % 6) {
        case 0:
            return protocol::FrameBegin{in.u32(), in.u32() % (max_side + 1),
                                        in.u32() % (max_side + 1), in.rgb()};
        case 1:
            return protocol::FillRect{in.i32(), in.i32(), in.u32(), in.u32(), in.rgb()};
        case 2:
            return protocol::DrawSpan{in.i32(), in.i32(), in.i32(), in.rgb()};
        case 3: {
            protocol::Marker m;
            const uint8_t n = in.u8();
            for (uint8_t i = 0; i < n && !in.done(); ++i)
                m.text.push_back(static_cast<char>(in.u8()));
            return m;
        }
        case 4:
            return protocol::FrameEnd{};
        default: {
            raw_size = true;
            protocol::FrameBegin f{in.u32(), in.u32(), in.u32(), in.rgb()};
            // Keep a raw size only when it is refused, so no input allocates a 16384^2 frame.
            if (f.width <= controller::kMaxFrameSide && f.height <= controller::kMaxFrameSide)
                f.width = f.height = 1;
            return f;
        }
    }
}

// After each command: storage matches the size.
void check_storage(const controller::Controller& c) {
    const controller::Framebuffer& fb = c.framebuffer();
    if (fb.pixels().size() != std::size_t{fb.width()} * fb.height() * 3)
        finding("framebuffer storage does not match its size");
}

// At the end (open_frame() takes a checksum, too slow for every command): the counters.
void check_frame(const controller::Controller& c) {
    if (!c.in_frame()) return;
    const controller::Framebuffer& fb = c.framebuffer();
    const controller::FrameResult f = c.open_frame();
    if (f.width != fb.width() || f.height != fb.height()) finding("frame size != framebuffer");
    const uint64_t area = uint64_t{f.width} * f.height;
    for (const auto& op : f.ops)
        if (op.pixels > area * std::max<uint64_t>(op.commands, 1))
            finding("an opcode wrote more pixels than its commands could");
    if (!std::isfinite(c.elapsed_us())) finding("elapsed time is not finite");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Bytes in(data, size);
    const uint8_t flags = in.u8();
    const uint32_t max_side = (flags & 1) ? 1024 : 64;
    const auto profiles = controller::builtin_profiles();
    const auto& profile = profiles[(flags >> 1) % profiles.size()];
    controller::Controller ctl(controller::load_profile(profile.name));

    for (int n = 0; n < kMaxCommands && !in.done(); ++n) {
        bool raw_size = false;
        const protocol::Command cmd = decode(in, max_side, raw_size);
        try {
            if (n % 2) {
                ctl.execute(cmd);
            } else {
                ctl.submit(cmd);  // through the CommandSink calls
            }
        } catch (const std::invalid_argument&) {
            if (!raw_size) finding("std::invalid_argument for a command within the limits");
            continue;
        }
        check_storage(ctl);
    }
    check_frame(ctl);
    (void)ctl.stats().to_json().dump();
    (void)ctl.stats().summary();
    return 0;
}
