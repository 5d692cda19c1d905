// What the bad-input tests share (docs/RELIABILITY.md, "Bad input"): running fb89 with a
// generous time-out, scratch files, and the check that a run was refused as it should be.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/cli/cli_runner.h"

namespace fb89::testing::bad_input {

// A crash shows as 128 + signal, a hang as timeout's 124.
inline CliRun run_with_timeout(const std::string& args) {
    return fb89::testing::run_fb89(args, "timeout -s KILL 120 ");
}

inline std::string scratch(const std::string& name) {
    return (test_dir() / name).string();
}

inline std::string write_file(const std::string& name, const std::string& text) {
    const std::string path = scratch(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

inline std::string write_bytes(const std::string& name, const std::vector<uint8_t>& bytes) {
    const std::string path = scratch(name);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    return path;
}

inline void put_u16(std::vector<uint8_t>& b, size_t at, uint16_t v) {
    b[at] = static_cast<uint8_t>(v), b[at + 1] = static_cast<uint8_t>(v >> 8);
}

inline void put_u32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i)
        b[at + i] = static_cast<uint8_t>(v >> (8 * i));
}

// Exit 2, the file named in an "fb89: error" or "fb89: usage" line, and every `needle`.
inline void expect_refused(const CliRun& r, const std::string& file,
                           const std::vector<std::string>& needles) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("fb89: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << "the message must name " << file << ":\n"
                                                   << r.err;
    for (const auto& n : needles)
        EXPECT_NE(r.err.find(n), std::string::npos) << "expected '" << n << "' in:\n" << r.err;
}

}  // namespace fb89::testing::bad_input
