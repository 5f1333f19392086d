!> Checked output of a finished run: the text on stdout, or into the file of `-o`. A
!> regular (or new) file is replaced atomically: a temporary beside it (after following
!> symbolic links: a link stays a link and its target is replaced), created with
!> O_EXCL|O_NOFOLLOW, mode 600 and a random name, written, given the mode (and, as root, the
!> owner) of the file it replaces, synced and renamed over it only when every byte was
!> written; on any failure the temporary is removed and the file is as it was. Anything
!> else (a device, FIFO, socket, /dev/stdout) is written directly. Every write is checked:
!> a full disk (ENOSPC), a file-size limit (EFBIG) or an I/O error (EIO) is an error.
module kinetostat_output
  use, intrinsic :: iso_fortran_env, only: output_unit
  use kinetostat_error, only: error_t, fatal_error, exit_input
  use kinetostat_posix, only: output_plan, temp_beside, temp_remove, open_direct, replace_file, write_fd, &
    close_fd, system_error_text, write_standard_output, plan_replace, plan_direct, plan_descriptor
  use kinetostat_text_buffer, only: text_buffer_t
  implicit none
  private
  public :: output_sink_t, write_output_file, write_output_stdout

  !> Where the output goes, while it is written: standard output, or the target of `-o`.
  type :: output_sink_t
    !> The path of `-o` as given (messages); not allocated: standard output.
    character(len=:), allocatable :: path
    !> plan_replace, plan_direct or plan_descriptor (kinetostat_posix); 0: standard output.
    integer :: plan = 0
    !> The file written (links followed): replaced (plan_replace) or opened (plan_direct).
    character(len=:), allocatable :: final
    !> The temporary beside `final` (plan_replace), once opened.
    character(len=:), allocatable :: temp
    !> The descriptor written to; -1: not open.
    integer :: fd = -1
    !> Whether `fd` was opened here (closed at the end; not so standard output's).
    logical :: owned = .false.
  contains
    procedure :: aim => sink_aim
    procedure :: start => sink_open
    procedure :: send => sink_write
    procedure :: finish => sink_close
    procedure :: abandon => sink_abandon
  end type output_sink_t

contains

  !> Aim at `-o path` (links followed now); without `path`, at standard output.
  subroutine sink_aim(self, error, path)
    class(output_sink_t), intent(inout) :: self
    !> The path cannot be written (a directory, a loop of links).
    type(error_t), allocatable, intent(out) :: error
    !> The path of `-o`.
    character(*), intent(in), optional :: path
    integer :: plan, fd
    if (.not. present(path)) then
      self%plan = 0
      return
    end if
    self%path = path
    plan = output_plan(path, self%final, fd)
    if (plan < 0) then
      call fatal_error(error, exit_input, path//": cannot write output: "//system_error_text(plan))
      return
    end if
    self%plan = plan
    if (plan == plan_descriptor) self%fd = fd
  end subroutine sink_aim

  !> Open the target: a new temporary beside a regular file, the device or FIFO itself (a
  !> FIFO waits here for its reader), or the descriptor.
  subroutine sink_open(self, error)
    class(output_sink_t), intent(inout) :: self
    !> It cannot be opened (no such directory, permission, ...).
    type(error_t), allocatable, intent(out) :: error
    integer :: fd
    select case (self%plan)
    case (plan_replace)
      fd = temp_beside(self%final, self%temp)
      self%owned = .true.
    case (plan_direct)
      fd = open_direct(self%final)
      self%owned = .true.
    case (plan_descriptor)
      fd = self%fd
      self%owned = .false.
    case default
      fd = 1
      self%owned = .false.
    end select
    if (fd < 0) then
      if (allocated(self%temp)) deallocate (self%temp)
      call fatal_error(error, exit_input, where(self)//system_error_text(fd))
      return
    end if
    self%fd = fd
  end subroutine sink_open

  !> Write `text` (every byte, checked).
  subroutine sink_write(self, text, error)
    class(output_sink_t), intent(inout) :: self
    !> The bytes.
    character(*), intent(in) :: text
    !> A write failed (ENOSPC, EFBIG, EIO, EPIPE); the sink is then abandoned.
    type(error_t), allocatable, intent(out) :: error
    integer :: err
    err = write_fd(self%fd, text)
    if (err /= 0) then
      call fatal_error(error, exit_input, where(self)//system_error_text(err))
      call self%abandon()
    end if
  end subroutine sink_write

  !> Finish: a temporary replaces its file (mode and owner kept, synced, renamed), a device
  !> or FIFO is closed. On failure the temporary is removed and the file is as it was.
  subroutine sink_close(self, error)
    class(output_sink_t), intent(inout) :: self
    !> Closing, syncing or renaming failed.
    type(error_t), allocatable, intent(out) :: error
    integer :: err
    err = 0
    if (self%plan == plan_replace .and. allocated(self%temp)) then
      err = replace_file(self%fd, self%temp, self%final)
      deallocate (self%temp)
    else if (self%owned) then
      err = close_fd(self%fd)
    end if
    self%fd = -1
    self%owned = .false.
    if (err /= 0) call fatal_error(error, exit_input, where(self)//system_error_text(err))
  end subroutine sink_close

  !> Give up: close, and remove the temporary (the file is as it was).
  subroutine sink_abandon(self)
    class(output_sink_t), intent(inout) :: self
    integer :: err
    if (self%owned .and. self%fd >= 0) err = close_fd(self%fd)
    if (allocated(self%temp)) then
      call temp_remove(self%temp)
      deallocate (self%temp)
    end if
    self%fd = -1
    self%owned = .false.
  end subroutine sink_abandon

  !> "FILE: cannot write output: " (or standard output's), for messages.
  function where(self) result(text)
    class(output_sink_t), intent(in) :: self
    character(len=:), allocatable :: text
    if (allocated(self%path)) then
      text = self%path//": cannot write output: "
    else
      text = "standard output: cannot write output: "
    end if
  end function where

  !> The output on stdout, checked: a failed write (a full disk, a closed pipe) is an error.
  subroutine write_output_stdout(out, error)
    !> The whole output.
    type(text_buffer_t), intent(in) :: out
    !> Set when a write failed.
    type(error_t), allocatable, intent(out) :: error
    integer :: err
    if (out%length == 0) return
    flush (output_unit)
    err = write_standard_output(out%data(1:out%length))
    if (err /= 0) then
      call fatal_error(error, exit_input, "standard output: cannot write output: "//system_error_text(err))
    end if
  end subroutine write_output_stdout

  !> The whole output into `-o path` (see the module's description); on any error the
  !> path's file is as it was and no temporary is left.
  subroutine write_output_file(path, out, error)
    !> Output file path (a regular file, a link, a device, a FIFO, /dev/stdout).
    character(*), intent(in) :: path
    !> The whole output.
    type(text_buffer_t), intent(in) :: out
    !> Set when the file cannot be written; the file is then as it was.
    type(error_t), allocatable, intent(out) :: error
    type(output_sink_t) :: sink
    call sink%aim(error, path)
    if (allocated(error)) return
    call sink%start(error)
    if (allocated(error)) return
    if (out%length > 0) call sink%send(out%data(1:out%length), error)
    if (allocated(error)) return
    call sink%finish(error)
  end subroutine write_output_file

end module kinetostat_output
