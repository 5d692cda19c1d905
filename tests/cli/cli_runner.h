// Running the fb89 executable from tests as a user would: in a shell, with stdout and
// stderr captured in a folder of the test's own (ctest runs tests in parallel processes).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fb89::testing {

struct CliRun {
    int exit_code = -1;
    std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// A folder of this test's own.
inline std::filesystem::path test_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    // one folder per test and per process, so that suites of two checkouts (or two runs)
    // on one machine never write into each other's files
    static const std::filesystem::path root = [] {
        std::filesystem::path r = std::filesystem::temp_directory_path() /
                                  ("fb89_cli_test." + std::to_string(::getpid()));
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(std::filesystem::temp_directory_path() /
                                            ("fb89_cli_test." + std::to_string(::getpid())),
                                        ec);
        });
        return r;
    }();
    std::filesystem::path dir = root / (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::create_directories(dir);
    return dir;
}

// Runs `prefix fb89 args` in a shell; `prefix` may set a directory or environment.
inline CliRun run_fb89(const std::string& args, const std::string& prefix = "") {
    const std::filesystem::path dir = test_dir();
    const std::string cmd = prefix + std::string(FB89_CLI_PATH) + " " + args + " >" +
                            (dir / "out").string() + " 2>" + (dir / "err").string() + " </dev/null";
    const int status = std::system(cmd.c_str());
    CliRun r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(dir / "out");
    r.err = slurp(dir / "err");
    return r;
}

}  // namespace fb89::testing
