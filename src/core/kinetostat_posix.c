/* The POSIX calls kinetostat needs that Fortran has no intrinsic for (as fpm's
 * filesystem_utilities.c): checked writes to file descriptors, output files replaced
 * atomically through temporaries that cannot be hijacked, temporaries and sweep children
 * removed when a signal ends the process, child processes, the number of processors. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* Two branches where Linux and the BSDs (macOS) differ: random bytes (getrandom on Linux,
 * getentropy elsewhere) and the links that name this process' own descriptors (procfs,
 * /proc/self/fd/N, on Linux; /dev/fd/N elsewhere). KINETOSTAT_FORCE_PORTABLE compiles the
 * other branch on Linux too (test/cli/test_binary.sh builds it so). */
#if defined(__linux__) && !defined(KINETOSTAT_FORCE_PORTABLE)
#define KS_LINUX 1
#include <sys/random.h>
#include <sys/statfs.h>
#ifndef PROC_SUPER_MAGIC
#define PROC_SUPER_MAGIC 0x9fa0
#endif
#else
#define KS_LINUX 0
#if defined(__APPLE__) || defined(__linux__)
#include <sys/random.h> /* getentropy (macOS 10.12+; glibc 2.25+) */
#endif
#endif

/* ---------------------------------------------------------------------------------------
 * Registered temporaries and children: what a fatal signal must clean up. */

#define KS_MAX_TEMPS 64
#define KS_MAX_CHILDREN 4096
#define KS_PATH 4096

static char ks_temp_path[KS_MAX_TEMPS][KS_PATH];
static volatile sig_atomic_t ks_temp_used[KS_MAX_TEMPS];
static volatile sig_atomic_t ks_child[KS_MAX_CHILDREN];

/* The signals that end the process and must clean up first. */
static const int ks_fatal_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
#define KS_FATAL_COUNT ((int) (sizeof ks_fatal_signals / sizeof ks_fatal_signals[0]))

/* Block the fatal signals while the registries change (restored by ks_unblock). */
static void ks_block(sigset_t *old) {
  sigset_t set;
  sigemptyset(&set);
  for (int i = 0; i < KS_FATAL_COUNT; i++) sigaddset(&set, ks_fatal_signals[i]);
  sigprocmask(SIG_BLOCK, &set, old);
}

static void ks_unblock(const sigset_t *old) { sigprocmask(SIG_SETMASK, old, NULL); }

/* Remove every registered temporary, kill and reap every registered child: only
 * async-signal-safe calls (unlink, kill, waitpid). */
static void ks_clean_up(void) {
  for (int i = 0; i < KS_MAX_CHILDREN; i++) {
    pid_t pid = (pid_t) ks_child[i];
    if (pid > 0) kill(pid, SIGKILL);
  }
  for (int i = 0; i < KS_MAX_CHILDREN; i++) {
    pid_t pid = (pid_t) ks_child[i];
    if (pid > 0) {
      while (waitpid(pid, NULL, 0) < 0 && errno == EINTR) {
      }
      ks_child[i] = 0;
    }
  }
  for (int i = 0; i < KS_MAX_TEMPS; i++) {
    if (ks_temp_used[i]) {
      unlink(ks_temp_path[i]);
      ks_temp_used[i] = 0;
    }
  }
}

/* A fatal signal: clean up, then die of the same signal with its default action (so the
 * exit status is the conventional 128 + signal number). */
static void ks_on_signal(int sig) {
  int saved = errno;
  sigset_t set;
  ks_clean_up();
  signal(sig, SIG_DFL);
  sigemptyset(&set);
  sigaddset(&set, sig);
  sigprocmask(SIG_UNBLOCK, &set, NULL);
  raise(sig);
  errno = saved;
}

/* Install the clean-up handler for SIGINT, SIGTERM, SIGHUP and SIGPIPE, except where the
 * signal is ignored already (nohup, a shell that ignores SIGPIPE: then a write to a closed
 * pipe fails with EPIPE and is reported). SIGXFSZ is ignored, so that a file-size limit
 * makes write(2) fail with EFBIG (reported, temporaries removed) instead of killing us. */
