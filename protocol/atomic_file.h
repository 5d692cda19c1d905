// Output files written whole or not at all (docs/RELIABILITY.md, "Outputs").
//
// The bytes go to a hidden temporary beside the target (`.out.png.tmp-XXXXXX`, made by
// mkstemp in the target's folder, so the rename stays within one file system), which is
// flushed, synced and closed with every error checked, then renamed over the target. On
// any failure the temporary is removed and the old target is left as it was; a process
// killed part-way leaves the old target and, at most, a hidden temporary.
//
// It lives in protocol/ because that is the lowest library every writer links:
// controller_sim (PNG), experiments (id buffers, results folders) and cli (JSON, CSV,
// calibration) all depend on fb89_protocol, which depends on nothing of ours.
//
// A file size limit (`ulimit -f`) only shows as an error (EFBIG) if SIGXFSZ is ignored;
// fb89's main does so. Errors are std::runtime_error naming the target:
// `out.png: File too large`.
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string_view>

namespace fb89::protocol {

class AtomicFile {
  public:
    // Creates the temporary beside `target` (a symbolic link is followed, so the file it
    // names is replaced, not the link). The file gets the target's permissions if it
    // exists, else 0666 less the umask.
    explicit AtomicFile(std::filesystem::path target);
    // Removes the temporary unless commit() succeeded.
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    std::FILE* stream() const { return m_stream; }
    const std::filesystem::path& temporary() const { return m_temporary; }

    // Flushes, syncs, closes and renames the temporary over the target. On failure the
    // temporary is removed and the error thrown.
    void commit();

  private:
    [[noreturn]] void fail(int error);

    std::filesystem::path m_target;  // as given, for messages
    std::filesystem::path m_final;   // where the rename goes (links followed)
    std::filesystem::path m_temporary;
    std::FILE* m_stream = nullptr;
    bool m_committed = false;
};

// Writes `bytes` to `path` atomically.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// Calls `write` with the temporary's stream, then commits. An exception from `write`
// leaves the target untouched and propagates; so does a write error left on the stream.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::FILE*)>& write);

}  // namespace fb89::protocol
