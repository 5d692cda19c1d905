// The Unix-domain socket transport (protocol/socket_stream.h) and the stream writer and
// reader on socket descriptors: a stream crosses intact, a vanished peer is an error and
// never a signal or a hang, stale socket files are replaced and live ones refused.
#include "protocol/socket_stream.h"

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include "protocol/stream_reader.h"
#include "protocol/stream_writer.h"
#include "tests/protocol/sample_streams.h"

namespace fb89::protocol {
namespace {

using namespace std::chrono_literals;
using testing::sample_properties;
using testing::two_frames;

// A socket path of this test's own under /tmp, removed at the end.
class SocketStream : public ::testing::Test {
  protected:
    void SetUp() override {
        m_path = "/tmp/fb89-sock-test-" + std::to_string(::getpid()) + "-" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".sock";
        std::filesystem::remove(m_path);
    }
    void TearDown() override { std::filesystem::remove(m_path); }
    std::string m_path;
};

// Two connected sockets, as a host and controller would hold them.
std::pair<UniqueFd, UniqueFd> socket_pair() {
    int fds[2];
    EXPECT_EQ(::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds), 0);
    return {UniqueFd(fds[0]), UniqueFd(fds[1])};
}

void send_all(int fd, const std::vector<uint8_t>& bytes) {
    ASSERT_EQ(::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL),
              static_cast<ssize_t>(bytes.size()));
}

TEST_F(SocketStream, StreamCrossesTheSocketAndTheControllerAnswers) {
    SocketListener listener(m_path);
    std::vector<Command> received;
    bool indexed = false;
    std::thread controller([&] {
        std::optional<UniqueFd> conn = listener.accept();
        ASSERT_TRUE(conn);
        StreamReader reader(conn->get(), "socket", 20s);
        EXPECT_EQ(reader.properties(), sample_properties());
        Command c;
        while (reader.next(c))
            received.push_back(c);
        indexed = reader.frame_index().has_value();
        EXPECT_TRUE(send_reply(conn->get(), "ok 9 commands, 2 frames"));
    });
    UniqueFd host = connect_socket(m_path);
    StreamWriter writer(host.get(), "socket " + m_path, sample_properties());
    for (const Command& c : two_frames())
        writer.submit(c);
    writer.close();
    EXPECT_EQ(writer.commands_flushed(), two_frames().size());
    std::optional<std::string> reply = finish_and_read_reply(host.get(), m_path, 20s);
    controller.join();
    EXPECT_EQ(reply, "ok 9 commands, 2 frames");
    EXPECT_EQ(received, two_frames());
    EXPECT_TRUE(indexed);
}

