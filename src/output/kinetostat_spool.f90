!> Where a run's output text goes while the run is not finished: memory up to a bound, then
!> a temporary file; only when the whole run succeeded does the text reach its target (the
!> file of `-o`, renamed into place, or standard output, copied out), so that no output is
!> ever partial. A run of any length thus holds at most `spool_bound` bytes of text.
module kinetostat_spool
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: int_str
  use kinetostat_posix, only: path_kind, path_special, rename_file, process_id, write_standard_output
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_output, only: write_output_file, write_output_stdout, remove_file
  implicit none
  private
  public :: spool_t, spool_bound

  !> Bytes of output text kept in memory before they go to the temporary file.
  integer, parameter :: spool_bound = 4 * 1024 * 1024
  !> Bytes copied at a time from the temporary file to the target.
  integer, parameter :: copy_chunk = 1024 * 1024

  !> The output of one run on its way to its target.
  type :: spool_t
    !> The target file (`-o`); not allocated: standard output.
    character(len=:), allocatable :: target
    !> The temporary file, once the text outgrew memory.
    character(len=:), allocatable :: file
    !> Its unit while open.
    integer :: unit = 0
    !> Whether the text went to the temporary file.
    logical :: spilled = .false.
    !> Bytes kept in memory before they go to the file (tests make it small).
    integer :: bound = spool_bound
  contains
    procedure :: aim
    procedure :: drain
    procedure :: absorb
    procedure :: commit
    procedure :: discard
  end type spool_t

  !> Temporary files made by this process so far (for unique names).
  integer :: spool_count = 0