void kinetostat_guard_signals(void) {
  for (int i = 0; i < KS_FATAL_COUNT; i++) {
    struct sigaction now, mine;
    if (sigaction(ks_fatal_signals[i], NULL, &now) != 0) continue;
    if (now.sa_handler == SIG_IGN) continue;
    memset(&mine, 0, sizeof mine);
    mine.sa_handler = ks_on_signal;
    sigfillset(&mine.sa_mask);
    sigaction(ks_fatal_signals[i], &mine, NULL);
  }
  signal(SIGXFSZ, SIG_IGN);
}

static int ks_register_temp(const char *path) {
  for (int i = 0; i < KS_MAX_TEMPS; i++) {
    if (!ks_temp_used[i]) {
      strncpy(ks_temp_path[i], path, KS_PATH - 1);
      ks_temp_path[i][KS_PATH - 1] = '\0';
      ks_temp_used[i] = 1;
      return 0;
    }
  }
  return -1;
}

static void ks_forget_temp(const char *path) {
  sigset_t old;
  ks_block(&old);
  for (int i = 0; i < KS_MAX_TEMPS; i++) {
    if (ks_temp_used[i] && strcmp(ks_temp_path[i], path) == 0) {
      ks_temp_used[i] = 0;
      break;
    }
  }
  ks_unblock(&old);
}

/* ---------------------------------------------------------------------------------------
 * Temporaries: O_CREAT|O_EXCL|O_NOFOLLOW, mode 600, unpredictable names. */

/* `count` random letters and digits (getrandom on Linux, getentropy elsewhere; else
 * /dev/urandom); 0 on success. */
static int ks_random_name(char *out, int count) {
  static const char alphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  unsigned char bytes[64];
  int got = 0;
  if (count > (int) sizeof bytes) return -1;
#if KS_LINUX
  while (got < count) {
    ssize_t n = getrandom(bytes + got, (size_t) (count - got), 0);
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    got += (int) n;
  }
#else
  /* at most 256 bytes at once; all or nothing */
  if (getentropy(bytes, (size_t) count) == 0) got = count;
#endif
  if (got < count) {
    int fd = open("/dev/urandom", O_RDONLY | O_CLOEXEC);
    if (fd < 0) return -1;
    while (got < count) {
      ssize_t n = read(fd, bytes + got, (size_t) (count - got));
      if (n <= 0) {
        if (n < 0 && errno == EINTR) continue;
        close(fd);
        return -1;
      }
      got += (int) n;
    }
    close(fd);
  }
  for (int i = 0; i < count; i++) out[i] = alphabet[bytes[i] % (sizeof alphabet - 1)];
  out[count] = '\0';
  return 0;
}

/* Create a new temporary `prefix` + 12 random characters (O_EXCL|O_NOFOLLOW, mode 600),
 * its name in `name` (capacity `cap`), registered for removal by a fatal signal. The file
 * descriptor, or -errno. */
static int ks_temp_create(const char *prefix, char *name, int cap) {
  char tail[16];
  for (int attempt = 0; attempt < 100; attempt++) {
    sigset_t old;
    int fd, err;
    if (ks_random_name(tail, 12) != 0) return -EIO;
    if (snprintf(name, (size_t) cap, "%s%s", prefix, tail) >= cap) return -ENAMETOOLONG;
    ks_block(&old);
    fd = open(name, O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY, 0600);
    err = errno;
    if (fd >= 0 && ks_register_temp(name) != 0) {
      unlink(name);
      close(fd);
      fd = -1;
      err = EMFILE;
    }
    ks_unblock(&old);
    if (fd >= 0) return fd;
    if (err != EEXIST) return -err;
  }
  return -EEXIST;
}

/* A temporary beside `final` (same directory, so that rename(2) replaces it atomically):
 * "FINAL.tmp.XXXXXXXXXXXX". Its name in `name`; the descriptor, or -errno. */
