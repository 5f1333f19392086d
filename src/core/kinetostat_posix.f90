!> The operating-system calls the program needs beyond Fortran's intrinsics (C in
!> kinetostat_posix.c): checked writes to file descriptors, where `-o PATH` goes (links
!> followed one by one), temporaries that cannot be hijacked (O_EXCL|O_NOFOLLOW, mode 600,
!> random names) removed when a signal ends the process, atomic replacement of a file, the
!> process id, whether standard error is a terminal, child processes (a deck's bytes are
!> read by kinetostat_deck_reader).
module kinetostat_posix
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_long_long
  use, intrinsic :: iso_fortran_env, only: int64
  implicit none
  private
  public :: process_id, write_standard_output
  public :: stderr_is_terminal, output_is_terminal
  public :: fork_process, wait_process, exit_now, cpu_count
  public :: guard_signals, output_plan, temp_beside, temp_anonymous, temp_remove, open_direct
  public :: replace_file, write_fd, read_fd_at, read_fd, open_read, close_fd, system_error_text
  public :: plan_replace, plan_direct, plan_descriptor

  !> Longest path handled (bytes).
  integer, parameter :: path_capacity = 4096

  !> output_plan: a regular (or new) file, replaced atomically through a temporary.
  integer, parameter :: plan_replace = 1
  !> output_plan: not a regular file (device, FIFO, socket): written directly.
  integer, parameter :: plan_direct = 2
  !> output_plan: a link to one of this process' descriptors (/dev/stdout): written to it.
  integer, parameter :: plan_descriptor = 3

  ! allow(assumed-size)
  interface
    function c_write_all(fd, buf, count) bind(c, name="kinetostat_write_all") result(err)
      import :: c_int, c_char, c_long_long
      implicit none
      integer(c_int), value :: fd
      character(kind=c_char), intent(in) :: buf(*)
      integer(c_long_long), value :: count
      integer(c_int) :: err
    end function c_write_all
    function c_read_at(fd, buf, count, offset) bind(c, name="kinetostat_read_at") result(got)
      import :: c_int, c_char, c_long_long
      implicit none
      integer(c_int), value :: fd
      integer(c_long_long), value :: count, offset
      character(kind=c_char), intent(out) :: buf(count)
      integer(c_long_long) :: got
    end function c_read_at
    function c_close(fd) bind(c, name="kinetostat_close") result(err)
      import :: c_int
      implicit none
      integer(c_int), value :: fd
      integer(c_int) :: err
    end function c_close
    subroutine c_error_text(err, text, cap) bind(c, name="kinetostat_error_text")
      import :: c_int, c_char
      implicit none
      integer(c_int), value :: err
      integer(c_int), value :: cap
      character(kind=c_char), intent(out) :: text(cap)
    end subroutine c_error_text
    subroutine c_guard_signals() bind(c, name="kinetostat_guard_signals")
      implicit none
    end subroutine c_guard_signals
    function c_output_plan(path, final, cap, fd) bind(c, name="kinetostat_output_plan") result(plan)
      import :: c_int, c_char
      implicit none
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: cap
      character(kind=c_char), intent(out) :: final(cap)
      integer(c_int), intent(out) :: fd
      integer(c_int) :: plan
    end function c_output_plan
    function c_temp_beside(final, name, cap) bind(c, name="kinetostat_temp_beside") result(fd)
      import :: c_int, c_char
      implicit none
      character(kind=c_char), intent(in) :: final(*)
      integer(c_int), value :: cap
      character(kind=c_char), intent(out) :: name(cap)
      integer(c_int) :: fd
    end function c_temp_beside
    function c_temp_anonymous() bind(c, name="kinetostat_temp_anonymous") result(fd)
      import :: c_int
      implicit none
      integer(c_int) :: fd
    end function c_temp_anonymous
    subroutine c_temp_remove(name) bind(c, name="kinetostat_temp_remove")
      import :: c_char
      implicit none
      character(kind=c_char), intent(in) :: name(*)
    end subroutine c_temp_remove
    function c_open_read(path) bind(c, name="kinetostat_open_read") result(fd)
      import :: c_int, c_char
      implicit none
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: fd
    end function c_open_read
    function c_open_direct(path) bind(c, name="kinetostat_open_direct") result(fd)
      import :: c_int, c_char
      implicit none
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: fd
    end function c_open_direct
    function c_replace(fd, name, final) bind(c, name="kinetostat_replace") result(err)
      import :: c_int, c_char
      implicit none
      integer(c_int), value :: fd
      character(kind=c_char), intent(in) :: name(*), final(*)
      integer(c_int) :: err
    end function c_replace
    function c_path_is_terminal(path) bind(c, name="kinetostat_path_is_terminal") result(yes)
      import :: c_int, c_char
      implicit none
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: yes
    end function c_path_is_terminal
    function c_isatty(fd) bind(c, name="isatty") result(yes)
      import :: c_int
      implicit none
      integer(c_int), value :: fd
      integer(c_int) :: yes
    end function c_isatty
    function c_getpid() bind(c, name="getpid") result(pid)
      import :: c_int
      implicit none
      integer(c_int) :: pid
    end function c_getpid
    function c_fork() bind(c, name="kinetostat_fork") result(pid)
      import :: c_int
      implicit none
      integer(c_int) :: pid
    end function c_fork
    function c_wait(pid) bind(c, name="kinetostat_wait") result(status)
      import :: c_int
      implicit none
      integer(c_int), value :: pid
      integer(c_int) :: status
    end function c_wait
    subroutine c_exit_now(code) bind(c, name="kinetostat_exit_now")
      import :: c_int
      implicit none
      integer(c_int), value :: code
    end subroutine c_exit_now
    function c_cpu_count() bind(c, name="kinetostat_cpu_count") result(n)
      import :: c_int
      implicit none
      integer(c_int) :: n
    end function c_cpu_count
  end interface

