!> Command line: argument parsing, the run of one deck through the pipeline, checked output
!> (stdout or an atomically replaced file), and the only place where an error becomes a
!> `kinetostat: error: ...` line on stderr and an exit code.
module kinetostat_cli
  use, intrinsic :: iso_fortran_env, only: error_unit
  use kinetostat_kinds, only: version_string
  use kinetostat_error, only: error_t, fatal_error, exit_success, exit_usage, exit_input
  use kinetostat_deck, only: deck_source_t, load_deck, read_group_name
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_output, only: write_output_file, write_output_stdout
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_labels, only: lang_from_name
  use kinetostat_run, only: run_options_t, run_mechanism, format_from_name, format_names
  use kinetostat_table_writer, only: selfcheck_verdict
  use kinetostat_registry, only: create_mechanism, known_kinds
  implicit none
  private
  public :: run_cli

  !> One-line usage, printed with usage errors.
  character(*), parameter :: usage_line = "usage: kinetostat DECK [-o FILE] [--format table|csv|json] " // &
    "[--lang en|ru] [--quiet] | kinetostat template KIND | --help | --version"

  !> Warning line when a run's self-check exceeds its tolerance.
  character(*), parameter :: selfcheck_warning_fmt = '(a,es9.2,a,es9.2)'

  !> Help text (the kinds are appended from the registry).
  character(*), parameter :: help_lines(*) = [character(len=88) :: &
    "kinetostat - kinetostatic force analysis of planar mechanisms", &
    "", &
    "  kinetostat DECK [-o FILE] [--format table|csv|json] [--lang en|ru] [--quiet]", &
    "  kinetostat template KIND      print a commented example deck", &
    "  kinetostat --help | --version", &
    "", &
    "DECK is a Fortran namelist file; its first group names the mechanism.", &
    "-o FILE     write to FILE (atomically: nothing is left behind on error)", &
    "--format    table (default, the legacy printout), csv (full precision) or json", &
    "--lang      language of the table's labels: en (default) or ru (the 1991 printouts)", &
    "--quiet     no warnings on stderr (errors are still reported)", &
    "", &
    "Exit codes: 0 ok, 1 usage, 2 input or output error, 3 geometry error or a result", &
    "that is not finite (the step is named)."]

  !> Parsed command line.
  type :: cli_args_t
    character(len=:), allocatable :: deck
    character(len=:), allocatable :: out_file
    character(len=:), allocatable :: template_kind
    type(run_options_t) :: options
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
    type(step_table_t) :: table
    type(text_buffer_t) :: out
    integer :: i
    logical :: ran

    ran = .false.
    call parse_args(args, error)
    if (.not. allocated(error)) then
      if (args%help) then
        do i = 1, size(help_lines)
          call out%put(trim(help_lines(i)))
        end do
        call out%put("Kinds: "//known_kinds())
        call out%put("Formats: "//format_names)
      else if (args%version) then
        call out%put(version_string)
      else if (allocated(args%template_kind)) then
        call write_template(args%template_kind, out, error)
      else
        call run_deck(args%deck, args%options, table, out, error)
        ran = .not. allocated(error)
      end if
    end if
    if (.not. allocated(error)) then
      if (allocated(args%out_file)) then
        call write_output_file(args%out_file, out, error)
      else
        call write_output_stdout(out, error)
      end if
    end if
    if (ran .and. .not. allocated(error) .and. .not. args%quiet) call warn(args%deck, table)

    if (allocated(error)) then
      write (error_unit, '(a)') "kinetostat: error: "//error%message
      if (error%code == exit_usage) write (error_unit, '(a)') usage_line
      exit_code = error%code
    else
      exit_code = exit_success
    end if
    flush (error_unit)
  end subroutine run_cli

  !> Read the deck's first group, create that mechanism, run it into `out`.
  subroutine run_deck(path, options, table, out, error)
    character(*), intent(in) :: path
    type(run_options_t), intent(in) :: options
    type(step_table_t), intent(out) :: table
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: group
    class(mechanism_t), allocatable :: mech
    type(deck_source_t) :: source
    call load_deck(path, source, error)
    if (allocated(error)) return
    call read_group_name(source, group, error)
    if (allocated(error)) return
    call create_mechanism(group, mech)
    if (.not. allocated(mech)) then
      call fatal_error(error, exit_input, path//": &"//group//": unknown mechanism (known: "//known_kinds()//")")
      return
    end if
    call run_mechanism(mech, group, source, options, table, out, error)
  end subroutine run_deck

  !> The commented template deck of a kind.
  subroutine write_template(kind, out, error)
    character(*), intent(in) :: kind
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    class(mechanism_t), allocatable :: mech
    call create_mechanism(kind, mech)
    if (.not. allocated(mech)) then
      call fatal_error(error, exit_usage, "template: unknown kind '"//kind//"' (known: "//known_kinds()//")")
      return
    end if
    call mech%write_template(out)
  end subroutine write_template

  !> Warnings of a successful run on stderr: the mechanism's remark, a failed self-check.
  subroutine warn(deck, table)
    character(*), intent(in) :: deck
    type(step_table_t), intent(in) :: table
    if (allocated(table%warning)) write (error_unit, '(a)') "kinetostat: warning: "//deck//": "//table%warning
    if (.not. table%has_selfcheck .or. table%row_count() == 0) return
    if (selfcheck_verdict(table%max_residual) /= "OK" .or. selfcheck_verdict(table%max_mismatch) /= "OK") then
      write (error_unit, selfcheck_warning_fmt) "kinetostat: warning: "//deck// &
        ": self-check failed (a bug; please report): max equilibrium residual", table%max_residual, &
        ", max "//table%driver//" mismatch", table%max_mismatch
    end if
  end subroutine warn

  subroutine parse_args(args, error)
    type(cli_args_t), intent(out) :: args
    type(error_t), allocatable, intent(out) :: error
    integer :: i, n, eq
    character(len=:), allocatable :: arg, name, value

    n = command_argument_count()
    if (n == 0) then
      call fatal_error(error, exit_usage, "no deck given")
      return
    end if
    i = 0
    do while (i < n)
      i = i + 1
      arg = argument(i)
      ! --name=value is the same as --name value
      eq = index(arg, "=")
      if (len(arg) > 2 .and. arg(1:min(2, len(arg))) == "--" .and. eq > 0) then
        name = arg(1:eq - 1)
        value = arg(eq + 1:)
      else
        name = arg
        if (any(name == [character(len=8) :: "-o", "--output", "--format", "--lang"])) then
          if (i == n) then
            call fatal_error(error, exit_usage, name//" needs a value")
            return
          end if
          i = i + 1
          value = argument(i)
        end if
      end if
      select case (name)
      case ("-h", "--help")
        args%help = .true.
      case ("-V", "--version")
        args%version = .true.
      case ("--quiet", "-q")
        args%quiet = .true.
      case ("-o", "--output")
        args%out_file = value
      case ("--format")
        args%options%format = format_from_name(value)
        if (args%options%format == 0) then
          call fatal_error(error, exit_usage, "--format must be one of "//format_names//" (got '"//value//"')")
          return
        end if
      case ("--lang")
        args%options%lang = lang_from_name(value)
        if (args%options%lang == 0) then
          call fatal_error(error, exit_usage, "--lang must be en or ru (got '"//value//"')")
          return
        end if
      case ("template")
        if (allocated(args%deck) .or. i == n) then
          call fatal_error(error, exit_usage, "template needs exactly one KIND (known: "//known_kinds()//")")
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

end module kinetostat_cli
