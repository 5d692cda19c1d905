// scripts/output_file.py saves the charts by the rule every fb89 output follows
// (protocol/output_file.h): a regular file whole, a FIFO and a descriptor in place.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/cli/cli_runner.h"
#include "tests/special_files.h"

namespace fs = std::filesystem;
using fb89::testing::identity_of;
using fb89::testing::slurp;
using fb89::testing::test_dir;

namespace {

// Saves a one-line chart to `target` with Debian's python3 (which has matplotlib).
int save_chart(const std::string& target, const std::string& redirect = "") {
    const std::string script = FB89_TEST_DATA_DIR "/../scripts";
    const std::string command =
        "/usr/bin/python3 -c \"import sys; sys.path.insert(0, '" + script +
        "'); import matplotlib; matplotlib.use('Agg'); import matplotlib.pyplot as plt; "
        "from output_file import save; fig = plt.figure(); plt.plot([1, 2]); save(fig, '" +
        target + "')\"" + redirect;
    return std::system(command.c_str());
}

bool have_matplotlib() {
    return std::system(
               "/usr/bin/python3 -c 'import importlib.util as u, sys; "
               "sys.exit(u.find_spec(\"matplotlib\") is None)'") == 0;
}

TEST(ChartOutput, ARegularFileIsReplacedWholeWithNoTemporaryLeft) {
    if (!have_matplotlib()) GTEST_SKIP() << "no python3-matplotlib";
    const fs::path dir = test_dir() / "charts", png = dir / "chart.png";
    fs::remove_all(dir);
    fs::create_directories(dir);
    ASSERT_EQ(save_chart(png.string()), 0);
    EXPECT_EQ(slurp(png).substr(1, 3), "PNG");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(ChartOutput, AFifoAndADescriptorLinkAreWrittenInPlaceAndStayWhatTheyWere) {
    if (!have_matplotlib()) GTEST_SKIP() << "no python3-matplotlib";
    const fs::path fifo = test_dir() / "chart_fifo";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    fb89::testing::FifoReader reader(fifo);
    ASSERT_EQ(save_chart(fifo.string()), 0);
    EXPECT_EQ(reader.stop().substr(1, 3), "PNG");
    EXPECT_EQ(identity_of(fifo).type, static_cast<mode_t>(S_IFIFO));

    const fs::path link = test_dir() / "chart_stdout", out = test_dir() / "through_stdout.png";
    fs::remove(link);
    fs::create_symlink("/proc/self/fd/1", link);
    ASSERT_EQ(save_chart(link.string(), " > " + out.string()), 0);
    EXPECT_EQ(slurp(out).substr(1, 3), "PNG");
    EXPECT_EQ(identity_of(link).type, static_cast<mode_t>(S_IFLNK));
}

}  // namespace