contains

  !> Install the clean-up of temporaries and sweep children for SIGINT, SIGTERM, SIGHUP and
  !> SIGPIPE (those not ignored already; the process then dies of the signal as before, exit
  !> status 128 + its number), and ignore SIGXFSZ (a file-size limit is a failed write).
  subroutine guard_signals()
    call c_guard_signals()
  end subroutine guard_signals

  !> Where `-o path` goes, links followed one by one: plan_replace (`final` the regular or
  !> new file at the end of the links), plan_direct (`final` a device, FIFO or socket) or
  !> plan_descriptor (`fd` this process' descriptor, e.g. for /dev/stdout); a negative errno
  !> when it cannot be written (EISDIR, ELOOP, EACCES...).
  integer function output_plan(path, final, fd)
    !> The path as given.
    character(*), intent(in) :: path
    !> The path written (plan_replace, plan_direct).
    character(len=:), allocatable, intent(out) :: final
    !> The descriptor written (plan_descriptor).
    integer, intent(out) :: fd
    character(kind=c_char, len=path_capacity) :: buf
    integer(c_int) :: c_fd
    buf = ""
    output_plan = int(c_output_plan(path//c_null_char, buf, int(path_capacity, c_int), c_fd))
    fd = int(c_fd)
    final = c_string(buf)
  end function output_plan

  !> A new temporary beside `final` ("FINAL.tmp." and 12 random characters; O_EXCL,
  !> O_NOFOLLOW, mode 600), removed if a signal ends the process: its descriptor (its name in
  !> `name`), or a negative errno.
  integer function temp_beside(final, name)
    !> The file it will replace.
    character(*), intent(in) :: final
    !> Its name.
    character(len=:), allocatable, intent(out) :: name
    character(kind=c_char, len=path_capacity) :: buf
    buf = ""
    temp_beside = int(c_temp_beside(final//c_null_char, buf, int(path_capacity, c_int)))
    name = c_string(buf)
  end function temp_beside

  !> A new temporary in $TMPDIR (default /tmp), unlinked at once (nothing is left whatever
  !> ends the process): its descriptor, or a negative errno.
  integer function temp_anonymous()
    temp_anonymous = int(c_temp_anonymous())
  end function temp_anonymous

  !> Remove the temporary `name` (after a failure).
  subroutine temp_remove(name)
    !> Its name.
    character(*), intent(in) :: name
    call c_temp_remove(name//c_null_char)
  end subroutine temp_remove

  !> Open a device, FIFO or socket for writing as it is: its descriptor, or a negative errno.
  integer function open_direct(path)
    !> Its path.
    character(*), intent(in) :: path
    open_direct = int(c_open_direct(path//c_null_char))
  end function open_direct

  !> The finished temporary `name` (descriptor `fd`, closed here) replaces `final`
  !> atomically: mode and (as root) owner of an existing `final` kept, synced, renamed. 0,
  !> or the errno of the failure (the temporary is then removed and `final` is as it was).
  integer function replace_file(fd, name, final)
    !> The temporary's descriptor.
    integer, intent(in) :: fd
    !> The temporary's name.
    character(*), intent(in) :: name
    !> The file replaced.
    character(*), intent(in) :: final
    replace_file = int(c_replace(int(fd, c_int), name//c_null_char, final//c_null_char))
  end function replace_file

  !> Write every byte of `text` to descriptor `fd`: 0, or the errno of the failed write
  !> (ENOSPC, EFBIG, EIO, EPIPE...).
  integer function write_fd(fd, text)
    !> The descriptor.
    integer, intent(in) :: fd
    !> The bytes.
    character(*), intent(in) :: text
    write_fd = 0
    if (len(text) == 0) return
    write_fd = int(c_write_all(int(fd, c_int), text, int(len(text), c_long_long)))
  end function write_fd

  !> Read up to `count` bytes of descriptor `fd` from byte `offset` (0: the first) into
  !> `text`: the number read (0 at its end), or a negative errno (`text` then empty).
  integer(int64) function read_fd_at(fd, count, offset, text)
    !> The descriptor.
    integer, intent(in) :: fd
    !> Bytes wanted (>= 1).
    integer, intent(in) :: count
    !> Offset, bytes.
    integer(int64), intent(in) :: offset
    !> The bytes read.
    character(len=:), allocatable, intent(out) :: text
    character(kind=c_char, len=count) :: buf
    read_fd_at = int(c_read_at(int(fd, c_int), buf, int(count, c_long_long), int(offset, c_long_long)), int64)
    if (read_fd_at > 0) then
      text = buf(1:int(read_fd_at))
    else
      text = ""
    end if
  end function read_fd_at

  !> The next bytes of `fd` as it is read in sequence (a pipe, a terminal, standard input, a
  !> file opened by open_read): the number read (0 at its end, -errno when refused).
  integer(int64) function read_fd(fd, count, text)
    !> The descriptor.
    integer, intent(in) :: fd
    !> Bytes wanted (>= 1).
    integer, intent(in) :: count
    !> The bytes read.
    character(len=:), allocatable, intent(out) :: text
    read_fd = read_fd_at(fd, count, -1_int64, text)
  end function read_fd

  !> Open `path` for reading: its descriptor, or -errno when it cannot be opened.
  integer function open_read(path)
    !> The file.
    character(*), intent(in) :: path
    open_read = int(c_open_read(path//c_null_char))
  end function open_read

  !> Close descriptor `fd`: 0, or the errno of a deferred write error.
  integer function close_fd(fd)
    !> The descriptor.
    integer, intent(in) :: fd
    close_fd = int(c_close(int(fd, c_int)))
  end function close_fd

  !> The system's text for errno `err` ("No space left on device").
  function system_error_text(err) result(text)
    !> An errno (its sign ignored).
    integer, intent(in) :: err
    character(len=:), allocatable :: text
    character(kind=c_char, len=256) :: buf
    buf = ""
    call c_error_text(int(abs(err), c_int), buf, int(len(buf), c_int))
    text = c_string(buf)
  end function system_error_text

  !> This process' id.
  integer function process_id()
    process_id = int(c_getpid())
  end function process_id

  !> A child process (fork): 0 in the child, the child's id in the parent, -1 on failure.
  !> A fatal signal to this process ends its children too.
  integer function fork_process()
    fork_process = int(c_fork())
  end function fork_process

  !> Wait for child `pid`: its exit status, or -1 when it did not exit normally.
  integer function wait_process(pid)
    !> Child's process id.
    integer, intent(in) :: pid
    wait_process = int(c_wait(int(pid, c_int)))
  end function wait_process

  !> End this (child) process at once with `code`, without flushing inherited buffers.
  subroutine exit_now(code)
    !> Exit status.
    integer, intent(in) :: code
    call c_exit_now(int(code, c_int))
  end subroutine exit_now

  !> Number of processors online (at least 1).
  integer function cpu_count()
    cpu_count = int(c_cpu_count())
  end function cpu_count

  !> Write `text` to standard output (file descriptor 1) unbuffered, every byte checked:
  !> 0, or the errno of the failed write (a full disk, a closed pipe).
  integer function write_standard_output(text)
    !> The bytes.
    character(*), intent(in) :: text
    write_standard_output = write_fd(1, text)
  end function write_standard_output

  !> Whether standard error (file descriptor 2) is a terminal (progress lines go there only then).
  logical function stderr_is_terminal()
    stderr_is_terminal = c_isatty(2_c_int) == 1
  end function stderr_is_terminal

  !> Whether the output would reach a terminal: `-o path` (links followed, as output_plan
  !> does), or standard output without `path`.
  logical function output_is_terminal(path)
    !> The path of `-o`.
    character(*), intent(in), optional :: path
    character(len=:), allocatable :: final
    integer :: fd
    output_is_terminal = .false.
    if (.not. present(path)) then
      output_is_terminal = c_isatty(1_c_int) == 1
      return
    end if
    select case (output_plan(path, final, fd))
    case (plan_descriptor)
      output_is_terminal = c_isatty(int(fd, c_int)) == 1
    case (plan_direct)
      output_is_terminal = c_path_is_terminal(final//c_null_char) == 1
    case default
      output_is_terminal = .false.
    end select
  end function output_is_terminal

  !> The text of a NUL-terminated C string in `buf`.
  function c_string(buf) result(text)
    character(*), intent(in) :: buf
    character(len=:), allocatable :: text
    integer :: n
    n = index(buf, c_null_char)
    if (n == 0) n = len(buf) + 1
    text = buf(1:n - 1)
  end function c_string

end module kinetostat_posix
