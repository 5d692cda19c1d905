#include "protocol/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
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

}  // namespace

AtomicFile::AtomicFile(fs::path target) : m_target(std::move(target)) {
    m_final = final_path(m_target);
    const fs::path dir = m_final.parent_path().empty() ? fs::path(".") : m_final.parent_path();
    std::string name = (dir / ("." + m_final.filename().string() + ".tmp-XXXXXX")).string();
    const int fd = ::mkstemp(name.data());
    if (fd < 0)
        throw std::runtime_error(fmt::format("{}: cannot open for writing: {}", m_target.string(),
                                             std::strerror(errno)));
    m_temporary = name;
    m_stream = ::fdopen(fd, "wb");
    if (!m_stream) {
        const int error = errno;
        ::close(fd);
        fail(error);
    }
    if (::fchmod(fd, output_mode(m_final)) != 0) fail(errno);
}

AtomicFile::~AtomicFile() {
    if (m_stream) std::fclose(m_stream);
    if (!m_committed && !m_temporary.empty()) ::unlink(m_temporary.c_str());
}

void AtomicFile::fail(int error) {
    if (m_stream) std::fclose(m_stream);
    m_stream = nullptr;
    ::unlink(m_temporary.c_str());
    m_temporary.clear();
    throw std::runtime_error(fmt::format("{}: {}", m_target.string(), std::strerror(error)));
}

void AtomicFile::commit() {
    // a write error the writer left on the stream: errno still holds its cause
    if (std::ferror(m_stream)) fail(errno != 0 ? errno : EIO);
    if (std::fflush(m_stream) != 0) fail(errno);
    // on disk before the name points at it, so a crash cannot leave an empty target
    if (::fsync(::fileno(m_stream)) != 0 && errno != EINVAL) fail(errno);
    std::FILE* f = m_stream;
    m_stream = nullptr;
    if (std::fclose(f) != 0) fail(errno);
    if (::rename(m_temporary.c_str(), m_final.c_str()) != 0) fail(errno);
    m_committed = true;
}

void write_file_atomically(const fs::path& path, std::string_view bytes) {
    AtomicFile file(path);
    errno = 0;
    if (std::fwrite(bytes.data(), 1, bytes.size(), file.stream()) != bytes.size()) {
        const int error = errno != 0 ? errno : EIO;
        throw std::runtime_error(fmt::format("{}: {}", path.string(), std::strerror(error)));
    }
    file.commit();
}

void write_file_atomically(const fs::path& path, const std::function<void(std::FILE*)>& write) {
    AtomicFile file(path);
    errno = 0;
    write(file.stream());
    file.commit();
}

}  // namespace fb89::protocol
