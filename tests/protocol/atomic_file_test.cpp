// Outputs written whole or not at all (protocol/atomic_file.h): a failure of any kind leaves
// the old file byte-identical and no temporary beside it.
#include "protocol/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/scratch.h"

namespace fs = std::filesystem;
using fb89::protocol::AtomicFile;
using fb89::protocol::write_file_atomically;

namespace {

// A fresh folder of this test's own.
fs::path folder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir =
        fb89::testing::scratch_dir() / (std::string(info->test_suite_name()) + "." + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void put(const fs::path& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary) << bytes;
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

const std::string kOld = "the old file\n";

TEST(AtomicFile, SuccessReplacesTheOldFileAndLeavesNoTemporary) {
    const fs::path dir = folder(), out = dir / "out.txt";
    put(out, kOld);
    write_file_atomically(out, std::string(100000, 'n'));
    EXPECT_EQ(slurp(out), std::string(100000, 'n'));
    EXPECT_TRUE(others(dir, "out.txt").empty());
}

TEST(AtomicFile, TheTemporaryIsHiddenBesideTheTarget) {
    const fs::path dir = folder(), out = dir / "out.png";
    AtomicFile file(out);
    EXPECT_EQ(file.temporary().parent_path(), dir);
    EXPECT_EQ(file.temporary().filename().string().rfind(".out.png.tmp-", 0), 0u)
        << file.temporary();
}

TEST(AtomicFile, AWriterThatThrowsLeavesTheOldFileByteIdentical) {
    const fs::path dir = folder(), out = dir / "out.txt";
    put(out, kOld);
    EXPECT_THROW(write_file_atomically(out,
                                       [](std::FILE* f) {
                                           std::fputs("half of a new file", f);
                                           throw std::runtime_error("the writer gave up");
                                       }),
                 std::runtime_error);
    EXPECT_EQ(slurp(out), kOld);
    EXPECT_TRUE(others(dir, "out.txt").empty());
}

TEST(AtomicFile, AnUncommittedFileLeavesTheOldFile) {
    const fs::path dir = folder(), out = dir / "out.txt";
    put(out, kOld);
    {
        AtomicFile file(out);
        std::fputs("never committed", file.stream());
    }
    EXPECT_EQ(slurp(out), kOld);
    EXPECT_TRUE(others(dir, "out.txt").empty());
}

// With SIGXFSZ ignored (as fb89's main does) a file size limit is EFBIG, reported by name.
TEST(AtomicFile, AFileSizeLimitIsFileTooLargeAndLeavesTheOldFile) {
    const fs::path dir = folder(), out = dir / "out.txt";
    put(out, kOld);
    const int status = in_child([&] {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) return 3;
        try {
            write_file_atomically(out, std::string(1 << 20, 'n'));
        } catch (const std::runtime_error& e) {
            return std::string(e.what()) == out.string() + ": File too large" ? 0 : 1;
        }
        return 2;  // no error
    });
    EXPECT_EQ(status, 0) << "1: another message, 2: no error, 3: setrlimit failed";
    EXPECT_EQ(slurp(out), kOld);
    EXPECT_TRUE(others(dir, "out.txt").empty());
}

// Root writes through permissions, so the child drops to nobody first.
TEST(AtomicFile, AnUnwritableFolderIsAnErrorNamingTheFileAndLeavesTheOldFile) {
    const fs::path dir = folder(), out = dir / "out.txt";
    put(out, kOld);
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                             fs::perms::group_exec | fs::perms::others_read |
                             fs::perms::others_exec);
    const int status = in_child([&] {
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) return 3;
        try {
            write_file_atomically(out, "new");
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
    EXPECT_EQ(slurp(out), kOld);
    EXPECT_TRUE(others(dir, "out.txt").empty());
}

TEST(AtomicFile, AMissingFolderIsAnErrorNamingTheFile) {
    const fs::path out = folder() / "no" / "such" / "out.txt";
    try {
        write_file_atomically(out, "new");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(out.string() + ": ", 0), 0u) << e.what();
    }
}

TEST(AtomicFile, ADirectoryInTheWayIsAnErrorAndStays) {
    const fs::path dir = folder(), out = dir / "out";
    fs::create_directory(out);
    EXPECT_THROW(write_file_atomically(out, "new"), std::runtime_error);
    EXPECT_TRUE(fs::is_directory(out));
    EXPECT_TRUE(others(dir, "out").empty());
}

TEST(AtomicFile, KeepsTheOldFilesPermissions) {
    const fs::path dir = folder(), out = dir / "out.txt";
    put(out, kOld);
    ::chmod(out.c_str(), 0640);
    write_file_atomically(out, "new");
    struct stat st {};
    ASSERT_EQ(::stat(out.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0640u);
}

TEST(AtomicFile, ANewFileGetsTheUmasksPermissionsNotMkstemps) {
    const fs::path dir = folder(), out = dir / "out.txt";
    const mode_t mask = ::umask(022);
    ::umask(mask);
    write_file_atomically(out, "new");
    struct stat st {};
    ASSERT_EQ(::stat(out.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0666u & ~mask);
}

TEST(AtomicFile, ASymbolicLinkIsFollowedAndKept) {
    const fs::path dir = folder(), real = dir / "real.txt", link = dir / "link.txt";
    put(real, kOld);
    fs::create_symlink(real, link);
    write_file_atomically(link, "new");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(slurp(real), "new");
}

}  // namespace
