// Running fb89 as a child process: in a given folder, stdin from /dev/null, stdout and
// stderr into files, no descriptor of ours inherited; waited for with a bound and killed
// past it. A child still running when its handle goes is killed and reaped: no zombie, no
// orphan.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fb89::soak {

// What wait() returns for a child that outlived its bound (it is then killed).
inline constexpr int kTimedOut = -1000;

class ChildProcess {
  public:
    ChildProcess() = default;
    ChildProcess(ChildProcess&& o) noexcept : m_pid(o.m_pid) { o.m_pid = -1; }
    ChildProcess& operator=(ChildProcess&& o) noexcept;
    ~ChildProcess();

    pid_t pid() const { return m_pid; }
    bool running() const { return m_pid > 0; }
    // The exit code, minus the signal that killed it, or kTimedOut.
    int wait(std::chrono::milliseconds bound);
    // The exit code if it has ended (it is then reaped), else nothing; never kills.
    std::optional<int> try_wait();

    // argv[0] is the executable's path. Throws std::runtime_error when fork fails.
    static ChildProcess spawn(const std::vector<std::string>& argv,
                              const std::filesystem::path& cwd, const std::filesystem::path& out,
                              const std::filesystem::path& err);

  private:
    explicit ChildProcess(pid_t pid) : m_pid(pid) {}
    pid_t m_pid = -1;
};

// Spawns and waits: the exit code as ChildProcess::wait gives it.
int run_process(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                const std::filesystem::path& out, const std::filesystem::path& err,
                std::chrono::milliseconds bound);

// "exit status 2", "killed by signal 11", "timed out"
std::string describe_exit(int code);

// The first `limit` bytes of a file, for messages ("" when there is none).
std::string head_of_file(const std::filesystem::path& file, std::size_t limit = 400);

}  // namespace fb89::soak
