// The Unix-domain socket transport between a host and a separate `fb89 controller`
// process (DESIGN.md "Protocol", docs/PROTOCOL.md "Transports: the controller socket").
//
// A connection carries exactly one fb89 stream, host to controller, in the file format
// (header, commands, frame index); StreamWriter and StreamReader take the connected file
// descriptor. After the stream the host shuts down its sending side and the controller
// answers with one line of text: "ok ..." or "error ...". This file only moves bytes:
// it creates and accepts sockets, connects, waits with time-outs and reads the answer.
// Every error names the socket path; nothing here ever waits without a bound unless the
// caller asks for it (a listener waiting for its next host).
#pragma once

#include <chrono>
#include <optional>
#include <string>

namespace fb89::protocol {

// Owns one file descriptor and closes it.
class UniqueFd {
  public:
    UniqueFd() = default;
    explicit UniqueFd(int fd) : m_fd(fd) {}
    ~UniqueFd() { reset(); }
    UniqueFd(UniqueFd&& o) noexcept : m_fd(o.release()) {}
    UniqueFd& operator=(UniqueFd&& o) noexcept;
    UniqueFd(const UniqueFd&) = delete;
    UniqueFd& operator=(const UniqueFd&) = delete;

    int get() const { return m_fd; }
    explicit operator bool() const { return m_fd >= 0; }
    int release();
    void reset(int fd = -1);

  private:
    int m_fd = -1;
};

// A listening socket at a path, accepting one host connection at a time (the controller
// serves hosts in turn; others wait in the backlog).
class SocketListener {
  public:
    // Creates the socket file. A stale socket file (nobody accepts on it) is removed; a
    // path in use by a live listener, or that exists and is not a socket, is refused.
    // Throws std::runtime_error naming the path.
    explicit SocketListener(std::string path);
    // Closes the socket and removes its file.
    ~SocketListener();
    SocketListener(const SocketListener&) = delete;
    SocketListener& operator=(const SocketListener&) = delete;

    const std::string& path() const { return m_path; }
    int fd() const { return m_fd.get(); }

    // Waits for the next host. Returns its connection, or nullopt as soon as wake_fd (if
    // not -1) becomes readable: a signal handler writes to it to stop the server. Throws
    // std::runtime_error naming the path on failure.
    std::optional<UniqueFd> accept(int wake_fd = -1);

  private:
    std::string m_path;
    UniqueFd m_fd;
};

// Connects to a controller listening at path. Throws std::runtime_error naming the path
// and saying why (no such file, nobody listening, not a socket).
UniqueFd connect_socket(const std::string& path);

// What waiting for a descriptor came to.
enum class WaitResult { kReady, kTimedOut };
// Waits until fd is readable (data, end of stream or an error). timeout < 0: no bound.
WaitResult wait_readable(int fd, std::chrono::milliseconds timeout);

// Whether the peer closed the connection without sending a byte (waits for the first
// byte or the end, at most timeout; nullopt when it timed out). Reads nothing.
std::optional<bool> connection_is_empty(int fd, std::chrono::milliseconds timeout);

// The controller's answer after a stream: one line, at most 4 KiB. Sends it ignoring
// errors (the host may be gone): returns false if it could not be sent.
bool send_reply(int fd, const std::string& line);
// The host's side: shuts down its sending half (so the controller sees the stream end),
// then reads the answer line. Returns the line without its newline; nullopt if the
// controller closed the connection without answering. Throws std::runtime_error naming
// path when the wait passes timeout or the read fails.
std::optional<std::string> finish_and_read_reply(int fd, const std::string& path,
                                                 std::chrono::milliseconds timeout);

}  // namespace fb89::protocol
