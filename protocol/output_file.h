// Where an output goes decides how it is written (docs/RELIABILITY.md, "Outputs").
//
// - "-" is standard output: written there, never named as a file. So is a name for one of
//   the process's descriptors — /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N —
//   whatever the descriptor is (a pipe, a terminal, a file the shell opened with `>`).
// - A regular file, or a path that does not exist yet, is written whole or not at all: the
//   bytes go to a hidden temporary beside the target (`.out.png.tmp-XXXXXX`, made by mkstemp
//   in the target's folder, so the rename stays within one file system), which is flushed,
//   synced and closed with every error checked, then renamed over the target. On any
//   failure the temporary is removed and the old target is left as it was; a process killed
//   part-way leaves the old target and, at most, a hidden temporary.
// - A regular file written as it is made (a stream, which a viewer may follow while it
//   grows: LiveFile) is written at the target itself, but is as all-or-nothing towards
//   the file it replaces: an old file there is first renamed aside to a hidden
//   `.out.fb89.old-XXXXXX` beside it, and renamed back over the new one when the output is
//   abandoned (the command fails, or the writer gives up); kept, the old one is removed.
//   A process killed part-way leaves the new, cut stream at the target and the old file
//   in the hidden name beside it.
// - Anything else that exists — a character device (/dev/null, /dev/full, a terminal), a
//   FIFO, a Unix socket — is opened and written in place, also when reached through a
//   symbolic link such as /dev/stdout. It is never renamed over: a device stays a device.
//   Bytes handed to a device or pipe cannot be taken back, so there "whole or not at all"
//   becomes "every error reported" (/dev/full: No space left on device).
// - A directory is an error naming it.
//
// It lives in protocol/ because that is the lowest library every writer links:
// controller_sim (PNG), experiments (id buffers, results folders), cli (JSON, CSV,
// calibration) and the stream writer all depend on fb89_protocol, which depends on nothing
// of ours. scripts/output_file.py follows the same rule for the charts.
//
// A file size limit (`ulimit -f`) only shows as an error (EFBIG) if SIGXFSZ is ignored;
// fb89's main does so. Errors are std::runtime_error naming the target:
// `out.png: File too large`.
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fb89::protocol {

// When a regular file is put in place: with the command (by the current OutputBatch, if
// any; at once otherwise), or at once whatever the command does later. `Now` is for what a
// long-running command reports as it goes (the controller's --png/--stats while it
// serves, the period runs' results folder, which later runs resume from).
enum class Publish { WithCommand, Now };

enum class OutputKind {
    Descriptor,  // "-" (standard output), or a name for an open descriptor (/dev/stdout)
    Replace,     // a regular file or a new path: a temporary renamed over it
    InPlace,     // a device, FIFO or socket: opened and written where it is
};

// How `target` will be written. Throws std::runtime_error naming it when it is a directory.
OutputKind output_kind(const std::filesystem::path& target);

// The descriptor a Descriptor target names (1 for "-" and /dev/stdout), else -1.
int named_descriptor(const std::filesystem::path& target);

// The name of an output in messages: "<stdout>" for "-", else the path as given.
std::string output_name(const std::filesystem::path& target);

// Opens an InPlace target for writing where it is (a device or FIFO with open(2), a Unix
// socket by connecting to it) and returns the descriptor. A FIFO waits for its reader, as
// any writer of a FIFO does. Throws std::runtime_error naming the target.
int open_in_place(const std::filesystem::path& target);

class OutputFile {
  public:
    // Opens the output as output_kind() says: a temporary beside a regular target (a
    // symbolic link is followed, so the file it names is replaced, not the link; the new
    // file gets the old one's permissions, else 0666 less the umask), the target itself
    // for a device, FIFO or socket, a duplicate of the descriptor for "-" or /dev/stdout
    // (std::cout is flushed first, so the order of what reaches stdout is kept).
    explicit OutputFile(std::filesystem::path target, Publish publish = Publish::WithCommand);
    // Removes the temporary unless commit() succeeded.
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    std::FILE* stream() const { return m_stream; }
    OutputKind kind() const { return m_kind; }
    // The hidden temporary (Replace only; empty otherwise).
    const std::filesystem::path& temporary() const { return m_temporary; }

    // Flushes and closes; for a regular file also syncs the temporary and renames it over
    // the target (or hands it to the current OutputBatch). On failure the temporary is
    // removed and the error thrown.
    void commit();

  private:
    [[noreturn]] void fail(int error);
    void open_temporary();
    void open_in_place();
    void open_descriptor();

    std::filesystem::path m_target;  // as given, for messages
    std::filesystem::path m_final;   // where the rename goes (links followed)
    std::filesystem::path m_temporary;
    OutputKind m_kind = OutputKind::Replace;
    Publish m_publish = Publish::WithCommand;
    std::FILE* m_stream = nullptr;
    bool m_committed = false;
};

// A regular file written in place as it is made (a stream a viewer follows), all or
// nothing towards an old file at its path (see the top of this file). Opening renames an
// old file aside and creates the target afresh, with the old one's permissions. While an
// OutputBatch exists (and `publish` is WithCommand) the batch decides the file's fate with
// the command: kept when it publishes, else removed and the old file put back; abandon()
// does that at once. Without a batch, keep() keeps it, and abandon() -- or destruction
// without either -- puts the old file back (a new path keeps what was written, a cut
// stream; there was nothing to lose).
class LiveFile {
  public:
    // Throws std::runtime_error naming the target when it cannot be made.
    explicit LiveFile(std::filesystem::path target, Publish publish = Publish::WithCommand);
    ~LiveFile();
    LiveFile(const LiveFile&) = delete;
    LiveFile& operator=(const LiveFile&) = delete;

    // The descriptor, open for writing; the LiveFile never closes it (its writer does).
    int fd() const { return m_fd; }
    // The target with links followed: where the bytes go.
    const std::filesystem::path& path() const { return m_final; }
    // The hidden name the old file waits under; empty when there was none.
    const std::filesystem::path& backup() const { return m_backup; }

    // The file stands (without a batch: the old one is removed now; under a batch the batch
    // decides with the command).
    void keep() noexcept;
    // The new file is removed and the old one, if any, put back where it was.
    void abandon() noexcept;

  private:
    std::filesystem::path m_final, m_backup;
    int m_fd = -1;
    bool m_batched = false;  // an OutputBatch decides
    bool m_decided = false;
};

// Puts a live file's old version back (`backup` renamed over `final`), or removes `final`
// when there was no old one (`backup` empty).
void restore_live(const std::filesystem::path& final, const std::filesystem::path& backup) noexcept;

// Writes `bytes` to the output `path` ("-": stdout).
void write_output(const std::filesystem::path& path, std::string_view bytes,
                  Publish publish = Publish::WithCommand);

// Calls `write` with the output's stream, then commits. An exception from `write` leaves a
// regular target untouched and propagates; so does a write error left on the stream.
void write_output(const std::filesystem::path& path, const std::function<void(std::FILE*)>& write,
                  Publish publish = Publish::WithCommand);

// A command's outputs, put in place together when it succeeds, so a command that fails
// leaves every old file as it was, or nothing where there was none (docs/RELIABILITY.md,
// "Outputs"). While a batch exists (fb89's main makes one around each command), an
// OutputFile to a regular file commits to its synced temporary and the batch renames every
// temporary over its target in publish(); a batch destroyed unpublished removes them, and
// puts back the old files the live ones (streams, written in place so that a viewer can
// follow them: LiveFile) replaced, removing what they wrote. Outputs to stdout, devices and pipes
// cannot wait: they are written at once. One batch at a time, shared by the process's threads.
class OutputBatch {
  public:
    OutputBatch();  // becomes the current batch; throws std::logic_error if one exists
    ~OutputBatch();
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;

    // Renames every waiting temporary over its target, in the order they were committed,
    // and keeps the streams. Throws std::runtime_error naming the first target that fails
    // (those before it are in place; the rest are removed with the batch).
    void publish();
    std::size_t waiting() const;

    // The current batch, or nullptr.
    static OutputBatch* current();

    // OutputFile::commit: `temporary` waits to be renamed to `final`.
    void add_temporary(const std::filesystem::path& temporary, const std::filesystem::path& final,
                       const std::string& name);
    // LiveFile: `final` written in place, the old file waiting under `backup` (empty: none):
    // publish() removes the backup; a batch destroyed unpublished puts it back.
    void add_live(const std::filesystem::path& final, const std::filesystem::path& backup);
    // LiveFile::abandon: the live file was put back already; the batch forgets it.
    void drop_live(const std::filesystem::path& final);

  private:
    struct Waiting {
        std::filesystem::path temporary, final;
        std::string name;
    };
    mutable std::mutex m_mutex;
    std::vector<Waiting> m_waiting;
    struct Live {
        std::filesystem::path final, backup;
    };
    std::vector<Live> m_live;
};

}  // namespace fb89::protocol