contains

  !> Aim the spool at a target file (`-o`); without `target`, at standard output.
  subroutine aim(self, target)
    class(spool_t), intent(inout) :: self
    !> Path of the target file.
    character(*), intent(in), optional :: target
    if (present(target)) self%target = target
  end subroutine aim

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
    integer :: ios
    character(len=512) :: msg
    logical :: now
    now = out%length > self%bound
    if (present(force)) now = now .or. (force .and. self%spilled)
    if (.not. now .or. out%length == 0) return
    if (.not. self%spilled) then
      call open_file(self, error)
      if (allocated(error)) return
    end if
    msg = ""
    write (self%unit, iostat=ios, iomsg=msg) out%data(1:out%length)
    if (ios /= 0) then
      call fatal_error(error, exit_input, where(self)//": cannot write output: "//trim(msg))
      call self%discard()
      return
    end if
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
    integer :: ios
    character(len=512) :: msg
    if (other%spilled) then
      call open_file_now(self, out, error)
      if (allocated(error)) return
      close (other%unit)
      other%unit = 0
      msg = ""
      call copy_file(other%file, self%unit, .true., ios, msg)
      other%spilled = .false.
      if (ios /= 0) then
        call fatal_error(error, exit_input, where(self)//": cannot write output: "//trim(msg))
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
    integer :: ios
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
    close (self%unit, iostat=ios)
    self%unit = 0
    if (ios /= 0) then
      call fatal_error(error, exit_input, where(self)//": cannot write output: the file cannot be closed")
      call self%discard()
      return
    end if
    if (beside_target(self)) then
      if (.not. rename_file(self%file, self%target)) then
        call fatal_error(error, exit_input, self%target//": cannot write output: cannot rename the finished "// &
          "output into place")
        call self%discard()
        return
      end if
      self%spilled = .false.
      return
    end if
    call copy_out(self, error)
    call self%discard()
  end subroutine commit

  !> The run failed: remove the temporary file, if any.
  subroutine discard(self)
    class(spool_t), intent(inout) :: self
    integer :: ios
    if (.not. self%spilled) return
    ios = 1
    if (self%unit /= 0) close (self%unit, status="delete", iostat=ios)
    self%unit = 0
    ! not deleted on closing (or already closed): remove it by name
    if (ios /= 0) call remove_file(self%file)
    self%spilled = .false.
  end subroutine discard

  !> Copy the temporary file to standard output or to a special target (a pipe, a device).
  subroutine copy_out(self, error)
    type(spool_t), intent(inout) :: self
    type(error_t), allocatable, intent(out) :: error
    integer :: out_unit, ios, ios_close
    character(len=512) :: msg
    msg = ""
    out_unit = 0
    ios = 0
    if (allocated(self%target)) then
      open (newunit=out_unit, file=self%target, access="stream", form="unformatted", action="write", &
            status="old", iostat=ios, iomsg=msg)
    end if
    if (ios == 0) call copy_file(self%file, out_unit, .false., ios, msg)
    if (out_unit /= 0) then
      close (out_unit, iostat=ios_close)
      if (ios == 0) ios = ios_close
    end if
    if (ios /= 0) then
      if (allocated(self%target)) then
        call fatal_error(error, exit_input, self%target//": cannot write output: "//trim(msg))
      else
        call fatal_error(error, exit_input, "standard output: cannot write the output ("//trim(msg)//")")
      end if
    end if
  end subroutine copy_out

  !> Append the file at `path` to the open stream `out_unit` (0: standard output), in chunks
  !> of copy_chunk bytes; `remove` deletes the file afterwards. ios /= 0 on failure, with `msg`.
  subroutine copy_file(path, out_unit, remove, ios, msg)
    !> The file to copy.
    character(*), intent(in) :: path
    !> Where to (0: standard output).
    integer, intent(in) :: out_unit
    !> Delete the file afterwards.
    logical, intent(in) :: remove
    !> 0 on success.
    integer, intent(out) :: ios
    !> iomsg of the failure (kept when there is none).
    character(len=512), intent(inout) :: msg
    character(len=:), allocatable :: chunk
    integer :: in_unit, ios_close
    integer(int64) :: size_left
    open (newunit=in_unit, file=path, access="stream", form="unformatted", action="read", status="old", &
          iostat=ios, iomsg=msg)
    if (ios /= 0) return
    inquire (unit=in_unit, size=size_left, iostat=ios)
    do while (ios == 0 .and. size_left > 0)
      allocate (character(len=int(min(int(copy_chunk, int64), size_left))) :: chunk)
      read (in_unit, iostat=ios, iomsg=msg) chunk
      if (ios == 0) then
        if (out_unit /= 0) then
          write (out_unit, iostat=ios, iomsg=msg) chunk
        else if (.not. write_standard_output(chunk)) then
          ios = 1
          msg = "disk full or pipe closed?"
        end if
      end if
      size_left = size_left - len(chunk)
      deallocate (chunk)
    end do
    if (remove) then
      close (in_unit, status="delete", iostat=ios_close)
    else
      close (in_unit, iostat=ios_close)
    end if
    if (ios == 0) ios = ios_close
  end subroutine copy_file

  !> Whether the temporary file lies beside the target (renamed into place at the end).
  logical function beside_target(self)
    type(spool_t), intent(in) :: self
    beside_target = .false.
    if (allocated(self%target)) beside_target = path_kind(self%target) /= path_special
  end function beside_target

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

  !> Create the temporary file: beside a regular target (renamed at the end), else in
  !> $TMPDIR (or /tmp).
  subroutine open_file(self, error)
    type(spool_t), intent(inout) :: self
    type(error_t), allocatable, intent(out) :: error
    character(len=4096) :: dir
    character(len=512) :: msg
    integer :: length, status, ios
    spool_count = spool_count + 1
    if (beside_target(self)) then
      self%file = self%target//".tmp."//int_str(process_id())
      if (spool_count > 1) self%file = self%file//"."//int_str(spool_count)
    else
      call get_environment_variable("TMPDIR", dir, length, status)
      if (status /= 0 .or. length == 0) dir = "/tmp"
      self%file = trim(dir)//"/kinetostat-"//int_str(process_id())//"-"//int_str(spool_count)//".out"
    end if
    msg = ""
    open (newunit=self%unit, file=self%file, access="stream", form="unformatted", action="readwrite", &
          status="replace", iostat=ios, iomsg=msg)
    if (ios /= 0) then
      self%unit = 0
      call fatal_error(error, exit_input, where(self)//": cannot write output: "//self%file//": "//trim(msg))
      return
    end if
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