int kinetostat_temp_beside(const char *final, char *name, int cap) {
  char prefix[KS_PATH];
  if (snprintf(prefix, sizeof prefix, "%s.tmp.", final) >= (int) sizeof prefix) return -ENAMETOOLONG;
  return ks_temp_create(prefix, name, cap);
}

/* An anonymous temporary in $TMPDIR (default /tmp): created as
 * "kinetostat-XXXXXXXXXXXX" and unlinked at once, so that nothing is left whatever ends
 * the process. The descriptor, or -errno. */
int kinetostat_temp_anonymous(void) {
  char prefix[KS_PATH], name[KS_PATH];
  const char *dir = getenv("TMPDIR");
  int fd;
  if (dir == NULL || dir[0] == '\0') dir = "/tmp";
  if (snprintf(prefix, sizeof prefix, "%s/kinetostat-", dir) >= (int) sizeof prefix) return -ENAMETOOLONG;
  fd = ks_temp_create(prefix, name, (int) sizeof name);
  if (fd < 0) return fd;
  unlink(name);
  ks_forget_temp(name);
  return fd;
}

/* Remove a registered temporary (after a failure). */
void kinetostat_temp_remove(const char *name) {
  unlink(name);
  ks_forget_temp(name);
}

/* ---------------------------------------------------------------------------------------
 * Where `-o PATH` goes. */

/* The directory part of `path` into `dir` (capacity KS_PATH): "." or "/" when it has none;
 * 0 when it is too long. */
static int ks_dir_of(const char *path, char *dir) {
  const char *slash = strrchr(path, '/');
  if (slash == NULL) {
    strcpy(dir, ".");
  } else if (slash == path) {
    strcpy(dir, "/");
  } else {
    size_t n = (size_t) (slash - path);
    if (n >= KS_PATH) return 0;
    memcpy(dir, path, n);
    dir[n] = '\0';
  }
  return 1;
}

