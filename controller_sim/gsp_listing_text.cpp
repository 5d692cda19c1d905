// Reading the GSP's listing as text (see gsp_listing_text.h).
//
// The listing is read line by line: "NAME .equ VALUE" defines a symbol, "label:" a label,
// other directives (".long") are data, and every other line is one instruction.
#include "controller_sim/gsp_listing_text.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include <fmt/format.h>

namespace fb89::controller::listing_text {

std::string upper(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())))
        s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
        s.remove_suffix(1);
    return s;
}

bool is_register(std::string_view s) {
    const std::string u = upper(s);
    if (u == "SP") return true;
    if (std::find(std::begin(kBFileNames), std::end(kBFileNames), u) != std::end(kBFileNames))
        return true;
    if (u.size() < 2 || u.size() > 3 || (u[0] != 'A' && u[0] != 'B')) return false;
    if (!std::all_of(u.begin() + 1, u.end(), [](char c) { return std::isdigit(c) != 0; }))
        return false;
    return std::stoi(u.substr(1)) <= 14;
}

std::optional<uint64_t> parse_number(std::string_view s) {
    s = trim(s);
    if (s.empty() || !std::isdigit(static_cast<unsigned char>(s[0]))) return std::nullopt;
    const bool hex = s.back() == 'h' || s.back() == 'H';
    if (hex) s.remove_suffix(1);
    uint64_t v = 0;
    for (char c : s) {
        const int d = std::isdigit(static_cast<unsigned char>(c))
                          ? c - '0'
                          : (hex && std::isxdigit(static_cast<unsigned char>(c))
                                 ? std::tolower(static_cast<unsigned char>(c)) - 'a' + 10
                                 : -1);
        if (d < 0) return std::nullopt;
        v = v * (hex ? 16 : 10) + static_cast<uint64_t>(d);
        if (v > 0xFFFFFFFFu) return std::nullopt;
    }
    return v;
}

Parsed parse(const Listing& listing) {
    Parsed out;
    int number = 0;
    std::string pending_label;
    std::string_view text = listing.text;
    const auto fail = [&](std::string_view what) {
        throw std::runtime_error(
            fmt::format("listing {}.asm line {}: {}", listing.name, number, what));
    };
    while (!text.empty()) {
        const std::size_t eol = text.find('\n');
        std::string_view line = text.substr(0, eol);
        text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
        ++number;
        std::string_view comment;
        if (const std::size_t semi = line.find(';'); semi != std::string_view::npos) {
            comment = trim(line.substr(semi + 1));
            line = line.substr(0, semi);
        }
        if (comment.starts_with("@path")) {
            std::vector<std::string> words;
            std::string_view rest = trim(comment.substr(5));
            while (!rest.empty()) {
                const std::size_t space = rest.find(' ');
                words.emplace_back(rest.substr(0, space));
                rest = space == std::string_view::npos ? std::string_view{}
                                                       : trim(rest.substr(space + 1));
            }
            if (words.size() < 2) fail("@path takes a name and a label");
            PathSpec spec{words[0], words[1], "", {}, {}};
            std::size_t i = 2;
            if (i < words.size() && words[i] != "take" && words[i] != "fall") spec.end = words[i++];
            for (; i < words.size(); i += 2) {
                if ((words[i] != "take" && words[i] != "fall") || i + 1 >= words.size())
                    fail("@path NAME START [END] [take LABEL | fall LABEL]...");
                (words[i] == "take" ? spec.taken : spec.fallen).push_back(words[i + 1]);
            }
            out.paths.push_back(std::move(spec));
            continue;
        }
        std::string_view code = line;
        std::string label;
        if (!code.empty() && !std::isspace(static_cast<unsigned char>(code[0]))) {
            std::size_t end = 0;
            while (end < code.size() && !std::isspace(static_cast<unsigned char>(code[end])))
                ++end;
            std::string_view first = code.substr(0, end);
            code = trim(code.substr(end));
            if (first.ends_with(":")) {
                label = std::string(first.substr(0, first.size() - 1));
            } else if (code.starts_with(".equ")) {
                const auto v = parse_number(code.substr(4));
                if (!v) fail("a .equ takes a number");
                out.symbols[std::string(first)] = *v;
                continue;
            } else {
                fail(fmt::format("{}: a label ends with ':'", first));
            }
        }
        code = trim(code);
        if (!label.empty()) {
            if (!pending_label.empty()) fail("two labels for one instruction");
            pending_label = label;
        }
        if (code.empty() || code.starts_with(".")) {
            if (code.starts_with(".")) pending_label.clear();  // a label on data
            continue;
        }
        Instruction in;
        in.line = number;
        in.label = pending_label;
        pending_label.clear();
        in.comment = std::string(comment);
        in.text = std::string(code);
        std::size_t space = 0;
        while (space < code.size() && !std::isspace(static_cast<unsigned char>(code[space])))
            ++space;
        in.mnemonic = upper(code.substr(0, space));
        std::string_view ops = trim(code.substr(space));
        while (!ops.empty()) {
            const std::size_t comma = ops.find(',');
            in.operands.emplace_back(trim(ops.substr(0, comma)));
            ops = comma == std::string_view::npos ? std::string_view{} : ops.substr(comma + 1);
        }
        if (!in.label.empty()) {
            if (out.labels.count(in.label)) fail(fmt::format("label {} defined twice", in.label));
            out.labels[in.label] = out.code.size();
        }
        out.code.push_back(std::move(in));
    }
    return out;
}

}  // namespace fb89::controller::listing_text
