// fb89's TMS34010 assembler (controller_sim/gsp_assembler.h) held to TI's own: the words TI's
// GSPA 2.00 (1987) wrote for the controller's executive and for tests/ti-gsp/fills.asm
// (tests/golden/gsp/*.gspa.txt, by scripts/gspa-words from GSPA's listings), address for
// address and word for word, every line that holds code or data and no other.
#include "controller_sim/gsp_assembler.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "controller_sim/gsp_listing.h"

namespace fb89::controller::gsp {
namespace {

struct TiLine {
    uint32_t address = 0;
    std::vector<uint16_t> words;
};

std::map<int, TiLine> tis_words(const std::string& name) {
    const std::filesystem::path path =
        std::filesystem::path(FB89_TEST_DATA_DIR) / "golden" / "gsp" / name;
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << path;
    std::map<int, TiLine> out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        int number = 0;
        std::string address, word;
        fields >> number >> address;
        TiLine& t = out[number];
        t.address = static_cast<uint32_t>(std::stoul(address, nullptr, 16));
        while (fields >> word)
            t.words.push_back(static_cast<uint16_t>(std::stoul(word, nullptr, 16)));
    }
    return out;
}

void expect_tis_words(const Program& program, const std::string& golden) {
    const std::map<int, TiLine> ti = tis_words(golden);
    ASSERT_GT(ti.size(), 50u) << golden;
    size_t with_words = 0;
    for (const AssembledLine& l : program.lines) {
        if (l.words.empty()) {
            EXPECT_EQ(ti.count(l.line), 0u)
                << "line " << l.line << " has no words here: " << l.text;
            continue;
        }
        ++with_words;
        const auto it = ti.find(l.line);
        ASSERT_NE(it, ti.end()) << "line " << l.line << " has words TI's has not: " << l.text;
        EXPECT_EQ(l.address, it->second.address) << "line " << l.line << ": " << l.text;
        EXPECT_EQ(l.words, it->second.words) << "line " << l.line << ": " << l.text;
    }
    EXPECT_EQ(with_words, ti.size());
}

TEST(GspAssemblerGolden, TheExecutiveAssemblesToTheWordsOfTisAssembler) {
    const Listing& executive = builtin_listing("tms34010");
    const Program p = assemble("tms34010.asm", executive.text);
    expect_tis_words(p, "tms34010.gspa.txt");
    // its size, from the words: more than the 256-byte instruction cache holds
    EXPECT_GT(p.text_bits / 8, kInstructionCacheBytes);
    // (The path pricer's lengths, gsp_listing.h, are not yet the words': it takes every DSJ
    // as the long form and every JRcc as the short, where GSPA writes DSJS, two long JRUCs
    // and a NOP.)
}

TEST(GspAssemblerGolden, TheSimulatorProgramAssemblesToTheWordsOfTisAssembler) {
    const std::filesystem::path path =
        std::filesystem::path(FB89_TEST_DATA_DIR) / "ti-gsp" / "fills.asm";
    std::ifstream in(path);
    ASSERT_TRUE(in.good()) << path;
    std::stringstream text;
    text << in.rdbuf();
    expect_tis_words(assemble("fills.asm", text.str()), "fills.gspa.txt");
}

}  // namespace
}  // namespace fb89::controller::gsp
