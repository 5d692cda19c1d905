// The man pages cli/man/make_pages makes at build time from the help: one per command, each
// naming in its options every method, profile, host and scene a registry holds, the period
// hosts' environment generated per instruction set, EXAMPLES whose commands and options
// exist, and a SEE ALSO of pages that exist.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "period/isa.h"
#include "tests/cli/help_text.h"

namespace {

namespace fs = std::filesystem;

using fb89::testing::names;
using fb89::testing::slurp;
using fb89::testing::unroff;

const fs::path kPages = fs::path(FB89_BUILD_DIR) / "cli" / "man";

std::string page_of(const std::string& command) {
    return slurp(kPages / ("fb89-" + command + ".1"));
}

// The text of a section, from its .SH to the next.
std::string section(const std::string& page, const std::string& title) {
    const size_t at = page.find(".SH " + title + "\n");
    if (at == std::string::npos) return "";
    const size_t end = page.find("\n.SH ", at + 1);
    return page.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

TEST(ManPages, EveryRegisteredNameIsInTheOptionsTakingIt) {
    std::set<std::string> checked;
    for (const std::string& command : fb89::testing::listed_commands()) {
        const std::string page = page_of(command);
        ASSERT_FALSE(page.empty()) << command;
        const auto paragraphs = fb89::testing::option_paragraphs(page, true);
        checked.merge(
            fb89::testing::expect_every_name_in(command, paragraphs, "fb89-" + command + "(1)"));
    }
    for (const char* expected : {"render --method", "render --host", "render --profile",
                                 "render scene", "experiment --host", "host-validate --profile"})
        EXPECT_EQ(checked.count(expected), 1u) << expected;
    // fb89(1) names them all too, from the foot of fb89 --help
    const std::string top = unroff(slurp(kPages / "fb89.1"));
    for (const auto& kind : {fb89::testing::registered_methods(), fb89::testing::registered_hosts(),
                             fb89::testing::registered_profiles()})
        for (const std::string& name : kind)
            EXPECT_TRUE(names(top, name)) << "fb89(1): " << name;
}

TEST(ManPages, TheEnvironmentNamesEachInstructionSetsVariablesAndHosts) {
    const std::string environment = unroff(section(page_of("render"), "ENVIRONMENT"));
    ASSERT_FALSE(environment.empty());
    std::set<std::string> hosts_named;
    for (const fb89::period::InstructionSet& isa : fb89::period::instruction_sets()) {
        const std::string prefix = "FB89_" + isa.env + "_";
        const size_t at =
            environment.find(prefix + "QEMU, " + prefix + "GUEST, " + prefix + "KERNELS_DIR");
        ASSERT_NE(at, std::string::npos) << prefix << "\n" << environment;
        const std::string entry = environment.substr(at, environment.find(".TP", at) - at);
        for (const std::string& host : fb89::testing::registered_host_profiles())
            if (fb89::period::load_host_profile(host).isa == isa.name) {
                EXPECT_TRUE(names(entry, host)) << host << " under " << prefix << "\n" << entry;
                hosts_named.insert(host);
            }
    }
    EXPECT_EQ(hosts_named.size(), fb89::testing::registered_host_profiles().size());
}

TEST(ManPages, EveryPageHasExamplesWhoseCommandsAndOptionsExist) {
    std::vector<std::string> commands = fb89::testing::listed_commands();
    const std::set<std::string> known(commands.begin(), commands.end());
    commands.push_back("");  // fb89(1) itself
    for (const std::string& command : commands) {
        const std::string page = command.empty() ? slurp(kPages / "fb89.1") : page_of(command);
        const std::string examples = unroff(section(page, "EXAMPLES"));
        ASSERT_FALSE(examples.empty()) << "fb89-" << command << "(1) has no EXAMPLES";
        std::istringstream lines(examples);
        int shown = 0;
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind(".B fb89", 0) != 0) continue;
            ++shown;
            std::istringstream words(line.substr(3));
            std::string fb89, used, word;
            words >> fb89 >> used;
            ASSERT_EQ(known.count(used), 1u) << line;
            const std::string help = fb89::testing::run_fb89(used + " --help").out;
            // its options, up to a "--" that hands the rest to another program
            while (words >> word && word != "--") {
                if (word.rfind("--", 0) == 0) {
                    EXPECT_TRUE(names(help, word.substr(0, word.find('='))))
                        << "fb89-" << command << "(1): " << line << ": " << word;
                }
            }
        }
        EXPECT_GE(shown, 1) << "fb89-" << command << "(1)";
    }
}

TEST(ManPages, SeeAlsoNamesFb89AndOnlyPagesThatExist) {
    const std::vector<std::string> commands = fb89::testing::listed_commands();
    const std::regex reference(R"(\b(fb89(-[a-z-]+)?)\(1\))");
    for (const std::string& command : commands) {
        const std::string see_also = unroff(section(page_of(command), "\"SEE ALSO\""));
        ASSERT_FALSE(see_also.empty()) << "fb89-" << command << "(1) has no SEE ALSO";
        EXPECT_NE(see_also.find("fb89(1)"), std::string::npos) << command;
        for (std::sregex_iterator m(see_also.begin(), see_also.end(), reference), end; m != end;
             ++m)
            EXPECT_TRUE(fs::exists(kPages / ((*m)[1].str() + ".1")))
                << "fb89-" << command << "(1) refers to " << (*m)[0];
    }
    // fb89(1) refers to every command's page
    const std::string top = unroff(section(slurp(kPages / "fb89.1"), "\"SEE ALSO\""));
    for (const std::string& command : commands)
        EXPECT_NE(top.find("fb89-" + command + "(1)"), std::string::npos) << command;
}

}  // namespace
