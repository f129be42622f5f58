#include "platform/syscall_filter.h"

#include <cerrno>
#include <cstddef>
#include <fcntl.h>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/syscall.h>

namespace fl::platform {

#if defined(__x86_64__) || defined(__aarch64__)

namespace {

#if defined(__x86_64__)
constexpr unsigned kArchitecture = AUDIT_ARCH_X86_64;
#else
constexpr unsigned kArchitecture = AUDIT_ARCH_AARCH64;
#endif

constexpr unsigned kNumber = offsetof(seccomp_data, nr);
constexpr unsigned kArch = offsetof(seccomp_data, arch);
// The low 32 bits of argument i (both architectures are little-endian).
constexpr unsigned argument(unsigned i) {
    return unsigned(offsetof(seccomp_data, args)) + 8 * i;
}

constexpr unsigned kDeny = SECCOMP_RET_ERRNO | (EPERM & SECCOMP_RET_DATA);
constexpr unsigned kNotHere = SECCOMP_RET_ERRNO | (ENOSYS & SECCOMP_RET_DATA);
constexpr unsigned kAllow = SECCOMP_RET_ALLOW;
constexpr unsigned kWriting = O_WRONLY | O_RDWR | O_CREAT | O_TRUNC | O_APPEND;

// Refused outright (EPERM).
constexpr long kRefused[] = {
#ifdef SYS_creat
    SYS_creat,
#endif
#ifdef SYS_unlink
    SYS_unlink,
#endif
#ifdef SYS_rmdir
    SYS_rmdir,
#endif
#ifdef SYS_mkdir
    SYS_mkdir,
#endif
#ifdef SYS_rename
    SYS_rename,
#endif
#ifdef SYS_link
    SYS_link,
#endif
#ifdef SYS_symlink
    SYS_symlink,
#endif
#ifdef SYS_chmod
    SYS_chmod,
#endif
#ifdef SYS_chown
    SYS_chown,
#endif
#ifdef SYS_lchown
    SYS_lchown,
#endif
#ifdef SYS_mknod
    SYS_mknod,
#endif
#ifdef SYS_utime
    SYS_utime,
#endif
#ifdef SYS_utimes
    SYS_utimes,
#endif
    SYS_unlinkat,
    SYS_mkdirat,
    SYS_renameat,
    SYS_renameat2,
    SYS_linkat,
    SYS_symlinkat,
    SYS_fchmodat,
    SYS_fchmod,
    SYS_fchownat,
    SYS_fchown,
    SYS_mknodat,
    SYS_truncate,
    SYS_ftruncate,
    SYS_fallocate,
    SYS_utimensat,
    SYS_setxattr,
    SYS_lsetxattr,
    SYS_fsetxattr,
    SYS_removexattr,
    SYS_lremovexattr,
    SYS_fremovexattr,
    SYS_setsid,
    SYS_setpgid,
    SYS_ptrace,
    SYS_mount,
    SYS_umount2,
    SYS_pivot_root,
    SYS_chroot,
    SYS_io_uring_setup,
    SYS_io_uring_enter,
    SYS_io_uring_register,
    SYS_openat2,
    SYS_open_by_handle_at,
    SYS_name_to_handle_at,
    SYS_process_vm_writev};

struct Program {
    static constexpr unsigned short kMax = 192;
    sock_filter code[kMax];
    unsigned short size = 0;
    bool overflow = false;

    void statement(unsigned short op, unsigned k) { put(sock_filter{op, 0, 0, k}); }
    void jump(unsigned short op, unsigned k, unsigned char yes, unsigned char no) {
        put(sock_filter{op, yes, no, k});
    }
    void put(sock_filter f) {
        if (size == kMax) {
            overflow = true;
            return;
        }
        code[size++] = f;
    }
    void loadNumber() { statement(BPF_LD | BPF_W | BPF_ABS, kNumber); }
    // if (nr == number) return verdict;
    void refuse(long number, unsigned verdict) {
        jump(BPF_JMP | BPF_JEQ | BPF_K, unsigned(number), 0, 1);
        statement(BPF_RET | BPF_K, verdict);
    }
    // if (nr == number) return (argument & mask) ? EPERM : ALLOW;
    void refuseWhenFlags(long number, unsigned arg, unsigned mask) {
        jump(BPF_JMP | BPF_JEQ | BPF_K, unsigned(number), 0, 4);
        statement(BPF_LD | BPF_W | BPF_ABS, argument(arg));
        jump(BPF_JMP | BPF_JSET | BPF_K, mask, 0, 1);
        statement(BPF_RET | BPF_K, kDeny);
        statement(BPF_RET | BPF_K, kAllow);
    }
    // if (nr == number) return argument == value ? ALLOW : EPERM;
    void allowOnlyWhen(long number, unsigned arg, unsigned value) {
        jump(BPF_JMP | BPF_JEQ | BPF_K, unsigned(number), 0, 4);
        statement(BPF_LD | BPF_W | BPF_ABS, argument(arg));
        jump(BPF_JMP | BPF_JEQ | BPF_K, value, 1, 0);
        statement(BPF_RET | BPF_K, kDeny);
        statement(BPF_RET | BPF_K, kAllow);
    }
};

} // namespace

bool installSyscallFilter() {
    Program p; // on the stack: no allocation between fork and exec
    p.statement(BPF_LD | BPF_W | BPF_ABS, kArch);
    p.jump(BPF_JMP | BPF_JEQ | BPF_K, kArchitecture, 1, 0);
    p.statement(BPF_RET | BPF_K, SECCOMP_RET_KILL_PROCESS); // another ABI: no way around
    p.loadNumber();
#if defined(__x86_64__)
    // The x32 ABI's numbers have bit 30 set: another way around the table.
    p.jump(BPF_JMP | BPF_JGE | BPF_K, 0x40000000u, 0, 1);
    p.statement(BPF_RET | BPF_K, kDeny);
#endif
    for (const long number : kRefused)
        p.refuse(number, kDeny);
    p.refuse(SYS_clone3, kNotHere); // threads fall back to clone(2), whose flags are read
    p.refuseWhenFlags(SYS_openat, 2, kWriting);
#ifdef SYS_open
    p.refuseWhenFlags(SYS_open, 1, kWriting);
#endif
    p.allowOnlyWhen(SYS_socket, 0, AF_UNIX);
    p.statement(BPF_RET | BPF_K, kAllow);
    if (p.overflow) return false;
    if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return false;
    sock_fprog program{p.size, p.code};
    return ::prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &program, 0, 0) == 0;
}

#else

bool installSyscallFilter() {
    return false;
}

#endif

} // namespace fl::platform
