!> Error type carried out of fallible routines (fpm's pattern) and the exit codes of the spec.
module kinetostat_error
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_text, only: int64_str
  implicit none
  private
  public :: error_t, fatal_error, out_of_memory
  public :: exit_success, exit_usage, exit_input, exit_geometry, exit_warning

  !> Exit code: success.
  integer, parameter :: exit_success = 0
  !> Exit code: bad command-line arguments.
  integer, parameter :: exit_usage = 1
  !> Exit code: unreadable deck, namelist error or invalid value.
  integer, parameter :: exit_input = 2
  !> Exit code: mechanism cannot be assembled or a reaction is undetermined at some step.
  integer, parameter :: exit_geometry = 3
  !> Exit code: the run succeeded and its output was written, but it warned and --strict
  !> was given.
  integer, parameter :: exit_warning = 4

  !> A failure: one-line message and the exit code it maps to.
  type :: error_t
    !> Exit code of the spec (`exit_usage`, `exit_input`, `exit_geometry`).
    integer :: code = exit_input
    !> One-line message, without the `kinetostat: error:` prefix.
    character(len=:), allocatable :: message
  end type error_t

contains

  !> Allocate `error` with an exit code and a message.
  pure subroutine fatal_error(error, code, message)
    !> The error to create.
    type(error_t), allocatable, intent(out) :: error
    !> Exit code the CLI will use.
    integer, intent(in) :: code
    !> One-line description.
    character(*), intent(in) :: message
    allocate (error)
    error%code = code
    error%message = message
  end subroutine fatal_error

  !> The error of an allocation that failed (stat /= 0): exit 2, one line naming what did not
  !> fit ("out of memory: no room for the deck's text (268435456 bytes)").
  pure subroutine out_of_memory(error, what, bytes)
    !> The error to create.
    type(error_t), allocatable, intent(out) :: error
    !> What was to be held ("the deck's text"), with the deck's name in front where known.
    character(*), intent(in) :: what
    !> Its size, bytes.
    integer(int64), intent(in) :: bytes
    call fatal_error(error, exit_input, "out of memory: no room for "//what//" ("//int64_str(bytes)//" bytes)")
  end subroutine out_of_memory

end module kinetostat_error
