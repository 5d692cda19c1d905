// The docs a user reads point only inside the project: every relative Markdown link
// resolves to a file of the checkout, and no doc sends the reader to a design note the
// project does not contain.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace {

namespace fs = std::filesystem;

const fs::path kRoot = fs::path(FB89_SCENES_DIR).parent_path();

std::vector<fs::path> docs() {
    std::vector<fs::path> out{kRoot / "README.md", kRoot / "scenes/README.md",
                              kRoot / "tests/golden/conformance/README.md"};
    for (const auto& e : fs::directory_iterator(kRoot / "docs"))
        if (e.path().extension() == ".md") out.push_back(e.path());
    return out;
}

std::string text_of(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(Docs, EveryRelativeLinkResolvesInsideTheProject) {
    const std::regex link(R"(\]\(([^)#\s]+)(#[^)]*)?\))");
    for (const fs::path& doc : docs()) {
        const std::string text = text_of(doc);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), link);
             it != std::sregex_iterator(); ++it) {
            const std::string target = (*it)[1];
            if (target.rfind("http", 0) == 0) continue;
            EXPECT_TRUE(fs::exists(doc.parent_path() / target))
                << doc.filename() << " links to " << target;
        }
    }
}

TEST(Docs, NoDocNamesADesignNoteTheProjectDoesNotHave) {
    for (const fs::path& doc : docs()) {
        const std::string text = text_of(doc);
        for (const char* outside : {"DESIGN.md", "REFERENCES.md", "STYLE.md", "../shared"})
            EXPECT_EQ(text.find(outside), std::string::npos) << doc << " names " << outside;
    }
}

}  // namespace
