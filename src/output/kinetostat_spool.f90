!> Where a run's output text goes while the run is not finished: memory up to a bound, then
!> a temporary file; only when the whole run succeeded does the text reach its target (the
!> file of `-o`, renamed into place, or standard output, copied out), so that no output is
!> ever partial. A run of any length thus holds at most `spool_bound` bytes of text.
!> The temporary of a regular `-o` target lies beside it (kinetostat_output: O_EXCL,
!> O_NOFOLLOW, mode 600, a random name, removed on failure and by a fatal signal); any other
!> run spools into an anonymous file in $TMPDIR (unlinked as soon as it is created, so that
!> nothing is left whatever ends the process).
module kinetostat_spool
  use, intrinsic :: iso_fortran_env, only: int64, output_unit
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_posix, only: temp_anonymous, write_fd, read_fd_at, close_fd, system_error_text, plan_replace
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_output, only: output_sink_t, write_output_file, write_output_stdout
  use kinetostat_row_blocks, only: text_sink_t
  implicit none
  private
  public :: spool_t, spool_bound

  !> Bytes of output text kept in memory before they go to the temporary file.
  integer, parameter :: spool_bound = 4 * 1024 * 1024
  !> Bytes copied at a time from the temporary file to the target.
  integer, parameter :: copy_chunk = 1024 * 1024
  !> errno EIO: the temporary file is shorter than what was written to it.
  integer, parameter :: eio = 5

  !> The output of one run on its way to its target.
  !> As a text sink (`take`), it takes a writer's rows as they are formatted and keeps the
  !> first failure to write them in `failure`.
  type, extends(text_sink_t) :: spool_t
    !> The target file (`-o`); not allocated: standard output.
    character(len=:), allocatable :: target
    !> The name of the temporary beside the target, once made (an anonymous one has none).
    character(len=:), allocatable :: file
    !> Where the text goes at the end.
    type(output_sink_t) :: sink
    !> The temporary file's descriptor while open; -1: none.
    integer :: fd = -1
    !> Bytes in the temporary file.
    integer(int64) :: size = 0
    !> Whether the text went to the temporary file.
    logical :: spilled = .false.
    !> Bytes kept in memory before they go to the file (tests make it small).
    integer :: bound = spool_bound
    !> A failed write of `take` (the run reports it after the block).
    type(error_t), allocatable :: failure
  contains
    procedure :: take
    procedure :: take_part => take_spool_part
    procedure :: aim
    procedure :: drain
    procedure :: absorb
    procedure :: commit
    procedure :: discard
  end type spool_t

