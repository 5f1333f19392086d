!> Reading a deck's bytes whose size is not known beforehand (standard input, a pipe, a
!> device such as /dev/zero, a file the system reports as empty) in chunks, never more than
!> a limit: endless input stops at the limit with an error instead of growing without end.
module kinetostat_deck_reader
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_posix, only: open_read, read_fd, close_fd
  implicit none
  private
  public :: read_bytes_limited, read_ok, read_too_long, read_failed, read_not_opened, read_no_memory

  !> Bytes asked for by one read.
  integer, parameter :: chunk = 65536
  !> Status of read_bytes_limited: all bytes read.
  integer, parameter :: read_ok = 0
  !> Status: the input is longer than the limit (the text holds the first `limit` bytes).
  integer, parameter :: read_too_long = 1
  !> Status: the system refused a read.
  integer, parameter :: read_failed = 2
  !> Status: the path could not be opened.
  integer, parameter :: read_not_opened = 3
  !> Status: the text read so far could not grow (out of memory; the text is what was read).
  integer, parameter :: read_no_memory = 4

contains

  !> All bytes of `path` ("" for standard input, file descriptor 0), at most `limit`: read
  !> in chunks of 64 KiB, the text grown by doubling (64-bit lengths). Stops as soon as more
  !> than `limit` bytes came (status read_too_long), so endless input costs at most `limit`
  !> bytes of memory and the time to read them.
  subroutine read_bytes_limited(path, limit, text, status)
    !> The file to read; "" for standard input.
    character(*), intent(in) :: path
    !> Largest number of bytes accepted (>= 0).
    integer(int64), intent(in) :: limit
    !> The bytes read (at most `limit`; empty when not opened).
    character(len=:), allocatable, intent(out) :: text
    !> read_ok, read_too_long, read_failed, read_not_opened or read_no_memory.
    integer, intent(out) :: status
    character(len=:), allocatable :: piece, grown
    integer(int64) :: n, got
    integer :: fd, stat
    fd = 0
    if (len(path) > 0) then
      fd = open_read(path)
      if (fd < 0) then
        status = read_not_opened
        text = ""
        return
      end if
    end if
    status = read_ok
    allocate (character(len=chunk) :: text)
    n = 0
    do
      got = read_fd(fd, chunk, piece)
      if (got < 0) status = read_failed
      if (got <= 0) exit
      if (n + got > len(text, int64)) then
        allocate (character(len=min(2 * len(text, int64), limit + chunk)) :: grown, stat=stat)
        if (stat /= 0) then
          status = read_no_memory
          exit
        end if
        grown(1:n) = text(1:n)
        call move_alloc(grown, text)
      end if
      text(n + 1:n + got) = piece(1:got)
      n = n + got
      if (n > limit) then
        status = read_too_long
        n = limit
        exit
      end if
    end do
    if (len(path) > 0) then
      if (close_fd(fd) /= 0 .and. status == read_ok) status = read_failed
    end if
    if (status == read_failed) n = 0
    if (status == read_no_memory) return
    text = text(1:n)
  end subroutine read_bytes_limited

end module kinetostat_deck_reader
