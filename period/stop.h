// Stopping long work from outside it: the Python module asks for a stop when Ctrl-C comes
// while fb89 works without the GIL, or when a progress callback raises. Emulated runs look
// every 50 ms and end their emulator; the experiments' loops look between rounds and runs.
// Work that stops throws Stopped, which is on purpose not a std::exception: no handler of
// errors mistakes it for one, and it reaches the caller that asked.
#pragma once

#include <atomic>

namespace fb89::period {

struct Stopped {};

namespace detail {
inline std::atomic<bool> stop_flag{false};
}

inline void request_stop() noexcept {
    detail::stop_flag.store(true, std::memory_order_relaxed);
}
inline void clear_stop() noexcept {
    detail::stop_flag.store(false, std::memory_order_relaxed);
}
inline bool stop_requested() noexcept {
    return detail::stop_flag.load(std::memory_order_relaxed);
}
inline void throw_if_stopped() {
    if (stop_requested()) throw Stopped{};
}

}  // namespace fb89::period