/* Whether directories `a` and `b` are the same (device and inode). */
static int ks_same_dir(const char *a, const char *b) {
  struct stat sa, sb;
  if (stat(a, &sa) != 0 || stat(b, &sb) != 0) return 0;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

/* The directory whose entries N name this process' descriptor N. */
#if KS_LINUX
#define KS_FD_DIR "/proc/self/fd"
#else
#define KS_FD_DIR "/dev/fd"
#endif

/* Whether the symbolic link `link` lies on procfs (/proc/self/fd/N, /dev/stdout's
 * target...), or elsewhere in the descriptor directory /dev/fd: such a link names an open
 * file, not a path to follow. */
static int ks_on_procfs(const char *link) {
  char dir[KS_PATH];
  if (!ks_dir_of(link, dir)) return 0;
#if KS_LINUX
  {
    struct statfs fs;
    if (statfs(dir, &fs) != 0) return 0;
    return fs.f_type == PROC_SUPER_MAGIC;
  }
#else
  return strcmp(dir, KS_FD_DIR) == 0 || ks_same_dir(dir, KS_FD_DIR);
#endif
}

/* The descriptor number N of a procfs link naming one of this process' descriptors
 * (/proc/self/fd/N, /dev/fd/N, /proc/thread-self/fd/N, /proc/PID/fd/N), else -1. */
static int ks_own_descriptor(const char *link) {
  const char *slash = strrchr(link, '/');
  char dir[KS_PATH], own[64];
  char *end;
  long n;
  if (slash == NULL || slash == link || (size_t) (slash - link) >= sizeof dir) return -1;
  errno = 0;
  n = strtol(slash + 1, &end, 10);
  if (errno != 0 || *end != '\0' || end == slash + 1 || n < 0 || n > INT_MAX) return -1;
  memcpy(dir, link, (size_t) (slash - link));
  dir[slash - link] = '\0';
  snprintf(own, sizeof own, "/proc/%ld/fd", (long) getpid());
  if (strcmp(dir, KS_FD_DIR) != 0 && strcmp(dir, "/proc/thread-self/fd") != 0 && strcmp(dir, own) != 0) {
    /* another name of the same directory (/dev/fd) */
    if (!ks_same_dir(dir, KS_FD_DIR)) return -1;
  }
  if (fcntl((int) n, F_GETFD) < 0) return -1;
  return (int) n;
}

/* What `-o path` means, following symbolic links one by one:
 *  1  replace: a regular file or a new one, its final path (links followed) in `final`;
 *  2  direct: not a regular file (device, FIFO, socket, a link on procfs to another
 *     process' descriptor): opened and written as it is, its path in `final`;
 *  3  descriptor: a procfs link to this process' descriptor (/dev/stdout,
 *     /proc/self/fd/1): written to descriptor `*fd` at its current offset;
 * -errno on failure (EISDIR: a directory; ELOOP: too many links). */
int kinetostat_output_plan(const char *path, char *final, int cap, int *fd) {
  char cur[KS_PATH], target[KS_PATH];
  struct stat st;
  *fd = -1;
  if (snprintf(cur, sizeof cur, "%s", path) >= (int) sizeof cur) return -ENAMETOOLONG;
  for (int hops = 0; hops <= 40; hops++) {
#if !KS_LINUX
    /* macOS's /dev/fd/N (fdesc) are no links: lstat gives the open file itself */
    if (ks_on_procfs(cur)) {
      int own = ks_own_descriptor(cur);
      if (own >= 0) {
        *fd = own;
        return 3;
      }
    }
#endif
    if (lstat(cur, &st) != 0) {
      if (errno != ENOENT) return -errno;
      if (snprintf(final, (size_t) cap, "%s", cur) >= cap) return -ENAMETOOLONG;
      return 1;
    }
    if (S_ISLNK(st.st_mode)) {
      ssize_t n;
      if (ks_on_procfs(cur)) {
        int own = ks_own_descriptor(cur);
        if (own >= 0) {
          *fd = own;
          return 3;
        }
        if (stat(cur, &st) != 0) return -errno;
        if (S_ISDIR(st.st_mode)) return -EISDIR;
        if (snprintf(final, (size_t) cap, "%s", cur) >= cap) return -ENAMETOOLONG;
        return 2;
      }
      n = readlink(cur, target, sizeof target - 1);
      if (n < 0) return -errno;
      target[n] = '\0';
      if (target[0] == '/') {
        memcpy(cur, target, (size_t) n + 1);
      } else {
        char *slash = strrchr(cur, '/');
        char joined[KS_PATH];
        if (slash == NULL) {
          if (snprintf(joined, sizeof joined, "%s", target) >= (int) sizeof joined) return -ENAMETOOLONG;
        } else {
          slash[1] = '\0';
          if (snprintf(joined, sizeof joined, "%s%s", cur, target) >= (int) sizeof joined) return -ENAMETOOLONG;
        }
        memcpy(cur, joined, strlen(joined) + 1);
      }
      continue;
    }
    if (S_ISDIR(st.st_mode)) return -EISDIR;
    if (snprintf(final, (size_t) cap, "%s", cur) >= cap) return -ENAMETOOLONG;
    return S_ISREG(st.st_mode) ? 1 : 2;
  }
  return -ELOOP;
}

/* Whether `path` (a non-regular output target, plan 2) is a terminal: 1 or 0. Only a
 * character device is opened (read-only, without becoming the controlling terminal, not
 * waiting) to ask; nothing else is touched. */
int kinetostat_path_is_terminal(const char *path) {
  struct stat st;
  int fd, yes;
  if (stat(path, &st) != 0 || !S_ISCHR(st.st_mode)) return 0;
  fd = open(path, O_RDONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return 0;
  yes = isatty(fd);
  close(fd);
  return yes;
}

/* Open `path` for reading: the descriptor, or -errno. */
int kinetostat_open_read(const char *path) {
  for (;;) {
    int fd = open(path, O_RDONLY | O_NOCTTY | O_CLOEXEC);
    if (fd >= 0) return fd;
    if (errno != EINTR) return -errno;
  }
}

/* Open a non-regular target (plan 2) for writing as it is: the descriptor, or -errno. A
 * FIFO blocks here until a reader opens it. */
int kinetostat_open_direct(const char *path) {
  struct stat st;
  int fd = open(path, O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) return -errno;
  /* a regular file reached through another process' descriptor: its contents are ours */
  if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && ftruncate(fd, 0) != 0) {
    int err = errno;
    close(fd);
    return -err;
  }
  return fd;
}

/* The finished temporary `name` (open as `fd`) replaces `final`: the mode and (as root)
 * owner of an existing `final` kept (a new file: 666 less the umask), synced, closed,
 * renamed. 0, or errno after removing the temporary; `fd` is closed either way. */
int kinetostat_replace(int fd, const char *name, const char *final) {
  struct stat st;
  int err = 0;
  if (stat(final, &st) == 0 && S_ISREG(st.st_mode)) {
    if (geteuid() == 0 && fchown(fd, st.st_uid, st.st_gid) != 0) err = errno;
    if (err == 0 && fchmod(fd, st.st_mode & 07777) != 0) err = errno;
  } else {
    mode_t mask = umask(022);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0) err = errno;
  }
  if (err == 0 && fsync(fd) != 0) err = errno;
  if (close(fd) != 0 && err == 0) err = errno;
  if (err == 0 && rename(name, final) != 0) err = errno;
  if (err != 0) {
    unlink(name);
  }
  ks_forget_temp(name);
  return err;
}

