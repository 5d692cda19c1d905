// Where a host renderer sends its commands. The host never sees what is behind a sink:
// an in-memory buffer, a stream file, a socket, or the controller itself.
#pragma once

#include "protocol/command.h"

namespace fb89::protocol {

class CommandSink {
  public:
    virtual ~CommandSink() = default;
    virtual void frame_begin(const FrameBegin& c) = 0;
    virtual void fill_rect(const FillRect& c) = 0;
    virtual void draw_span(const DrawSpan& c) = 0;
    virtual void marker(const Marker& c) = 0;
    virtual void frame_end(const FrameEnd& c) = 0;
    // Version 3's depth commands. A sink that cannot take them (a tiling-only controller
    // path, a version-1 writer) says so by throwing; these defaults throw
    // std::invalid_argument naming the command.
    virtual void depth_clear(const DepthClear& c);
    virtual void depth_span(const DepthSpan& c);
    virtual void face(const Face& c);

    // Dispatches a decoded command to the matching call.
    void submit(const Command& c);
};

}  // namespace fb89::protocol
