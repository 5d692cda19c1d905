// The docs a user reads point only inside the project, and only at what is there: every
// relative Markdown link resolves to a file of the checkout and its #fragment to a heading of
// that file (GitHub's anchors); every path of the checkout a doc cites in backquotes
// (`docs/COST_MODEL.md`, `scenes/README.md`) exists, and a doc cited with a section's name
// after it (`docs/PROTOCOL.md`, "Call sets") has that section, a heading or a paragraph named
// in bold; and no doc sends the reader to a design note the project does not contain.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace {

namespace fs = std::filesystem;

const fs::path kRoot = fs::path(FB89_SCENES_DIR).parent_path();

std::vector<fs::path> docs() {
    std::vector<fs::path> out{kRoot / "README.md", kRoot / "scenes/README.md",
                              kRoot / "tests/golden/conformance/README.md"};
    for (const auto& e : fs::directory_iterator(kRoot / "docs"))
        if (e.path().extension() == ".md") out.push_back(e.path());
    for (const auto& e : fs::recursive_directory_iterator(kRoot / "bench"))
        if (e.path().filename() == "README.md") out.push_back(e.path());
    return out;
}

std::string text_of(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Runs of white space (a line break inside a quoted name among them) as one space.
std::string one_line(const std::string& text) {
    return std::regex_replace(text, std::regex(R"(\s+)"), " ");
}

// A heading's anchor as GitHub makes it: lower case, markup and punctuation dropped (general
// punctuation such as dashes and quotes too), spaces as hyphens.
std::string anchor_of(const std::string& heading) {
    std::string out;
    for (size_t i = 0; i < heading.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(heading[i]);
        if (std::isalnum(c))
            out += static_cast<char>(std::tolower(c));
        else if (c == ' ' || c == '-')
            out += '-';
        else if (c == '_')
            out += '_';
        else if (c == 0xE2 && i + 2 < heading.size() &&
                 (static_cast<unsigned char>(heading[i + 1]) == 0x80 ||
                  static_cast<unsigned char>(heading[i + 1]) == 0x81))
            i += 2;  // U+2000-U+207F: dashes, quotes, ellipses
        else if (c == 0xC2 && i + 1 < heading.size())
            ++i;  // U+0080-U+00BF: §, ·, non-breaking space
        else if (c >= 0x80)
            out += static_cast<char>(c);  // letters beyond ASCII stay
    }
    return out;
}

// A Markdown file's headings (outside fenced code), as written.
std::vector<std::string> headings_of(const fs::path& doc) {
    std::vector<std::string> out;
    std::istringstream in(text_of(doc));
    bool fenced = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        if (fenced || line.empty() || line[0] != '#') continue;
        const size_t text = line.find_first_not_of('#');
        if (text == std::string::npos || line[text] != ' ') continue;
        out.push_back(line.substr(text + 1));
    }
    return out;
}

// Its sections by name: the headings, and the paragraphs that open with a name in bold
// ("**What the depth arithmetic can get wrong: nothing beyond a tie.** The controller ...").
std::vector<std::string> sections_of(const fs::path& doc) {
    std::vector<std::string> out = headings_of(doc);
    std::istringstream in(text_of(doc));
    for (std::string line; std::getline(in, line);)
        if (line.rfind("**", 0) == 0 && line.find("**", 2) != std::string::npos)
            out.push_back(line.substr(2, line.find("**", 2) - 2));
    return out;
}

// Its headings' anchors, a repeated one numbered as GitHub numbers it ("-1", "-2").
std::set<std::string> anchors_of(const fs::path& doc) {
    std::set<std::string> out;
    for (const std::string& h : headings_of(doc)) {
        const std::string a = anchor_of(h);
        std::string unique = a;
        for (int n = 1; out.count(unique); ++n)
            unique = a + "-" + std::to_string(n);
        out.insert(unique);
    }
    return out;
}

