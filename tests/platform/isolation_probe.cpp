// A child that really tries to get out of its isolation (issue 27 §2): each
// command attempts one thing and exits 0 when it succeeded — which the
// isolation must never let happen — and 1 (saying why) when it was refused.
//   isolation_probe connect HOST PORT   a TCP connection
//   isolation_probe create PATH         a new file
//   isolation_probe write PATH          append to a file
//   isolation_probe truncate PATH       empty a file
//   isolation_probe unlink PATH         delete a file
//   isolation_probe read PATH           read a file (allowed: checkers read)
//   isolation_probe private-tmp         write and read back /tmp/probe
//   isolation_probe alloc BYTES         allocate and touch that much memory
//   isolation_probe escape TOKEN        leave the process group and linger
//   isolation_probe linger TOKEN        sleep 30 s (TOKEN marks the process)
#include <arpa/inet.h>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <netinet/in.h>
#include <new>
#include <poll.h>
#include <string>
#include <sys/socket.h>
#include <unistd.h>

namespace {

int refused(const char* what) {
    std::printf("refused: %s: %s\n", what, std::strerror(errno));
    return 1;
}

int connectTo(const char* host, int port) {
    const int s = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
    if (s < 0) return refused("socket");
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(std::uint16_t(port));
    ::inet_pton(AF_INET, host, &a.sin_addr);
    if (::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) return 0;
    if (errno != EINPROGRESS) return refused("connect");
    pollfd p{s, POLLOUT, 0};
    if (::poll(&p, 1, 2000) != 1) return refused("connect (no answer)");
    int error = 0;
    socklen_t length = sizeof error;
    ::getsockopt(s, SOL_SOCKET, SO_ERROR, &error, &length);
    errno = error;
    return error == 0 ? 0 : refused("connect");
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) return 2;
    const std::string what = argv[1];
    const char* arg = argc > 2 ? argv[2] : "";
    if (what == "connect" && argc > 3) return connectTo(arg, std::atoi(argv[3]));
    if (what == "create") {
        const int fd = ::open(arg, O_WRONLY | O_CREAT | O_EXCL, 0644);
        return fd >= 0 ? 0 : refused("create");
    }
    if (what == "write") {
        const int fd = ::open(arg, O_WRONLY | O_APPEND);
        if (fd < 0) return refused("open for writing");
        return ::write(fd, "hostile\n", 8) == 8 ? 0 : refused("write");
    }
    if (what == "truncate") return ::truncate(arg, 0) == 0 ? 0 : refused("truncate");
    if (what == "unlink") return ::unlink(arg) == 0 ? 0 : refused("unlink");
    if (what == "read") {
        const int fd = ::open(arg, O_RDONLY);
        char c;
        return fd >= 0 && ::read(fd, &c, 1) == 1 ? 0 : refused("read");
    }
    if (what == "private-tmp") {
        const int fd = ::open("/tmp/probe", O_RDWR | O_CREAT | O_TRUNC, 0644);
        if (fd < 0) return refused("create /tmp/probe");
        char c = 0;
        return ::write(fd, "x", 1) == 1 && ::pread(fd, &c, 1, 0) == 1 && c == 'x' ? 0
                                                                                  : refused("tmp");
    }
    if (what == "alloc") {
        const std::size_t bytes = std::strtoull(arg, nullptr, 10);
        char* p = new (std::nothrow) char[bytes];
        if (!p) return refused("allocate");
        for (std::size_t i = 0; i < bytes; i += 4096)
            p[i] = 1;
        return 0;
    }
    if (what == "escape") {
        const pid_t child = ::fork();
        if (child == 0) {
            ::setsid(); // leave the group a wall-clock kill ends (refused under the filter)
            if (::fork() == 0) {
                ::execl("/proc/self/exe", argv[0], "linger", arg, static_cast<char*>(nullptr));
                ::_exit(1);
            }
            ::_exit(0);
        }
        ::sleep(30);
        return 1;
    }
    if (what == "linger") {
        ::sleep(30);
        return 0;
    }
    return 2;
}
