// Load on `fb89 controller --listen` as its own process: one host streams over a million
// commands in several frames, and several hosts connect at once and are served in turn.
// Every frame must arrive complete with exactly the counts sent: the counts are known
// from how the commands are made, and the checksums come from an in-process
// controller::Controller fed the same commands. Every wait has a generous bound; no
// wall-clock figure is checked (scripts/bench-replay measures throughput).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "controller_sim/controller.h"
#include "protocol/socket_stream.h"
#include "protocol/stream_writer.h"
#include "tests/cli/cli_process.h"
#include "tests/cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using fb89::protocol::Command;
using fb89::protocol::connect_socket;
using fb89::protocol::DrawSpan;
using fb89::protocol::FillRect;
using fb89::protocol::finish_and_read_reply;
using fb89::protocol::FrameBegin;
using fb89::protocol::FrameEnd;
using fb89::protocol::Rgb;
using fb89::protocol::StreamWriter;
using fb89::protocol::UniqueFd;
using fb89::testing::Process;
using fb89::testing::slurp;
using fb89::testing::spawn_fb89;
using fb89::testing::test_dir;
using fb89::testing::wait_until_listening;
namespace controller = fb89::controller;

// Generous: a sanitizer build replays the million commands several times slower.
constexpr auto kGenerousUnderLoad = 120s;
constexpr uint32_t kFrameWidth = 640, kFrameHeight = 480;

// One frame's commands, made on the fly: `count` commands between FRAME_BEGIN and
// FRAME_END, every fifth a FILL_RECT, the rest DRAW_SPANs, all inside the frame.
struct FramePlan {
    uint32_t frame = 0;
    uint32_t count = 0;
    uint64_t spans = 0, span_pixels = 0, fills = 0, fill_pixels = 0;

    template <typename Sink>
    void emit(Sink&& sink) {
        spans = span_pixels = fills = fill_pixels = 0;
        sink(Command{FrameBegin{frame, kFrameWidth, kFrameHeight, Rgb{}}});
        for (uint32_t i = 0; i < count; ++i) {
            const auto shade = static_cast<uint8_t>(i * 7 + frame);
            if (i % 5 == 4) {
                const FillRect f{static_cast<int32_t>((i * 7) % (kFrameWidth - 16)),
                                 static_cast<int32_t>((i * 13) % (kFrameHeight - 16)), 1 + i % 16,
                                 1 + (i / 16) % 16, Rgb{shade, 40, 200}};
                ++fills;
                fill_pixels += uint64_t{f.w} * f.h;
                sink(Command{f});
            } else {
                const auto x0 = static_cast<int32_t>((i * 31) % (kFrameWidth - 128));
                const DrawSpan s{static_cast<int32_t>(i % kFrameHeight), x0,
                                 x0 + static_cast<int32_t>(i % 128), Rgb{200, shade, 40}};
                ++spans;
                span_pixels += static_cast<uint64_t>(s.x1 - s.x0 + 1);
                sink(Command{s});
            }
        }
        sink(Command{FrameEnd{}});
    }
    uint64_t commands() const { return count + 2; }  // with FRAME_BEGIN and FRAME_END
};

// Streams the frames over the socket as one host and returns the controller's answer
// (throws std::runtime_error if it gives none). The same commands go into `model`.
std::string stream_frames(const std::string& socket, const std::string& scene,
                          std::vector<FramePlan>& frames, controller::Controller& model) {
    UniqueFd fd = connect_socket(socket);
    StreamWriter writer(fd.get(), "socket " + socket, {{"scene", scene}});
    for (FramePlan& f : frames) {
        f.emit([&](const Command& c) {
            writer.submit(c);
            model.execute(c);
        });
    }
    writer.close();
    std::optional<std::string> reply = finish_and_read_reply(fd.get(), socket, kGenerousUnderLoad);
    if (!reply) throw std::runtime_error("the controller closed without answering");
    return *reply;
}

