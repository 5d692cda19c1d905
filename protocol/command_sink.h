// Where a host renderer sends its commands. The host never sees what is behind a sink:
// an in-memory buffer, a stream file, a socket, or the controller itself.
#pragma once

#include "protocol/command.h"

namespace fb89::protocol {

class CommandSink {
  public:
    virtual ~CommandSink() = default;
    // A call a command. Each defaults to take() (command_sink.cpp), so that a sink that treats
    // every command alike (a buffer, a writer) overrides take() alone, and a new command needs no
    // call of its own in such sinks.
    virtual void frame_begin(const FrameBegin& c);
    virtual void fill_rect(const FillRect& c);
    virtual void draw_span(const DrawSpan& c);
    virtual void marker(const Marker& c);
    virtual void frame_end(const FrameEnd& c);
    // version 3's depth commands
    virtual void depth_clear(const DepthClear& c);
    virtual void depth_span(const DepthSpan& c);
    virtual void face(const Face& c);
    // What the sink does with a command it has no call of its own for. This default refuses
    // it: a sink that cannot take depth commands (a tiling-only controller path, a version-1
    // writer) says so by throwing std::invalid_argument naming the command.
    virtual void take(const Command& c);

    // Dispatches a decoded command to the matching call.
    void submit(const Command& c);
};

}  // namespace fb89::protocol
