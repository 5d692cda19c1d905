#include "bench/soak/resource_sampler.h"

#include <malloc.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace fb89::soak {

namespace {

std::filesystem::path proc_dir(pid_t pid) {
    return pid == 0 ? std::filesystem::path("/proc/self")
                    : std::filesystem::path("/proc/" + std::to_string(pid));
}

uint64_t vm_rss_kib(const std::filesystem::path& proc) {
    std::ifstream status(proc / "status");
    if (!status) throw std::runtime_error(fmt::format("cannot read {}/status", proc.string()));
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmRSS:", 0) == 0) return std::stoull(line.substr(6));  // "  1234 kB"
    throw std::runtime_error(fmt::format("no VmRSS in {}/status", proc.string()));
}

// The listing of /proc/self/fd includes the descriptor that reads it: the count is one more
// than the process holds otherwise, the same at every sample.
int open_fds(const std::filesystem::path& proc) {
    int n = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(proc / "fd"))
        ++n;
    return n;
}

}  // namespace

ResourceSample sample_process(pid_t pid, int cycle) {
    const std::filesystem::path proc = proc_dir(pid);
    ResourceSample s;
    s.cycle = cycle;
    s.rss_kib = vm_rss_kib(proc);
    s.fds = open_fds(proc);
    if (pid == 0) {
        ::malloc_trim(0);
        s.trimmed_kib = vm_rss_kib(proc);
        const struct mallinfo2 heap = ::mallinfo2();
        s.heap_bytes = heap.uordblks + heap.hblkhd;
    }
    return s;
}

bool asleep_in_poll(pid_t pid) {
    const std::filesystem::path proc = proc_dir(pid);
    std::ifstream stat(proc / "stat");
    std::string text;
    if (!std::getline(stat, text)) return false;
    // "PID (COMM) STATE ...": COMM may hold spaces and parentheses; the state follows the last ')'
    const std::size_t close = text.rfind(')');
    if (close == std::string::npos || close + 2 >= text.size() || text[close + 2] != 'S')
        return false;
    std::ifstream wchan(proc / "wchan");
    std::string channel;
    std::getline(wchan, channel);
    return channel.find("poll") != std::string::npos;
}

bool is_sample_point(int done, int every, int last) {
    return done == 1 || done == last || (every > 0 && done % every == 0);
}

}  // namespace fb89::soak
