#include "platform/isolated_run.h"

#include "platform/syscall_filter.h"

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fl::platform {
namespace {

std::string bubblewrapPath() {
    for (const char* p : {"/usr/bin/bwrap", "/bin/bwrap"})
        if (::access(p, X_OK) == 0) return p;
    return {};
}

// bubblewrap's arguments before the command: the whole file system
// read-only (/tmp too: submissions are often there, and a checker writes
// nothing), in the same working folder, no network, its own process tree
// (when bwrap dies, every process in it dies), no capabilities, a new
// session (no typing into the terminal).
std::vector<std::string> bubblewrapArguments(const std::string& bwrap) {
    char here[4096];
    const std::string cwd = ::getcwd(here, sizeof here) ? here : "/";
    return {bwrap,
            "--unshare-net",
            "--unshare-pid",
            "--unshare-ipc",
            "--die-with-parent",
            "--new-session",
            "--cap-drop",
            "ALL",
            "--ro-bind",
            "/",
            "/",
            "--dev",
            "/dev",
            "--proc",
            "/proc",
            "--chdir",
            cwd,
            "--"};
}

void limit(int resource, rlim_t value) {
    const rlimit r{value, value};
    ::setrlimit(resource, &r);
}

} // namespace

std::string_view isolationName(Isolation isolation) {
    switch (isolation) {
    case Isolation::Bubblewrap:
        return "bubblewrap";
    case Isolation::SyscallFilter:
        return "syscall filter";
    case Isolation::LimitsOnly:
        return "limits only";
    }
    return "limits only";
}

Isolation bestIsolation() {
    // Whether bubblewrap runs here is tried once: installed is not enough
    // (without user namespaces, or in some containers, it cannot start).
    static const Isolation best = [] {
        IsolationLimits probe;
        probe.wallSeconds = 10;
        probe.isolation = Isolation::Bubblewrap;
        if (!bubblewrapPath().empty() && runIsolated({"/bin/true"}, probe).exitCode == 0)
            return Isolation::Bubblewrap;
        probe.isolation = Isolation::SyscallFilter;
        const ChildResult r = runIsolated({"/bin/true"}, probe);
        return r.exitCode == 0 && r.isolation == Isolation::SyscallFilter ? Isolation::SyscallFilter
                                                                          : Isolation::LimitsOnly;
    }();
    return best;
}

ChildResult runIsolated(const std::vector<std::string>& command, const IsolationLimits& limits) {
    ChildResult result;
    if (command.empty() || ::access(command.front().c_str(), X_OK) != 0) {
        result.startError = "cannot run " +
                            (command.empty() ? std::string("nothing") : command[0]) + ": " +
                            std::strerror(errno);
        return result;
    }
    Isolation wanted = Isolation::LimitsOnly;
    if (limits.isolate) wanted = limits.isolation ? *limits.isolation : bestIsolation();
    std::vector<std::string> argv;
    if (wanted == Isolation::Bubblewrap) {
        const std::string bwrap = bubblewrapPath();
        if (bwrap.empty()) {
            result.startError = "bubblewrap (bwrap) is not installed: apt-get install bubblewrap";
            return result;
        }
        argv = bubblewrapArguments(bwrap);
    }
    argv.insert(argv.end(), command.begin(), command.end());
    std::vector<char*> args;
    for (std::string& a : argv)
        args.push_back(a.data());
    args.push_back(nullptr);

    int out[2], err[2], failed[2], filtered[2];
    if (::pipe2(out, O_CLOEXEC) || ::pipe2(err, O_CLOEXEC) || ::pipe2(failed, O_CLOEXEC) ||
        ::pipe2(filtered, O_CLOEXEC)) {
        result.startError = std::strerror(errno);
        return result;
    }
    const pid_t pid = ::fork();
    if (pid < 0) {
        result.startError = std::strerror(errno);
        return result;
    }
    if (pid == 0) {
        // Only async-signal-safe calls from here to exec.
        ::setpgid(0, 0); // its own group: a wall-clock kill takes its children too
        ::dup2(out[1], 1);
        ::dup2(err[1], 2);
        const int null = ::open("/dev/null", O_RDONLY);
        if (null >= 0) ::dup2(null, 0);
        limit(RLIMIT_CPU, rlim_t(std::ceil(limits.cpuSeconds)));
        limit(RLIMIT_AS, rlim_t(limits.memoryBytes));
        limit(RLIMIT_FSIZE, rlim_t(limits.fileBytes));
        limit(RLIMIT_CORE, 0);
        if (wanted == Isolation::SyscallFilter) {
            // A network namespace too where the kernel gives one (defence in
            // depth; the filter alone already refuses sockets).
            if (::unshare(CLONE_NEWNET) != 0) ::unshare(CLONE_NEWUSER | CLONE_NEWNET);
            const char said = installSyscallFilter() ? 'y' : 'n';
            [[maybe_unused]] auto n = ::write(filtered[1], &said, 1);
            if (said == 'n') ::_exit(126); // never run unfiltered when a filter was asked for
        }
        ::execv(args[0], args.data());
        const int e = errno;
        [[maybe_unused]] auto n = ::write(failed[1], &e, sizeof e);
        ::_exit(127);
    }
    ::close(out[1]);
    ::close(err[1]);
    ::close(failed[1]);
    ::close(filtered[1]);
    result.isolation = wanted;
    if (wanted == Isolation::SyscallFilter) {
        char said = 'n';
        if (::read(filtered[0], &said, 1) != 1 || said != 'y') {
            result.isolation = Isolation::LimitsOnly;
            result.startError = "the syscall filter could not be installed (no seccomp here?)";
        }
    }
    ::close(filtered[0]);

    const auto start = std::chrono::steady_clock::now();
    pollfd fds[2] = {{out[0], POLLIN, 0}, {err[0], POLLIN, 0}};
    std::string* sinks[2] = {&result.out, &result.err};
    int open = 2;
    char buffer[1 << 15];
    while (open > 0) {
        const double left =
            limits.wallSeconds -
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (left <= 0) {
            result.timedOut = true;
            ::kill(-pid, SIGKILL);
            break;
        }
        if (::poll(fds, 2, int(std::min(left, 1.0) * 1000) + 1) < 0 && errno != EINTR) break;
        for (int i = 0; i < 2; ++i) {
            if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            const ssize_t n = ::read(fds[i].fd, buffer, sizeof buffer);
            if (n <= 0) {
                ::close(fds[i].fd);
                fds[i].fd = -1;
                --open;
                continue;
            }
            if (sinks[i]->size() + std::size_t(n) > limits.outputBytes) {
                result.outputCut = true;
                ::kill(-pid, SIGKILL);
            } else {
                sinks[i]->append(buffer, std::size_t(n));
            }
        }
    }
    for (const pollfd& f : fds)
        if (f.fd >= 0) ::close(f.fd);
    // Whatever the child left running goes with it: its group (it cannot
    // leave it under the filter) or, in bubblewrap, its whole process tree.
    // The child is waited for unreaped first, so its group's id stays its.
    siginfo_t ended{};
    ::waitid(P_PID, id_t(pid), &ended, WEXITED | WNOWAIT);
    ::kill(-pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    int startErrno = 0;
    if (::read(failed[0], &startErrno, sizeof startErrno) == sizeof startErrno)
        result.startError = std::string("cannot run ") + args[0] + ": " + std::strerror(startErrno);
    ::close(failed[0]);
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    // bubblewrap exits 128 + N when the command was killed by signal N.
    if (wanted == Isolation::Bubblewrap && result.exitCode > 128 && result.exitCode < 128 + 65) {
        result.signal = result.exitCode - 128;
        result.exitCode = -1;
    }
    return result;
}

} // namespace fl::platform
