#include "protocol/output_file.h"

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace fb89::protocol {

namespace fs = std::filesystem;

namespace {

// The process's umask, read without changing it where Linux shows it (/proc/self/status,
// "Umask:"), else by setting and restoring it once.
mode_t process_umask() {
    static const mode_t mask = [] {
        std::ifstream status("/proc/self/status");
        std::string key;
        while (status >> key) {
            if (key == "Umask:") {
                std::string octal;
                status >> octal;
                return static_cast<mode_t>(std::stoul(octal, nullptr, 8));
            }
        }
        const mode_t m = ::umask(022);
        ::umask(m);
        return m;
    }();
    return mask;
}

// The permissions the new file takes: the old target's, else what open(0666) would give.
mode_t output_mode(const fs::path& target) {
    struct stat st {};
    if (::stat(target.c_str(), &st) == 0 && S_ISREG(st.st_mode)) return st.st_mode & 07777;
    return 0666 & ~process_umask();
}

// A symbolic link is replaced by way of the file it names.
fs::path final_path(const fs::path& target) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(target, ec))) return target;
    const fs::path resolved = fs::weakly_canonical(target, ec);
    return ec ? target : resolved;
}

[[noreturn]] void fail_open(const fs::path& target, int error) {
    throw std::runtime_error(
        fmt::format("{}: cannot open for writing: {}", output_name(target), std::strerror(error)));
}

int connect_unix_socket(const fs::path& target) {
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    const std::string path = target.string();
    if (path.size() >= sizeof addr.sun_path) fail_open(target, ENAMETOOLONG);
    std::memcpy(addr.sun_path, path.c_str(), path.size() + 1);
    const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) fail_open(target, errno);
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
        const int error = errno;
        ::close(fd);
        fail_open(target, error);
    }
    return fd;
}

// N when `path` reads /dev/fd/N, /proc/self/fd/N or /proc/<this process>/fd/N.
int descriptor_in(const fs::path& path) {
    const std::string s = path.lexically_normal().string();
    for (const std::string& prefix : {std::string("/dev/fd/"), std::string("/proc/self/fd/"),
                                      fmt::format("/proc/{}/fd/", ::getpid())}) {
        if (s.size() <= prefix.size() || s.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string digits = s.substr(prefix.size());
        if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
            return -1;
        return std::stoi(digits);
    }
    return -1;
}

}  // namespace

int named_descriptor(const fs::path& target) {
    if (target == "-") return STDOUT_FILENO;
    // follow the links one at a time: /dev/stdout -> /proc/self/fd/1 -> (the pipe or file)
    fs::path p = target;
    for (int hop = 0; hop < 40; ++hop) {
        if (const int fd = descriptor_in(p); fd >= 0) return fd;
        std::error_code ec;
        if (!fs::is_symlink(fs::symlink_status(p, ec))) return -1;
        const fs::path next = fs::read_symlink(p, ec);
        if (ec) return -1;
        p = next.is_absolute() ? next : p.parent_path() / next;
    }
    return -1;
}

OutputKind output_kind(const fs::path& target) {
    if (named_descriptor(target) >= 0) return OutputKind::Descriptor;
    struct stat st {};
    if (::stat(target.c_str(), &st) != 0) return OutputKind::Replace;  // a new file
    if (S_ISDIR(st.st_mode))
        throw std::runtime_error(
            fmt::format("{}: is a directory, not a file to write", target.string()));
    return S_ISREG(st.st_mode) ? OutputKind::Replace : OutputKind::InPlace;
}

std::string output_name(const fs::path& target) {
    return target == "-" ? std::string("<stdout>") : target.string();
}

int open_in_place(const fs::path& target) {
    struct stat st {};
    if (::stat(target.c_str(), &st) == 0 && S_ISSOCK(st.st_mode))
        return connect_unix_socket(target);
    // no O_CREAT: the device or FIFO is there; no O_TRUNC: it means nothing for either
    int fd;
    do {
        fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) fail_open(target, errno);
    return fd;
}

