// Outputs written by what their target is (protocol/output_file.h): a regular file whole or
// not at all (a failure of any kind leaves the old file byte-identical and no temporary
// beside it); a device, FIFO or socket in place, never renamed over; "-" and names of open
// descriptors through the descriptor; a command's files put in place by its OutputBatch.
#include "protocol/output_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "tests/cli/cli_runner.h"
#include "tests/scratch.h"
#include "tests/special_files.h"

namespace fs = std::filesystem;
using fb89::protocol::output_kind;
using fb89::protocol::OutputBatch;
using fb89::protocol::OutputFile;
using fb89::protocol::OutputKind;
using fb89::protocol::Publish;
using fb89::protocol::write_output;
using fb89::testing::identity_of;

namespace {

using fb89::testing::put;
using fb89::testing::slurp;

// A fresh folder of this test's own.
fs::path folder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir =
        fb89::testing::scratch_dir() / (std::string(info->test_suite_name()) + "." + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// The names in `dir` other than `keep`: temporaries left behind, if any.
std::vector<std::string> others(const fs::path& dir, const std::string& keep) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename() != keep) names.push_back(e.path().filename().string());
    return names;
}

// Runs `body` in a forked child; returns its exit status (or 100 + signal).
int in_child(const std::function<int()>& body) {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(body());
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 100 + WTERMSIG(status);
}

const std::string kOldFile = "the old file\n";

TEST(OutputFile, SuccessReplacesTheOldFileAndLeavesNoTemporary) {
    const fs::path dir = folder(), out = dir / "out.txt";
    put(out, kOldFile);
    write_output(out, std::string(100000, 'n'));
    EXPECT_EQ(slurp(out), std::string(100000, 'n'));
    EXPECT_TRUE(others(dir, "out.txt").empty());
}

TEST(OutputFile, TheTemporaryIsHiddenBesideTheTarget) {
    const fs::path dir = folder(), out = dir / "out.png";
    OutputFile file(out);
    EXPECT_EQ(file.temporary().parent_path(), dir);
    EXPECT_EQ(file.temporary().filename().string().rfind(".out.png.tmp-", 0), 0u)
        << file.temporary();
}

TEST(OutputFile, AWriterThatThrowsLeavesTheOldFileByteIdentical) {
    const fs::path dir = folder(), out = dir / "out.txt";
    put(out, kOldFile);
    EXPECT_THROW(write_output(out,
                              [](std::FILE* f) {
                                  std::fputs("half of a new file", f);
                                  throw std::runtime_error("the writer gave up");
                              }),
                 std::runtime_error);
    EXPECT_EQ(slurp(out), kOldFile);
    EXPECT_TRUE(others(dir, "out.txt").empty());
}

TEST(OutputFile, AnUncommittedFileLeavesTheOldFile) {
    const fs::path dir = folder(), out = dir / "out.txt";
    put(out, kOldFile);
    {
        OutputFile file(out);
        std::fputs("never committed", file.stream());
    }
    EXPECT_EQ(slurp(out), kOldFile);
    EXPECT_TRUE(others(dir, "out.txt").empty());
}

// With SIGXFSZ ignored (as fb89's main does) a file size limit is EFBIG, reported by name.
TEST(OutputFile, AFileSizeLimitIsFileTooLargeAndLeavesTheOldFile) {
    const fs::path dir = folder(), out = dir / "out.txt";
    put(out, kOldFile);
    const int status = in_child([&] {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) return 3;
        try {
            write_output(out, std::string(1 << 20, 'n'));
        } catch (const std::runtime_error& e) {
            return std::string(e.what()) == out.string() + ": File too large" ? 0 : 1;
        }
        return 2;  // no error
    });
    EXPECT_EQ(status, 0) << "1: another message, 2: no error, 3: setrlimit failed";
    EXPECT_EQ(slurp(out), kOldFile);
    EXPECT_TRUE(others(dir, "out.txt").empty());
}

