// Isolated child processes: what a hostile submission can do to a batch is
// bounded — wall clock, CPU time, output, no files written — and ordinary
// exits come back as they were.
#include "isolated_run.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>

using namespace fl::grading;

namespace {

ChildResult shell(const std::string& script, IsolationLimits limits = {}) {
    return runIsolated({"/bin/sh", "-c", script}, limits);
}

} // namespace

TEST(IsolatedRun, ExitCodesAndOutputComeBack) {
    const ChildResult r = shell("echo out; echo err >&2; exit 3");
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_EQ(r.out, "out\n");
    EXPECT_EQ(r.err, "err\n");
    EXPECT_FALSE(r.timedOut);
    EXPECT_FALSE(r.isolation.empty());
}

TEST(IsolatedRun, AHangIsKilledAtTheWallClock) {
    IsolationLimits l;
    l.wallSeconds = 1;
    const ChildResult r = shell("sleep 30 & wait", l);
    EXPECT_TRUE(r.timedOut);
    EXPECT_EQ(r.signal, SIGKILL);
}

TEST(IsolatedRun, ASpinIsStoppedByItsCpuLimit) {
    IsolationLimits l;
    l.cpuSeconds = 1;
    l.wallSeconds = 20;
    const ChildResult r = shell("while :; do :; done", l);
    EXPECT_FALSE(r.timedOut);
    EXPECT_TRUE(r.signal == SIGXCPU || r.signal == SIGKILL) << r.signal;
}

TEST(IsolatedRun, TooMuchOutputIsCut) {
    IsolationLimits l;
    l.outputBytes = 4096;
    const ChildResult r = shell("yes", l);
    EXPECT_TRUE(r.outputCut);
    EXPECT_LE(r.out.size(), 4096u);
}

TEST(IsolatedRun, NoFilesAreWritten) {
    const auto file = std::filesystem::path(testing::TempDir()) / "isolated-write.txt";
    std::filesystem::remove(file);
    const ChildResult r = shell("echo hostile > " + file.string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_TRUE(!std::filesystem::exists(file) || std::filesystem::file_size(file) == 0);
}

TEST(IsolatedRun, AMissingProgramSaysSo) {
    const ChildResult r = runIsolated({"/nonexistent/checker"}, {});
    EXPECT_FALSE(r.startError.empty());
}
