// The CLI soak: each cycle runs the fb89 executable three times in a work folder,
//   fb89 render SCENE -m METHOD --stream cycle.fb89s --png render.png --stats render.json -q
//   fb89 replay cycle.fb89s --png replay.png --stats replay.json -q
//   fb89 diff refs/SCENE-METHOD.fb89s cycle.fb89s -q
// where the reference is the pair's first stream, kept; so later renders of a pair are
// held to its first. Each must exit 0, the two PNG files must be the same bytes, and the
// two --stats must agree on frames, checksum and commands. After each cycle the folder
// must hold only those files (an atomic write that left its temporary, say, is a stray).
#include <chrono>
#include <fstream>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/soak/soak_modes.h"
#include "bench/soak/subprocess.h"

namespace fb89::soak {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::set<std::string> kOutputs = {"cycle.fb89s",  "render.png",  "replay.png",
                                        "render.json",  "replay.json", "child.stdout",
                                        "child.stderr", "refs"};

std::string slurp(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class CliCycle {
  public:
    CliCycle(const SoakOptions& options, const fs::path& dir)
        : m_options(options), m_dir(dir), m_fb89(fs::absolute(options.fb89).string()) {
        fs::create_directories(dir / "refs");
    }

    // "" when the cycle went through; else what failed. Counts frames into r.
    std::string run(const Pair& pair, SoakResult& r);
    // Files in the folder that no step asked for, each counted once over the soak.
    void check_strays(SoakResult& r, int cycle);

  private:
    // "" when `fb89 args` exited with `expected`
    std::string fb89(const std::vector<std::string>& args, int expected = 0);
    std::string compare(const json& render, const json& replay, SoakResult& r);

    const SoakOptions& m_options;
    fs::path m_dir;
    std::string m_fb89;
    std::set<std::string> m_strays;
};

std::string CliCycle::fb89(const std::vector<std::string>& args, int expected) {
    std::vector<std::string> argv{m_fb89};
    argv.insert(argv.end(), args.begin(), args.end());
    const int code = run_process(argv, m_dir, m_dir / "child.stdout", m_dir / "child.stderr",
                                 std::chrono::seconds(m_options.child_timeout_s));
    if (code == expected) return "";
    return fmt::format("fb89 {}: {}: {}", args.front(), describe_exit(code),
                       head_of_file(m_dir / "child.stderr"));
}

std::string CliCycle::compare(const json& render, const json& replay, SoakResult& r) {
    const json& a = render.at("controller");
    const json& b = replay.at("controller");
    r.commands_checked += render.at("host").at("commands").get<uint64_t>();
    if (b.at("frames_closed") != 1 || a.at("frames_closed") != 1)
        return fmt::format("frames: {} rendered, {} replayed", a.at("frames_closed").dump(),
                           b.at("frames_closed").dump());
    if (a.at("frames")[0].at("checksum") != b.at("frames")[0].at("checksum"))
        return fmt::format("checksum {} rendered, {} replayed",
                           a.at("frames")[0].at("checksum").dump(),
                           b.at("frames")[0].at("checksum").dump());
    if (render.at("host").at("commands") != replay.at("stream").at("commands_read"))
        return fmt::format("commands: {} rendered, {} replayed",
                           render.at("host").at("commands").dump(),
                           replay.at("stream").at("commands_read").dump());
    if (a.at("totals") != b.at("totals")) return "per-opcode counts differ";
    if (slurp(m_dir / "render.png") != slurp(m_dir / "replay.png"))
        return "render.png and replay.png differ";
    return "";
}

std::string CliCycle::run(const Pair& pair, SoakResult& r) {
    for (const char* f : {"cycle.fb89s", "render.png", "replay.png", "render.json", "replay.json"})
        fs::remove(m_dir / f);
    r.frames_expected += 1;
    if (auto e = fb89({"render", pair.scene.string(), "-m", pair.method, "--stream", "cycle.fb89s",
                       "--png", "render.png", "--stats", "render.json", "-q"});
        !e.empty())
        return e;
    if (auto e =
            fb89({"replay", "cycle.fb89s", "--png", "replay.png", "--stats", "replay.json", "-q"});
        !e.empty())
        return e;
    const json render = json::parse(slurp(m_dir / "render.json"));
    const json replay = json::parse(slurp(m_dir / "replay.json"));
    const bool received = replay.at("controller").at("frames_closed").get<int>() > 0;
    r.frames_received += received;
    const fs::path ref = m_dir / "refs" / (pair.stem() + ".fb89s");
    if (!fs::exists(ref)) fs::copy_file(m_dir / "cycle.fb89s", ref);
    std::string problem = compare(render, replay, r);
    if (auto e = fb89({"diff", "refs/" + pair.stem() + ".fb89s", "cycle.fb89s", "-q"});
        !e.empty() && problem.empty())
        problem = "differs from the pair's first stream: " + e;
    if (!problem.empty() && received) ++r.frames_mismatched;
    return problem;
}

void CliCycle::check_strays(SoakResult& r, int cycle) {
    auto stray = [&](const fs::path& p) {
        if (!m_strays.insert(p.string()).second) return;
        ++r.stray_files;
        r.fail(fmt::format("cycle {}: a file nobody asked for: {}", cycle, p.string()));
    };
    for (const fs::directory_entry& e : fs::directory_iterator(m_dir))
        if (!kOutputs.contains(e.path().filename().string())) stray(e.path());
    for (const fs::directory_entry& e : fs::directory_iterator(m_dir / "refs"))
        if (e.path().extension() != ".fb89s") stray(e.path());
}

}  // namespace

SoakResult run_cli(const SoakOptions& options) {
    SoakResult r = start_result("cli", options);
    r.watched = "fb89_soak";
    const WorkDir work(options);
    CliCycle cycle(options, work.path());
    const auto start = std::chrono::steady_clock::now();
    for (int c = 0; c < options.cycles; ++c) {
        const Pair pair = pair_of(options, c);
        try {
            if (std::string e = cycle.run(pair, r); !e.empty())
                r.fail(fmt::format("cycle {} ({}): {}", c, pair.label(), e));
        } catch (const std::exception& e) {
            r.fail(fmt::format("cycle {} ({}): {}", c, pair.label(), e.what()));
        }
        cycle.check_strays(r, c);
        r.cycles = c + 1;
        if (is_sample_point(r.cycles, options.every, options.cycles)) {
            r.samples.push_back(sample_process(0, r.cycles));
            report_progress(options, r, r.samples.back());
        }
    }
    r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace fb89::soak
