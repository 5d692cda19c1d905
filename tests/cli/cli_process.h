// What the CLI tests that run fb89 as a child process share: the process (output in files,
// killed at the end if still running), and waiting for a controller to listen.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "protocol/socket_stream.h"
#include "tests/cli/cli_runner.h"

namespace fb89::testing {

// A child process running fb89 with its output in files; killed if still running at the end.
struct Process {
    pid_t pid = -1;
    std::filesystem::path out, err;
    Process() = default;
    Process(Process&& o) noexcept : pid(o.pid), out(std::move(o.out)), err(std::move(o.err)) {
        o.pid = -1;
    }
    Process& operator=(Process&&) = delete;
    ~Process() {
        if (pid > 0) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, nullptr, 0);
        }
    }
    // The exit code, -signal if killed, or -1000 if it did not end within the bound.
    int wait(std::chrono::seconds bound) {
        const auto deadline = std::chrono::steady_clock::now() + bound;
        int status = 0;
        while (::waitpid(pid, &status, WNOHANG) == 0) {
            if (std::chrono::steady_clock::now() > deadline) return -1000;
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        pid = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
    }
};

// Starts fb89 with `args`; its stdout and stderr go to TAG.out and TAG.err in test_dir().
inline Process spawn_fb89(const std::vector<std::string>& args, const std::string& tag) {
    Process p;
    p.out = test_dir() / (tag + ".out");
    p.err = test_dir() / (tag + ".err");
    p.pid = ::fork();
    if (p.pid == 0) {
        const int out = ::open(p.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = ::open(p.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(out, 1);
        ::dup2(err, 2);
        std::vector<char*> argv{const_cast<char*>(FB89_CLI_PATH)};
        for (const auto& a : args)
            argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(FB89_CLI_PATH, argv.data());
        ::_exit(127);
    }
    return p;
}

// True once a connection to `socket` succeeds within `bound` (the controller ignores such
// empty probes).
inline bool wait_until_listening(const std::string& socket, std::chrono::seconds bound) {
    const auto deadline = std::chrono::steady_clock::now() + bound;
    while (std::chrono::steady_clock::now() < deadline) {
        try {
            protocol::connect_socket(socket);
            return true;
        } catch (const std::runtime_error&) {
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
    }
    return false;
}

}  // namespace fb89::testing
