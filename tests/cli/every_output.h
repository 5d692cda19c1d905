// Every output option of every command, on inputs small enough to run in a blink: the one
// table the output tests walk (tests/cli/output_targets_test.cpp: where an output goes;
// tests/cli/failed_command_test.cpp: what a failing command leaves).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tests/cli/cli_runner.h"

namespace fb89::testing {

// One output option of one command; "@OUT@" stands for the target.
struct OutputCase {
    std::string option;  // for messages: "render --png"
    std::string command;
    int exit_code = 0;  // diff finds a difference: 1
};

// Streams for replay, trim and diff: two small ones that differ, and the first cut inside
// its frame (a truncated command: damage a reader finds only part way).
struct Streams {
    std::string demo, other, cut;
};

inline const Streams& streams() {
    static const Streams s = [] {
        const std::string scenes = FB89_SCENES_DIR;
        const std::filesystem::path dir = scratch_dir() / "every_output_streams";
        std::filesystem::create_directories(dir);
        Streams out{(dir / "demo.fb89").string(), (dir / "a.fb89").string(),
                    (dir / "cut.fb89").string()};
        run_fb89("render " + scenes + "/demo.json --size 64x48 -q --stream " + out.demo);
        run_fb89("render " + scenes + "/A.json --size 64x48 -q --stream " + out.other);
        std::filesystem::copy_file(out.demo, out.cut,
                                   std::filesystem::copy_options::overwrite_existing);
        std::filesystem::resize_file(out.cut, std::filesystem::file_size(out.demo) * 2 / 3);
        return out;
    }();
    return s;
}

inline std::vector<OutputCase> every_output() {
    const std::string scenes = FB89_SCENES_DIR;
    const std::string demo = scenes + "/demo.json --size 64x48 -q";
    const std::string room = scenes + "/garish_room.json --size 64x48 -q";
    const std::string a = scenes + "/A.json --size 64x48 -q --repeat 1";
    std::vector<OutputCase> cases;
    for (const char* option : {"--png", "--ids", "--ids-view", "--stream", "--stats", "--timeline"})
        cases.push_back(
            {std::string("render ") + option, "render " + demo + " " + option + " @OUT@"});
    cases.push_back({"render --mask", "render " + demo + " -m beam --mask @OUT@"});
    for (const char* option : {"--png", "--ids", "--ids-view", "--stream", "--stats"})
        cases.push_back(
            {std::string("radiosity ") + option, "radiosity " + room + " " + option + " @OUT@"});
    cases.push_back({"experiment --csv", "experiment fig2.1 " + a + " --csv @OUT@"});
    cases.push_back({"sweep --csv", "sweep threshold " + a + " --steps 2 --csv @OUT@"});
    cases.push_back({"model --csv", "model --es 64 --fv 16 --csv @OUT@"});
    cases.push_back({"controller-validate --csv", "controller-validate -q --csv @OUT@"});
    cases.push_back({"calibrate --csv", "calibrate --dry-run --repeat 1 --steps 2 -q " + scenes +
                                            "/A.json --csv @OUT@"});
    cases.push_back({"compare --sheet", "compare " + demo + " --repeat 1 --sheet @OUT@"});
    for (const char* option : {"--csv", "--json"})
        cases.push_back({std::string("compare ") + option,
                         "compare " + demo + " --repeat 1 --sheet " +
                             (test_dir() / "sheet.png").string() + " " + option + " @OUT@"});
    const Streams& s = streams();
    for (const char* option : {"--png", "--stats", "--timeline"})
        cases.push_back(
            {std::string("replay ") + option, "replay -q " + s.demo + " " + option + " @OUT@"});
    cases.push_back({"trim -o", "trim -q " + s.demo + " --frames 0 -o @OUT@"});
    cases.push_back({"diff --image", "diff -q " + s.demo + " " + s.other + " --image @OUT@", 1});
    return cases;
}

inline std::string with_target(std::string command, const std::string& target) {
    const std::string mark = "@OUT@";
    const auto at = command.find(mark);
    return command.replace(at, mark.size(), target);
}

}  // namespace fb89::testing
