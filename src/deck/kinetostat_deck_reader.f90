!> Reading a deck's bytes whose size is not known beforehand (standard input, a pipe, a
!> device such as /dev/zero, a file the system reports as empty) in chunks, never more than
!> a limit: endless input stops at the limit with an error instead of growing without end.
module kinetostat_deck_reader
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_char, c_int, c_long, &
    c_size_t, c_null_char
  use, intrinsic :: iso_fortran_env, only: int64
  implicit none
  private
  public :: read_bytes_limited, read_ok, read_too_long, read_failed, read_not_opened

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

  ! allow(assumed-size)
  interface
    function c_fopen(path, mode) bind(c, name="fopen") result(stream)
      import :: c_ptr, c_char
      implicit none
      character(kind=c_char), intent(in) :: path(*), mode(*)
      type(c_ptr) :: stream
    end function c_fopen
    function c_fread(buf, size, count, stream) bind(c, name="fread") result(got)
      import :: c_ptr, c_char, c_size_t, chunk
      implicit none
      character(kind=c_char), intent(out) :: buf(chunk)
      integer(c_size_t), value :: size, count
      type(c_ptr), value :: stream
      integer(c_size_t) :: got
    end function c_fread
    function c_ferror(stream) bind(c, name="ferror") result(status)
      import :: c_ptr, c_int
      implicit none
      type(c_ptr), value :: stream
      integer(c_int) :: status
    end function c_ferror
    function c_fclose(stream) bind(c, name="fclose") result(status)
      import :: c_ptr, c_int
      implicit none
      type(c_ptr), value :: stream
      integer(c_int) :: status
    end function c_fclose
    function c_read(fd, buf, count) bind(c, name="read") result(got)
      import :: c_int, c_char, c_size_t, c_long, chunk
      implicit none
      integer(c_int), value :: fd
      character(kind=c_char), intent(out) :: buf(chunk)
      integer(c_size_t), value :: count
      integer(c_long) :: got
    end function c_read
  end interface

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
    !> read_ok, read_too_long, read_failed or read_not_opened.
    integer, intent(out) :: status
    character(len=chunk) :: buf
    character(len=:), allocatable :: grown
    type(c_ptr) :: stream
    integer(int64) :: n, got
    stream = c_null_ptr
    if (len(path) > 0) then
      stream = c_fopen(path//c_null_char, "rb"//c_null_char)
      if (.not. c_associated(stream)) then
        status = read_not_opened
        text = ""
        return
      end if
    end if
    status = read_ok
    allocate (character(len=chunk) :: text)
    n = 0
    do
      if (c_associated(stream)) then
        got = int(c_fread(buf, 1_c_size_t, int(chunk, c_size_t), stream), int64)
        if (got == 0 .and. c_ferror(stream) /= 0) status = read_failed
      else
        got = int(c_read(0_c_int, buf, int(chunk, c_size_t)), int64)
        if (got < 0) status = read_failed
      end if
      if (got <= 0) exit
      if (n + got > len(text, int64)) then
        allocate (character(len=min(2 * len(text, int64), limit + chunk)) :: grown)
        grown(1:n) = text(1:n)
        call move_alloc(grown, text)
      end if
      text(n + 1:n + got) = buf(1:got)
      n = n + got
      if (n > limit) then
        status = read_too_long
        n = limit
        exit
      end if
    end do
    if (c_associated(stream)) then
      if (c_fclose(stream) /= 0 .and. status == read_ok) status = read_failed
    end if
    if (status == read_failed) n = 0
    text = text(1:n)
  end subroutine read_bytes_limited

end module kinetostat_deck_reader
