#include "isolated_run.h"

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

namespace fl::grading {
namespace {

std::string bubblewrap() {
    for (const char* p : {"/usr/bin/bwrap", "/bin/bwrap"})
        if (::access(p, X_OK) == 0) return p;
    return {};
}

void limit(int resource, rlim_t value) {
    const rlimit r{value, value};
    ::setrlimit(resource, &r);
}

} // namespace

ChildResult runIsolated(const std::vector<std::string>& command, const IsolationLimits& limits) {
    ChildResult result;
    std::vector<std::string> argv;
    const std::string bwrap = limits.noNetwork ? bubblewrap() : std::string{};
    if (!bwrap.empty()) {
        // The whole file system read-only, a private /tmp, no network.
        argv = {
            bwrap,    "--unshare-net", "--die-with-parent", "--ro-bind", "/", "/", "--dev", "/dev",
            "--proc", "/proc",         "--tmpfs",           "/tmp",      "--"};
        result.isolation = "bubblewrap";
    }
    argv.insert(argv.end(), command.begin(), command.end());
    std::vector<char*> args;
    for (std::string& a : argv)
        args.push_back(a.data());
    args.push_back(nullptr);

    int out[2], err[2], failed[2], netns[2];
    if (::pipe2(out, O_CLOEXEC) || ::pipe2(err, O_CLOEXEC) || ::pipe2(failed, O_CLOEXEC) ||
        ::pipe2(netns, O_CLOEXEC)) {
        result.startError = std::strerror(errno);
        return result;
    }
    const pid_t pid = ::fork();
    if (pid < 0) {
        result.startError = std::strerror(errno);
        return result;
    }
    if (pid == 0) {
        ::setpgid(0, 0); // its own group: a wall-clock kill takes its children too
        ::dup2(out[1], 1);
        ::dup2(err[1], 2);
        const int null = ::open("/dev/null", O_RDONLY);
        if (null >= 0) ::dup2(null, 0);
        limit(RLIMIT_CPU, rlim_t(std::ceil(limits.cpuSeconds)));
        limit(RLIMIT_AS, rlim_t(limits.memoryBytes));
        limit(RLIMIT_FSIZE, rlim_t(limits.fileBytes)); // 0: writes no files
        limit(RLIMIT_CORE, 0);
        if (limits.noNetwork && bwrap.empty()) {
            // Without bubblewrap: a network namespace of its own, if allowed.
            const bool alone =
                ::unshare(CLONE_NEWNET) == 0 || ::unshare(CLONE_NEWUSER | CLONE_NEWNET) == 0;
            const char said = alone ? 'y' : 'n';
            [[maybe_unused]] auto n = ::write(netns[1], &said, 1);
        }
        ::execv(args[0], args.data());
        const int e = errno;
        [[maybe_unused]] auto n = ::write(failed[1], &e, sizeof e);
        ::_exit(127);
    }
    ::close(out[1]);
    ::close(err[1]);
    ::close(failed[1]);
    ::close(netns[1]);
    if (result.isolation.empty()) {
        char said = 'n';
        const bool told = ::read(netns[0], &said, 1) == 1;
        result.isolation = told && said == 'y' ? "network namespace" : "limits only";
    }
    ::close(netns[0]);

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
    int status = 0;
    ::waitpid(pid, &status, 0);
    int startErrno = 0;
    if (::read(failed[0], &startErrno, sizeof startErrno) == sizeof startErrno)
        result.startError = std::string("cannot run ") + args[0] + ": " + std::strerror(startErrno);
    ::close(failed[0]);
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    return result;
}

} // namespace fl::grading