TEST_F(SocketStream, ConnectingWhereNobodyListensNamesThePath) {
    try {
        connect_socket(m_path);
        FAIL() << "connected to nothing";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(m_path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no such socket"), std::string::npos) << e.what();
    }
    { SocketListener gone(m_path); }  // a listener that has closed: its file is removed
    EXPECT_FALSE(std::filesystem::exists(m_path));
}

TEST_F(SocketStream, StaleSocketFileIsReplacedAndALiveOneRefused) {
    // a socket file left by a process that died: bound, never unlinked
    {
        UniqueFd dead(::socket(AF_UNIX, SOCK_STREAM, 0));
        sockaddr_un addr{};
        addr.sun_family = AF_UNIX;
        std::strncpy(addr.sun_path, m_path.c_str(), sizeof(addr.sun_path) - 1);
        ASSERT_EQ(::bind(dead.get(), reinterpret_cast<sockaddr*>(&addr), sizeof(addr)), 0);
    }
    ASSERT_TRUE(std::filesystem::exists(m_path));
    EXPECT_THROW(connect_socket(m_path), std::runtime_error);  // refused: nobody listens
    SocketListener live(m_path);
    try {
        SocketListener second(m_path);
        FAIL() << "two listeners on one path";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("in use"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(m_path), std::string::npos) << e.what();
    }
}

TEST_F(SocketStream, PathThatIsNotASocketIsNotReplaced) {
    std::ofstream(m_path) << "precious";
    EXPECT_THROW(SocketListener listener(m_path), std::runtime_error);
    EXPECT_EQ(std::filesystem::file_size(m_path), 8u);
}

TEST_F(SocketStream, AcceptReturnsNothingWhenWoken) {
    SocketListener listener(m_path);
    int wake[2];
    ASSERT_EQ(::pipe(wake), 0);
    ASSERT_EQ(::write(wake[1], "x", 1), 1);
    EXPECT_FALSE(listener.accept(wake[0]));
    ::close(wake[0]);
    ::close(wake[1]);
}

TEST(SocketTransport, WriterToAVanishedReaderThrowsInsteadOfSigpipe) {
    auto [host, controller] = socket_pair();
    controller.reset();  // the controller dies
    StreamWriter writer(host.get(), "socket test", {});
    writer.frame_begin(FrameBegin{0, 8, 6, Rgb{}});
    try {
        writer.frame_end(FrameEnd{});  // flushes
        FAIL() << "wrote to a closed socket";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("socket test"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("Broken pipe"), std::string::npos) << e.what();
    }
    EXPECT_EQ(writer.commands_flushed(), 0u);
}

// Version 1 delivers every complete command of the frame cut short; version 4 a batch at a
// time, checked whole, so none of the cut batch (the frame's, here).
TEST(SocketTransport, ReaderDeliversCompleteCommandsThenReportsTheCut) {
    for (const Checksums checksums : {Checksums::Off, Checksums::On}) {
        auto [host, controller] = socket_pair();
        std::vector<uint8_t> bytes = encode_stream(two_frames(), {}, false, checksums);
        bytes.resize(bytes.size() - 10);  // the host dies inside the second frame's DRAW_SPAN
        send_all(host.get(), bytes);
        host.reset();
        StreamReader reader(controller.get(), "socket test", 20s);
        Command c;
        std::size_t delivered = 0;
        const std::size_t complete = checksums == Checksums::On ? 5 : 6;
        try {
            while (reader.next(c))
                ++delivered;
            FAIL() << "a cut record read as complete";
        } catch (const StreamError& e) {
            EXPECT_NE(
                std::string(e.what()).find(checksums == Checksums::On ? "truncated batch 1 at byte"
                                                                      : "truncated DRAW_SPAN"),
                std::string::npos)
                << e.what();
            EXPECT_EQ(e.command(), complete);
        }
        EXPECT_EQ(delivered, complete);
    }
}

TEST(SocketTransport, QuietPeerIsCutAfterTheIdleTimeout) {
    auto [host, controller] = socket_pair();
    send_all(host.get(), encode_stream({FrameBegin{0, 8, 6, Rgb{}}}, {}, false));
    StreamReader reader(controller.get(), "socket test", 50ms);
    Command c;
    ASSERT_TRUE(reader.next(c));
    try {
        reader.next(c);
        FAIL() << "waited past the idle time-out";
    } catch (const StreamError& e) {
        EXPECT_NE(std::string(e.what()).find("idle time-out"), std::string::npos) << e.what();
        EXPECT_EQ(e.command(), 1u);
    }
}

TEST(SocketTransport, ControllerClosingWithoutAnAnswerIsNoReply) {
    auto [host, controller] = socket_pair();
    controller.reset();
    EXPECT_EQ(finish_and_read_reply(host.get(), "test", 20s), std::nullopt);
}

TEST(SocketTransport, EmptyConnectionIsTellable) {
    auto [host, controller] = socket_pair();
    EXPECT_EQ(connection_is_empty(controller.get(), 0ms), std::nullopt);  // nothing yet
    send_all(host.get(), {1});
    EXPECT_EQ(connection_is_empty(controller.get(), 20s), false);
    auto [probe, listener_side] = socket_pair();
    probe.reset();
    EXPECT_EQ(connection_is_empty(listener_side.get(), 20s), true);
}

}  // namespace
}  // namespace fb89::protocol
