// Running one piece of work in a child process of its own, so that its peak memory is its
// own: the growth benchmark (bench/growth) forks once per scene and method, and the kernel's
// high-water mark of the child's resident set (wait4's ru_maxrss) is that run's peak. The
// child hands back one text (JSON) through a pipe; nothing it allocates outlives it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace fb89::growth {

struct ChildOutcome {
    bool ok = false;        // exited with status 0
    std::string output;     // what the work returned (or, on failure, the error's text)
    std::string failure;    // "exit status 3", "killed by signal 9 (out of memory?)", ...
    uint64_t peak_rss = 0;  // bytes, the child's high-water resident set
};

// Forks; the child runs `work` and exits, the parent waits and collects. An exception in the
// child is its failure, with the exception's text. With `timeout_s` > 0 the child is killed
// (SIGALRM) when it runs longer.
ChildOutcome run_in_child(const std::function<std::string()>& work, unsigned timeout_s);

// The peak resident set of a child that does nothing: what every child starts with.
uint64_t baseline_peak_rss();

}  // namespace fb89::growth