OutputFile::OutputFile(fs::path target, Publish publish)
    : m_target(std::move(target)), m_publish(publish) {
    m_kind = output_kind(m_target);
    switch (m_kind) {
        case OutputKind::Descriptor:
            open_descriptor();
            break;
        case OutputKind::InPlace:
            open_in_place();
            break;
        case OutputKind::Replace:
            open_temporary();
            break;
    }
}

void OutputFile::open_temporary() {
    m_final = final_path(m_target);
    const fs::path dir = m_final.parent_path().empty() ? fs::path(".") : m_final.parent_path();
    std::string hidden(".");
    hidden += m_final.filename().string();
    hidden += ".tmp-XXXXXX";
    std::string name = (dir / hidden).string();
    const int fd = ::mkstemp(name.data());
    if (fd < 0) fail_open(m_target, errno);
    m_temporary = name;
    m_stream = ::fdopen(fd, "wb");
    if (!m_stream) {
        const int error = errno;
        ::close(fd);
        fail(error);
    }
    if (::fchmod(fd, output_mode(m_final)) != 0) fail(errno);
}

void OutputFile::open_in_place() {
    const int fd = protocol::open_in_place(m_target);
    m_stream = ::fdopen(fd, "wb");
    if (!m_stream) {
        const int error = errno;
        ::close(fd);
        fail(error);
    }
}

void OutputFile::open_descriptor() {
    std::cout.flush();
    std::fflush(stdout);
    const int fd = ::fcntl(named_descriptor(m_target), F_DUPFD_CLOEXEC, 3);
    if (fd < 0) fail_open(m_target, errno);
    m_stream = ::fdopen(fd, "wb");
    if (!m_stream) {
        const int error = errno;
        ::close(fd);
        fail(error);
    }
}

OutputFile::~OutputFile() {
    if (m_stream) std::fclose(m_stream);
    if (!m_committed && !m_temporary.empty()) ::unlink(m_temporary.c_str());
}

void OutputFile::fail(int error) {
    if (m_stream) std::fclose(m_stream);
    m_stream = nullptr;
    if (!m_temporary.empty()) ::unlink(m_temporary.c_str());
    m_temporary.clear();
    throw std::runtime_error(fmt::format("{}: {}", output_name(m_target), std::strerror(error)));
}

void OutputFile::commit() {
    // a write error the writer left on the stream: errno still holds its cause
    if (std::ferror(m_stream)) fail(errno != 0 ? errno : EIO);
    if (std::fflush(m_stream) != 0) fail(errno);
    if (m_kind == OutputKind::Replace) {
        // on disk before the name points at it, so a crash cannot leave an empty target
        if (::fsync(::fileno(m_stream)) != 0 && errno != EINVAL) fail(errno);
    }
    std::FILE* f = m_stream;
    m_stream = nullptr;
    if (std::fclose(f) != 0) fail(errno);
    if (m_kind == OutputKind::Replace) {
        OutputBatch* batch = m_publish == Publish::WithCommand ? OutputBatch::current() : nullptr;
        if (batch)
            batch->add_temporary(m_temporary, m_final, output_name(m_target));
        else if (::rename(m_temporary.c_str(), m_final.c_str()) != 0)
            fail(errno);
    }
    m_committed = true;
}

