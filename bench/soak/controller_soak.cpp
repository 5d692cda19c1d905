// The controller soak: one `fb89 controller --listen SOCK --max-clients N --stats FILE
// --profile ideal -q` child, and N hosts in turn, each
//   fb89 render SCENE -m METHOD --connect SOCK --profile ideal --stats host.json -q
// which must exit 0 (the controller answered "ok"). After the first host, every K-th and
// the last but one (after the last the controller exits), once the controller is back
// waiting for the next host, its VmRSS and descriptors are sampled. At the end the
// controller must exit 0 with its socket file removed, and its --stats must list N
// complete connections, each with the commands its host sent, and N complete frames with
// the checksums the hosts computed locally: no frame lost, none changed on the way.
//
// With --no-controller-stats the controller runs without --stats (which keeps a record of
// every frame it served), and each host's "ok C commands, F frames" answer is checked
// instead: one frame, every command.
#include <chrono>
#include <fstream>
#include <regex>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/soak/soak_modes.h"
#include "bench/soak/subprocess.h"
#include "protocol/socket_stream.h"

namespace fb89::soak {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace std::chrono_literals;

// What a host sent, from its own --stats, and what the controller answered it.
struct Sent {
    bool ok = false;
    std::string method;
    uint64_t commands = 0;
    std::string checksum;                           // of its local controller's frame
    uint64_t reply_commands = 0, reply_frames = 0;  // without the controller's --stats
};

json read_json(const fs::path& file) {
    std::ifstream in(file);
    return json::parse(in);
}

class ControllerSoak {
  public:
    ControllerSoak(const SoakOptions& options, const fs::path& dir)
        : m_options(options),
          m_dir(dir),
          m_fb89(fs::absolute(options.fb89).string()),
          m_socket((dir / "controller.sock").string()),
          m_stats(dir / "controller.json") {
        m_sent.reserve(static_cast<std::size_t>(options.cycles));
    }

    void start();
    // One host; false when the controller is gone.
    bool serve_host(const Pair& pair, SoakResult& r, int cycle);
    // Waits (bounded) until the controller is back in its accept loop.
    void wait_idle();
    pid_t pid() const { return m_controller.pid(); }
    // After the last host: the exit, the socket file, and the frames against what was sent.
    void finish(SoakResult& r);

  private:
    void read_reply(Sent& sent);
    void check_connections(const json& stats, SoakResult& r);
    void check_replies(SoakResult& r);