// One frame of the controller's --stats against what was sent and the model's result.
void expect_frame(const nlohmann::json& got, const FramePlan& sent,
                  const controller::FrameResult& model) {
    SCOPED_TRACE(fmt::format("frame {}", sent.frame));
    EXPECT_EQ(got["frame"].get<uint32_t>(), sent.frame);
    EXPECT_TRUE(got["complete"].get<bool>());
    const nlohmann::json& ops = got["opcodes"];
    EXPECT_EQ(ops["all"]["commands"].get<uint64_t>(), sent.commands());
    EXPECT_EQ(ops["DRAW_SPAN"]["commands"].get<uint64_t>(), sent.spans);
    EXPECT_EQ(ops["DRAW_SPAN"]["pixels"].get<uint64_t>(), sent.span_pixels);
    EXPECT_EQ(ops["FILL_RECT"]["commands"].get<uint64_t>(), sent.fills);
    EXPECT_EQ(ops["FILL_RECT"]["pixels"].get<uint64_t>(), sent.fill_pixels);
    for (const char* op : {"DRAW_SPAN", "FILL_RECT"}) {
        EXPECT_EQ(ops[op]["clipped"].get<uint64_t>(), 0u) << op;
        EXPECT_EQ(ops[op]["outside"].get<uint64_t>(), 0u) << op;
    }
    EXPECT_EQ(ops["all"]["cycles"].get<uint64_t>(), model.total().cycles);
    EXPECT_EQ(got["checksum"].get<std::string>(), fmt::format("{:016x}", model.checksum));
}

class ControllerLoad : public ::testing::Test {
  protected:
    void SetUp() override {
        m_socket = "/tmp/fb89-load-test-" + std::to_string(::getpid()) + "-" +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".sock";
        fs::remove(m_socket);
    }
    void TearDown() override { fs::remove(m_socket); }

    Process start_controller(const std::vector<std::string>& extra) {
        std::vector<std::string> args = {"controller", "--listen", m_socket};
        args.insert(args.end(), extra.begin(), extra.end());
        Process p = spawn_fb89(args, "controller");
        if (!wait_until_listening(m_socket, kGenerousUnderLoad))
            ADD_FAILURE() << "the controller did not listen on " << m_socket;
        return p;
    }

    std::string m_socket;
};

