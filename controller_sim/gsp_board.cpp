// fb89's board running the executive (see gsp_board.h).
#include "controller_sim/gsp_board.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <variant>

#include <fmt/format.h>

#include "controller_sim/cost_model.h"
#include "controller_sim/gsp_listing_text.h"

namespace fb89::controller::gsp {

ExecutedCounters& ExecutedCounters::operator+=(const ExecutedCounters& o) {
    commands += o.commands;
    instructions += o.instructions;
    states += o.states;
    host_states += o.host_states;
    cache_misses += o.cache_misses;
    cache_miss_states += o.cache_miss_states;
    wraps += o.wraps;
    queue_overlapped += o.queue_overlapped;
    return *this;
}

namespace {

// Where the board keeps things (bit addresses; the executive's own variables are its
// listing's .equ's, from 10000h).
constexpr uint32_t kStackTop = 0x00100000;  // SP, growing down
constexpr uint32_t kRingStart = 0x00100000;
constexpr uint32_t kDepthBase = 0x00400000;  // the listing's ZBASE
// The largest command's words (a FACE of 64 points), which may run past the ring's end.
constexpr uint32_t kLargestCommandWords =
    protocol::kCommandRows[protocol::opcode_index(protocol::Opcode::Face)].port_words +
    4 * protocol::kMaxFacePoints;
// The board's display: 1,024 pixels a line (the pitch is that many pixels' bits).
constexpr uint32_t kDisplayWidth = 1024;

uint32_t label(const Program& p, const std::string& name, std::string_view file) {
    const auto it = p.labels.find(name);
    if (it == p.labels.end())
        throw std::invalid_argument(fmt::format(
            "{}: no label \"{}\": the board starts the executive at `next` and fills its "
            "dispatch `table` with each command's handler (docs/COST_MODEL.md, \"The GSP as "
            "code\")",
            file, name));
    return it->second;
}

uint32_t symbol(const Program& p, const std::string& name, std::string_view file) {
    const auto it = p.symbols.find(name);
    if (it == p.symbols.end())
        throw std::invalid_argument(fmt::format(
            "{}: no symbol \"{}\": the board sets the executive's variables where its .equ's "
            "put them (HOST_WP, FPSHIFT, ZSHIFT, ZPITCH)",
            file, name));
    return static_cast<uint32_t>(it->second);
}

int16_t clamp16(int64_t v) {
    return static_cast<int16_t>(std::clamp<int64_t>(v, INT16_MIN, INT16_MAX));
}

// A span the host's 16-bit words cannot carry: none of its pixels is in a frame.
bool outside16(int32_t x0, int32_t x1, int32_t y) {
    return x0 > x1 || y < INT16_MIN || y > INT16_MAX;
}

void push_long(std::vector<uint16_t>& w, uint32_t v) {
    w.push_back(static_cast<uint16_t>(v));
    w.push_back(static_cast<uint16_t>(v >> 16));
}

}  // namespace

GspBoard::GspBoard(const CostProfile& profile, std::string_view file, std::string_view listing,
                   const GspBoardOptions& options)
    : m_profile(profile), m_file(file), m_program(assemble(file, listing)), m_options(options) {
    if (m_profile.gsp.empty())
        throw std::invalid_argument(fmt::format(
            "profile {} has no listing (\"gsp\"): the board runs the executive a profile with "
            "one names",
            m_profile.name));
    if (m_profile.gsp_chip != Chip::Tms34010)
        throw std::invalid_argument(
            fmt::format("profile {} prices the executive on the {}; the emulated GSP is a TMS34010",
                        m_profile.name, chip_name(m_profile.gsp_chip)));
    if (m_profile.bpp != 8 && m_profile.bpp != 16)
        throw std::invalid_argument(
            fmt::format("profile {}: {} bits a pixel; the board's frame is 8 or 16", m_profile.name,
                        m_profile.bpp));
    if (m_options.ring_words < 2 * kLargestCommandWords ||
        kRingStart + uint64_t{m_options.ring_words + kLargestCommandWords} * 16 > kDepthBase)
        throw std::invalid_argument(fmt::format(
            "a ring of {} words: it must hold {} to {}", m_options.ring_words,
            2 * kLargestCommandWords, (kDepthBase - kRingStart) / 16 - kLargestCommandWords));
    for (std::size_t i = 0; i < m_program.lines.size(); ++i)
        if (!m_program.lines[i].words.empty())
            m_line_at[m_program.lines[i].address] = static_cast<int>(i);

    GspTiming t;
    const uint32_t wait = m_profile.wait_states;
    t.cycle_states = m_profile.memory_cycle_states + wait;
    t.io_cycle_states = m_profile.memory_cycle_states;
    t.pixel_write_states = (m_profile.byte_strobes || m_profile.bpp >= m_profile.bus_bits)
                               ? t.cycle_states
                               : 2 * t.cycle_states;
    t.fill_row = m_profile.c_row;
    t.fill_word = m_profile.c_op;
    t.fill_partial_word = m_profile.c_op_partial;
    t.line_pixel = m_profile.c_line_pix;
    t.line_step = m_profile.c_line_extra;  // [EST] the model's step beyond the memory cycles
    t.cache = m_options.cache;
    m_cpu = std::make_unique<Tms34010>(t);
    Tms34010& cpu = *m_cpu;
    if (m_program.text_bits + m_program.data_bits > 0x10000)
        throw std::invalid_argument(fmt::format(
            "{}: {} bytes; the board loads the executive below its variables at 10000h (8 KB)",
            file, (m_program.text_bits + m_program.data_bits) / 8));
    cpu.load_words(0, m_program.image());

    // the dispatch table, an entry by opcode: each command's handler as its row names it
    // (protocol/command.h), FRAME_BEGIN's and DRAW_SPAN's as the profile chooses
    const uint32_t table = label(m_program, "table", file);
    m_next = label(m_program, "next", file);
    for (const protocol::CommandRow& row : protocol::kCommandRows) {
        if (!row.handler) continue;
        std::string handler = row.handler;
        if (row.opcode == protocol::Opcode::FrameBegin && m_profile.clear_as == ClearAs::Fill)
            handler = "frame_begin_fill";
        if (row.opcode == protocol::Opcode::DrawSpan && m_profile.span_as == SpanAs::Line)
            handler = "span_line";
        cpu.write_field(table + 32 * static_cast<uint32_t>(row.opcode), 32,
                        label(m_program, handler, file));
    }

    // start-up, as the listing's header says: the fields, the frame's pixel size, pitch and
    // offset, the window with clipping on, the depth buffer's word and pitch, the ring
    cpu.set_field(0, 16, false);
    cpu.set_field(1, 32, false);
    cpu.set_io(kPsize, static_cast<uint16_t>(m_profile.bpp));
    cpu.set_io(kControl, 0x00C0);  // W = 3: clip to the window
    cpu.set_io(kDpyctl, 0x9000);   // ENV and SRE: the display on
    cpu.set_reg(1, 4, kVramStart);
    cpu.set_reg(1, 5, 0);
    cpu.set_reg(1, 6, ((kDefaultHeight - 1) << 16) | (kDisplayWidth - 1));
    m_fpshift = symbol(m_program, "FPSHIFT", file);
    m_zpitch = symbol(m_program, "ZPITCH", file);
    cpu.write_field(symbol(m_program, "ZSHIFT", file), 16, m_profile.depth_bits == 32 ? 1 : 0);
    set_pitch(kDisplayWidth);
    m_host_wp = symbol(m_program, "HOST_WP", file);
    m_ring_start = kRingStart;
    m_ring_end = kRingStart + m_options.ring_words * 16;
    m_write = m_ring_start;
    cpu.write_field(m_host_wp, 32, m_write);
    cpu.set_reg(0, 0, m_ring_start);
    cpu.set_reg(0, 1, m_ring_start);
    cpu.set_reg(0, 2, m_ring_end);
    cpu.set_reg(0, 3, m_ring_start);
    cpu.set_reg(0, 4, table);
    cpu.set_reg(0, 15, kStackTop);
    cpu.set_pc(m_next);
    cpu.reset_counters();
}

// The display's pitch for frames `width` wide: the width rounded up to a power of two (as
// the cost model's), in DPTCH, CONVDP and the listing's FPSHIFT, and the depth buffer's row
// (ZPITCH) likewise; the host's driver sets it as it sets a display mode, before a frame of
// another width, outside the commands' cycles.
void GspBoard::set_pitch(uint32_t width) {
    Tms34010& cpu = *m_cpu;
    const uint32_t pixels = std::bit_ceil(width);
    m_pitch_bits = pixels * m_profile.bpp;
    cpu.set_reg(1, 3, m_pitch_bits);
    cpu.set_io(kConvdp, static_cast<uint16_t>(std::countl_zero(m_pitch_bits)));
    cpu.write_field(m_fpshift, 16, static_cast<uint32_t>(std::countr_zero(m_pitch_bits)));
    cpu.write_field(m_zpitch, 16,
                    static_cast<uint32_t>(std::countr_zero(pixels * m_profile.depth_bits)));
}

uint16_t GspBoard::colour_word(protocol::Rgb c) {
    const uint32_t key = (uint32_t{c.r} << 16) | (uint32_t{c.g} << 8) | c.b;
    auto it = m_index.find(key);
    if (it == m_index.end()) {
        const uint64_t room = uint64_t{1} << m_profile.bpp;
        if (m_palette.size() >= room)
            throw std::invalid_argument(fmt::format(
                "command {}: colour {}: the stream has more colours than a {}-bit pixel holds "
                "({}); the board draws palette indices: replay it with a profile of 16-bit "
                "pixels (controller_sim/profiles/variants/tms34010-50mhz-16bpp.json)",
                m_number, protocol::to_string(c), m_profile.bpp, room));
        it = m_index.emplace(key, static_cast<uint16_t>(m_palette.size())).first;
        m_palette.push_back(c);
    }
    const uint16_t i = it->second;
    return m_profile.bpp == 8 ? static_cast<uint16_t>(i | (i << 8)) : i;
}

namespace {

// A command as the host's 16-bit words can carry it: its coordinates cut so as to keep every
// pixel of the frame it covers (a rectangle to what the words hold; a span's columns in their
// order, a row beyond their reach above or below the frame, Z stepped to the first column the
// words hold; a FACE's reference pixel moved to one they hold, Z with it).
template <class C>
C port_form(const C& c) {
    using namespace protocol;
    if constexpr (std::is_same_v<C, FillRect>) {
        const int16_t x0 = clamp16(c.x), y0 = clamp16(c.y);
        const int64_t x1 = clamp16(int64_t{c.x} + c.w), y1 = clamp16(int64_t{c.y} + c.h);
        return FillRect{x0, y0, static_cast<uint32_t>(std::max<int64_t>(0, x1 - x0)),
                        static_cast<uint32_t>(std::max<int64_t>(0, y1 - y0)), c.color};
    } else if constexpr (std::is_same_v<C, DrawSpan>) {
        const bool none = outside16(c.x0, c.x1, c.y);
        return DrawSpan{none ? -1 : c.y, clamp16(c.x0), clamp16(c.x1), c.color};
    } else if constexpr (std::is_same_v<C, DepthSpan>) {
        uint32_t z = c.z;
        if (c.x0 < INT16_MIN)
            z += static_cast<uint32_t>(c.dz) * static_cast<uint32_t>(INT16_MIN - c.x0);
        return DepthSpan{clamp16(c.y), clamp16(c.x0), clamp16(c.x1), z, c.dz, c.color};
    } else if constexpr (std::is_same_v<C, Face>) {
        Face f = c;
        f.x_ref = clamp16(c.x_ref);
        f.y_ref = clamp16(c.y_ref);
        f.z = c.z +
              static_cast<uint32_t>(c.dzdx) * static_cast<uint32_t>(int64_t{f.x_ref} - c.x_ref) +
              static_cast<uint32_t>(c.dzdy) * static_cast<uint32_t>(int64_t{f.y_ref} - c.y_ref);
        return f;
    } else {
        return c;
    }
}

}  // namespace

// The opcode's word, then the words the command's row lays out (protocol/command.h), then a
// FACE's points.
std::vector<uint16_t> GspBoard::words_of(const protocol::Command& command) {
    using namespace protocol;
    if (const auto* c = std::get_if<FrameBegin>(&command)) {
        const uint64_t rows = kVramBits / (uint64_t{std::bit_ceil(c->width)} * m_profile.bpp);
        if (c->width == 0 || c->height == 0 || c->width > kDisplayWidth || c->height > rows)
            throw std::invalid_argument(fmt::format(
                "command {}: {}: the board's frame is 1 to {} pixels wide and 1 to {} rows at "
                "this width (its VRAM at {} bits a pixel)",
                m_number, to_string(command), kDisplayWidth, rows, m_profile.bpp));
        if (std::bit_ceil(c->width) * m_profile.bpp != m_pitch_bits) m_mode_width = c->width;
        m_width = c->width;
        m_height = c->height;
    }
    std::vector<uint16_t> w;
    std::visit(
        [&](const auto& original) {
            using C = std::decay_t<decltype(original)>;
            using I = CommandInfo<C>;
            if constexpr (I::handler != nullptr) {
                const C c = port_form(original);
                w.push_back(static_cast<uint16_t>(I::opcode));
                for (const PortWord& pw : I::port) {
                    uint32_t v = 0;
                    if constexpr (I::tail == Tail::Points)
                        if (pw.field == kPortCount) v = static_cast<uint32_t>(c.points.size());
                    int index = 0;
                    for_each_field(c, [&](const auto& value, const auto&) {
                        if (index++ != pw.field) return;
                        if constexpr (std::is_same_v<std::decay_t<decltype(value)>, Rgb>)
                            v = colour_word(value);
                        else
                            v = static_cast<uint32_t>(value);
                    });
                    if (pw.form == PortForm::Long)
                        push_long(w, v);
                    else
                        w.push_back(static_cast<uint16_t>(v));
                }
                if constexpr (I::tail == Tail::Points)
                    for (const SnappedPoint& p : c.points) {
                        push_long(w, static_cast<uint32_t>(p.x));
                        push_long(w, static_cast<uint32_t>(p.y));
                    }
            }
        },
        command);
    return w;
}

void GspBoard::execute(std::span<const protocol::Command> commands) {
    uint64_t batch = 0;  // words written since the executive last caught up
    const uint64_t room = m_options.ring_words - kLargestCommandWords;
    for (const protocol::Command& c : commands) {
        std::vector<uint16_t> w = words_of(c);
        const uint64_t number = m_number++;
        if (w.empty()) continue;
        if (batch + w.size() > room || m_mode_width) {
            run();  // (a mode set waits for the frame before it)
            batch = 0;
        }
        if (m_mode_width) {
            set_pitch(m_mode_width);
            m_mode_width = 0;
        }
        if (m_write >= m_ring_end) m_write = m_ring_start;  // the host wraps between commands
        m_cpu->load_words(m_write, w);
        m_write += static_cast<uint32_t>(w.size()) * 16;
        batch += w.size();
        m_pending.push_back(
            Pending{protocol::opcode_of(c), number, static_cast<uint32_t>(w.size())});
        if (m_options.trace && *m_options.trace == number) {
            run();  // traced alone
            batch = 0;
        }
    }
    run();
}

std::string GspBoard::where(uint32_t address) const {
    auto it = m_line_at.upper_bound(address);
    if (it == m_line_at.begin()) return fmt::format("{:08X}h", address);
    --it;
    const AssembledLine& l = m_program.lines[static_cast<std::size_t>(it->second)];
    if (address >= l.address + 16 * l.words.size()) return fmt::format("{:08X}h", address);
    return fmt::format("{} line {}: {}", m_file, l.line, listing_text::trim(l.text));
}

void GspBoard::run() {
    Tms34010& cpu = *m_cpu;
    cpu.write_field(m_host_wp, 32, m_write);  // HOST_WP: the host's write pointer
    enum class Segment { None, Poll, Command };
    Segment segment = Segment::None;
    const Pending* current = nullptr;
    GspCounters before = cpu.counters();
    // the write queue at the segment's start, and what of it the loop overlapped before its
    // first memory access
    uint64_t queue_at_start = cpu.queued_states();
    uint64_t warm_queue_at_start = cpu.warm_queued_states();
    uint64_t overlap_at_start = before.queue_overlap_states;
    uint64_t overlapped = 0;
    bool memory_seen = false;
    uint64_t steps = 0;
    bool tracing = false;
    bool wrapped = false;
    const auto close = [&]() {
        const GspCounters& now = cpu.counters();
        if (!memory_seen) overlapped = now.queue_overlap_states - overlap_at_start;
        ExecutedCounters e;
        e.instructions = now.instructions - before.instructions;
        // a segment is charged the queue it leaves, not the one it found (the model's rule)
        e.states = now.states - before.states + cpu.queued_states() - queue_at_start;
        const uint64_t warm =
            now.warm_states - before.warm_states + cpu.warm_queued_states() - warm_queue_at_start;
        e.cache_misses = now.cache_misses - before.cache_misses;
        e.cache_miss_states = e.states - warm;  // what the cache's misses added, waits too
        e.queue_overlapped = overlapped;
        if (segment == Segment::Poll) {
            m_polls += e;
            m_polls.commands += 1;
        } else if (segment == Segment::Command) {
            e.commands = 1;
            e.host_states = uint64_t{current->words} * m_profile.c_host_word;
            e.wraps = wrapped ? 1 : 0;
            m_executed[static_cast<std::size_t>(protocol::opcode_index(current->op))] += e;
        } else {
            m_polls.queue_overlapped += e.queue_overlapped;  // (none: only at a run's start)
            m_polls.states += e.states;
        }
        before = now;
        queue_at_start = cpu.queued_states();
        warm_queue_at_start = cpu.warm_queued_states();
        overlap_at_start = now.queue_overlap_states;
        overlapped = 0;
        memory_seen = false;
    };
    try {
        for (;;) {
            if (cpu.pc() == m_next) {
                close();
                const uint32_t a0 = cpu.reg(0, 0), a1 = cpu.reg(0, 1);
                steps = 0;
                tracing = false;
                if (a0 == m_write) {
                    segment = Segment::None;
                    break;
                }
                if (a0 == a1) {
                    segment = Segment::Poll;
                } else {
                    if (m_pending_next >= m_pending.size())
                        throw GspFault(cpu.pc(), "the executive reads past what the host wrote");
                    current = &m_pending[m_pending_next++];
                    segment = Segment::Command;
                    wrapped = a0 >= cpu.reg(0, 2);
                    tracing = m_options.trace && *m_options.trace == current->number;
                }
            }
            if (memory_seen && !tracing && steps < m_options.budget) {
                // nothing to look at after each instruction until `next`: the CPU's own loop
                steps += cpu.run_until(m_next, m_options.budget - steps);
                continue;
            }
            const uint32_t at = cpu.pc();
            const uint32_t states = cpu.step();
            if (!memory_seen && cpu.touched_memory()) {
                memory_seen = true;
                overlapped = cpu.counters().queue_overlap_states - overlap_at_start;
            }
            if (tracing) {
                TracedInstruction t{at, states, 0, ""};
                auto it = m_line_at.find(at);
                if (it != m_line_at.end()) {
                    const AssembledLine& l = m_program.lines[static_cast<std::size_t>(it->second)];
                    t.line = l.line;
                    t.text = l.text;
                }
                m_trace.push_back(std::move(t));
            }
            if (++steps > m_options.budget)
                throw GspFault(at, fmt::format("{} instructions in one command without returning "
                                               "to `next`: a loop that does not end?",
                                               m_options.budget));
        }
    } catch (const GspFault& f) {
        throw GspFault(f.pc(),
                       fmt::format("{} ({}{})", f.what(), where(f.pc()),
                                   current ? fmt::format(", command {}", current->number) : ""));
    }
    m_pending.clear();
    m_pending_next = 0;
}

Framebuffer GspBoard::frame() const {
    Framebuffer fb(m_width, m_height);
    const uint32_t offset = (m_cpu->reg(1, 4) - kVramStart) / 8, pitch = m_pitch_bits / 8;
    const std::span<const uint8_t> vram = m_cpu->vram();
    for (uint32_t y = 0; y < m_height; ++y)
        for (uint32_t x = 0; x < m_width; ++x) {
            const std::size_t at = offset + std::size_t{y} * pitch + x * (m_profile.bpp / 8);
            const uint32_t i =
                m_profile.bpp == 8 ? vram[at] : uint32_t{vram[at]} | (uint32_t{vram[at + 1]} << 8);
            fb.set_pixel(x, y, i < m_palette.size() ? m_palette[i] : protocol::Rgb{255, 0, 255});
        }
    return fb;
}

ExecutedCounters GspBoard::total() const {
    ExecutedCounters t;
    for (const ExecutedCounters& e : m_executed)
        t += e;
    return t;
}

}  // namespace fb89::controller::gsp
