// The default transport: commands kept in memory in order, so host hidden-surface time
// can be measured without an encoder or a controller in the loop.
#pragma once

#include <vector>

#include "protocol/command_sink.h"

namespace fb89::protocol {

class MemoryBuffer final : public CommandSink {
  public:
    void frame_begin(const FrameBegin& c) override { m_commands.emplace_back(c); }
    void fill_rect(const FillRect& c) override { m_commands.emplace_back(c); }
    void draw_span(const DrawSpan& c) override { m_commands.emplace_back(c); }
    void marker(const Marker& c) override { m_commands.emplace_back(c); }
    void frame_end(const FrameEnd& c) override { m_commands.emplace_back(c); }

    const std::vector<Command>& commands() const { return m_commands; }
    std::size_t size() const { return m_commands.size(); }
    void clear() { m_commands.clear(); }
    void reserve(std::size_t n) { m_commands.reserve(n); }

    // Sends every command, in order, to another sink (an encoder or the controller).
    void replay_into(CommandSink& sink) const;

  private:
    std::vector<Command> m_commands;
};

}  // namespace fb89::protocol
