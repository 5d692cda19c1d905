// Special files of a test's own, in its scratch folder, so that no test writes to a system
// path (/dev/null, /dev/full, /dev/stdout) through fb89's output options: a character
// device made with mknod (root only), a FIFO with a reader, and what each was before.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>

namespace fb89::testing {

// A character device at `path` with the numbers of Linux's /dev/null (1, 3) or /dev/full
// (1, 7), or the reason there is none: mknod needs root, and a folder on a file system
// mounted nodev refuses to open devices.
inline std::optional<std::string> make_char_device(const std::filesystem::path& path,
                                                   unsigned minor) {
    if (::geteuid() != 0) return "making a character device needs root (mknod)";
    std::filesystem::remove(path);
    if (::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, minor)) != 0)
        return std::string("mknod: ") + std::strerror(errno);
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) {
        const std::string why = std::string("a device of our own cannot be opened here (") +
                                std::strerror(errno) + "; is the folder mounted nodev?)";
        std::filesystem::remove(path);
        return why;
    }
    ::close(fd);
    return std::nullopt;
}

// What a special file is: its type and, for a device, its numbers.
struct FileIdentity {
    mode_t type = 0;
    dev_t rdev = 0;
    bool operator==(const FileIdentity&) const = default;
};

// lstat: a symbolic link is itself, not what it names.
inline FileIdentity identity_of(const std::filesystem::path& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) return {};
    return {static_cast<mode_t>(st.st_mode & S_IFMT), st.st_rdev};
}

inline std::string describe(const FileIdentity& id) {
    switch (id.type) {
        case S_IFCHR:
            return "a character device " + std::to_string(major(id.rdev)) + "," +
                   std::to_string(minor(id.rdev));
        case S_IFIFO:
            return "a FIFO";
        case S_IFLNK:
            return "a symbolic link";
        case S_IFREG:
            return "a regular file";
        case S_IFSOCK:
            return "a socket";
        case 0:
            return "nothing";
    }
    return "something else";
}

// Reads everything written into a FIFO while it lives, without ever blocking: the read end
// is opened non-blocking, so a writer that never comes costs nothing. stop() collects
// what is left once the writer has finished.
class FifoReader {
  public:
    explicit FifoReader(const std::filesystem::path& fifo) {
        m_fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        m_thread = std::thread([this] { loop(); });
    }
    ~FifoReader() { stop(); }
    FifoReader(const FifoReader&) = delete;
    FifoReader& operator=(const FifoReader&) = delete;

    // Waits for the reader to drain what the (finished) writer left, then returns it all.
    const std::string& stop() {
        if (m_thread.joinable()) {
            m_done = true;
            m_thread.join();
            if (m_fd >= 0) ::close(m_fd);
            m_fd = -1;
        }
        return m_bytes;
    }
    bool opened() const { return m_fd >= 0; }

  private:
    void loop() {
        if (m_fd < 0) return;
        char buffer[65536];
        for (;;) {
            pollfd p{m_fd, POLLIN, 0};
            ::poll(&p, 1, 20);
            const ssize_t n = ::read(m_fd, buffer, sizeof buffer);
            if (n > 0) {
                m_bytes.append(buffer, static_cast<size_t>(n));
                continue;
            }
            // 0: no writer now; EAGAIN: a writer with nothing yet. Once the command has
            // ended, an empty read means everything has been taken.
            if (m_done) return;
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }

    int m_fd = -1;
    std::string m_bytes;
    std::atomic<bool> m_done{false};
    std::thread m_thread;
};

}  // namespace fb89::testing
