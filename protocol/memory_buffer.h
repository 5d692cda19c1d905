// The default transport: commands kept in memory in order, so host hidden-surface time
// can be measured without an encoder or a controller in the loop.
//
// Send times (the pipeline in time, controller_sim/timed_pipeline.h): with time_packets(n)
// on, the buffer reads the steady clock each time n more commands have come, and at every
// FRAME_END. The host sends its commands in packets, as a TIGA host fills a communication
// buffer and hands it over, so each command is sent when its packet is: the reading that
// closes it. A clock read per command would cost more than the commands (10-25 ns each);
// one per packet of 64 costs well under 1 ns a command.
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

#include "protocol/command_sink.h"

namespace fb89::protocol {

// The host's packet: 64 commands, about 700 bytes at the TMS34010 profile's 10-12 bytes a
// command (TIGA hosts hand over communication buffers of a few hundred bytes to a few KB).
inline constexpr uint32_t kSendPacketCommands = 64;

class MemoryBuffer final : public CommandSink {
  public:
    void take(const Command& c) override { add(c); }
    void frame_end(const FrameEnd& c) override {
        m_commands.emplace_back(c);
        if (m_packet) stamp();
    }

    const std::vector<Command>& commands() const { return m_commands; }
    std::size_t size() const { return m_commands.size(); }
    void clear() {
        m_commands.clear();
        m_stamps.clear();
        m_unstamped = 0;
    }
    void reserve(std::size_t n) { m_commands.reserve(n); }

    // Sends every command, in order, to another sink (an encoder or the controller).
    void replay_into(CommandSink& sink) const;

    // Reads the clock every `commands_per_packet` commands (0: never) from now on, times
    // counted from now.
    void time_packets(uint32_t commands_per_packet);
    // Instead of reading the clock, calls `hook` with the commands sent so far each time a
    // packet closes (on a 1989 host the guest marks its sends so: period/guest). Its
    // send_times_us() are then empty.
    using PacketHook = void (*)(uint64_t commands_sent);
    void mark_packets(uint32_t commands_per_packet, PacketHook hook) {
        time_packets(commands_per_packet);
        m_hook = hook;
    }
    bool timed() const { return m_packet > 0; }
    // Each command's send time in microseconds from time_packets(): its packet's reading.
    // Commands after the last reading (a frame not yet ended) take a reading now. Empty when
    // not timed.
    std::vector<double> send_times_us();

  private:
    template <class C>
    void add(const C& c) {
        m_commands.emplace_back(c);
        if (m_packet && ++m_unstamped == m_packet) stamp();
    }
    void stamp() {
        m_unstamped = 0;
        if (m_hook) return m_hook(m_commands.size());
        m_stamps.push_back({m_commands.size(), std::chrono::steady_clock::now()});
    }

    struct Stamp {
        std::size_t end;  // the commands before it were sent by then
        std::chrono::steady_clock::time_point at;
    };
    std::vector<Command> m_commands;
    uint32_t m_packet = 0, m_unstamped = 0;
    std::chrono::steady_clock::time_point m_origin{};
    std::vector<Stamp> m_stamps;
    PacketHook m_hook = nullptr;
};

}  // namespace fb89::protocol
