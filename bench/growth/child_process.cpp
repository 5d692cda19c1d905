#include "bench/growth/child_process.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <exception>
#include <stdexcept>

#include <fmt/format.h>

namespace fb89::growth {

namespace {

// Writes all of `text` to `fd`; false when the pipe broke.
bool write_all(int fd, const std::string& text) {
    size_t done = 0;
    while (done < text.size()) {
        ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<size_t>(n);
    }
    return true;
}

std::string read_all(int fd) {
    std::string text;
    char block[65536];
    for (;;) {
        ssize_t n = ::read(fd, block, sizeof block);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        text.append(block, static_cast<size_t>(n));
    }
    return text;
}

// In the child: run the work, hand its text over, and leave without running the parent's
// destructors or flushing its buffers a second time.
[[noreturn]] void child_main(int fd, const std::function<std::string()>& work, unsigned timeout_s) {
    if (timeout_s > 0) ::alarm(timeout_s);
    int status = 0;
    std::string text;
    try {
        text = work();
    } catch (const std::exception& e) {
        text = e.what();
        status = 3;
    } catch (...) {
        text = "unknown exception";
        status = 3;
    }
    if (!write_all(fd, text)) status = 4;
    ::close(fd);
    ::_exit(status);
}

std::string describe(int status, unsigned timeout_s) {
    if (WIFEXITED(status)) return fmt::format("exit status {}", WEXITSTATUS(status));
    if (!WIFSIGNALED(status)) return "stopped";
    const int sig = WTERMSIG(status);
    if (sig == SIGALRM) return fmt::format("timed out after {} s", timeout_s);
    if (sig == SIGKILL) return "killed by signal 9 (out of memory?)";
    return fmt::format("killed by signal {} ({})", sig, ::strsignal(sig));
}

}  // namespace

ChildOutcome run_in_child(const std::function<std::string()>& work, unsigned timeout_s) {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error(fmt::format("pipe: {}", std::strerror(errno)));
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error(fmt::format("fork: {}", std::strerror(errno)));
    if (pid == 0) {
        ::close(fds[0]);
        child_main(fds[1], work, timeout_s);
    }
    ::close(fds[1]);
    ChildOutcome outcome;
    outcome.output = read_all(fds[0]);
    ::close(fds[0]);

    // collect: the child's own rusage, not the sum over all children
    int status = 0;
    struct rusage usage {};
    while (::wait4(pid, &status, 0, &usage) < 0)
        if (errno != EINTR)
            throw std::runtime_error(fmt::format("wait4: {}", std::strerror(errno)));
    outcome.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (!outcome.ok) outcome.failure = describe(status, timeout_s);
    outcome.peak_rss = static_cast<uint64_t>(usage.ru_maxrss) * 1024;  // Linux: kilobytes
    return outcome;
}

uint64_t baseline_peak_rss() {
    return run_in_child([] { return std::string(); }, 0).peak_rss;
}

}  // namespace fb89::growth