TEST(Docs, EveryRelativeLinkResolvesToAFileAndItsFragmentToAHeading) {
    const std::regex link(R"(\]\(([^)#\s]*)(#[^)\s]*)?\))");
    for (const fs::path& doc : docs()) {
        const std::string text = text_of(doc);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), link);
             it != std::sregex_iterator(); ++it) {
            const std::string target = (*it)[1], fragment = (*it)[2];
            if (target.rfind("http", 0) == 0 || target.rfind("mailto:", 0) == 0) continue;
            const fs::path file = target.empty() ? doc : doc.parent_path() / target;
            EXPECT_TRUE(fs::exists(file)) << doc.filename() << " links to " << target;
            if (fragment.empty() || !fs::exists(file) || file.extension() != ".md") continue;
            EXPECT_EQ(anchors_of(file).count(fragment.substr(1)), 1u)
                << doc.filename() << " links to " << target << fragment << ", a heading "
                << file.filename() << " does not have";
        }
    }
}

// A path in backquotes is the checkout's when it opens with one of the checkout's folders;
// not one a reader makes (`out/...`), nor a pattern (`controller_sim/profiles/NAME.json`),
// nor another repository's file, cited right after that repository.
bool cites_the_checkout(const std::string& text, size_t at, const std::string& path) {
    static const std::regex placeholder(R"([<>*{}$]|(^|/)[A-Z]+\.[a-z]+$)");
    if (std::regex_search(path, placeholder) && !path.ends_with(".md")) return false;
    const std::string top = path.substr(0, path.find('/'));
    if (path.find('/') == std::string::npos || top == "build" || top.empty() || top[0] == '.' ||
        !fs::is_directory(kRoot / top))
        return false;
    const size_t from = at > 200 ? at - 200 : 0;
    return text.substr(from, at - from).find("repository") == std::string::npos;
}

TEST(Docs, EveryPathOfTheCheckoutADocCitesExists) {
    const std::regex cited(R"(`([A-Za-z0-9_./+-]+)`)");
    for (const fs::path& doc : docs()) {
        const std::string text = text_of(doc);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), cited);
             it != std::sregex_iterator(); ++it) {
            const std::string path = (*it)[1];
            if (!cites_the_checkout(text, static_cast<size_t>(it->position()), path)) continue;
            EXPECT_TRUE(fs::exists(kRoot / path)) << doc.filename() << " cites " << path;
        }
    }
}

TEST(Docs, EveryDocCitedWithASectionsNameHasThatSection) {
    // `docs/X.md`, "Section" or `docs/X.md` "Section": the section's heading opens with it
    const std::regex cited(R"re(`([A-Za-z0-9_./-]+\.md)`,?\s+"([^"]+)")re");
    for (const fs::path& doc : docs()) {
        const std::string text = text_of(doc);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), cited);
             it != std::sregex_iterator(); ++it) {
            const fs::path file = kRoot / (*it)[1].str();
            if (!fs::exists(file)) continue;  // the test above says so
            const std::string section = one_line((*it)[2]);
            bool found = false;
            for (const std::string& h : sections_of(file))
                found = found || one_line(h).rfind(section, 0) == 0;
            EXPECT_TRUE(found) << doc.filename() << " cites " << (*it)[1] << ", \"" << section
                               << "\": no such heading there";
        }
    }
}

TEST(Docs, TheAnchorsAreGitHubs) {
    EXPECT_EQ(anchor_of("TI's practice: the handlers and the board"),
              "tis-practice-the-handlers-and-the-board");
    EXPECT_EQ(anchor_of("The TMS34010 on a 386's ISA bus (`tms34010-isa`)"),
              "the-tms34010-on-a-386s-isa-bus-tms34010-isa");
    EXPECT_EQ(anchor_of("Bands: the estimates' ranges"), "bands-the-estimates-ranges");
    EXPECT_EQ(anchor_of("A — B"), "a--b");
}

TEST(Docs, NoDocNamesADesignNoteTheProjectDoesNotHave) {
    for (const fs::path& doc : docs()) {
        const std::string text = text_of(doc);
        for (const char* outside : {"DESIGN.md", "REFERENCES.md", "STYLE.md", "../shared"})
            EXPECT_EQ(text.find(outside), std::string::npos) << doc << " names " << outside;
    }
}

}  // namespace