/* ---------------------------------------------------------------------------------------
 * Checked descriptor I/O. */

/* Write all `count` bytes of `buf` to `fd`: 0, or errno (ENOSPC, EFBIG, EIO, EPIPE...). */
int kinetostat_write_all(int fd, const char *buf, long long count) {
  long long done = 0;
  while (done < count) {
    long long chunk = count - done;
    ssize_t n;
    if (chunk > (1LL << 30)) chunk = 1LL << 30;
    n = write(fd, buf + done, (size_t) chunk);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return EIO;
    done += n;
  }
#if KS_LINUX && defined(SYNC_FILE_RANGE_WRITE)
  /* A large write to a file: the disk starts writing what the file holds so far (without
   * waiting for it), while the run computes the next rows; the fsync before the file
   * replaces its target then waits for the last part only instead of the whole file (a
   * serial wait at the run's end). On a pipe or a terminal the call fails (ESPIPE,
   * EINVAL): nothing to do. */
  if (count >= (1LL << 16)) (void) sync_file_range(fd, 0, 0, SYNC_FILE_RANGE_WRITE);
#endif
  return 0;
}

/* Read up to `count` bytes of `fd` at `offset` (offset < 0: from where it stands, as a pipe
 * or a terminal is read): the number read (0 at its end), or -errno. */
long long kinetostat_read_at(int fd, char *buf, long long count, long long offset) {
  for (;;) {
    ssize_t n = offset < 0 ? read(fd, buf, (size_t) count) : pread(fd, buf, (size_t) count, (off_t) offset);
    if (n >= 0) return n;
    if (errno != EINTR) return -errno;
  }
}

/* close(2): 0, or errno (a deferred write error of some file systems). */
int kinetostat_close(int fd) { return close(fd) == 0 ? 0 : errno; }

/* The system's text for errno `err`, into `text` (capacity `cap`, NUL-terminated). */
void kinetostat_error_text(int err, char *text, int cap) {
  snprintf(text, (size_t) cap, "%s", strerror(err));
}

/* ---------------------------------------------------------------------------------------
 * Parallel sweeps run blocks of variants in child processes (gfortran's run-time library
 * is not safe for concurrent internal I/O in threads, processes are). */

/* A child ends with its parent, however the parent ends (SIGKILL runs no handler): the
 * parent holds the only write end of a pipe that every child watches. The child reads the
 * pipe's read end (non-blocking) from a SIGALRM every KS_WATCH_MS; the read returns 0, end
 * of file, once the write end is closed, i.e. once the parent is gone, and the child then
 * leaves at once. Portable POSIX (pipe, setitimer, sigaction); no thread. */
