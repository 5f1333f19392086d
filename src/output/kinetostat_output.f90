!> Checked output of a finished run: the text on stdout, or into a file replaced atomically
!> (a temporary beside it, renamed over it only when every byte was written).
module kinetostat_output
  use, intrinsic :: iso_fortran_env, only: output_unit
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_text, only: int_str
  use kinetostat_posix, only: path_kind, path_special, rename_file, process_id, write_standard_output
  use kinetostat_text_buffer, only: text_buffer_t
  implicit none
  private
  public :: write_output_file, write_output_stdout, remove_file

contains

  !> The output on stdout, checked: a failed write (a full disk, a closed pipe) is an error.
  subroutine write_output_stdout(out, error)
    !> The whole output.
    type(text_buffer_t), intent(in) :: out
    !> Set when a write failed.
    type(error_t), allocatable, intent(out) :: error
    if (out%length == 0) return
    flush (output_unit)
    if (.not. write_standard_output(out%data(1:out%length))) then
      call fatal_error(error, exit_input, "standard output: cannot write the output (disk full or pipe closed?)")
    end if
  end subroutine write_output_stdout

  !> The output into FILE. A regular (or new) FILE is written as a temporary beside it and
  !> renamed over it only when every byte was written and closed without error; on any error
  !> the temporary is removed and FILE is left as it was. A device or FIFO is written directly.
  subroutine write_output_file(path, out, error)
    !> Output file path (or a device/FIFO).
    character(*), intent(in) :: path
    !> The whole output.
    type(text_buffer_t), intent(in) :: out
    !> Set when the file cannot be written; FILE is then as it was.
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: target
    logical :: direct
    direct = path_kind(path) == path_special
    if (direct) then
      target = path
    else
      target = path//".tmp."//int_str(process_id())
    end if
    call write_bytes(target, direct, out, error)
    if (allocated(error)) then
      error%message = path//": cannot write output: "//error%message
      if (.not. direct) call remove_file(target)
      return
    end if
    if (direct) return
    if (.not. rename_file(target, path)) then
      call remove_file(target)
      call fatal_error(error, exit_input, path//": cannot write output: cannot rename the finished output into place")
    end if
  end subroutine write_output_file

  !> Write the buffer's bytes to `path`; every write and the close are checked.
  subroutine write_bytes(path, existing, out, error)
    character(*), intent(in) :: path
    !> True for a device or FIFO (opened as it is, not replaced).
    logical, intent(in) :: existing
    type(text_buffer_t), intent(in) :: out
    type(error_t), allocatable, intent(out) :: error
    integer :: unit, ios
    character(len=512) :: msg
    msg = ""
    if (existing) then
      open (newunit=unit, file=path, access='stream', form='unformatted', action='write', status='old', &
            iostat=ios, iomsg=msg)
    else
      open (newunit=unit, file=path, access='stream', form='unformatted', action='write', status='replace', &
            iostat=ios, iomsg=msg)
    end if
    if (ios /= 0) then
      call fatal_error(error, exit_input, trim(msg))
      return
    end if
    if (out%length > 0) write (unit, iostat=ios, iomsg=msg) out%data(1:out%length)
    if (ios == 0) flush (unit, iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call fatal_error(error, exit_input, trim(msg))
      close (unit, iostat=ios)
      if (ios /= 0) error%message = error%message//" (and the file could not be closed)"
      return
    end if
    close (unit, iostat=ios, iomsg=msg)
    if (ios /= 0) call fatal_error(error, exit_input, trim(msg))
  end subroutine write_bytes

  !> Delete a file if it exists (clean-up after an error: a failure here changes nothing
  !> about the error already being reported, so it is not reported again).
  subroutine remove_file(path)
    character(*), intent(in) :: path
    integer :: unit, ios
    open (newunit=unit, file=path, status='old', iostat=ios)
    if (ios /= 0) return
    close (unit, status='delete', iostat=ios)
    if (ios /= 0) return
  end subroutine remove_file

end module kinetostat_output
