#include "period/emulator.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "period/phases.h"
#include "period/stop.h"

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

// $FB89_<env>_<what>, for m68k also $FB89_<what>; "" when neither is set.
std::string given(const InstructionSet& isa, const std::string& what, std::string* name) {
    const std::string variable = "FB89_" + std::string(isa.env) + "_" + what;
    if (const char* v = std::getenv(variable.c_str()); v && *v) {
        *name = variable;
        return v;
    }
    if (isa.name == "m68k")
        if (const char* v = std::getenv(("FB89_" + what).c_str()); v && *v) {
            *name = "FB89_" + what;
            return v;
        }
    *name = variable;
    return "";
}

// How to build a missing guest part: the guests' own target, in the build tree the part's
// path lies in (<build>/guest-<isa>/...), which a full build and scripts/test build too.
std::string how_to_build(const std::string& built, const InstructionSet& isa) {
    std::filesystem::path tree;
    for (std::filesystem::path p = built; !p.empty() && p != p.parent_path(); p = p.parent_path())
        if (p.filename().string().rfind("guest-", 0) == 0) tree = p.parent_path();
    return fmt::format(
        "build it with `cmake --build {} --target fb89_guests` (a full build and scripts/test "
        "build it too), with Debian's {} installed (scripts/bootstrap installs them)",
        tree.empty() ? std::string("BUILD") : tree.string(), isa.packages);
}

std::string part(const char* variable, const std::string& set, const std::string& built,
                 const std::string& what, const InstructionSet& isa) {
    if (!set.empty()) {
        if (::access(set.c_str(), R_OK) != 0)
            throw EmulatorError(fmt::format("{} ({}={}) cannot be read", what, variable, set));
        return set;
    }
    if (built.empty() || ::access(built.c_str(), R_OK) != 0)
        throw EmulatorError(fmt::format(
            "{} is not built ({}): {}, or set {}", what,
            built.empty() ? "the cross build was off" : built + " is missing",
            built.empty() ? fmt::format("configure fb89 with -DFB89_PERIOD_GUEST=ON and Debian's "
                                        "{} installed (scripts/bootstrap installs them)",
                                        isa.packages)
                          : how_to_build(built, isa),
            variable));
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

// The bounds of one emulated run: the caller's time limit unless $FB89_GUEST_TIME_LIMIT
// (seconds) is lower, and $FB89_GUEST_MEMORY_LIMIT MiB of guest memory (default
// kGuestMemoryMiB).
struct GuestLimits {
    double seconds;
    rlim_t memory_bytes;
};
GuestLimits guest_limits(double time_limit_s) {
    GuestLimits l{time_limit_s, static_cast<rlim_t>(kGuestMemoryMiB) << 20};
    if (const char* t = std::getenv("FB89_GUEST_TIME_LIMIT"); t && *t) {
        const double s = std::strtod(t, nullptr);
        if (s > 0) l.seconds = std::min(l.seconds, s);
    }
    if (const char* m = std::getenv("FB89_GUEST_MEMORY_LIMIT"); m && *m) {
        const long long mib = std::strtoll(m, nullptr, 10);
        if (mib > 0) l.memory_bytes = static_cast<rlim_t>(mib) << 20;
    }
    return l;
}

// "in phase hidden_surface" from the plugin's phase file (then removed), or "" when the
// guest marked no phase.
std::string last_phase(const char* path) {
    std::ifstream in(path);
    int phase = -1;
    in >> phase;
    std::filesystem::remove(path);
    return phase >= 0 ? fmt::format("in phase {}", phase_name(phase)) : "before its first phase";
}

// Whether `sig` is one a program gets for going wrong itself (a bad address or instruction, an
// abort): the emulator passes on the guest's. Any other (SIGTERM, SIGKILL, SIGINT, SIGHUP) was
// sent from outside.
bool is_fault(int sig) {
    return sig == SIGSEGV || sig == SIGBUS || sig == SIGILL || sig == SIGFPE || sig == SIGABRT ||
           sig == SIGTRAP || sig == SIGSYS;
}

// The child's resident memory in bytes, from /proc; 0 if it cannot be read.
uint64_t resident_bytes(pid_t child) {
    std::ifstream status("/proc/" + std::to_string(child) + "/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmRSS:", 0) == 0) return std::strtoull(line.c_str() + 6, nullptr, 10) << 10;
    return 0;
}

