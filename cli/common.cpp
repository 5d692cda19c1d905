#include "cli/common.h"

#include <fstream>
#include <iostream>
#include <regex>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace fb89::cli {

ImageSize parse_size(const std::string& text) {
    static const std::regex pattern(R"((\d{1,5})x(\d{1,5}))");
    std::smatch m;
    if (!std::regex_match(text, m, pattern))
        throw UsageError(fmt::format("--size: expected WxH such as 1024x780, got '{}'", text));
    ImageSize s{std::stoi(m[1]), std::stoi(m[2])};
    if (s.width < 1 || s.height < 1 || s.width > 16384 || s.height > 16384)
        throw UsageError(
            fmt::format("--size: width and height must be in [1, 16384], got '{}'", text));
    return s;
}

void make_parent_dirs(const std::string& path) {
    if (path == "-") return;
    std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
}

void write_json(const std::string& path, const nlohmann::json& value) {
    write_text(path, value.dump(2) + "\n");
}

void write_text(const std::string& path, const std::string& text) {
    if (path == "-") {
        std::cout << text << std::flush;
        return;
    }
    make_parent_dirs(path);
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error(fmt::format("{}: cannot write the file", path));
}

void Console::note(const std::string& text) const {
    if (!quiet) std::cerr << text << '\n';
}

}  // namespace fb89::cli