// Root writes through permissions, so the child drops to nobody first.
TEST(OutputFile, AnUnwritableFolderIsAnErrorNamingTheFileAndLeavesTheOldFile) {
    const fs::path dir = folder(), out = dir / "out.txt";
    put(out, kOldFile);
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                             fs::perms::group_exec | fs::perms::others_read |
                             fs::perms::others_exec);
    const int status = in_child([&] {
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) return 3;
        try {
            write_output(out, "new");
        } catch (const std::runtime_error& e) {
            const std::string what = e.what();
            return what.rfind(out.string() + ": ", 0) == 0 &&
                           what.find("Permission denied") != std::string::npos
                       ? 0
                       : 1;
        }
        return 2;
    });
    fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add);
    EXPECT_EQ(status, 0) << "1: another message, 2: no error, 3: could not drop root";
    EXPECT_EQ(slurp(out), kOldFile);
    EXPECT_TRUE(others(dir, "out.txt").empty());
}

TEST(OutputFile, AMissingFolderIsAnErrorNamingTheFile) {
    const fs::path out = folder() / "no" / "such" / "out.txt";
    try {
        write_output(out, "new");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(out.string() + ": ", 0), 0u) << e.what();
    }
}

TEST(OutputFile, ADirectoryInTheWayIsAnErrorAndStays) {
    const fs::path dir = folder(), out = dir / "out";
    fs::create_directory(out);
    EXPECT_THROW(write_output(out, "new"), std::runtime_error);
    EXPECT_TRUE(fs::is_directory(out));
    EXPECT_TRUE(others(dir, "out").empty());
}

TEST(OutputFile, KeepsTheOldFilesPermissions) {
    const fs::path dir = folder(), out = dir / "out.txt";
    put(out, kOldFile);
    ::chmod(out.c_str(), 0640);
    write_output(out, "new");
    struct stat st {};
    ASSERT_EQ(::stat(out.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0640u);
}

TEST(OutputFile, ANewFileGetsTheUmasksPermissionsNotMkstemps) {
    const fs::path dir = folder(), out = dir / "out.txt";
    const mode_t mask = ::umask(022);
    ::umask(mask);
    write_output(out, "new");
    struct stat st {};
    ASSERT_EQ(::stat(out.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0666u & ~mask);
}

TEST(OutputFile, ASymbolicLinkIsFollowedAndKept) {
    const fs::path dir = folder(), real = dir / "real.txt", link = dir / "link.txt";
    put(real, kOldFile);
    fs::create_symlink(real, link);
    write_output(link, "new");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(slurp(real), "new");
}

TEST(OutputKinds, EachTargetIsWrittenAsWhatItIs) {
    const fs::path dir = folder();
    put(dir / "file", kOldFile);
    ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
    fs::create_symlink(dir / "fifo", dir / "link_to_fifo");
    fs::create_symlink("/proc/self/fd/1", dir / "stdout");
    fs::create_directory(dir / "folder");
    EXPECT_EQ(output_kind("-"), OutputKind::Descriptor);
    EXPECT_EQ(output_kind(dir / "stdout"), OutputKind::Descriptor);
    EXPECT_EQ(output_kind("/dev/fd/2"), OutputKind::Descriptor);
    EXPECT_EQ(fb89::protocol::named_descriptor(dir / "stdout"), 1);
    EXPECT_EQ(output_kind(dir / "file"), OutputKind::Replace);
    EXPECT_EQ(output_kind(dir / "new"), OutputKind::Replace);
    EXPECT_EQ(output_kind(dir / "fifo"), OutputKind::InPlace);
    EXPECT_EQ(output_kind(dir / "link_to_fifo"), OutputKind::InPlace);
    EXPECT_THROW(output_kind(dir / "folder"), std::runtime_error);
}

TEST(OutputKinds, ACharacterDeviceIsWrittenInPlaceAndStaysOne) {
    const fs::path dir = folder(), null = dir / "null";
    if (const auto why = fb89::testing::make_char_device(null, 3)) GTEST_SKIP() << *why;
    const auto before = identity_of(null);
    EXPECT_EQ(output_kind(null), OutputKind::InPlace);
    write_output(null, std::string(100000, 'n'));
    EXPECT_EQ(identity_of(null), before);
    EXPECT_TRUE(others(dir, "null").empty());
}

TEST(OutputKinds, AFullDeviceIsNoSpaceLeftOnDeviceAndStaysOne) {
    const fs::path dir = folder(), full = dir / "full";
    if (const auto why = fb89::testing::make_char_device(full, 7)) GTEST_SKIP() << *why;
    const auto before = identity_of(full);
    try {
        write_output(full, std::string(100000, 'n'));
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), full.string() + ": No space left on device");
    }
    EXPECT_EQ(identity_of(full), before);
}

