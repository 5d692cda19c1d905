// The README's commands, run as a newcomer would: in a scratch copy of the checkout, with
// `fb89` on the PATH, one after another. Each must succeed; afterwards the copy's tree is
// unchanged (`git status --porcelain` empty: everything went under out/, which git ignores);
// and each sample session ("$ fb89 ..." followed by its output) still matches what the
// command prints, in shape -- the same lines with the same words and columns, "..." standing
// for lines left out -- and in every figure a run does not measure: counts, cycles, modelled
// times, checksums (the times measured on this machine, wall and CPU, send times and what
// follows from them, are left out: tests/readme_samples.h lists them). ReadmeTour.TheSamples*
// runs the sessions alone, in seconds.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "period/host_profile.h"
#include "period/isa.h"
#include "tests/readme_samples.h"
#include "tests/scratch.h"

namespace {

namespace fs = std::filesystem;
using fb89::testing::lines_of;
using fb89::testing::matches;

const fs::path kSource = fs::path(FB89_SCENES_DIR).parent_path();

struct Step {
    std::string command;
    bool session = false;               // from a "$ " session: its output is compared
    std::vector<std::string> expected;  // the sample output, "..." for lines left out
    int line = 0;                       // in README.md
};

std::string read(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

bool is_command(const std::string& text) {
    for (const char* start : {"fb89 ", "scripts/", "parallel ", "cmake "})
        if (text.rfind(start, 0) == 0) return true;
    return false;
}

// A command line's trailing comment ("  # ..."), and the spaces before it, cut off.
std::string without_comment(const std::string& line) {
    const size_t hash = line.find("  #");
    std::string out = hash == std::string::npos ? line : line.substr(0, hash);
    out.erase(out.find_last_not_of(' ') + 1);
    return out;
}

// The README's indented blocks: command blocks (every line a command) and sessions.
std::vector<Step> steps_of(const std::string& readme, std::vector<std::string>& problems) {
    std::vector<Step> steps;
    const std::vector<std::string> lines = lines_of(readme);
    for (size_t i = 0; i < lines.size();) {
        if (lines[i].rfind("    ", 0) != 0 || (i > 0 && !lines[i - 1].empty())) {
            ++i;
            continue;
        }
        std::vector<std::pair<int, std::string>> block;  // an indented block after a blank line
        for (; i < lines.size() && lines[i].rfind("    ", 0) == 0; ++i)
            block.emplace_back(static_cast<int>(i + 1), lines[i].substr(4));
        if (block.front().second.rfind("$ ", 0) == 0) {
            for (const auto& [number, text] : block) {
                if (text.rfind("$ ", 0) == 0)
                    steps.push_back({without_comment(text.substr(2)), true, {}, number});
                else
                    steps.back().expected.push_back(text);
            }
        } else if (is_command(block.front().second)) {
            for (size_t k = 0; k < block.size(); ++k) {
                std::string command = without_comment(block[k].second);
                while (!command.empty() && command.back() == '\\' && k + 1 < block.size())
                    command.pop_back(), command += " " + without_comment(block[++k].second);
                if (!command.empty() && command[0] == '#') continue;  // a comment line
                if (!is_command(command))
                    problems.push_back("line " + std::to_string(block[k].first) +
                                       ": neither a command nor a comment: " + command);
                steps.push_back({command, false, {}, block[k].first});
            }
        } else {
            problems.push_back("line " + std::to_string(block.front().first) +
                               ": an indented block that is neither commands nor a session "
                               "(\"$ command\" and its output)");
        }
    }
    return steps;
}

// Why a command is not run here, or "" to run it.
std::string skip_reason(const std::string& command) {
    if (command.rfind("scripts/run", 0) == 0 || command.rfind("scripts/test", 0) == 0)
        return "the harness itself";
    if (command.rfind("scripts/figures", 0) == 0)
        return "an hour of the commands run here, at full size";
    if (command.rfind("cmake --install", 0) == 0)
        return "ListCommand.AnInstalledPrefixRunsOnItsOwn installs and runs a prefix";
    if (command.rfind("parallel", 0) == 0 && !fb89::testing::on_path("parallel"))
        return "GNU parallel is not installed (scripts/bootstrap installs it)";
    if (command.rfind("scripts/slurm-sweep", 0) == 0 &&
        (!fb89::testing::on_path("sbatch") || !fs::exists("/usr/sbin/slurmctld")))
        return "Slurm is not installed (scripts/bootstrap installs slurm-wlm and munge)";
    if (command.rfind("fb89 view", 0) == 0)
        return "needs a display (ViewCommand.* run it under xvfb)";
    // a command on a 1989 host needs that host's guest; host-validate needs every one
    const bool validate = command.rfind("fb89 host-validate", 0) == 0;
    const std::size_t host_at = command.find("--host ");
    std::string isa;
    if (host_at != std::string::npos) {
        const std::size_t from = host_at + 7;
        const std::string host = command.substr(from, command.find(' ', from) - from);
        try {
            if (host != "native") isa = fb89::period::load_host_profile(host).isa;
        } catch (const std::runtime_error&) {
            // a profile file the tour makes itself: the command says what it runs on
        }
    }
    for (const auto& s : fb89::period::instruction_sets())
        if ((validate || s.name == isa) && s.guest_path.empty())
            return "the " + s.name + " guest is not built here";
    return "";
}

struct Outcome {
    int status = -1;
    std::string output;  // stdout and stderr, as a terminal shows them
};

// The single-node Slurm the README's cluster section runs on (scripts/slurm-local), started
// by the first `scripts/slurm-sweep` and stopped, by the process ids it recorded, when the
// tour ends however it ends. Its folder is a short one of its own (munged's socket lives in
// it), removed with it.
class LocalSlurm {
  public:
    explicit LocalSlurm(fs::path checkout) : m_checkout(std::move(checkout)) {}
    LocalSlurm(const LocalSlurm&) = delete;
    LocalSlurm& operator=(const LocalSlurm&) = delete;
    ~LocalSlurm() {
        if (m_dir.empty()) return;
        const std::string stop =
            "'" + (m_checkout / "scripts/slurm-local").string() + "' stop '" + m_dir.string() + "'";
        if (std::system(stop.c_str()) != 0) ADD_FAILURE() << stop;
        std::error_code ec;
        fs::remove_all(m_dir, ec);
    }
    // "" when it runs (SLURM_CONF is conf()), else what went wrong
    std::string start() {
        if (!m_dir.empty()) return "";
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/fb89-tour-slurm.XXXXXX";
        if (!::mkdtemp(pattern.data())) return "mkdtemp failed";
        m_dir = pattern;
        fs::permissions(m_dir, fs::perms::owner_all | fs::perms::group_read |
                                   fs::perms::group_exec | fs::perms::others_read |
                                   fs::perms::others_exec);
        const std::string start = "'" + (m_checkout / "scripts/slurm-local").string() +
                                  "' start '" + m_dir.string() + "' > '" +
                                  (m_dir / "start.out").string() + "' 2>&1";
        if (std::system(start.c_str()) != 0) return read(m_dir / "start.out");
        return "";
    }
    fs::path conf() const { return m_dir.empty() ? fs::path() : m_dir / "slurm.conf"; }

  private:
    fs::path m_checkout, m_dir;
};

Outcome run(const std::string& command, const fs::path& dir, const fs::path& home,
            const fs::path& slurm_conf = {}) {
    const fs::path log = home / "log";
    const std::string slurm = slurm_conf.empty() ? "" : " SLURM_CONF='" + slurm_conf.string() + "'";
    const std::string shell = "cd '" + dir.string() + "' &&" + slurm + " PATH='" +
                              (fs::path(FB89_BUILD_DIR) / "cli").string() + "':\"$PATH\" HOME='" +
                              home.string() + "' XDG_CONFIG_HOME='" + (home / "config").string() +
                              "' FB89_CALIBRATION='" + (home / "calibration.json").string() +
                              "' timeout 600 bash -c '" +
                              std::regex_replace(command, std::regex("'"), "'\\''") + "' >'" +
                              log.string() + "' 2>&1 </dev/null";
    Outcome r;
    const int status = std::system(shell.c_str());
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.output = read(log);
    return r;
}

TEST(ReadmeTourLong, TheCommandsRunInACopyLeaveItCleanAndPrintWhatTheSamplesShow) {
    std::vector<std::string> problems;
    const std::vector<Step> steps = steps_of(read(kSource / "README.md"), problems);
    for (const std::string& p : problems)
        ADD_FAILURE() << "README.md " << p;
    ASSERT_GE(steps.size(), 20u);

    // the copy: the checkout's files as git sees them, in a repository of their own
    const fs::path home = fb89::testing::scratch_path("readme-home");
    const fs::path copy = fb89::testing::scratch_path("readme-checkout");
    fs::remove_all(home);
    fs::remove_all(copy);
    fs::create_directories(home);
    fs::create_directories(copy);
    if (!fs::exists(kSource / ".git")) GTEST_SKIP() << "not a git checkout: " << kSource;
    const std::string make_copy =
        "cd '" + kSource.string() +
        "' && git ls-files -z --cached --others --exclude-standard | tar --null -T - "
        "--ignore-failed-read -cf - | tar -xf - -C '" +
        copy.string() + "' && cd '" + copy.string() +
        "' && git init -q && git add -A && git -c user.name=t -c user.email=t@t commit -qm copy";
    ASSERT_EQ(std::system(make_copy.c_str()), 0) << make_copy;

    LocalSlurm slurm(copy);
    for (const Step& step : steps) {
        const std::string why = skip_reason(step.command);
        if (!why.empty()) {
            std::printf("README.md:%d: not run (%s): %s\n", step.line, why.c_str(),
                        step.command.c_str());
            continue;
        }
        if (step.command.rfind("scripts/slurm-sweep", 0) == 0) {
            const std::string failed = slurm.start();
            ASSERT_EQ(failed, "") << "README.md:" << step.line
                                  << ": the single-node Slurm did not start";
        }
        const Outcome r = run(step.command, copy, home, slurm.conf());
        EXPECT_EQ(r.status, 0) << "README.md:" << step.line << ": " << step.command << "\n"
                               << r.output;
        if (step.session) {
            const std::string differs = matches(step.expected, r.output, true);
            EXPECT_EQ(differs, "")
                << "README.md:" << step.line << ": " << step.command << "\nprinted:\n"
                << r.output;
        }
    }
    const Outcome status = run("git status --porcelain", copy, home);
    EXPECT_EQ(status.output, "") << "the tour left the checkout changed";
}

// The sessions alone ("$ fb89 ..." and what it prints), one after another in a scratch
// folder as a newcomer runs them: each printed line the sample shows carries the sample's
// figures -- counts, cycles, modelled times, checksums -- but for the times a run measures.
TEST(ReadmeTour, TheSamplesFiguresAreWhatTheCommandsPrint) {
    std::vector<std::string> problems;
    const std::vector<Step> steps = steps_of(read(kSource / "README.md"), problems);
    const fs::path home = fb89::testing::scratch_path("readme-samples-home");
    const fs::path dir = fb89::testing::scratch_path("readme-samples");
    fs::remove_all(home);
    fs::remove_all(dir);
    fs::create_directories(home);
    fs::create_directories(dir);
    int sessions = 0;
    for (const Step& step : steps) {
        if (!step.session || !skip_reason(step.command).empty()) continue;
        ++sessions;
        const Outcome r = run(step.command, dir, home);
        EXPECT_EQ(r.status, 0) << "README.md:" << step.line << ": " << step.command << "\n"
                               << r.output;
        EXPECT_EQ(matches(step.expected, r.output, true), "")
            << "README.md:" << step.line << ": " << step.command << "\nprinted:\n"
            << r.output;
    }
    EXPECT_GE(sessions, 10);
}

}  // namespace
