// `fb89 controller --view`: a live window on the controller, under Xvfb, while a host
// streams to it over the socket.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "tests/cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;

TEST(ControllerView, ShowsALiveStreamAndKeepsItsFrame) {
    if (!fb89::testing::on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
    const fs::path dir = fb89::testing::test_dir();
    const std::string sock = "/tmp/fb89-view-test-" + std::to_string(getpid()) + ".sock";
    const std::string fb89 = FB89_CLI_PATH;
    const std::string repo = fs::path(FB89_SCENES_DIR).parent_path().string();
    const std::string script =
        "cd " + repo + "\nrm -f " + sock + "\n(" + fb89::testing::xvfb_run() + "timeout 120 " +
        fb89 + " controller --listen " + sock + " --view --once --png " +
        (dir / "live.png").string() + " > " + (dir / "controller.out").string() +
        " 2>&1; echo $? > " + (dir / "controller.rc").string() +
        ") & for i in $(seq 1 900); do [ -S " + sock + " ] && break; sleep 0.1; done; timeout 60 " +
        fb89 + " render scenes/A.json --size 256x195 -q --connect " + sock + " --png " +
        (dir / "host.png").string() + " 2> " + (dir / "host.err").string() + "; echo $? > " +
        (dir / "host.rc").string() + "; wait";
    std::ofstream(dir / "run.sh") << script << "\n";
    ASSERT_EQ(std::system(("bash " + (dir / "run.sh").string()).c_str()), 0);
    EXPECT_EQ(fb89::testing::slurp(dir / "host.rc"), "0\n")
        << fb89::testing::slurp(dir / "host.err");
    EXPECT_EQ(fb89::testing::slurp(dir / "controller.rc"), "0\n")
        << fb89::testing::slurp(dir / "controller.out");
    EXPECT_EQ(fb89::testing::slurp(dir / "live.png"), fb89::testing::slurp(dir / "host.png"));
    fs::remove(sock);
}

}  // namespace