enum class Drained { Closed, OutOfTime, OutOfMemory, Stopped };

// Reads the child's stdout and stderr until both close, the time runs out, or the child's
// resident memory passes `memory_bytes`, or a stop is asked for (period/stop.h; both looked at
// every 50 ms).
Drained drain(pid_t child, int out_fd, int err_fd, std::vector<uint8_t>& out, std::string& err,
              std::chrono::steady_clock::time_point deadline, uint64_t memory_bytes) {
    pollfd fds[2] = {{out_fd, POLLIN, 0}, {err_fd, POLLIN, 0}};
    int open = 2;
    char buf[65536];
    auto next_look = std::chrono::steady_clock::now();
    while (open > 0) {
        const auto now = std::chrono::steady_clock::now();
        if (now >= next_look) {
            if (resident_bytes(child) > memory_bytes) return Drained::OutOfMemory;
            if (stop_requested()) return Drained::Stopped;
            next_look = now + std::chrono::milliseconds(50);
        }
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count();
        if (left <= 0) return Drained::OutOfTime;
        if (::poll(fds, 2, static_cast<int>(std::min<int64_t>(left, 50))) < 0) {
            if (errno == EINTR) continue;
            return Drained::OutOfTime;
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
    return Drained::Closed;
}

}  // namespace

EmulatorParts find_emulator_parts(const InstructionSet& isa) {
    EmulatorParts parts;
    parts.isa = &isa;
    std::string variable;
    parts.qemu = given(isa, "QEMU", &variable);
    if (parts.qemu.empty()) parts.qemu = on_path(std::string(isa.qemu));
    if (parts.qemu.empty() || ::access(parts.qemu.c_str(), X_OK) != 0)
        throw EmulatorError(
            fmt::format("{} not found (on PATH or as ${}): install Debian's qemu-user "
                        "(scripts/bootstrap installs it)",
                        isa.qemu, variable));
    const char* plugin = std::getenv("FB89_COUNT_PLUGIN");
    parts.plugin = part("FB89_COUNT_PLUGIN", plugin ? plugin : "", FB89_COUNT_PLUGIN_PATH,
                        "the counting plugin", isa);
    const std::string guest = given(isa, "GUEST", &variable);
    parts.guest = part(variable.c_str(), guest, std::string(isa.guest_path),
                       fmt::format("the guest program for {}", isa.name), isa);
    return parts;
}

namespace {

// Runs `program` (an executable of the parts' instruction set, given relative to `folder`)
// under its emulator with the counting plugin, in `folder`, with an empty environment;
// `what` names the run in errors.
GuestRun run_program(const EmulatorParts& parts, const std::string& program,
                     const std::filesystem::path& folder, const std::vector<std::string>& args,
                     const std::string& what, double time_limit_s) {
    char counts_path[] = "/tmp/fb89_counts_XXXXXX";
    char phase_path[] = "/tmp/fb89_phase_XXXXXX";
    for (char* path : {counts_path, phase_path}) {
        const int fd = ::mkstemp(path);
        if (fd < 0) throw EmulatorError("cannot make a temporary file for the counts");
        ::close(fd);
    }
    const GuestLimits limits = guest_limits(time_limit_s);
    std::string plugin = parts.plugin + ",out=" + counts_path + ",phase=" + phase_path;
    for (const std::string_view option : parts.isa->plugin_options)
        plugin.append(",").append(option);
    // A fixed seed for the random bytes the emulator hands the guest (AT_RANDOM, getrandom):
    // the C library's start-up draws on them, and without the seed the SPARC guest's start-up
    // phase took 364,000 or 364,028 instructions at random, run to run.
    std::vector<std::string> argv_text{parts.qemu, "-seed", "1989"};
    for (const std::string_view option : parts.isa->qemu_options)
        argv_text.emplace_back(option);
    argv_text.insert(argv_text.end(), {"-plugin", plugin, program});
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
        // the guest's memory: every page it maps is a writable private mapping of qemu's.
        // The parent watches resident memory against the limit; this bound, above it by
        // room for the emulator's own buffers, only stops a guest that maps far more than
        // it touches (qemu then searches for room until the time limit ends it)
        const rlim_t mapped = 2 * limits.memory_bytes + (rlim_t{512} << 20);
        const rlimit data{mapped, mapped};
        ::setrlimit(RLIMIT_DATA, &data);
        // no core file: a guest's would land in the scene's folder, and writing one of a
        // large guest under the emulator takes minutes
        const rlimit no_core{0, 0};
        ::setrlimit(RLIMIT_CORE, &no_core);
        if (::chdir(folder.c_str()) != 0) ::_exit(126);
        ::execve(argv[0], argv.data(), envp);
        ::_exit(127);
    }
    ::close(out.fd[1]), out.fd[1] = -1;
    ::close(err.fd[1]), err.fd[1] = -1;
    GuestRun run;
    std::string guest_err;
    const Drained drained = drain(child, out.fd[0], err.fd[0], run.stream, guest_err,
                                  start + std::chrono::duration_cast<std::chrono::nanoseconds>(
                                              std::chrono::duration<double>(limits.seconds)),
                                  limits.memory_bytes);
    if (drained != Drained::Closed) ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::ifstream counts(counts_path, std::ios::binary);
    std::stringstream text;
    text << counts.rdbuf();
    run.counts_json = text.str();
    std::filesystem::remove(counts_path);
    const std::string where = last_phase(phase_path);
    // a stop asked for (period/stop.h) ends the run however the emulator ended: by our kill, or
    // by the same signal reaching it first (Ctrl-C reaches the whole process group; Slurm's
    // scancel every process of a task)
    if (drained == Drained::Stopped || (WIFSIGNALED(status) && stop_requested())) throw Stopped{};

    const std::string said = guest_err.empty() ? "" : ": " + guest_err.substr(0, 2000);
    if (drained == Drained::OutOfTime)
        throw EmulatorError(
            fmt::format("the emulated host ran past its limit of {:g} s {} on {} "
                        "(stopped; nothing written)",
                        limits.seconds, where, what));
    if (drained == Drained::OutOfMemory || guest_err.find("std::bad_alloc") != std::string::npos ||
        guest_err.find("Cannot allocate memory") != std::string::npos)
        throw EmulatorError(
            fmt::format("the emulated host ran out of memory (limit {} MiB) {} "
                        "on {} (nothing written){}",
                        limits.memory_bytes >> 20, where, what, said));
    if (WIFSIGNALED(status)) {
        const int sig = WTERMSIG(status);
        const char* name = ::sigabbrev_np(sig);
        const std::string signal =
            fmt::format("signal {}, SIG{}", sig, name != nullptr ? name : "?");
        if (is_fault(sig))
            throw EmulatorError(
                fmt::format("the emulated host crashed ({}) {} on {} (nothing written){}", signal,
                            where, what, said));
        // a kill, a hang-up, an interrupt aimed at the emulator alone: no fault of the guest's
        throw EmulatorError(fmt::format(
            "the emulated host was ended from outside ({}{}) {} on {} (nothing written){}", signal,
            sig == SIGKILL ? ", which the system's out-of-memory killer also sends" : "", where,
            what, said));
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw EmulatorError(
            fmt::format("the emulated host failed (exit {}) {} on {} (nothing "
                        "written){}",
                        WIFEXITED(status) ? WEXITSTATUS(status) : -1, where, what, said));
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

std::filesystem::path find_kernel(const InstructionSet& isa, const std::string& name) {
    std::string variable;
    const std::string set = given(isa, "KERNELS_DIR", &variable);
    const std::filesystem::path dir =
        set.empty() ? std::filesystem::path(isa.kernels_dir) : std::filesystem::path(set);
    const std::filesystem::path path = dir / name;
    if (dir.empty() || ::access(path.c_str(), R_OK) != 0)
        throw EmulatorError(fmt::format(
            "the validation kernel {} for {} is not built ({} is missing): {}, or set {}", name,
            isa.name, path.string(), how_to_build(path.string(), isa), variable));
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
