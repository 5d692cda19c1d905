// fb89 controller --listen PATH: the frame-buffer controller as its own process
// (DESIGN.md "Protocol" transports; docs/PROTOCOL.md "Transports: the controller socket").
//
// Serves hosts one after another on a Unix-domain socket. Each connection carries one
// fb89 stream; its commands are executed into a controller::Controller as they arrive,
// each frame is reported when it completes, and each connection ends with a summary of
// the counts and modelled cost of the frames it completed. A connection cut mid-frame
// (the host died, went quiet past --idle-timeout, or sent a corrupt record) has its
// partial frame reported and dropped; every complete frame and its counts are kept, and
// the server goes on (or exits 2 with --once). Frames accumulate over connections into
// --png (the last complete frame) and --stats. SIGINT/SIGTERM end it cleanly, removing
// the socket file. No host time is measured here: the host measures its own.
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <optional>
#include <variant>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "controller_sim/controller.h"
#include "controller_sim/display.h"
#include "controller_sim/png_io.h"
#include "controller_sim/recorder.h"
#include "protocol/socket_stream.h"
#include "protocol/stream_reader.h"

namespace fb89::cli {

namespace {

using std::chrono::milliseconds;

struct ControllerArgs {
    std::string listen, png, stats;
    std::string profile = std::string(controller::kDefaultProfile);
    bool once = false;
    int max_clients = 0;  // 0: no limit
    double idle_timeout = 30;
    bool quiet = false;
    bool view = false;  // show the framebuffer live in a window
};

// --- signals: SIGINT/SIGTERM wake the accept loop and cut the current connection --------

volatile std::sig_atomic_t g_signal = 0;
int g_wake_write = -1;
std::atomic<int> g_active_fd{-1};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_stop_signal(int sig) {
    g_signal = sig;
    const char byte = 1;
    [[maybe_unused]] const ssize_t n = ::write(g_wake_write, &byte, 1);
    const int fd = g_active_fd.load();
    if (fd >= 0) ::shutdown(fd, SHUT_RDWR);  // the reader then sees the stream end
}

class StopSignals {
  public:
    StopSignals() {
        if (::pipe2(m_pipe, O_CLOEXEC | O_NONBLOCK) != 0)
            throw std::runtime_error("cannot create the signal pipe");
        g_wake_write = m_pipe[1];
        struct sigaction sa {};
        sa.sa_handler = on_stop_signal;
        sigemptyset(&sa.sa_mask);
        ::sigaction(SIGINT, &sa, &m_old_int);
        ::sigaction(SIGTERM, &sa, &m_old_term);
        std::signal(SIGPIPE, SIG_IGN);  // replies to a vanished host fail, never kill us
    }
    ~StopSignals() {
        ::sigaction(SIGINT, &m_old_int, nullptr);
        ::sigaction(SIGTERM, &m_old_term, nullptr);
        g_wake_write = -1;
        ::close(m_pipe[0]);
        ::close(m_pipe[1]);
    }
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;
    int wake_fd() const { return m_pipe[0]; }

