#include "period/emulator.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace fb89::period {

namespace {

std::string on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        if (dir.empty()) continue;
        const std::filesystem::path candidate = std::filesystem::path(dir) / name;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    }
    return "";
}

std::string part(const char* variable, const char* built, const char* what) {
    if (const char* given = std::getenv(variable); given && *given) {
        if (::access(given, R_OK) != 0)
            throw EmulatorError(fmt::format("{} ({}={}) cannot be read", what, variable, given));
        return given;
    }
    if (::access(built, R_OK) != 0)
        throw EmulatorError(fmt::format(
            "{} is not built ({} is missing): build fb89 with Debian's g++-m68k-linux-gnu "
            "installed (scripts/bootstrap installs it), or set {}",
            what, built, variable));
    return built;
}

struct Pipe {
    int fd[2] = {-1, -1};
    Pipe() {
        if (::pipe2(fd, O_CLOEXEC) != 0) throw EmulatorError("cannot make a pipe for the guest");
    }
    ~Pipe() {
        for (int f : fd)
            if (f >= 0) ::close(f);
    }
};

// Reads the child's stdout and stderr until both close or the time runs out.
bool drain(int out_fd, int err_fd, std::vector<uint8_t>& out, std::string& err,
           std::chrono::steady_clock::time_point deadline) {
    pollfd fds[2] = {{out_fd, POLLIN, 0}, {err_fd, POLLIN, 0}};
    int open = 2;
    char buf[65536];
    while (open > 0) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return false;
        if (::poll(fds, 2, static_cast<int>(std::min<int64_t>(left.count(), 1000))) < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        for (int i = 0; i < 2; ++i) {
            if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            const ssize_t n = ::read(fds[i].fd, buf, sizeof buf);
            if (n <= 0) {
                fds[i].fd = -1;
                --open;
            } else if (i == 0) {
                out.insert(out.end(), buf, buf + n);
            } else if (err.size() < 65536) {
                err.append(buf, static_cast<size_t>(n));
            }
        }
    }
    return true;
}

}  // namespace

EmulatorParts find_emulator_parts() {
    EmulatorParts parts;
    if (const char* given = std::getenv("FB89_QEMU"); given && *given)
        parts.qemu = given;
    else
        parts.qemu = on_path("qemu-m68k");
    if (parts.qemu.empty() || ::access(parts.qemu.c_str(), X_OK) != 0)
        throw EmulatorError(
            "qemu-m68k not found (on PATH or as $FB89_QEMU): install Debian's qemu-user "
            "(scripts/bootstrap installs it)");
    parts.plugin = part("FB89_COUNT_PLUGIN", FB89_COUNT_PLUGIN_PATH, "the counting plugin");
    parts.guest = part("FB89_GUEST", FB89_GUEST_PATH, "the guest program for the MC68020");
    return parts;
}

namespace {

// Runs `program` (an m68k executable, given relative to `folder`) under qemu-m68k with the
// counting plugin, in `folder`, with an empty environment; `what` names the run in errors.
GuestRun run_program(const EmulatorParts& parts, const std::string& program,
                     const std::filesystem::path& folder, const std::vector<std::string>& args,
                     const std::string& what, double time_limit_s) {
    char counts_path[] = "/tmp/fb89_counts_XXXXXX";
    const int counts_fd = ::mkstemp(counts_path);
    if (counts_fd < 0) throw EmulatorError("cannot make a temporary file for the counts");
    ::close(counts_fd);
    std::vector<std::string> argv_text{
        parts.qemu, "-cpu", "m68020", "-plugin", parts.plugin + ",out=" + counts_path, program};
    argv_text.insert(argv_text.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_text)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    char* envp[] = {nullptr};  // an empty environment: counts independent of the caller's

    Pipe out, err;
    const auto start = std::chrono::steady_clock::now();
    const pid_t child = ::fork();
    if (child < 0) throw EmulatorError("cannot start the emulator (fork failed)");
    if (child == 0) {
        ::dup2(out.fd[1], STDOUT_FILENO);
        ::dup2(err.fd[1], STDERR_FILENO);
        if (::chdir(folder.c_str()) != 0) ::_exit(126);
        ::execve(argv[0], argv.data(), envp);
        ::_exit(127);
    }
    ::close(out.fd[1]), out.fd[1] = -1;
    ::close(err.fd[1]), err.fd[1] = -1;
    GuestRun run;
    std::string guest_err;
    const bool in_time = drain(out.fd[0], err.fd[0], run.stream, guest_err,
                               start + std::chrono::duration_cast<std::chrono::nanoseconds>(
                                           std::chrono::duration<double>(time_limit_s)));
    if (!in_time) ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::ifstream counts(counts_path, std::ios::binary);
    std::stringstream text;
    text << counts.rdbuf();
    run.counts_json = text.str();
    std::filesystem::remove(counts_path);

    const std::string said = guest_err.empty() ? "" : ": " + guest_err.substr(0, 2000);
    if (!in_time)
        throw EmulatorError(fmt::format("the emulated host ran past its limit of {:.0f} s on {}",
                                        time_limit_s, what));
    if (WIFSIGNALED(status))
        throw EmulatorError(fmt::format("the emulated host crashed (signal {}) on {}{}",
                                        WTERMSIG(status), what, said));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw EmulatorError(fmt::format("the emulated host failed (exit {}) on {}{}",
                                        WIFEXITED(status) ? WEXITSTATUS(status) : -1, what, said));
    run.counts = parse_guest_counts(run.counts_json, "the counting plugin's output");
    return run;
}

}  // namespace

GuestRun run_guest(const EmulatorParts& parts, const std::filesystem::path& scene,
                   const std::vector<std::string>& options, double time_limit_s) {
    const std::filesystem::path absolute = std::filesystem::absolute(scene);
    std::vector<std::string> args{absolute.filename().string()};
    args.insert(args.end(), options.begin(), options.end());
    args.insert(args.end(), {"--stream", "-"});
    return run_program(parts, parts.guest, absolute.parent_path(), args, scene.string(),
                       time_limit_s);
}

std::filesystem::path find_kernel(const std::string& name) {
    std::filesystem::path dir = FB89_KERNELS_DIR;
    if (const char* given = std::getenv("FB89_KERNELS_DIR"); given && *given) dir = given;
    const std::filesystem::path path = dir / name;
    if (dir.empty() || ::access(path.c_str(), R_OK) != 0)
        throw EmulatorError(fmt::format(
            "the validation kernel {} is not built ({} is missing): build fb89 with Debian's "
            "g++-m68k-linux-gnu installed (scripts/bootstrap installs it), or set "
            "FB89_KERNELS_DIR",
            name, path.string()));
    return path;
}

GuestRun run_kernel(const EmulatorParts& parts, const std::filesystem::path& kernel,
                    const std::vector<std::string>& options, double time_limit_s) {
    const std::filesystem::path absolute = std::filesystem::absolute(kernel);
    // Relative to its folder, so that argv (and the counts) do not depend on the checkout.
    return run_program(parts, "./" + absolute.filename().string(), absolute.parent_path(), options,
                       kernel.string(), time_limit_s);
}

}  // namespace fb89::period
