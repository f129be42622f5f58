#pragma once
// Runs one command in a child process with limits, so a hostile submission
// costs its own budget and never the batch's: CPU time, address space, no
// files written, no network (bubblewrap when installed, else a fresh network
// namespace when the kernel allows one), a wall clock after which the whole
// process group is killed, and a cap on what it may print.
#include <cstddef>
#include <string>
#include <vector>

namespace fl::grading {

struct IsolationLimits {
    double cpuSeconds = 30;
    std::size_t memoryBytes = std::size_t(2) << 30;
    double wallSeconds = 60;
    std::size_t outputBytes = std::size_t(8) << 20; // stdout and stderr each
    std::size_t fileBytes = 0;                      // the largest file it may write (0: none)
    bool noNetwork = true;
};

struct ChildResult {
    int exitCode = -1; // when it exited
    int signal = 0;    // when a signal ended it (SIGXCPU, SIGKILL ...)
    bool timedOut = false;
    bool outputCut = false; // printed more than outputBytes
    std::string out, err;
    std::string isolation;  // "bubblewrap", "network namespace" or "limits only"
    std::string startError; // the command could not be started
};

ChildResult runIsolated(const std::vector<std::string>& argv, const IsolationLimits& limits);

} // namespace fl::grading