  private:
    int m_pipe[2] = {-1, -1};
    struct sigaction m_old_int {
    }, m_old_term{};
};

// --- what a connection kept ------------------------------------------------------------

void subtract(controller::OpcodeCounters& a, const controller::OpcodeCounters& b) {
    a.commands -= b.commands;
    a.pixels -= b.pixels;
    a.bytes -= b.bytes;
    a.cycles -= b.cycles;
    a.clipped -= b.clipped;
    a.outside -= b.outside;
}

// The controller's figures without its open (partial) frame, which is dropped.
controller::ControllerStats kept_stats(const controller::Controller& ctl) {
    controller::ControllerStats s = ctl.stats();
    if (!ctl.in_frame()) return s;
    const controller::FrameResult open = ctl.open_frame();
    for (std::size_t i = 0; i < s.totals.size(); ++i)
        subtract(s.totals[i], open.ops[i]);
    s.bus_busy_us -= open.bus_busy_us;
    s.controller_busy_us -= open.controller_busy_us;
    return s;
}

// Adds one connection's figures to the server's; its frames themselves only when
// `keep_frames` (for --stats), so that a long-running controller stays the same size.
void add_into(controller::ControllerStats& all, const controller::ControllerStats& s,
              bool keep_frames) {
    if (keep_frames) all.frames.insert(all.frames.end(), s.frames.begin(), s.frames.end());
    all.frames_closed += s.frames_closed;
    all.frames_incomplete += s.frames_incomplete;
    for (std::size_t i = 0; i < all.totals.size(); ++i) {
        all.totals[i] += s.totals[i];
        all.unframed[i] += s.unframed[i];
    }
    all.bus_busy_us += s.bus_busy_us;
    all.controller_busy_us += s.controller_busy_us;
    all.frames_end_us += s.frames_end_us;
}

std::string describe_host(const protocol::Properties& p) {
    std::string text;
    for (const char* key : {"scene", "method", "resolution", "tool"}) {
        if (auto it = p.find(key); it != p.end())
            text += fmt::format("{}{} {}", text.empty() ? "" : ", ", key, it->second);
    }
    return text.empty() ? "no properties" : text;
}

// --- the server ------------------------------------------------------------------------

class Server {
  public:
    explicit Server(const ControllerArgs& args)
        : m_args(args),
          m_console{args.quiet},
          m_idle(static_cast<int64_t>(args.idle_timeout * 1e3)) {
        if (m_args.stats == "-") m_args.quiet = true;  // stdout carries the JSON
        m_all.profile = controller::load_profile(args.profile);
        if (args.idle_timeout <= 0) m_idle = milliseconds(-1);
        if (args.view) {
            try {
                m_display =
                    std::make_unique<controller::Display>("fb89 controller " + args.listen, 1);
            } catch (const controller::DisplayUnavailable& e) {
                throw std::runtime_error(fmt::format("--view: {}", e.what()));
            }
        }
    }

    int run() {
        StopSignals signals;
        protocol::SocketListener listener(m_args.listen);
        const int limit = m_args.once ? 1 : m_args.max_clients;
        m_console.note(
            fmt::format("controller ({}) listening on {}", m_all.profile.name, listener.path()));
        while (g_signal == 0 && (limit == 0 || m_served < limit)) {
            std::optional<protocol::UniqueFd> conn = listener.accept(signals.wake_fd());
            if (!conn) break;
            serve(*conn);
            // --png and --stats: after a connection, at most once a second (rewriting a
            // growing --stats after each of thousands of hosts would cost their square)
            const auto now = std::chrono::steady_clock::now();
            if (now - m_last_written >= std::chrono::seconds(1)) {
                write_outputs();
                m_last_written = now;
            }
        }
        if (g_signal != 0)
            m_console.note(fmt::format("controller: stopped by signal {}; removing {}",
                                       static_cast<int>(g_signal), listener.path()));
        if (m_served > 1 && !m_args.quiet)
            fmt::print("all {} connections: {} frames kept, {} cut\n{}", m_served,
                       m_all.frames_closed, m_cut, m_all.summary());
        write_outputs();
        return m_cut > 0 ? kBadInput : kSuccess;
    }

  private:
    void serve(protocol::UniqueFd& conn);
    std::string read_stream(int fd, controller::Controller& ctl, std::string& host);
    void report_frame(const controller::FrameResult& f);
    void write_outputs();