    const SoakOptions& m_options;
    fs::path m_dir;
    std::string m_fb89, m_socket;
    fs::path m_stats;
    ChildProcess m_controller;
    std::vector<Sent> m_sent;
};

void ControllerSoak::start() {
    std::vector<std::string> argv{m_fb89,      "controller",    "--listen",
                                  m_socket,    "--max-clients", std::to_string(m_options.cycles),
                                  "--profile", "ideal",         "-q"};
    if (m_options.controller_stats) argv.insert(argv.end(), {"--stats", m_stats.string()});
    m_controller =
        ChildProcess::spawn(argv, m_dir, m_dir / "controller.stdout", m_dir / "controller.stderr");
    const auto deadline = std::chrono::steady_clock::now() + 30s;
    for (;;) {
        try {
            protocol::connect_socket(m_socket);  // an empty probe, which it ignores
            return;
        } catch (const std::runtime_error&) {
        }
        if (auto code = m_controller.try_wait())
            throw std::runtime_error(fmt::format("fb89 controller: {} before listening: {}",
                                                 describe_exit(*code),
                                                 head_of_file(m_dir / "controller.stderr")));
        if (std::chrono::steady_clock::now() > deadline)
            throw std::runtime_error("fb89 controller: not listening after 30 s");
        std::this_thread::sleep_for(2ms);
    }
}

// "controller at SOCK: ok 1234 commands, 1 frames (...)" on the host's stderr.
void ControllerSoak::read_reply(Sent& sent) {
    static const std::regex kReply(R"(: ok (\d+) commands, (\d+) frames)");
    const std::string err = head_of_file(m_dir / "host.stderr", 4096);
    std::smatch m;
    if (!std::regex_search(err, m, kReply)) return;
    sent.reply_commands = std::stoull(m[1]);
    sent.reply_frames = std::stoull(m[2]);
}

bool ControllerSoak::serve_host(const Pair& pair, SoakResult& r, int cycle) {
    fs::remove(m_dir / "host.json");
    Sent& sent = m_sent.emplace_back();
    sent.method = pair.method;
    std::vector<std::string> argv{m_fb89,      "render", pair.scene.string(), "-m",    pair.method,
                                  "--connect", m_socket, "--profile",         "ideal", "--stats",
                                  "host.json"};
    if (m_options.controller_stats) argv.push_back("-q");  // else its answer is read
    const int code = run_process(argv, m_dir, m_dir / "host.stdout", m_dir / "host.stderr",
                                 std::chrono::seconds(m_options.child_timeout_s));
    if (code != 0) {
        r.fail(fmt::format("cycle {} ({}): fb89 render --connect: {}: {}", cycle, pair.label(),
                           describe_exit(code), head_of_file(m_dir / "host.stderr")));
    } else {
        const json host = read_json(m_dir / "host.json");
        sent.ok = true;
        sent.commands = host.at("host").at("commands").get<uint64_t>();
        sent.checksum = host.at("controller").at("frames").at(0).at("checksum").get<std::string>();
        if (!m_options.controller_stats) read_reply(sent);
    }
    const bool last = cycle + 1 == m_options.cycles;  // after which it exits
    if (auto gone = last ? std::nullopt : m_controller.try_wait()) {
        r.fail(fmt::format("cycle {}: the controller ended early: {}: {}", cycle,
                           describe_exit(*gone), head_of_file(m_dir / "controller.stderr")));
        return false;
    }
    return true;
}

void ControllerSoak::wait_idle() {
    const auto deadline = std::chrono::steady_clock::now() + 30s;
    while (!asleep_in_poll(pid())) {
        if (std::chrono::steady_clock::now() > deadline)
            throw std::runtime_error("the controller did not go back to waiting within 30 s");
        std::this_thread::sleep_for(200us);
    }
}

void ControllerSoak::check_connections(const json& stats, SoakResult& r) {
    const json& connections = stats.at("connections");
    const json& frames = stats.at("controller").at("frames");
    if (connections.size() != m_sent.size())
        r.fail(fmt::format("the controller served {} connections of {}", connections.size(),
                           m_sent.size()));
    std::size_t frame = 0;  // frames are kept in connection order
    for (std::size_t i = 0; i < connections.size() && i < m_sent.size(); ++i) {
        const json& c = connections[i];
        const Sent& s = m_sent[i];
        const uint64_t kept = c.at("frames_kept").get<uint64_t>();
        r.commands_checked += c.at("commands").get<uint64_t>();
        if (kept == 0 || frame >= frames.size() || !frames[frame].at("complete").get<bool>()) {
            r.fail(fmt::format("connection {}: no complete frame kept ({})", i + 1, c.dump()));
            frame += kept;
            continue;
        }
        r.frames_received += 1;
        std::string problem;
        if (!c.at("complete").get<bool>())
            problem = "the stream was cut: " + c.dump();
        else if (kept != 1)
            problem = fmt::format("{} frames kept, one sent", kept);
        else if (!s.ok)
            problem = "its host failed, yet a frame arrived";
        else if (c.at("commands").get<uint64_t>() != s.commands)
            problem =
                fmt::format("{} commands received, {} sent", c.at("commands").dump(), s.commands);
        else if (frames[frame].at("checksum") != s.checksum)
            problem = fmt::format("checksum {} received, {} rendered",
                                  frames[frame].at("checksum").dump(), s.checksum);
        else if (c.at("host").get<std::string>().find("method " + s.method) == std::string::npos)
            problem = "served out of order: " + c.at("host").get<std::string>();
        frame += kept;
        if (problem.empty()) continue;
        ++r.frames_mismatched;
        r.fail(fmt::format("connection {}: {}", i + 1, problem));
    }
    const json& ctl = stats.at("controller");
    if (ctl.at("frames_closed") != m_sent.size() || ctl.at("frames_incomplete") != 0)
        r.fail(fmt::format("the controller closed {} frames ({} incomplete) for {} hosts",
                           ctl.at("frames_closed").dump(), ctl.at("frames_incomplete").dump(),
                           m_sent.size()));
}

void ControllerSoak::check_replies(SoakResult& r) {
    for (std::size_t i = 0; i < m_sent.size(); ++i) {
        const Sent& s = m_sent[i];
        r.commands_checked += s.reply_commands;
        if (!s.ok || s.reply_frames == 0) continue;  // its failure is already named
        r.frames_received += 1;
        if (s.reply_frames == 1 && s.reply_commands == s.commands) continue;
        ++r.frames_mismatched;
        r.fail(
            fmt::format("connection {}: the controller answered {} commands, {} frames; {} "
                        "commands, one frame sent",
                        i + 1, s.reply_commands, s.reply_frames, s.commands));
    }
    r.notes.push_back(
        "without --stats: frames and commands checked from the hosts' answers, "
        "checksums not checked");
}

void ControllerSoak::finish(SoakResult& r) {
    r.frames_expected = m_sent.size();
    if (m_controller.running()) {
        const int code = m_controller.wait(60s);
        if (code != 0)
            r.fail(fmt::format("fb89 controller: {}: {}", describe_exit(code),
                               head_of_file(m_dir / "controller.stderr")));
    }
    if (fs::exists(m_socket)) r.fail("the controller left its socket file " + m_socket);
    if (std::string err = head_of_file(m_dir / "controller.stderr"); !err.empty())
        r.notes.push_back("controller stderr: " + err);
    if (!m_options.controller_stats) {
        check_replies(r);
    } else if (!fs::exists(m_stats)) {
        r.fail("the controller wrote no --stats");
    } else {
        check_connections(read_json(m_stats), r);
    }
}

}  // namespace

SoakResult run_controller(const SoakOptions& options) {
    SoakResult r = start_result("controller", options);
    const WorkDir work(options);
    ControllerSoak soak(options, work.path());
    const auto start = std::chrono::steady_clock::now();
    try {
        soak.start();
        r.watched = fmt::format("fb89 controller{} (pid {})",
                                options.controller_stats ? " --stats" : "", soak.pid());
        const int last_sampled = options.cycles - 1;  // after the last host it exits
        for (int c = 0; c < options.cycles; ++c) {
            const Pair pair = pair_of(options, c);
            const bool alive = soak.serve_host(pair, r, c);
            r.cycles = c + 1;
            if (!alive) break;
            if (r.cycles > last_sampled || !is_sample_point(r.cycles, options.every, last_sampled))
                continue;
            soak.wait_idle();
            r.samples.push_back(sample_process(soak.pid(), r.cycles));
            r.parent_samples.push_back(sample_process(0, r.cycles));
            report_progress(options, r, r.samples.back());
        }
        soak.finish(r);
    } catch (const std::exception& e) {
        r.fail(e.what());
    }
    r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace fb89::soak
