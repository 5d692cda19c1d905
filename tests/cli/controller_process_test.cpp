// `fb89 controller --listen` as its own process, with `fb89 render --connect` and with
// hand-made hosts: the image crosses intact, hosts are served in turn, and when either
// side dies mid-stream the other says so and exits non-zero promptly. Every wait has a
// generous bound (20 s or more); none of them is a timing the test checks.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <thread>

#include <nlohmann/json.hpp>

#include "controller_sim/png_io.h"
#include "protocol/socket_stream.h"
#include "protocol/stream_writer.h"
#include "tests/cli/cli_process.h"
#include "tests/cli/cli_runner.h"
#include "tests/scenes_dir.h"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using fb89::protocol::Checksums;
using fb89::protocol::Command;
using fb89::protocol::connect_socket;
using fb89::protocol::DrawSpan;
using fb89::protocol::encode_stream;
using fb89::protocol::FillRect;
using fb89::protocol::FrameBegin;
using fb89::protocol::FrameEnd;
using fb89::protocol::Rgb;
using fb89::protocol::SocketListener;
using fb89::protocol::StreamWriter;
using fb89::protocol::UniqueFd;
using fb89::protocol::wait_readable;
using fb89::protocol::WaitResult;
using fb89::testing::CliRun;
using fb89::testing::Process;
using fb89::testing::slurp;
using fb89::testing::spawn_fb89;
using fb89::testing::test_dir;
using fb89::testing::wait_until_listening;

using fb89::testing::kScenes;
constexpr auto kGenerous = 30s;

class ControllerProcess : public ::testing::Test {
  protected:
    void SetUp() override {
        m_socket = "/tmp/fb89-ctl-test-" + std::to_string(::getpid()) + "-" +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".sock";
        fs::remove(m_socket);
    }
    void TearDown() override { fs::remove(m_socket); }

    Process start_controller(std::vector<std::string> args) {
        args.insert(args.begin(), {"controller", "--listen", m_socket});
        Process p = spawn_fb89(args, "controller");
        if (!wait_until_listening(m_socket, kGenerous))
            ADD_FAILURE() << "the controller did not listen on " << m_socket;
        return p;
    }

    CliRun render(const std::string& scene, const std::string& size, const std::string& extra) {
        return fb89::testing::run_fb89("render " + kScenes + "/" + scene + " --size " + size +
                                       " --connect " + m_socket + " " + extra);
    }

    std::string m_socket;
};

TEST_F(ControllerProcess, ControllerImageEqualsInProcessRender) {
    const fs::path remote = test_dir() / "controller.png", local = test_dir() / "host.png";
    Process ctl = start_controller({"--once", "--png", remote.string()});
    CliRun host = render("A.json", "256x195", "--png " + local.string());
    EXPECT_EQ(host.exit_code, 0) << host.err;
    EXPECT_NE(host.err.find("controller at " + m_socket + ": ok "), std::string::npos) << host.err;
    EXPECT_EQ(ctl.wait(kGenerous), 0) << slurp(ctl.err);
    const std::string out = slurp(ctl.out);
    EXPECT_NE(out.find("frame 0 (connection 1)"), std::string::npos) << out;
    EXPECT_NE(out.find("stream complete: 1 frames"), std::string::npos) << out;
    const auto a = fb89::controller::read_png(remote), b = fb89::controller::read_png(local);
    EXPECT_EQ(a.width, 256u);
    EXPECT_EQ(a.height, 195u);
    EXPECT_EQ(a.pixels, b.pixels);
}

TEST_F(ControllerProcess, TwoHostsInTurnAreBothKept) {
    const fs::path stats = test_dir() / "stats.json";
    Process ctl = start_controller({"--max-clients", "2", "--stats", stats.string()});
    EXPECT_EQ(render("A.json", "128x98", "").exit_code, 0);
    EXPECT_EQ(render("B.json", "128x98", "").exit_code, 0);
    EXPECT_EQ(ctl.wait(kGenerous), 0) << slurp(ctl.err);
    const std::string out = slurp(ctl.out);
    EXPECT_NE(out.find("connection 2 (scene"), std::string::npos) << out;
    EXPECT_NE(out.find("all 2 connections: 2 frames kept, 0 cut"), std::string::npos) << out;
    nlohmann::json j = nlohmann::json::parse(slurp(stats));
    ASSERT_EQ(j["connections"].size(), 2u);
    EXPECT_TRUE(j["connections"][1]["complete"].get<bool>());
    EXPECT_EQ(j["controller"]["frames_closed"], 2);
    const uint64_t commands = j["connections"][0]["commands"].get<uint64_t>() +
                              j["connections"][1]["commands"].get<uint64_t>();
    EXPECT_EQ(j["controller"]["totals"]["all"]["commands"].get<uint64_t>(), commands) << j.dump();
}

