#pragma once
// The sandbox where bubblewrap cannot run: a seccomp filter the child of an
// isolated run installs on itself before it executes the checker (no root or
// user namespace needed). The checker reads files and prints; the filter
// refuses (EPERM) what a hostile submission would need to reach beyond that:
// - writing files: open/openat/creat for writing, truncate, unlink, rename,
//   mkdir, rmdir, links, chmod/chown, mknod, extended attributes;
// - the network: any socket but a local (AF_UNIX) one;
// - leaving the process group a wall-clock kill ends: setsid, setpgid;
// - the rest of the machine: ptrace, mount, io_uring (whose operations no
//   filter sees), openat2 and clone3 (whose arguments it cannot read; clone3
//   answers ENOSYS, so threads fall back to clone).
// Everything else is allowed. x86-64 and AArch64; elsewhere it is not
// installed (installSyscallFilter says so).

namespace fl::platform {

// Installs the filter on the calling thread and all it will execute (with
// no_new_privs). False when the kernel or the architecture cannot.
// Async-signal-safe: it is called between fork and exec.
bool installSyscallFilter();

} // namespace fl::platform
