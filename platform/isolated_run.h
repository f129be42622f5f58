#pragma once
// Runs one command in a child process with limits, so a hostile submission
// costs its own budget and never the batch's: CPU time, address space, a
// wall clock after which the child and everything it started are killed, a
// cap on what it may print, and — the isolation — no files written and no
// network:
// - bubblewrap (Debian's `bwrap`) where it runs: the whole file system
//   read-only, no network, its own process tree (a grandchild cannot
//   outlive the kill);
// - else a syscall filter (seccomp, grading/syscall_filter.h) the child
//   puts on itself: no file opened for writing, created, truncated or
//   deleted, no socket but a local one, no leaving its process group;
// - else limits only, which `grade batch` refuses unless told
//   --no-isolation (docs/grading.md).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::platform {

enum class Isolation : unsigned char { Bubblewrap, SyscallFilter, LimitsOnly };
std::string_view
isolationName(Isolation isolation); // "bubblewrap", "syscall filter", "limits only"

// The strongest isolation this machine gives (bubblewrap is tried once).
Isolation bestIsolation();

struct IsolationLimits {
    double cpuSeconds = 30;
    std::size_t memoryBytes = std::size_t(2) << 30;
    double wallSeconds = 60;
    std::size_t outputBytes = std::size_t(8) << 20; // stdout and stderr each
    std::size_t fileBytes = 0;                      // the largest file it may write (0: none)
    bool isolate = true; // false: limits only (a renderer, which must write files)
    // The isolation to use when isolating; bestIsolation() when unset (the
    // tests run each one).
    std::optional<Isolation> isolation;
};

struct ChildResult {
    int exitCode = -1; // when it exited
    int signal = 0;    // when a signal ended it (SIGXCPU, SIGKILL ...)
    bool timedOut = false;
    bool outputCut = false; // printed more than outputBytes
    std::string out, err;
    Isolation isolation = Isolation::LimitsOnly; // what it ran under
    std::string startError;                      // the command could not be started
};

ChildResult runIsolated(const std::vector<std::string>& argv, const IsolationLimits& limits);

} // namespace fl::platform
