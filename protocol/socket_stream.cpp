// The Unix-domain socket transport (socket_stream.h): AF_UNIX stream sockets, poll() for
// every wait that has a bound, MSG_NOSIGNAL on sends so a vanished peer is an error
// (EPIPE) and never a SIGPIPE.
#include "protocol/socket_stream.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace fb89::protocol {

namespace {

constexpr std::size_t kMaxReply = 4096;

[[noreturn]] void fail(const std::string& path, const std::string& what, int error) {
    throw std::runtime_error(fmt::format("socket {}: {}: {}", path, what, std::strerror(error)));
}

sockaddr_un address_of(const std::string& path) {
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    if (path.empty() || path.size() >= sizeof(addr.sun_path)) {
        throw std::runtime_error(fmt::format("socket {}: the path must have 1 to {} bytes", path,
                                             sizeof(addr.sun_path) - 1));
    }
    std::memcpy(addr.sun_path, path.c_str(), path.size() + 1);
    return addr;
}

UniqueFd new_socket(const std::string& path) {
    UniqueFd fd(::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0));
    if (!fd) fail(path, "cannot create a socket", errno);
    return fd;
}

// Tries to connect; returns the connection or the errno of the failure.
int try_connect(const std::string& path, const sockaddr_un& addr, UniqueFd& out) {
    out = new_socket(path);
    while (::connect(out.get(), reinterpret_cast<const sockaddr*>(&addr), sizeof(addr)) != 0) {
        if (errno == EINTR) continue;
        const int error = errno;
        out.reset();
        return error;
    }
    return 0;
}

// A path that exists before we listen: remove it if it is a stale socket, else refuse.
void clear_stale_socket(const std::string& path, const sockaddr_un& addr) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) return;  // nothing there
    if (!S_ISSOCK(st.st_mode)) {
        throw std::runtime_error(
            fmt::format("socket {}: the path exists and is not a socket; not replacing it", path));
    }
    UniqueFd probe;
    const int error = try_connect(path, addr, probe);
    if (error == 0) {
        throw std::runtime_error(fmt::format(
            "socket {}: in use (another controller is listening there); stop it or choose "
            "another path",
            path));
    }
    if (error != ECONNREFUSED) fail(path, "cannot check the existing socket file", error);
    if (::unlink(path.c_str()) != 0 && errno != ENOENT) {
        fail(path, "cannot remove the stale socket file", errno);
    }
}

}  // namespace

// --- UniqueFd ------------------------------------------------------------------------

UniqueFd& UniqueFd::operator=(UniqueFd&& o) noexcept {
    if (this != &o) reset(o.release());
    return *this;
}

int UniqueFd::release() {
    const int fd = m_fd;
    m_fd = -1;
    return fd;
}

void UniqueFd::reset(int fd) {
    if (m_fd >= 0) ::close(m_fd);
    m_fd = fd;
}

// --- listener ------------------------------------------------------------------------

SocketListener::SocketListener(std::string path) : m_path(std::move(path)) {
    const sockaddr_un addr = address_of(m_path);
    clear_stale_socket(m_path, addr);
    m_fd = new_socket(m_path);
    if (::bind(m_fd.get(), reinterpret_cast<const sockaddr*>(&addr), sizeof(addr)) != 0) {
        fail(m_path, "cannot create the socket file", errno);
    }
    if (::listen(m_fd.get(), 16) != 0) {
        const int error = errno;
        ::unlink(m_path.c_str());
        fail(m_path, "cannot listen", error);
    }
}

SocketListener::~SocketListener() {
    m_fd.reset();
    ::unlink(m_path.c_str());
}

std::optional<UniqueFd> SocketListener::accept(int wake_fd) {
    pollfd fds[2] = {{m_fd.get(), POLLIN, 0}, {wake_fd, POLLIN, 0}};
    const nfds_t count = wake_fd >= 0 ? 2 : 1;
    for (;;) {
        const int n = ::poll(fds, count, -1);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail(m_path, "cannot wait for a host", errno);
        if (count == 2 && fds[1].revents != 0) return std::nullopt;
        const int fd = ::accept4(m_fd.get(), nullptr, nullptr, SOCK_CLOEXEC);
        if (fd >= 0) return UniqueFd(fd);
        if (errno == EINTR || errno == ECONNABORTED || errno == EAGAIN) continue;
        fail(m_path, "cannot accept a host", errno);
    }
}

// --- client --------------------------------------------------------------------------

UniqueFd connect_socket(const std::string& path) {
    const sockaddr_un addr = address_of(path);
    UniqueFd fd;
    const int error = try_connect(path, addr, fd);
    if (error == ECONNREFUSED) {
        throw std::runtime_error(fmt::format(
            "socket {}: no controller is listening there (connection refused); start one with "
            "`fb89 controller --listen {}`",
            path, path));
    }
    if (error == ENOENT) {
        throw std::runtime_error(fmt::format(
            "socket {}: no such socket; start a controller with `fb89 controller --listen {}`",
            path, path));
    }
    if (error != 0) fail(path, "cannot connect to the controller", error);
    return fd;
}

// --- waiting and the reply -----------------------------------------------------------

WaitResult wait_readable(int fd, std::chrono::milliseconds timeout) {
    pollfd p{fd, POLLIN, 0};
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        int ms = -1;
        if (timeout.count() >= 0) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                deadline - std::chrono::steady_clock::now());
            ms = static_cast<int>(std::max<int64_t>(0, left.count()));
        }
        const int n = ::poll(&p, 1, ms);
        if (n > 0) return WaitResult::kReady;
        if (n == 0) return WaitResult::kTimedOut;
        if (errno != EINTR) return WaitResult::kReady;  // the read that follows reports it
    }
}

std::optional<bool> connection_is_empty(int fd, std::chrono::milliseconds timeout) {
    if (wait_readable(fd, timeout) == WaitResult::kTimedOut) return std::nullopt;
    char byte = 0;
    ssize_t n = 0;
    do {
        n = ::recv(fd, &byte, 1, MSG_PEEK | MSG_DONTWAIT);
    } while (n < 0 && errno == EINTR);
    return n == 0;
}

bool send_reply(int fd, const std::string& line) {
    std::string text = line.substr(0, kMaxReply - 1) + "\n";
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::send(fd, text.data() + done, text.size() - done, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

std::optional<std::string> finish_and_read_reply(int fd, const std::string& path,
                                                 std::chrono::milliseconds timeout) {
    if (::shutdown(fd, SHUT_WR) != 0) fail(path, "cannot end the stream", errno);
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    std::string reply;
    char chunk[512];
    while (reply.find('\n') == std::string::npos && reply.size() < kMaxReply) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0 || wait_readable(fd, left) == WaitResult::kTimedOut) {
            throw std::runtime_error(
                fmt::format("socket {}: the controller did not answer within {} s", path,
                            std::chrono::duration_cast<std::chrono::seconds>(timeout).count()));
        }
        const ssize_t n = ::recv(fd, chunk, sizeof(chunk), 0);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail(path, "cannot read the controller's answer", errno);
        if (n == 0) break;
        reply.append(chunk, static_cast<std::size_t>(n));
    }
    const std::size_t end = reply.find('\n');
    if (end == std::string::npos) return std::nullopt;  // closed without a whole line
    return reply.substr(0, end);
}

}  // namespace fb89::protocol