// A host that sends frame 0 whole, then frame 1's FRAME_BEGIN, two fills and half a
// record, and is killed. In format version 1, whose commands are read one by one (version 4
// reads a batch whole: a cut batch delivers none, stream_checksum_test.cpp).
TEST_F(ControllerProcess, HostKilledMidStreamDropsOnlyThePartialFrame) {
    const fs::path stats = test_dir() / "stats.json";
    Process ctl = start_controller({"--once", "--stats", stats.string()});
    const std::vector<Command> commands = {FrameBegin{0, 16, 12, Rgb{}},
                                           FillRect{0, 0, 4, 4, Rgb{255, 0, 0}},
                                           DrawSpan{3, 0, 9, Rgb{0, 255, 0}},
                                           FillRect{8, 8, 4, 4, Rgb{0, 0, 255}},
                                           FrameEnd{},
                                           FrameBegin{1, 16, 12, Rgb{}},
                                           FillRect{1, 1, 2, 2, Rgb{9, 9, 9}},
                                           FillRect{2, 2, 2, 2, Rgb{8, 8, 8}},
                                           FillRect{3, 3, 2, 2, Rgb{7, 7, 7}}};
    std::vector<uint8_t> bytes =
        encode_stream(commands, {{"scene", "killed-host"}}, false, Checksums::Off);
    bytes.resize(bytes.size() - 9);  // the last FILL_RECT is cut in half
    const pid_t host = ::fork();
    if (host == 0) {
        try {
            UniqueFd fd = connect_socket(m_socket);
            if (::send(fd.get(), bytes.data(), bytes.size(), MSG_NOSIGNAL) < 0) ::_exit(3);
        } catch (...) {
            ::_exit(3);
        }
        ::raise(SIGKILL);
    }
    ::waitpid(host, nullptr, 0);
    EXPECT_EQ(ctl.wait(kGenerous), 2);
    const std::string err = slurp(ctl.err);
    EXPECT_NE(err.find("host closed the connection in frame 1 after command 7: partial frame "
                       "(3 commands) dropped; 1 complete frames kept"),
              std::string::npos)
        << err;
    EXPECT_NE(err.find("truncated FILL_RECT"), std::string::npos) << err;
    nlohmann::json j = nlohmann::json::parse(slurp(stats));
    EXPECT_EQ(j["controller"]["frames_closed"], 1);
    EXPECT_EQ(j["controller"]["totals"]["all"]["commands"], 5) << j.dump();
    EXPECT_EQ(j["connections"][0]["partial_frame"]["commands"], 3);
}

TEST_F(ControllerProcess, QuietHostIsCutAfterTheIdleTimeout) {
    Process ctl = start_controller({"--once", "--idle-timeout", "0.2"});
    UniqueFd silent = connect_socket(m_socket);  // connects, then sends nothing
    EXPECT_EQ(ctl.wait(kGenerous), 2);
    const std::string err = slurp(ctl.err);
    EXPECT_NE(err.find("idle time-out"), std::string::npos) << err;
    EXPECT_NE(err.find(m_socket), std::string::npos) << err;
}

TEST_F(ControllerProcess, HostReportsAControllerThatIsKilledMidStream) {
    Process ctl = start_controller({});
    UniqueFd fd = connect_socket(m_socket);
    StreamWriter writer(fd.get(), "socket " + m_socket, {});
    writer.frame_begin(FrameBegin{0, 64, 48, Rgb{}});
    writer.frame_end(FrameEnd{});
    ::kill(ctl.pid, SIGKILL);
    EXPECT_EQ(ctl.wait(kGenerous), -SIGKILL);
    const auto start = std::chrono::steady_clock::now();
    std::string error;
    try {
        for (uint32_t frame = 1; frame < 1000 && error.empty(); ++frame) {
            writer.frame_begin(FrameBegin{frame, 64, 48, Rgb{}});
            for (int i = 0; i < 1000; ++i)
                writer.draw_span(DrawSpan{i % 48, 0, 63, Rgb{1, 2, 3}});
            writer.frame_end(FrameEnd{});
        }
    } catch (const std::runtime_error& e) {
        error = e.what();
    }
    EXPECT_LT(std::chrono::steady_clock::now() - start, kGenerous);
    EXPECT_NE(error.find(m_socket), std::string::npos) << error;
    EXPECT_LT(writer.commands_flushed(), 1000u * 1002u);
}

// A stand-in controller that reads the header and a little more, then disappears while
// the host is still sending.
TEST_F(ControllerProcess, RenderSaysTheControllerWentAwayAndExitsTwo) {
    SocketListener listener(m_socket);
    std::thread vanishing([&] {
        if (wait_readable(listener.fd(), kGenerous) == WaitResult::kTimedOut) return;
        std::optional<UniqueFd> conn = listener.accept();
        char some[256];
        if (conn) (void)::recv(conn->get(), some, sizeof(some), 0);
    });  // the connection closes here, unread bytes and all
    CliRun host = render("F.json", "1024x780", "");  // 82,048 commands: more than a socket holds
    vanishing.join();
    EXPECT_EQ(host.exit_code, 2) << host.err;
    EXPECT_NE(host.err.find("the controller at " + m_socket + " went away mid-stream"),
              std::string::npos)
        << host.err;
    EXPECT_NE(host.err.find(" of 82048 commands had got through"), std::string::npos) << host.err;
}

TEST_F(ControllerProcess, ConnectingWhereNobodyListensExitsTwoNamingThePath) {
    CliRun host = render("A.json", "64x48", "");
    EXPECT_EQ(host.exit_code, 2);
    EXPECT_NE(host.err.find(m_socket), std::string::npos) << host.err;
}

TEST_F(ControllerProcess, SecondControllerIsRefusedAndSigtermRemovesTheSocket) {
    Process first = start_controller({});
    Process second = spawn_fb89({"controller", "--listen", m_socket}, "second");
    EXPECT_EQ(second.wait(kGenerous), 2);
    const std::string err = slurp(second.err);
    EXPECT_NE(err.find("in use"), std::string::npos) << err;
    EXPECT_NE(err.find(m_socket), std::string::npos) << err;
    ::kill(first.pid, SIGTERM);
    EXPECT_EQ(first.wait(kGenerous), 0) << slurp(first.err);
    EXPECT_FALSE(fs::exists(m_socket));
}

}  // namespace
