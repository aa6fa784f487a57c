#include "mesh/worker_sandbox.hpp"

#include <algorithm>

#include <fcntl.h>
#include <linux/landlock.h>
#include <sched.h>
#include <seccomp.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace iga {

namespace {

void set_limit(int resource, rlim_t soft, rlim_t hard) {
  // Never above a limit the worker inherited (e.g. `ulimit -v` in the caller's shell): raising a
  // hard limit fails (EPERM), and a lower inherited limit is already as strict as ours.
  rlimit inherited{};
  if (::getrlimit(resource, &inherited) == 0 && inherited.rlim_max != RLIM_INFINITY) {
    hard = std::min(hard, inherited.rlim_max);
    soft = std::min(soft, hard);
  }
  const rlimit limit{soft, hard};
  if (::setrlimit(resource, &limit) != 0)
    throw std::runtime_error(std::string("gmsh worker: setrlimit failed: ") + std::strerror(errno));
}

/// Landlock: reading only inside `folders`; nothing else on the file system (no writing, no
/// executing). Skipped where the kernel has no Landlock (the seccomp filter still applies).
void restrict_file_system(const std::vector<std::string>& folders) {
  const long abi = ::syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
  if (abi < 1) return;
  landlock_ruleset_attr ruleset{};
  ruleset.handled_access_fs = (LANDLOCK_ACCESS_FS_MAKE_SYM << 1) - 1;  // every right of ABI 1
  if (abi >= 2) ruleset.handled_access_fs |= LANDLOCK_ACCESS_FS_REFER;
  const int fd = static_cast<int>(::syscall(SYS_landlock_create_ruleset, &ruleset, sizeof ruleset, 0));
  if (fd < 0) return;
  for (const std::string& folder : folders) {
    landlock_path_beneath_attr rule{};
    rule.allowed_access = LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR;
    rule.parent_fd = ::open(folder.c_str(), O_PATH | O_CLOEXEC);
    if (rule.parent_fd < 0) continue;
    ::syscall(SYS_landlock_add_rule, fd, LANDLOCK_RULE_PATH_BENEATH, &rule, 0);
    ::close(rule.parent_fd);
  }
  ::syscall(SYS_landlock_restrict_self, fd, 0);
  ::close(fd);
}

void install_syscall_filter() {
  scmp_filter_ctx filter = ::seccomp_init(SCMP_ACT_ALLOW);
  if (!filter) throw std::runtime_error("gmsh worker: seccomp_init failed");
  int failures = 0;
  auto deny = [&](int call, unsigned count = 0, scmp_arg_cmp arg = {}) {
    failures += ::seccomp_rule_add(filter, SCMP_ACT_ERRNO(EPERM), call, count, arg) != 0;
  };
  // clang-format off
  for (int call :
       {SCMP_SYS(execve), SCMP_SYS(execveat), SCMP_SYS(fork), SCMP_SYS(vfork), SCMP_SYS(ptrace),
        SCMP_SYS(process_vm_readv), SCMP_SYS(process_vm_writev), SCMP_SYS(socket), SCMP_SYS(socketpair),
        SCMP_SYS(connect), SCMP_SYS(bind), SCMP_SYS(creat), SCMP_SYS(unlink), SCMP_SYS(unlinkat),
        SCMP_SYS(rename), SCMP_SYS(renameat), SCMP_SYS(renameat2), SCMP_SYS(mkdir), SCMP_SYS(mkdirat),
        SCMP_SYS(rmdir), SCMP_SYS(link), SCMP_SYS(linkat), SCMP_SYS(symlink), SCMP_SYS(symlinkat),
        SCMP_SYS(chmod), SCMP_SYS(fchmod), SCMP_SYS(fchmodat), SCMP_SYS(chown), SCMP_SYS(fchown),
        SCMP_SYS(lchown), SCMP_SYS(fchownat), SCMP_SYS(truncate), SCMP_SYS(mknod), SCMP_SYS(mknodat),
        SCMP_SYS(utimensat), SCMP_SYS(setrlimit), SCMP_SYS(tkill), SCMP_SYS(mount), SCMP_SYS(umount2),
        SCMP_SYS(chroot), SCMP_SYS(pivot_root), SCMP_SYS(unshare), SCMP_SYS(setns), SCMP_SYS(bpf),
        SCMP_SYS(perf_event_open), SCMP_SYS(keyctl), SCMP_SYS(add_key), SCMP_SYS(request_key),
        SCMP_SYS(open_by_handle_at), SCMP_SYS(name_to_handle_at), SCMP_SYS(io_uring_setup),
        SCMP_SYS(io_uring_enter), SCMP_SYS(io_uring_register), SCMP_SYS(init_module),
        SCMP_SYS(finit_module), SCMP_SYS(delete_module), SCMP_SYS(kexec_load), SCMP_SYS(reboot),
        SCMP_SYS(setuid), SCMP_SYS(setgid), SCMP_SYS(setreuid), SCMP_SYS(setregid), SCMP_SYS(setresuid),
        SCMP_SYS(setresgid), SCMP_SYS(memfd_create)})
    deny(call);
  // clang-format on
  // New processes: clone without CLONE_THREAD (fork, posix_spawn, system); clone3's flags live in
  // memory the filter cannot read, so it reports "not implemented" and glibc falls back to clone.
  deny(SCMP_SYS(clone), 1, SCMP_A0(SCMP_CMP_MASKED_EQ, CLONE_THREAD, 0));
  failures += ::seccomp_rule_add(filter, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0) != 0;
  failures += ::seccomp_rule_add(filter, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(openat2), 0) != 0;
  // Files opened for writing or created.
  for (int flag : {O_WRONLY, O_RDWR, O_CREAT, O_TRUNC, O_APPEND}) {
    const auto f = static_cast<scmp_datum_t>(flag);
    deny(SCMP_SYS(open), 1, SCMP_A1(SCMP_CMP_MASKED_EQ, f, f));
    deny(SCMP_SYS(openat), 1, SCMP_A2(SCMP_CMP_MASKED_EQ, f, f));
  }
  // Signals only to itself (abort and raise use tgkill on the own process).
  const auto self = static_cast<scmp_datum_t>(::getpid());
  deny(SCMP_SYS(kill), 1, SCMP_A0(SCMP_CMP_NE, self));
  deny(SCMP_SYS(tgkill), 1, SCMP_A0(SCMP_CMP_NE, self));
  // Limits may be read, not set.
  deny(SCMP_SYS(prlimit64), 1, SCMP_A2(SCMP_CMP_NE, 0));
  const int loaded = failures == 0 ? ::seccomp_load(filter) : -1;
  ::seccomp_release(filter);
  if (failures != 0 || loaded != 0) throw std::runtime_error("gmsh worker: cannot install the system-call filter");
}

}  // namespace

void limit_worker_resources(const MeshLimits& limits) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() == 1) ::_exit(1);  // the parent is already gone
  const auto cpu = static_cast<rlim_t>(limits.seconds) + 1;
  set_limit(RLIMIT_CPU, cpu, cpu + 1);
#if !defined(__SANITIZE_ADDRESS__)  // AddressSanitizer reserves terabytes of address space for its shadow
  set_limit(RLIMIT_AS, limits.memory_bytes, limits.memory_bytes);
#endif
  set_limit(RLIMIT_CORE, 0, 0);
}

void confine_worker(const std::vector<std::string>& readable_folders) {
  if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0)
    throw std::runtime_error(std::string("gmsh worker: no_new_privs failed: ") + std::strerror(errno));
  // No file can grow from here on (after Gmsh's start-up, whose FLTK rewrites its preference
  // files: with the limit in place they would be truncated to nothing).
  set_limit(RLIMIT_FSIZE, 0, 0);
  ::signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails with EFBIG instead of killing
  restrict_file_system(readable_folders);
  install_syscall_filter();
}

}  // namespace iga