contains

  !> Aim the spool at a target file (`-o`); without `target`, at standard output.
  subroutine aim(self, target)
    class(spool_t), intent(inout) :: self
    !> Path of the target file.
    character(*), intent(in), optional :: target
    if (present(target)) self%target = target
  end subroutine aim

  !> The rows' text so far to the file, called by the writers after every part of the rows
  !> formatted in parallel: over the bound, or any text once the spool has its file (so a
  !> part is written while the next are formatted); a failure is kept in `failure`.
  subroutine take(self, out)
    class(spool_t), intent(inout) :: self
    !> The text written so far that is not in the file yet.
    type(text_buffer_t), intent(inout) :: out
    if (allocated(self%failure)) return
    call self%drain(out, self%failure, force=.true.)
  end subroutine take

  !> take, then `part` after the text so far: once the text goes to the file, `part` is
  !> written from its own buffer (not copied into `out` first: this runs while the other
  !> threads wait their turn to hand over their parts).
  subroutine take_spool_part(self, out, part)
    class(spool_t), intent(inout) :: self
    !> The text written so far that is not in the file yet.
    type(text_buffer_t), intent(inout) :: out
    !> The text that comes after it (left as it is).
    type(text_buffer_t), intent(in) :: part
    if (allocated(self%failure)) return
    if (self%spilled .and. out%length > 0) call self%drain(out, self%failure, force=.true.)
    if (allocated(self%failure)) return
    if (self%spilled .and. out%length == 0) then
      if (part%length > 0) call put(self, part%data(1:part%length), self%failure)
      return
    end if
    if (part%length > 0) call out%append(part%data(1:part%length))
    call self%drain(out, self%failure, force=.true.)
  end subroutine take_spool_part

  !> When `out` holds more than `bound` bytes (or `force` and the text went to the file
  !> already), move its text to the temporary file and empty it.
  subroutine drain(self, out, error, force)
    class(spool_t), intent(inout) :: self
    !> The text written so far that is not in the file yet.
    type(text_buffer_t), intent(inout) :: out
    !> The file cannot be written (disk full?).
    type(error_t), allocatable, intent(out) :: error
    !> Move the text even below the bound, if the spool has a file.
    logical, intent(in), optional :: force
    logical :: now
    now = out%length > self%bound
    if (present(force)) now = now .or. (force .and. self%spilled)
    if (.not. now .or. out%length == 0) return
    if (.not. self%spilled) then
      call open_file(self, error)
      if (allocated(error)) return
    end if
    call put(self, out%data(1:out%length), error)
    if (allocated(error)) return
    out%length = 0
    ! a buffer that grew far beyond the bound (a long head) is not kept for the whole run
    if (len(out%data) > 4 * self%bound) deallocate (out%data)
  end subroutine drain

  !> Put the text of `other` (its file, then `other_out`) after the text of this spool (its
  !> file, then `out`); `other` is emptied and its file removed.
  subroutine absorb(self, out, other, other_out, error)
    class(spool_t), intent(inout) :: self
    !> This spool's text not in its file yet.
    type(text_buffer_t), intent(inout) :: out
    !> The spool whose text comes after.
    type(spool_t), intent(inout) :: other
    !> Its text not in its file yet.
    type(text_buffer_t), intent(inout) :: other_out
    !> A file cannot be read or written.
    type(error_t), allocatable, intent(out) :: error
    integer :: err
    if (other%spilled) then
      call open_file_now(self, out, error)
      if (allocated(error)) then
        call other%discard()
        return
      end if
      call copy_file(other%fd, other%size, self%fd, err)
      if (err == 0) self%size = self%size + other%size
      call other%discard()
      if (err /= 0) then
        call fatal_error(error, exit_input, where(self)//": cannot write output: "//system_error_text(err))
        call self%discard()
        return
      end if
    end if
    if (other_out%length > 0) call out%append(other_out%data(1:other_out%length))
    other_out%length = 0
    call self%drain(out, error)
  end subroutine absorb

  !> The run succeeded: its whole text (the file, then `out`) goes to the target.
  subroutine commit(self, out, error)
    class(spool_t), intent(inout) :: self
    !> The text not in the file yet.
    type(text_buffer_t), intent(inout) :: out
    !> The target cannot be written.
    type(error_t), allocatable, intent(out) :: error
    integer :: err
    if (.not. self%spilled) then
      if (allocated(self%target)) then
        call write_output_file(self%target, out, error)
      else
        call write_output_stdout(out, error)
      end if
      return
    end if
    call self%drain(out, error, force=.true.)
    if (allocated(error)) return
    if (self%sink%plan == plan_replace) then
      ! the file is the temporary beside the target: renamed into place
      self%spilled = .false.
      self%fd = -1
      call self%sink%finish(error)
      return
    end if
    ! a device, FIFO or standard output: copied out of the anonymous file
    call self%sink%start(error)
    if (allocated(error)) then
      call self%discard()
      return
    end if
    if (self%sink%fd == 1) flush (output_unit)
    call copy_file(self%fd, self%size, self%sink%fd, err)
    if (err /= 0) then
      call fatal_error(error, exit_input, where(self)//": cannot write output: "//system_error_text(err))
      call self%sink%abandon()
    else
      call self%sink%finish(error)
    end if
    call self%discard()
  end subroutine commit

  !> The run failed (or the text was copied out): close and remove the temporary file, if any.
  subroutine discard(self)
    class(spool_t), intent(inout) :: self
    integer :: err
    if (.not. self%spilled) return
    if (self%sink%plan == plan_replace .and. allocated(self%sink%temp)) then
      call self%sink%abandon()
    else if (self%fd >= 0) then
      err = close_fd(self%fd)
    end if
    self%fd = -1
    self%size = 0
    self%spilled = .false.
  end subroutine discard

  !> Append `text` to the temporary file.
  subroutine put(self, text, error)
    type(spool_t), intent(inout) :: self
    character(*), intent(in) :: text
    type(error_t), allocatable, intent(out) :: error
    integer :: err
    err = write_fd(self%fd, text)
    if (err /= 0) then
      call fatal_error(error, exit_input, where(self)//": cannot write output: "//system_error_text(err))
      call self%discard()
      return
    end if
    self%size = self%size + len(text, int64)
  end subroutine put

  !> Copy the first `size` bytes of descriptor `from` to descriptor `to`, copy_chunk bytes at
  !> a time; `err` is 0, or the errno of the failed read or write.
  subroutine copy_file(from, size, to, err)
    !> The temporary file's descriptor.
    integer, intent(in) :: from
    !> Its bytes.
    integer(int64), intent(in) :: size
    !> Where to.
    integer, intent(in) :: to
    !> 0 on success.
    integer, intent(out) :: err
    character(len=:), allocatable :: chunk
    integer(int64) :: offset, got
    err = 0
    offset = 0
    do while (offset < size)
      got = read_fd_at(from, int(min(int(copy_chunk, int64), size - offset)), offset, chunk)
      if (got <= 0) then
        err = int(-got)
        if (got == 0) err = eio
        return
      end if
      err = write_fd(to, chunk)
      if (err /= 0) return
      offset = offset + got
    end do
  end subroutine copy_file

  !> Move everything so far to the file, opening it first if needed.
  subroutine open_file_now(self, out, error)
    type(spool_t), intent(inout) :: self
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    if (.not. self%spilled) then
      call open_file(self, error)
      if (allocated(error)) return
    end if
    call self%drain(out, error, force=.true.)
  end subroutine open_file_now

  !> Create the temporary file: beside a regular target (renamed at the end), else an
  !> anonymous one in $TMPDIR (or /tmp).
  subroutine open_file(self, error)
    type(spool_t), intent(inout) :: self
    type(error_t), allocatable, intent(out) :: error
    character(len=4096) :: dir
    integer :: length, status, fd
    if (allocated(self%target)) then
      call self%sink%aim(error, self%target)
    else
      call self%sink%aim(error)
    end if
    if (allocated(error)) return
    if (self%sink%plan == plan_replace) then
      call self%sink%start(error)
      if (allocated(error)) return
      self%fd = self%sink%fd
      self%file = self%sink%temp
    else
      fd = temp_anonymous()
      if (fd < 0) then
        call get_environment_variable("TMPDIR", dir, length, status)
        if (status /= 0 .or. length == 0) dir = "/tmp"
        call fatal_error(error, exit_input, where(self)//": cannot write output: a temporary file in "// &
          trim(dir)//": "//system_error_text(fd))
        return
      end if
      self%fd = fd
    end if
    self%size = 0
    self%spilled = .true.
  end subroutine open_file

  !> The target for messages.
  function where(self) result(text)
    type(spool_t), intent(in) :: self
    character(len=:), allocatable :: text
    if (allocated(self%target)) then
      text = self%target
    else
      text = "standard output"
    end if
  end function where

end module kinetostat_spool
