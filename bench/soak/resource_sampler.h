// What a long-running process holds, read from /proc: its resident set (VmRSS of
// /proc/PID/status) and its open file descriptors (the entries of /proc/PID/fd), sampled
// every so many cycles (the slope of the resident set is in rss_slope.h).
#pragma once

#include <sys/types.h>

#include "bench/soak/rss_slope.h"

namespace fb89::soak {

// For `pid` (0: this process, then also after malloc_trim(0)). Throws std::runtime_error
// when the process is gone.
ResourceSample sample_process(pid_t pid, int cycle);

// Whether `pid` is asleep in poll(2): state S in /proc/PID/stat and a wait channel
// (/proc/PID/wchan) naming a poll function. The controller between hosts is, waiting in
// its accept loop for the next; false when the process is gone.
bool asleep_in_poll(pid_t pid);

// Whether cycle `done` (1-based) is one to sample after: the first, every `every`-th, the last.
bool is_sample_point(int done, int every, int last);

}  // namespace fb89::soak
