!> Command line: argument parsing, atomic output files, and the only place where an
!> error becomes a `kinetostat: error: ...` line on stderr and an exit code.
module kinetostat_cli
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
  use kinetostat_kinds, only: version_string
  use kinetostat_error, only: error_t, fatal_error, exit_success, exit_usage, exit_input
  use kinetostat_output, only: format_table, format_from_name, run_summary_t, selfcheck_ok
  use kinetostat_mechanisms, only: run_deck, write_template, known_kinds
  implicit none
  private
  public :: run_cli

  !> One-line usage, printed with usage errors.
  character(*), parameter :: usage_line = &
    "usage: kinetostat DECK [-o FILE] [--format table|csv] [--quiet] | kinetostat template KIND | --help | --version"

  !> Warning line when a run's self-check exceeds its tolerance.
  character(*), parameter :: selfcheck_warning_fmt = '(a,es9.2,a,es9.2)'

  !> Help text.
  character(*), parameter :: help_lines(*) = [character(len=88) :: &
    "kinetostat - kinetostatic force analysis of planar mechanisms", &
    "", &
    "  kinetostat DECK [-o FILE] [--format table|csv] [--quiet]", &
    "  kinetostat template KIND      print a commented example deck", &
    "  kinetostat --help | --version", &
    "", &
    "DECK is a Fortran namelist file; its first group names the mechanism.", &
    "-o FILE     write to FILE (atomically: nothing is left behind on error)", &
    "--format    table (default, the legacy printout) or csv (full precision)", &
    "--quiet     no self-check warnings on stderr (errors are still reported)", &
    "", &
    "Exit codes: 0 ok, 1 usage, 2 input error, 3 geometry error (step named)."]

  interface
    function c_rename(old, new) bind(c, name="rename") result(status)
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: old(*), new(*)
      integer(c_int) :: status
    end function c_rename
    function c_getpid() bind(c, name="getpid") result(pid)
      import :: c_int
      integer(c_int) :: pid
    end function c_getpid
  end interface

  !> Parsed command line.
  type :: cli_args_t
    character(len=:), allocatable :: deck
    character(len=:), allocatable :: out_file
    character(len=:), allocatable :: template_kind
    integer :: output_format = format_table
    logical :: quiet = .false.
    logical :: help = .false.
    logical :: version = .false.
  end type cli_args_t