TEST(OutputKinds, AFifoGetsTheBytesAndStaysAFifo) {
    const fs::path dir = folder(), fifo = dir / "fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    fb89::testing::FifoReader reader(fifo);
    const std::string bytes(200000, 'f');  // more than a pipe holds: the reader must keep up
    write_output(fifo, bytes);
    EXPECT_EQ(reader.stop(), bytes);
    EXPECT_EQ(identity_of(fifo).type, static_cast<mode_t>(S_IFIFO));
}

TEST(OutputKinds, AUnixSocketIsConnectedToAndStaysASocket) {
    const fs::path dir = folder(), path = dir / "sock";
    const int server = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::strncpy(addr.sun_path, path.c_str(), sizeof addr.sun_path - 1);
    ASSERT_EQ(::bind(server, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
    ASSERT_EQ(::listen(server, 1), 0);
    std::string got;
    std::thread accept_thread([&] {
        const int c = ::accept(server, nullptr, nullptr);
        char buffer[4096];
        for (ssize_t n; (n = ::read(c, buffer, sizeof buffer)) > 0;)
            got.append(buffer, static_cast<size_t>(n));
        ::close(c);
    });
    write_output(path, "through the socket");
    accept_thread.join();
    ::close(server);
    EXPECT_EQ(got, "through the socket");
    EXPECT_EQ(identity_of(path).type, static_cast<mode_t>(S_IFSOCK));
}

// A link of the test's own to /proc/self/fd/N is what /dev/stdout is to descriptor 1.
TEST(OutputKinds, ANameForADescriptorWritesThroughItAndStaysALink) {
    const fs::path dir = folder();
    int pipe_fds[2];
    ASSERT_EQ(::pipe(pipe_fds), 0);
    const fs::path link = dir / "pipe";
    fs::create_symlink("/proc/self/fd/" + std::to_string(pipe_fds[1]), link);
    EXPECT_EQ(output_kind(link), OutputKind::Descriptor);
    write_output(link, "through the descriptor");
    ::close(pipe_fds[1]);
    char buffer[64] = {};
    const ssize_t n = ::read(pipe_fds[0], buffer, sizeof buffer);
    ::close(pipe_fds[0]);
    EXPECT_EQ(std::string(buffer, static_cast<size_t>(std::max<ssize_t>(n, 0))),
              "through the descriptor");
    EXPECT_EQ(identity_of(link).type, static_cast<mode_t>(S_IFLNK));
}

TEST(OutputBatches, FilesWaitHiddenUntilPublishedAndAnUnpublishedBatchLeavesTheOld) {
    const fs::path dir = folder(), out = dir / "out.txt", fresh = dir / "fresh.txt";
    put(out, kOldFile);
    {
        OutputBatch batch;
        write_output(out, "new");
        write_output(fresh, "fresh");
        EXPECT_EQ(slurp(out), kOldFile) << "not in place before publish()";
        EXPECT_FALSE(fs::exists(fresh));
        EXPECT_EQ(batch.waiting(), 2u);
    }
    EXPECT_EQ(slurp(out), kOldFile);
    EXPECT_FALSE(fs::exists(fresh));
    EXPECT_TRUE(others(dir, "out.txt").empty()) << "no temporary left";
    {
        OutputBatch batch;
        write_output(out, "new");
        write_output(fresh, "fresh");
        batch.publish();
    }
    EXPECT_EQ(slurp(out), "new");
    EXPECT_EQ(slurp(fresh), "fresh");
}

TEST(OutputBatches, PublishNowIsPutInPlaceAtOnceWhateverTheBatchDoes) {
    const fs::path dir = folder(), out = dir / "results.json";
    {
        OutputBatch batch;
        write_output(out, "cached", Publish::Now);
        EXPECT_EQ(slurp(out), "cached");
    }
    EXPECT_EQ(slurp(out), "cached");
}

TEST(OutputBatches, OnlyOneAtATime) {
    OutputBatch batch;
    EXPECT_THROW(OutputBatch second, std::logic_error);
    EXPECT_EQ(OutputBatch::current(), &batch);
}

}  // namespace