    ControllerArgs m_args;
    Console m_console;
    milliseconds m_idle;
    void show_live(const controller::Controller& ctl, bool force);
    std::unique_ptr<controller::Display> m_display;  // --view
    controller::Recorder m_writers;
    std::chrono::steady_clock::time_point m_last_shown;
    // every connection's figures (and, for --stats, its frames and a record of it)
    controller::ControllerStats m_all;
    std::optional<controller::Framebuffer> m_last;  // the last complete frame, for --png
    nlohmann::json m_connections = nlohmann::json::array();
    std::chrono::steady_clock::time_point m_last_written;
    int m_served = 0, m_cut = 0;
};

// Reads one stream into ctl, reporting frames as they complete. Returns "" if the stream
// ended with its frame index, else what went wrong ("" problems become a plain cut).
std::string Server::read_stream(int fd, controller::Controller& ctl, std::string& host) {
    const std::string name = fmt::format("socket {} (connection {})", m_args.listen, m_served);
    try {
        protocol::StreamReader reader(fd, name, m_idle);
        host = describe_host(reader.properties());
        m_console.note(fmt::format("connection {}: host connected: {}", m_served, host));
        protocol::Command c;
        std::size_t reported = 0;
        if (m_display) {
            m_writers.reset();
            ctl.set_observer(
                [this](uint64_t n, const protocol::Command& cmd) { m_writers.record(n, cmd); });
        }
        while (reader.next(c)) {
            ctl.execute(c);
            if (m_display) show_live(ctl, std::holds_alternative<protocol::FrameEnd>(c));
            for (; reported < ctl.frames().size(); ++reported) {
                report_frame(ctl.frames()[reported]);
                if (m_args.png.empty() || !ctl.frames()[reported].complete) continue;
                m_last = ctl.framebuffer();
            }
        }
        return reader.frame_index() ? "" : "the stream ended without its frame index";
    } catch (const protocol::StreamError& e) {
        return e.what();
    }
}

// --view: the live framebuffer, at most 30 times a second and at every frame's end.
void Server::show_live(const controller::Controller& ctl, bool force) {
    const auto now = std::chrono::steady_clock::now();
    if (!force && now - m_last_shown < std::chrono::milliseconds(33)) return;
    m_last_shown = now;
    for (const auto& e : m_display->poll(0))
        if (e.kind == controller::InputEvent::Kind::Quit) g_signal = SIGINT;
    controller::Hud hud;
    hud.status.push_back(
        fmt::format("fb89 controller --view  {}  connection {}  command {}  frames {}",
                    m_args.listen, m_served, ctl.commands_executed(), ctl.frames().size()));
    m_display->show(ctl.framebuffer(), nullptr, hud);
}

void Server::serve(protocol::UniqueFd& conn) {
    const int fd = conn.get();
    // a connection that closes without a byte is a probe (e.g. a check that the path is in
    // use): not a host, not counted
    const std::optional<bool> empty = protocol::connection_is_empty(fd, m_idle);
    if (empty && *empty) {
        m_console.note("controller: a connection closed without sending anything (ignored)");
        return;
    }
    ++m_served;
    g_active_fd = fd;
    controller::Controller ctl(m_all.profile);
    std::string host = "unknown";
    const std::string problem =
        empty ? read_stream(fd, ctl, host)
              : fmt::format("socket {}: idle time-out: the host sent nothing for {:.3g} s",
                            m_args.listen, m_args.idle_timeout);
    const bool peer_closed = protocol::connection_is_empty(fd, milliseconds(0)).value_or(false);
    g_active_fd = -1;

    const controller::ControllerStats kept = kept_stats(ctl);
    const bool keep_records = !m_args.stats.empty();
    add_into(m_all, kept, keep_records);
    const uint64_t commands = ctl.commands_executed();
    nlohmann::json record = {{"connection", m_served},
                             {"host", host},
                             {"commands", commands},
                             {"frames_kept", kept.frames.size()},
                             {"complete", problem.empty()}};
    if (problem.empty()) {
        protocol::send_reply(
            fd, fmt::format("ok {} commands, {} frames", commands, kept.frames.size()));
        if (!m_args.quiet)
            fmt::print("connection {} ({}): stream complete: {} frames, {} commands\n{}", m_served,
                       host, kept.frames.size(), commands, kept.summary());
    } else {
        ++m_cut;
        const char* lead = g_signal != 0 ? "stopped by a signal"
                           : peer_closed ? "host closed the connection"
                                         : "connection cut";
        std::string what;
        if (ctl.in_frame()) {
            const controller::FrameResult open = ctl.open_frame();
            what = fmt::format(
                "{} in frame {} after command {}: partial frame ({} commands) "
                "dropped",
                lead, open.frame, commands - 1, open.total().commands);
            record["partial_frame"] = {{"frame", open.frame}, {"commands", open.total().commands}};
        } else {
            what = commands == 0 ? fmt::format("{} before any command", lead)
                                 : fmt::format(
                                       "{} between frames, after command {}: no frame "
                                       "lost",
                                       lead, commands - 1);
        }
        record["problem"] = problem;
        if (!peer_closed) protocol::send_reply(fd, "error " + problem);
        fmt::print(stderr,
                   "fb89 controller: connection {} ({}): {}; {} complete frames kept\n"
                   "  ({})\n",
                   m_served, host, what, kept.frames.size(), problem);
        if (!m_args.quiet) fmt::print("{}", kept.summary());
    }
    std::fflush(stdout);
    if (keep_records) m_connections.push_back(std::move(record));
    conn.reset();
}

void Server::report_frame(const controller::FrameResult& f) {
    if (m_args.quiet) return;
    fmt::print("frame {} (connection {}): {} commands, modelled {:.3f} ms, checksum {:016x}{}\n",
               f.frame, m_served, f.total().commands, f.end_us / 1e3, f.checksum,
               f.complete ? "" : " (closed by the next FRAME_BEGIN)");
    std::fflush(stdout);
}

void Server::write_outputs() {
    if (!m_args.png.empty() && m_last) {
        make_parent_dirs(m_args.png);
        controller::write_png(m_args.png, *m_last, protocol::Publish::Now);
    }
    if (!m_args.stats.empty()) {
        nlohmann::json j = {{"tool", std::string("fb89 ") + FB89_VERSION},
                            {"socket", m_args.listen},
                            {"connections", m_connections},
                            {"controller", m_all.to_json()}};
        write_json(m_args.stats, j, protocol::Publish::Now);
    }
}

}  // namespace

void register_controller(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<ControllerArgs>();
    CLI::App* sub = app.add_subcommand(
        "controller", "Run the frame-buffer controller as its own process on a Unix socket");
    sub->add_option("--listen", args->listen, "Socket path to create and serve hosts on")
        ->required();
    sub->add_option("--profile", args->profile, profile_option_help())
        ->check(profile_validator())
        ->capture_default_str();
    sub->add_option("--png", args->png,
                    "Write the last complete frame as PNG (at most once a second, and at exit)");
    sub->add_option("--stats", args->stats,
                    "Write per-connection, per-frame and controller figures as JSON ('-' for "
                    "stdout; at most once a second, and at exit; the record grows with every "
                    "connection)");
    sub->add_flag("--once", args->once,
                  "Serve one connection, then exit (0: stream complete, 2: cut)");
    sub->add_option("--max-clients", args->max_clients,
                    "Exit after serving N connections (0: until SIGINT/SIGTERM)")
        ->check(CLI::Range(0, 1 << 30))
        ->capture_default_str();
    sub->add_option("--idle-timeout", args->idle_timeout,
                    "Cut a host that sends nothing for S seconds (0: never)")
        ->check(CLI::Range(0.0, 1e6))
        ->capture_default_str();
    sub->add_flag("--view", args->view,
                  "Show the framebuffer live in a window as commands arrive (needs a display)");
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing but errors");
    sub->callback([args, &exit_code] {
        Server server(*args);
        exit_code = server.run();
    });
}

}  // namespace fb89::cli
