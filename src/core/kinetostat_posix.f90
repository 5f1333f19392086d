!> The operating-system calls the program needs beyond Fortran's intrinsics: the kind of
!> file a path names, renaming a file, the process id, reading standard input as bytes,
!> whether standard error is a terminal.
module kinetostat_posix
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_size_t, c_long
  implicit none
  private
  public :: path_kind, rename_file, process_id, write_standard_output, read_standard_input
  public :: stderr_is_terminal
  public :: fork_process, wait_process, exit_now, cpu_count
  public :: path_absent, path_regular, path_directory, path_special

  !> Bytes asked for by one read of standard input.
  integer, parameter :: read_chunk = 65536

  !> path_kind: no such file.
  integer, parameter :: path_absent = 0
  !> path_kind: a regular file.
  integer, parameter :: path_regular = 1
  !> path_kind: a directory.
  integer, parameter :: path_directory = 2
  !> path_kind: a device, FIFO or socket.
  integer, parameter :: path_special = 3

  ! allow(assumed-size)
  interface
    function c_path_kind(path) bind(c, name="kinetostat_path_kind") result(kind)
      import :: c_int, c_char
      implicit none
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: kind
    end function c_path_kind
    function c_rename(old, new) bind(c, name="rename") result(status)
      import :: c_int, c_char
      implicit none
      character(kind=c_char), intent(in) :: old(*), new(*)
      integer(c_int) :: status
    end function c_rename
    function c_write(fd, buf, count) bind(c, name="write") result(written)
      import :: c_int, c_char, c_size_t, c_long
      implicit none
      integer(c_int), value :: fd
      character(kind=c_char), intent(in) :: buf(*)
      integer(c_size_t), value :: count
      integer(c_long) :: written
    end function c_write
    function c_read(fd, buf, count) bind(c, name="read") result(got)
      import :: c_int, c_char, c_size_t, c_long, read_chunk
      implicit none
      integer(c_int), value :: fd
      character(kind=c_char), intent(out) :: buf(read_chunk)
      integer(c_size_t), value :: count
      integer(c_long) :: got
    end function c_read
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

  !> What `path` names: path_absent, path_regular, path_directory or path_special.
  integer function path_kind(path)
    !> File path.
    character(*), intent(in) :: path
    path_kind = int(c_path_kind(path//c_null_char))
  end function path_kind

  !> Rename `old` to `new` (atomic on one file system); true on success.
  logical function rename_file(old, new)
    !> Existing file.
    character(*), intent(in) :: old
    !> New name (replaced if it exists).
    character(*), intent(in) :: new
    rename_file = c_rename(old//c_null_char, new//c_null_char) == 0
  end function rename_file

  !> This process' id.
  integer function process_id()
    process_id = int(c_getpid())
  end function process_id

  !> A child process (fork): 0 in the child, the child's id in the parent, -1 on failure.
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

  !> Write `text` to standard output (file descriptor 1) unbuffered, every byte checked;
  !> false when the system refused a write (a full disk, a closed pipe).
  logical function write_standard_output(text)
    !> The bytes.
    character(*), intent(in) :: text
    integer(c_long) :: written
    integer :: done
    done = 0
    write_standard_output = .true.
    do while (done < len(text))
      written = c_write(1_c_int, text(done + 1:), int(len(text) - done, c_size_t))
      if (written <= 0) then
        write_standard_output = .false.
        return
      end if
      done = done + int(written)
    end do
  end function write_standard_output

  !> All of standard input (file descriptor 0) as bytes, read to its end: a pipe, a
  !> terminal or a redirected file alike (read once; nothing is rewound). False when the
  !> system refused a read.
  logical function read_standard_input(text)
    !> The bytes read (empty on failure).
    character(len=:), allocatable, intent(out) :: text
    character(len=read_chunk) :: buf
    character(len=:), allocatable :: grown
    integer(c_long) :: got
    integer :: n
    allocate (character(len=read_chunk) :: text)
    n = 0
    read_standard_input = .true.
    do
      got = c_read(0_c_int, buf, int(read_chunk, c_size_t))
      if (got == 0) exit
      if (got < 0) then
        read_standard_input = .false.
        text = ""
        return
      end if
      if (n + int(got) > len(text)) then
        allocate (character(len=2 * len(text) + int(got)) :: grown)
        grown(1:n) = text(1:n)
        call move_alloc(grown, text)
      end if
      text(n + 1:n + int(got)) = buf(1:int(got))
      n = n + int(got)
    end do
    text = text(1:n)
  end function read_standard_input

  !> Whether standard error (file descriptor 2) is a terminal (progress lines go there only then).
  logical function stderr_is_terminal()
    stderr_is_terminal = c_isatty(2_c_int) == 1
  end function stderr_is_terminal

end module kinetostat_posix