LiveFile::LiveFile(fs::path target, Publish publish) : m_final(final_path(target)) {
    const auto fail_at = [&](const char* what, int error) {
        throw std::runtime_error(
            fmt::format("{}: {}: {}", output_name(target), what, std::strerror(error)));
    };
    const mode_t mode = output_mode(m_final);
    struct stat st {};
    if (::stat(m_final.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
        // the old file aside, under a hidden name of its own beside it (same file system)
        const fs::path dir = m_final.parent_path().empty() ? fs::path(".") : m_final.parent_path();
        // (formatted, not "." + name: GCC 12's -Wrestrict misreads that insert at -O2 and up)
        std::string name =
            (dir / fmt::format(".{}.old-XXXXXX", m_final.filename().string())).string();
        const int placeholder = ::mkstemp(name.data());
        if (placeholder < 0) fail_at("cannot open for writing", errno);
        ::close(placeholder);
        if (::rename(m_final.c_str(), name.c_str()) != 0) {
            const int error = errno;
            ::unlink(name.c_str());
            fail_at("cannot open for writing", error);
        }
        m_backup = name;
    }
    m_fd = ::open(m_final.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if (m_fd < 0) {
        const int error = errno;
        if (!m_backup.empty()) ::rename(m_backup.c_str(), m_final.c_str());
        fail_at("cannot open for writing", error);
    }
    ::fchmod(m_fd, mode);  // open's mode passed through the umask; the old file's is kept whole
    OutputBatch* batch = publish == Publish::WithCommand ? OutputBatch::current() : nullptr;
    if (batch) {
        batch->add_live(m_final, m_backup);
        m_batched = true;
    }
}

LiveFile::~LiveFile() {
    if (m_decided || m_batched) return;
    if (!m_backup.empty()) restore_live(m_final, m_backup);  // never lose the old file
}

void LiveFile::keep() noexcept {
    if (m_decided) return;
    m_decided = true;
    if (!m_batched && !m_backup.empty()) ::unlink(m_backup.c_str());
}

void LiveFile::abandon() noexcept {
    if (m_decided) return;
    m_decided = true;
    if (m_batched)
        if (OutputBatch* batch = OutputBatch::current()) batch->drop_live(m_final);
    restore_live(m_final, m_backup);
}

void restore_live(const fs::path& final, const fs::path& backup) noexcept {
    if (backup.empty())
        ::unlink(final.c_str());
    else
        ::rename(backup.c_str(), final.c_str());  // over the new file, in one step
}

void write_output(const fs::path& path, std::string_view bytes, Publish publish) {
    OutputFile file(path, publish);
    errno = 0;
    if (std::fwrite(bytes.data(), 1, bytes.size(), file.stream()) != bytes.size()) {
        const int error = errno != 0 ? errno : EIO;
        throw std::runtime_error(fmt::format("{}: {}", output_name(path), std::strerror(error)));
    }
    file.commit();
}

void write_output(const fs::path& path, const std::function<void(std::FILE*)>& write,
                  Publish publish) {
    OutputFile file(path, publish);
    errno = 0;
    write(file.stream());
    file.commit();
}

namespace {
std::mutex g_current_mutex;
OutputBatch* g_current = nullptr;
}  // namespace

OutputBatch::OutputBatch() {
    std::lock_guard lock(g_current_mutex);
    if (g_current) throw std::logic_error("an OutputBatch exists already");
    g_current = this;
}

OutputBatch::~OutputBatch() {
    {
        std::lock_guard lock(g_current_mutex);
        g_current = nullptr;
    }
    for (const Waiting& w : m_waiting)
        ::unlink(w.temporary.c_str());
    for (const Live& l : m_live)
        restore_live(l.final, l.backup);
}

OutputBatch* OutputBatch::current() {
    std::lock_guard lock(g_current_mutex);
    return g_current;
}

void OutputBatch::add_temporary(const fs::path& temporary, const fs::path& final,
                                const std::string& name) {
    std::lock_guard lock(m_mutex);
    m_waiting.push_back({temporary, final, name});
}

void OutputBatch::add_live(const fs::path& final, const fs::path& backup) {
    std::lock_guard lock(m_mutex);
    m_live.push_back({final, backup});
}

void OutputBatch::drop_live(const fs::path& final) {
    std::lock_guard lock(m_mutex);
    std::erase_if(m_live, [&](const Live& l) { return l.final == final; });
}

std::size_t OutputBatch::waiting() const {
    std::lock_guard lock(m_mutex);
    return m_waiting.size();
}

void OutputBatch::publish() {
    std::lock_guard lock(m_mutex);
    for (const Live& l : m_live)
        if (!l.backup.empty()) ::unlink(l.backup.c_str());
    m_live.clear();
    for (std::size_t i = 0; i < m_waiting.size(); ++i) {
        const Waiting& w = m_waiting[i];
        if (::rename(w.temporary.c_str(), w.final.c_str()) != 0) {
            const int error = errno;
            m_waiting.erase(m_waiting.begin(), m_waiting.begin() + static_cast<std::ptrdiff_t>(i));
            throw std::runtime_error(fmt::format("{}: {}", w.name, std::strerror(error)));
        }
    }
    m_waiting.clear();
}

}  // namespace fb89::protocol
