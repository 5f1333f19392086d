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
