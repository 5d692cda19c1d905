// Running the fb89 executable from tests as a user would: in a shell, with stdout and
// stderr captured in a folder of the test's own (ctest runs tests in parallel processes).
#pragma once

#include <gtest/gtest.h>
#include <poll.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/scratch.h"

namespace fb89::testing {

struct CliRun {
    int exit_code = -1;
    std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Writes `bytes` to `p`, replacing what was there.
inline void put(const std::filesystem::path& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary) << bytes;
}

// A folder of this test's own.
inline std::filesystem::path test_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::filesystem::path dir =
        scratch_dir() / (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::create_directories(dir);
    return dir;
}

// `name` in test_dir().
inline std::filesystem::path test_file(const std::string& name) {
    return test_dir() / name;
}

// `xvfb-run` on a free display, 24-bit so colours survive, with its X authority file in this
// test's folder: left to itself, xvfb-run makes a temporary folder for it and, when removing
// that folder fails, exits 5 in place of the command's status and leaves its server running.
inline std::string xvfb_run() {
    return "xvfb-run -a -f " + (test_dir() / "Xauthority").string() +
           " -s '-screen 0 1280x1024x24' ";
}

// Runs `prefix fb89 args` in a shell; `prefix` may set a directory or environment.
inline CliRun run_fb89(const std::string& args, const std::string& prefix = "") {
    const std::filesystem::path dir = test_dir();
    const std::string cmd = prefix + std::string(FB89_CLI_PATH) + " " + args + " >" +
                            (dir / "out").string() + " 2>" + (dir / "err").string() + " </dev/null";
    const int status = std::system(cmd.c_str());
    CliRun r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(dir / "out");
    r.err = slurp(dir / "err");
    return r;
}

// Runs `sh -c command` with a pseudo-terminal as its stdin, stdout and stderr, as a user
// at a terminal would, and waits for it: `out` is everything the terminal was shown.
// (`script` is no substitute: with its own stdin at end of file it returns at once and
// leaves the command writing its log behind the test's back.) A command still running
// after `limit` is killed and reported as exit code -1.
inline CliRun run_in_terminal(const std::string& command,
                              std::chrono::seconds limit = std::chrono::seconds(300)) {
    CliRun r;
    int master = -1;
    winsize size{};
    size.ws_row = 24;
    size.ws_col = 200;
    const pid_t pid = forkpty(&master, nullptr, nullptr, &size);
    if (pid < 0) {
        r.err = std::string("forkpty: ") + std::strerror(errno);
        return r;
    }
    if (pid == 0) {
        ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + limit;
    bool killed = false;
    char buf[4096];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            ::kill(-pid, SIGKILL);  // forkpty made it a session and group leader
            killed = true;
            break;
        }
        pollfd p{master, POLLIN, 0};
        const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) continue;
        const ssize_t n = ::read(master, buf, sizeof buf);
        if (n > 0)
            r.out.append(buf, static_cast<size_t>(n));
        else if (n < 0 && errno == EINTR)
            continue;
        else
            break;  // EIO: every holder of the terminal's other side has closed it
    }
    ::close(master);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    r.exit_code = !killed && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

}  // namespace fb89::testing
