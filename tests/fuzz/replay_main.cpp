// Replays fuzz inputs without libFuzzer: runs LLVMFuzzerTestOneInput on every regular file
// of the directories (or files) given, in sorted order, so that a normal build's ctest
// checks every seed and every crash ever found. A missing directory counts as empty.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

std::vector<uint8_t> read_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    std::vector<fs::path> inputs;
    for (int i = 1; i < argc; ++i) {
        fs::path arg = fs::absolute(argv[i]);
        if (fs::is_regular_file(arg)) {
            inputs.push_back(arg);
        } else if (fs::is_directory(arg)) {
            for (const auto& e : fs::recursive_directory_iterator(arg))
                if (e.is_regular_file()) inputs.push_back(e.path());
        }
    }
    std::sort(inputs.begin(), inputs.end());
    for (const fs::path& p : inputs) {
        std::vector<uint8_t> bytes = read_bytes(p);
        std::fprintf(stderr, "replay %s (%zu bytes)\n", p.c_str(), bytes.size());
        // An empty vector's data() may be null; libFuzzer passes a valid pointer.
        static const uint8_t kEmpty = 0;
        LLVMFuzzerTestOneInput(bytes.empty() ? &kEmpty : bytes.data(), bytes.size());
    }
    std::printf("replayed %zu inputs\n", inputs.size());
    return 0;
}