// 5 frames of 200,002 commands (160,000 spans, 40,000 fills): 1,000,010 commands.
TEST_F(ControllerLoad, MillionCommandStreamKeepsEveryFrameAndItsCounts) {
    const fs::path stats = test_dir() / "stats.json";
    Process ctl = start_controller({"--once", "--stats", stats.string()});
    std::vector<FramePlan> frames;
    for (uint32_t f = 0; f < 5; ++f)
        frames.push_back(FramePlan{f, 200'000});
    controller::Controller model;
    const std::string reply = stream_frames(m_socket, "load-one-host", frames, model);
    uint64_t commands = 0;
    for (const FramePlan& f : frames)
        commands += f.commands();
    ASSERT_GE(commands, 1'000'000u);
    EXPECT_EQ(reply, fmt::format("ok {} commands, 5 frames", commands));
    ASSERT_EQ(ctl.wait(kGenerousUnderLoad), 0) << slurp(ctl.err);

    const std::string out = slurp(ctl.out);
    for (const FramePlan& f : frames)
        EXPECT_NE(
            out.find(fmt::format("frame {} (connection 1): {} commands,", f.frame, f.commands())),
            std::string::npos)
            << out;
    EXPECT_NE(out.find(fmt::format("stream complete: 5 frames, {} commands", commands)),
              std::string::npos)
        << out;

    const nlohmann::json j = nlohmann::json::parse(slurp(stats));
    ASSERT_EQ(j["connections"].size(), 1u);
    EXPECT_TRUE(j["connections"][0]["complete"].get<bool>());
    EXPECT_EQ(j["connections"][0]["commands"].get<uint64_t>(), commands);
    EXPECT_EQ(j["connections"][0]["frames_kept"].get<uint64_t>(), 5u);
    const nlohmann::json& c = j["controller"];
    EXPECT_EQ(c["frames_closed"].get<uint64_t>(), 5u);
    EXPECT_EQ(c["frames_incomplete"].get<uint64_t>(), 0u);
    EXPECT_EQ(c["totals"]["all"]["commands"].get<uint64_t>(), commands);
    EXPECT_EQ(c["unframed"]["all"]["commands"].get<uint64_t>(), 0u);
    ASSERT_EQ(c["frames"].size(), 5u);
    ASSERT_EQ(model.frames().size(), 5u);
    for (std::size_t i = 0; i < frames.size(); ++i)
        expect_frame(c["frames"][i], frames[i], model.frames()[i]);
}

// 4 host processes connect at once, 3 frames each; the controller serves them in turn
// (the others wait in the backlog) and keeps all 12 frames.
TEST_F(ControllerLoad, SeveralHostsInTurnKeepEveryFrame) {
    constexpr int kHosts = 4, kFrames = 3;
    const fs::path stats = test_dir() / "stats.json";
    Process ctl =
        start_controller({"--max-clients", std::to_string(kHosts), "--stats", stats.string()});
    auto plan = [](int host) {
        std::vector<FramePlan> frames;
        for (int f = 0; f < kFrames; ++f)
            frames.push_back(FramePlan{static_cast<uint32_t>(100 * host + f),
                                       static_cast<uint32_t>(30'000 + 1'000 * host + f)});
        return frames;
    };
    std::vector<pid_t> hosts;
    for (int h = 0; h < kHosts; ++h) {
        const pid_t pid = ::fork();
        if (pid == 0) {  // a host: exit 0 only if the controller answers ok with our counts
            try {
                std::vector<FramePlan> frames = plan(h);
                controller::Controller model;
                const std::string reply =
                    stream_frames(m_socket, fmt::format("load-host-{}", h), frames, model);
                ::_exit(reply == fmt::format("ok {} commands, {} frames", model.commands_executed(),
                                             kFrames)
                            ? 0
                            : 1);
            } catch (...) {
                ::_exit(3);
            }
        }
        hosts.push_back(pid);
    }
    for (pid_t pid : hosts) {
        Process host;
        host.pid = pid;
        EXPECT_EQ(host.wait(kGenerousUnderLoad), 0) << "host process " << pid;
    }
    ASSERT_EQ(ctl.wait(kGenerousUnderLoad), 0) << slurp(ctl.err);
    const std::string out = slurp(ctl.out);
    EXPECT_NE(out.find(fmt::format("all {} connections: {} frames kept, 0 cut", kHosts,
                                   kHosts * kFrames)),
              std::string::npos)
        << out;

    // connections in the order served; their frames follow in the same order
    const nlohmann::json j = nlohmann::json::parse(slurp(stats));
    ASSERT_EQ(j["connections"].size(), static_cast<std::size_t>(kHosts));
    const nlohmann::json& frames_json = j["controller"]["frames"];
    ASSERT_EQ(frames_json.size(), static_cast<std::size_t>(kHosts * kFrames));
    std::vector<bool> seen(kHosts, false);
    uint64_t all_commands = 0;
    for (int k = 0; k < kHosts; ++k) {
        const nlohmann::json& conn = j["connections"][static_cast<std::size_t>(k)];
        const std::string host = conn["host"].get<std::string>();
        const int h = host.back() - '0';
        ASSERT_EQ(host, fmt::format("scene load-host-{}", h));
        ASSERT_FALSE(seen[h]) << host;
        seen[h] = true;
        EXPECT_TRUE(conn["complete"].get<bool>()) << host;
        EXPECT_EQ(conn["frames_kept"].get<int>(), kFrames) << host;
        std::vector<FramePlan> frames = plan(h);
        controller::Controller model;
        for (FramePlan& f : frames)
            f.emit([&](const Command& c) { model.execute(c); });
        EXPECT_EQ(conn["commands"].get<uint64_t>(), model.commands_executed()) << host;
        all_commands += model.commands_executed();
        for (int f = 0; f < kFrames; ++f)
            expect_frame(frames_json[static_cast<std::size_t>(k * kFrames + f)], frames[f],
                         model.frames()[f]);
    }
    EXPECT_EQ(j["controller"]["totals"]["all"]["commands"].get<uint64_t>(), all_commands);
}

}  // namespace