contains

  !> Run the program for the current command line; returns the exit code.
  subroutine run_cli(exit_code)
    !> Exit code of the spec.
    integer, intent(out) :: exit_code
    type(cli_args_t) :: args
    type(error_t), allocatable :: error
    type(run_summary_t) :: summary
    integer :: i

    call parse_args(args, error)
    if (.not. allocated(error)) then
      if (args%help) then
        do i = 1, size(help_lines)
          write (output_unit, '(a)') trim(help_lines(i))
        end do
        write (output_unit, '(a)') "Kinds: "//known_kinds
      else if (args%version) then
        write (output_unit, '(a)') version_string
      else if (allocated(args%template_kind)) then
        call write_template(args%template_kind, output_unit, error)
      else if (allocated(args%out_file)) then
        call run_to_file(args, error, summary)
      else
        call run_deck(args%deck, args%output_format, output_unit, error, summary)
      end if
    end if
    if (.not. allocated(error) .and. .not. args%quiet .and. allocated(summary%warning)) then
      write (error_unit, '(a)') "kinetostat: warning: "//args%deck//": "//summary%warning
    end if
    if (.not. allocated(error) .and. .not. args%quiet .and. summary%steps > 0) then
      if (.not. selfcheck_ok(summary%max_residual, summary%max_mismatch)) then
        write (error_unit, selfcheck_warning_fmt) "kinetostat: warning: "//args%deck// &
          ": self-check failed (a bug; please report): max equilibrium residual", summary%max_residual, &
          ", max "//summary%driver//" mismatch vs power balance", summary%max_mismatch
      end if
    end if

    if (allocated(error)) then
      write (error_unit, '(a)') "kinetostat: error: "//error%message
      if (error%code == exit_usage) write (error_unit, '(a)') usage_line
      exit_code = error%code
    else
      exit_code = exit_success
    end if
    flush (output_unit)
    flush (error_unit)
  end subroutine run_cli

  subroutine parse_args(args, error)
    type(cli_args_t), intent(out) :: args
    type(error_t), allocatable, intent(out) :: error
    integer :: i, n
    character(len=:), allocatable :: arg

    n = command_argument_count()
    if (n == 0) then
      call fatal_error(error, exit_usage, "no deck given")
      return
    end if
    i = 0
    do while (i < n)
      i = i + 1
      arg = argument(i)
      select case (arg)
      case ("-h", "--help")
        args%help = .true.
      case ("-V", "--version")
        args%version = .true.
      case ("--quiet", "-q")
        args%quiet = .true.
      case ("-o", "--output")
        if (i == n) then
          call fatal_error(error, exit_usage, arg//" needs a file name")
          return
        end if
        i = i + 1
        args%out_file = argument(i)
      case ("--format")
        if (i == n) then
          call fatal_error(error, exit_usage, "--format needs table or csv")
          return
        end if
        i = i + 1
        args%output_format = format_from_name(argument(i))
        if (args%output_format == 0) then
          call fatal_error(error, exit_usage, "--format must be table or csv (got '"//argument(i)//"')")
          return
        end if
      case ("template")
        if (allocated(args%deck) .or. i == n) then
          call fatal_error(error, exit_usage, "template needs exactly one KIND (known: "//known_kinds//")")
          return
        end if
        i = i + 1
        args%template_kind = argument(i)
      case default
        if (len(arg) > 1 .and. arg(1:1) == "-") then
          call fatal_error(error, exit_usage, "unknown option '"//arg//"'")
          return
        end if
        if (allocated(args%deck) .or. allocated(args%template_kind)) then
          call fatal_error(error, exit_usage, "more than one deck given ('"//arg//"')")
          return
        end if
        args%deck = arg
      end select
    end do
    if (args%help .or. args%version .or. allocated(args%template_kind)) return
    if (.not. allocated(args%deck)) call fatal_error(error, exit_usage, "no deck given")
  end subroutine parse_args

  function argument(i) result(arg)
    integer, intent(in) :: i
    character(len=:), allocatable :: arg
    integer :: length
    call get_command_argument(i, length=length)
    allocate (character(len=length) :: arg)
    if (length > 0) call get_command_argument(i, arg)
  end function argument

  !> Write to a temporary file beside the target, rename it over the target on success,
  !> delete it on failure: an error never leaves a partial file.
  subroutine run_to_file(args, error, summary)
    type(cli_args_t), intent(in) :: args
    type(error_t), allocatable, intent(out) :: error
    type(run_summary_t), intent(out) :: summary
    character(len=:), allocatable :: tmp
    character(len=16) :: pid_text
    character(len=512) :: msg
    integer :: unit, ios

    write (pid_text, '(i0)') c_getpid()
    tmp = args%out_file//".tmp."//trim(pid_text)
    open (newunit=unit, file=tmp, status='replace', action='write', form='formatted', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call fatal_error(error, exit_input, args%out_file//": cannot write output: "//trim(msg))
      return
    end if
    call run_deck(args%deck, args%output_format, unit, error, summary)
    if (allocated(error)) then
      close (unit, status='delete')
      return
    end if
    close (unit, iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call fatal_error(error, exit_input, args%out_file//": cannot write output: "//trim(msg))
      return
    end if
    if (c_rename(tmp//c_null_char, args%out_file//c_null_char) /= 0) then
      open (newunit=unit, file=tmp, status='old', iostat=ios)
      if (ios == 0) close (unit, status='delete')
      call fatal_error(error, exit_input, args%out_file//": cannot rename the finished output into place")
    end if
  end subroutine run_to_file

end module kinetostat_cli
