!> Error type carried out of fallible routines (fpm's pattern) and the exit codes of the spec.
module kinetostat_error
  implicit none
  private
  public :: error_t, fatal_error
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

end module kinetostat_error