#define KS_WATCH_MS 100
/* Exit status of a child that found its parent gone. */
#define KS_ORPHAN_EXIT 70
static int ks_watch_pipe[2] = {-1, -1};
static volatile sig_atomic_t ks_watch_fd = -1;

/* SIGALRM in a child: end when the parent's end of the pipe is closed. */
static void ks_on_watch(int sig) {
  char c;
  int saved = errno;
  (void) sig;
  if (ks_watch_fd >= 0 && read((int) ks_watch_fd, &c, 1) == 0) _exit(KS_ORPHAN_EXIT);
  errno = saved;
}

/* In a new child: keep the read end only, and look at it every KS_WATCH_MS. */
static void ks_watch_parent(void) {
  struct sigaction act;
  struct itimerval every;
  int flags;
  if (ks_watch_pipe[0] < 0) return;
  close(ks_watch_pipe[1]);
  ks_watch_pipe[1] = -1;
  flags = fcntl(ks_watch_pipe[0], F_GETFL);
  if (flags < 0 || fcntl(ks_watch_pipe[0], F_SETFL, flags | O_NONBLOCK) != 0) return;
  ks_watch_fd = ks_watch_pipe[0];
  memset(&act, 0, sizeof act);
  act.sa_handler = ks_on_watch;
  sigemptyset(&act.sa_mask);
  act.sa_flags = SA_RESTART;
  if (sigaction(SIGALRM, &act, NULL) != 0) return;
  every.it_interval.tv_sec = 0;
  every.it_interval.tv_usec = KS_WATCH_MS * 1000;
  every.it_value = every.it_interval;
  setitimer(ITIMER_REAL, &every, NULL);
}

/* fork(2): 0 in the child, the child's id in the parent, -1 on failure. The child is
 * registered, so that a fatal signal to the parent ends it too, and watches a pipe to the
 * parent, so that it ends when the parent is killed outright; the child starts with empty
 * registries (its parent's temporaries and siblings are not its own). */
int kinetostat_fork(void) {
  sigset_t old;
  pid_t pid;
  ks_block(&old);
  if (ks_watch_pipe[0] < 0 && pipe(ks_watch_pipe) != 0) {
    ks_watch_pipe[0] = -1;
    ks_watch_pipe[1] = -1;
  }
  pid = fork();
  if (pid == 0) {
    for (int i = 0; i < KS_MAX_TEMPS; i++) ks_temp_used[i] = 0;
    for (int i = 0; i < KS_MAX_CHILDREN; i++) ks_child[i] = 0;
    ks_watch_parent();
  } else if (pid > 0) {
    int slot = -1;
    for (int i = 0; i < KS_MAX_CHILDREN; i++) {
      if (ks_child[i] == 0) {
        slot = i;
        break;
      }
    }
    if (slot >= 0) {
      ks_child[slot] = (sig_atomic_t) pid;
    } else {
      kill(pid, SIGKILL);
      waitpid(pid, NULL, 0);
      pid = -1;
    }
  }
  ks_unblock(&old);
  return (int) pid;
}

/* Wait for child `pid`; its exit status, or -1 when it did not exit normally. */
int kinetostat_wait(int pid) {
  int status, result;
  sigset_t old;
  pid_t got;
  do {
    got = waitpid((pid_t) pid, &status, 0);
  } while (got < 0 && errno == EINTR);
  ks_block(&old);
  for (int i = 0; i < KS_MAX_CHILDREN; i++) {
    if (ks_child[i] == pid) ks_child[i] = 0;
  }
  ks_unblock(&old);
  if (got < 0) return -1;
  result = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

/* _exit(2): end a child at once, without running the parent's exit handlers or flushing
 * buffers it inherited. */
void kinetostat_exit_now(int code) { _exit(code); }

/* Number of processors online (at least 1). */
int kinetostat_cpu_count(void) {
  long n = sysconf(_SC_NPROCESSORS_ONLN);
  return n < 1 ? 1 : (int) n;
}
