/* The one POSIX call kinetostat needs that Fortran has no intrinsic for (as fpm's
 * filesystem_utilities.c): what kind of file a path names, so that `-o` onto a device or
 * a FIFO writes to it directly instead of renaming a temporary file over it. */
#include <sys/stat.h>

/* 0: no such file; 1: regular file; 2: directory; 3: anything else (device, FIFO, socket). */
int kinetostat_path_kind(const char *path) {
  struct stat st;
  if (stat(path, &st) != 0) return 0;
  if (S_ISREG(st.st_mode)) return 1;
  if (S_ISDIR(st.st_mode)) return 2;
  return 3;
}

/* Parallel sweeps run blocks of variants in child processes (gfortran's run-time library
 * is not safe for concurrent internal I/O in threads, processes are). */
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* fork(2): 0 in the child, the child's id in the parent, -1 on failure. */
int kinetostat_fork(void) { return (int) fork(); }

/* Wait for child `pid`; its exit status, or -1 when it did not exit normally. */
int kinetostat_wait(int pid) {
  int status;
  if (waitpid((pid_t) pid, &status, 0) < 0) return -1;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return -1;
}

/* _exit(2): end a child at once, without running the parent's exit handlers or flushing
 * buffers it inherited. */
void kinetostat_exit_now(int code) { _exit(code); }

/* Number of processors online (at least 1). */
int kinetostat_cpu_count(void) {
  long n = sysconf(_SC_NPROCESSORS_ONLN);
  return n < 1 ? 1 : (int) n;
}
