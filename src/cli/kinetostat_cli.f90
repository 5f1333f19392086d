!> Command line: argument parsing, the run of one deck through the pipeline, checked output
!> (stdout or an atomically replaced file), and the only place where an error becomes a
!> `kinetostat: error: ...` line on stderr and an exit code.
module kinetostat_cli
  use, intrinsic :: iso_fortran_env, only: error_unit
  use kinetostat_kinds, only: wp, version_string
  use kinetostat_error, only: error_t, fatal_error, exit_success, exit_usage, exit_input, exit_warning
  use kinetostat_deck, only: deck_source_t, load_deck, read_group_name
  use kinetostat_override, only: override_t, parse_override, apply_overrides
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_output, only: write_output_file, write_output_stdout
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_labels, only: lang_from_name
  use kinetostat_run, only: run_options_t, run_mechanism, format_from_name, format_names, format_svg
  use kinetostat_table_writer, only: selfcheck_verdict
  use kinetostat_registry, only: create_mechanism, known_kinds, known_columns
  use kinetostat_step_table, only: column_t
  use kinetostat_diff, only: diff_options_t, diff_outputs
  use kinetostat_assur_presets, only: assur_preset, preset_names
  implicit none
  private
  public :: run_cli

  !> One-line usage, printed with usage errors.
  character(*), parameter :: usage_line = "usage: kinetostat DECK|- [--set NAME=VALUE]... [-o FILE] " // &
    "[--format table|csv|json|svg] [--pairs LIST] [--at K] [--lang en|ru] [--kinematics] [--quiet] [--strict] | " // &
    "kinetostat template KIND [-o FILE] | kinetostat diff A B [--rtol R] [--atol A] | --help | --version"

  !> Warning line when a run's self-check exceeds its tolerance.
  character(*), parameter :: selfcheck_warning_fmt = '(a,es9.2,a,es9.2)'

  !> Help text (the kinds are appended from the registry).
  character(*), parameter :: help_lines(*) = [character(len=92) :: &
    "kinetostat - kinetostatic force analysis of planar mechanisms", &
    "", &
    "  kinetostat DECK [--set NAME=VALUE]... [-o FILE] [--format table|csv|json|svg]", &
    "                  [--pairs LIST] [--at K] [--lang en|ru] [--kinematics] [--quiet] [--strict]", &
    "  kinetostat template KIND [-o FILE]   a commented deck to start from (KIND: a mechanism,", &
    "                                       or a preset of the generic engine)", &
    "  kinetostat diff A B [--rtol R] [--atol A] [--quiet]   compare two outputs", &
    "  kinetostat --help | --version", &
    "", &
    "DECK is a Fortran namelist file; its first group names the mechanism; - reads it", &
    "from standard input (so does a pipe given as a path, e.g. /dev/stdin).", &
    "--set NAME=VALUE  set a deck variable as if the deck ended with NAME = VALUE", &
    "            (repeatable; l_ab=0.12, f5c(3)=0, 'dyad(2)%l2=0.45'); marked (--set)", &
    "-o FILE, --output FILE  write to FILE (atomically: nothing is left behind on error)", &
    "--format    table (default, the legacy printout), csv (full precision), json, or svg", &
    "            (a sheet of force hodographs and diagrams; see docs/pictures.md)", &
    "--pairs     with svg: only these pair forces, e.g. --pairs F16,F36", &
    "--at K      with svg: the mechanism drawn at step K with every force of the step", &
    "--lang      language of the table's labels: en (default) or ru (the 1991 printouts)", &
    "--kinematics  csv and json add positions of joints and centres of mass, link angles,", &
    "            angular speeds and accelerations, accelerations of the centres of mass and", &
    "            the x, y components of the pair forces (the table is unchanged)", &
    "-q, --quiet no warnings on stderr (errors are still reported); diff: no report", &
    "--strict    a run that warns (self-check above its limit, a dead position between", &
    "            steps, a jammed cam or lost contact, a coarse step near a load edge)", &
    "            exits 4; the output is still written", &
    "-h, --help  this text;  -V, --version  the version", &
    "--rtol R, --atol A  the tolerances of diff (below)", &
    "--name=VALUE is the same as --name VALUE.", &
    "", &
    "diff compares two tables (same --lang) or two CSV files of the program value by value:", &
    "  |a - b| <= atol + rtol*max(|a|,|b|); angles modulo 360 deg with atol + rtol*(1 rad);", &
    "  the angle of a force at or below the noise floor (1e-12 of its step's largest force,", &
    "  or atol) is not compared; title and deck lines are ignored. Defaults: --rtol 1e-6,", &
    "  --atol per unit: 1e-6 N, N*m, deg and mm, 1e-9 m and everything else.", &
    "  Prints the first differences ('step 2, column F16: 2741.19 vs 2741.25 (rel 2.2e-05)')", &
    "  and exits 0 same, 1 different, 2 unreadable or not the same mechanism/columns.", &
    "", &
    "Exit codes: 0 ok, 1 usage, 2 input or output error, 3 geometry error or a result", &
    "that is not finite (the step is named), 4 warnings with --strict (output written)."]

  !> Usage of the diff subcommand (its errors exit 2: exit 1 means "different").
  character(*), parameter :: diff_usage = "usage: kinetostat diff A B [--rtol R] [--atol A] [--quiet]"

  !> Parsed command line.
  type :: cli_args_t
    character(len=:), allocatable :: deck
    character(len=:), allocatable :: out_file
    character(len=:), allocatable :: template_kind
    type(run_options_t) :: options
    logical :: quiet = .false.
    !> --strict: a run that warned exits with exit_warning (its output is still written).
    logical :: strict = .false.
    logical :: help = .false.
    logical :: version = .false.
    !> `kinetostat diff A B`: the two files.
    character(len=:), allocatable :: diff_files(:)
    !> Tolerances of `diff`.
    type(diff_options_t) :: diff_options
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
    integer :: i, warnings
    logical :: ran

    ran = .false.
    call parse_args(args, error)
    if (.not. allocated(error) .and. allocated(args%diff_files) .and. .not. args%help) then
      call run_diff(args, exit_code)
      return
    end if
    if (.not. allocated(error)) then
      if (args%help) then
        do i = 1, size(help_lines)
          call out%put(trim(help_lines(i)))
        end do
        call out%put("Kinds: "//known_kinds())
        call out%put("Presets (template): "//preset_names)
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
    warnings = 0
    if (ran .and. .not. allocated(error)) call warn(table, args%quiet, warnings)

    if (allocated(error)) then
      write (error_unit, '(a)') "kinetostat: error: "//error%message
      if (error%code == exit_usage) write (error_unit, '(a)') usage_line
      exit_code = error%code
    else if (args%strict .and. warnings > 0) then
      exit_code = exit_warning
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
    type(deck_source_t) :: patched
    call load_deck(path, source, error)
    if (allocated(error)) return
    call read_group_name(source, group, error)
    if (allocated(error)) return
    call create_mechanism(group, mech)
    if (.not. allocated(mech)) then
      call fatal_error(error, exit_input, source%path//": &"//group//": unknown mechanism (known: "// &
        known_kinds()//")")
      return
    end if
    if (.not. allocated(options%overrides)) then
      call run_mechanism(mech, group, source, options, table, out, error)
      return
    end if
    call apply_overrides(source, options%overrides, patched)
    call run_mechanism(mech, group, patched, options, table, out, error)
    if (allocated(error)) then
      if (error%code == exit_input) call blame_override(source, group, options%overrides, error)
    end if
  end subroutine run_deck

  !> Append the override "NAME=VALUE" of a --set.
  subroutine add_override(overrides, arg, error)
    !> The overrides so far.
    type(override_t), allocatable, intent(inout) :: overrides(:)
    !> The argument of --set.
    character(*), intent(in) :: arg
    !> Malformed argument (exit 2).
    type(error_t), allocatable, intent(out) :: error
    type(override_t) :: one
    call parse_override(arg, "--set", one, error)
    if (allocated(error)) return
    if (.not. allocated(overrides)) allocate (overrides(0))
    overrides = [overrides, one]
  end subroutine add_override

  !> An input error of a run with overrides: when the first k overrides give an error the
  !> first k-1 do not (or a different one), override k is named in the message as its cause;
  !> an error of the deck itself stays as it is.
  subroutine blame_override(source, group, overrides, error)
    !> The deck as read (without overrides).
    type(deck_source_t), intent(in) :: source
    !> Its first group.
    character(*), intent(in) :: group
    !> The overrides.
    type(override_t), intent(in) :: overrides(:)
    !> The run's error; its message is replaced when an override is found to be the cause.
    type(error_t), intent(inout) :: error
    type(error_t), allocatable :: previous, current
    type(deck_source_t) :: patched
    class(mechanism_t), allocatable :: mech
    integer :: k
    do k = 0, size(overrides)
      call apply_overrides(source, overrides(1:k), patched)
      if (allocated(mech)) deallocate (mech)
      call create_mechanism(group, mech)
      call mech%read_deck(patched, current)
      if (k > 0 .and. allocated(current)) then
        if (.not. allocated(previous)) then
          call name_cause(current%message)
          return
        else if (current%message /= previous%message) then
          call name_cause(current%message)
          return
        end if
      end if
      if (allocated(previous)) deallocate (previous)
      if (allocated(current)) call move_alloc(current, previous)
    end do
  contains
    subroutine name_cause(message)
      character(*), intent(in) :: message
      error%message = message//" (from --set "//overrides(k)%name//"="//overrides(k)%value//")"
      error%code = exit_input
    end subroutine name_cause
  end subroutine blame_override

  !> The commented template deck of a kind, or a preset of the generic engine.
  subroutine write_template(kind, out, error)
    character(*), intent(in) :: kind
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    class(mechanism_t), allocatable :: mech
    logical :: found
    call create_mechanism(kind, mech)
    if (allocated(mech)) then
      call mech%write_template(out)
      return
    end if
    call assur_preset(kind, out, found)
    if (.not. found) then
      call fatal_error(error, exit_usage, "template: unknown kind '"//kind//"' (known: "//known_kinds()// &
        "; presets: "//preset_names//")")
    end if
  end subroutine write_template

  !> Warnings of a successful run, one stderr line each unless `quiet`: the mechanism's
  !> remarks, a failed self-check.
  subroutine warn(table, quiet, count)
    !> The run's results.
    type(step_table_t), intent(in) :: table
    !> --quiet: count the warnings, print none.
    logical, intent(in) :: quiet
    !> Number of warnings.
    integer, intent(out) :: count
    integer :: i
    character(len=:), allocatable :: prefix
    prefix = "kinetostat: warning: "//table%deck//": "
    count = table%warning_count()
    if (.not. quiet) then
      do i = 1, table%warning_count()
        write (error_unit, '(a)') prefix//table%warnings(i)%text
      end do
    end if
    if (.not. table%has_selfcheck .or. table%row_count() == 0) return
    if (selfcheck_verdict(table%max_residual) /= "OK" .or. selfcheck_verdict(table%max_mismatch) /= "OK") then
      count = count + 1
      if (quiet) return
      write (error_unit, selfcheck_warning_fmt) prefix// &
        "self-check failed (a bug; please report): max equilibrium residual", table%max_residual, &
        ", max "//table%driver//" mismatch", table%max_mismatch
    end if
  end subroutine warn

  subroutine parse_args(args, error)
    type(cli_args_t), intent(out) :: args
    type(error_t), allocatable, intent(out) :: error
    integer :: i, n, eq, ios
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
        if (any(name == [character(len=8) :: "-o", "--output", "--format", "--lang", "--set", "--pairs", "--at"])) then
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
      case ("--strict")
        args%strict = .true.
      case ("--kinematics")
        args%options%kinematics = .true.
      case ("-o", "--output")
        args%out_file = value
      case ("--format")
        args%options%format = format_from_name(value)
        if (args%options%format == 0) then
          call fatal_error(error, exit_usage, "--format must be one of "//format_names//" (got '"//value//"')")
          return
        end if
      case ("--pairs")
        args%options%pairs = value
      case ("--at")
        read (value, *, iostat=ios) args%options%at_step
        if (ios /= 0 .or. args%options%at_step < 1 .or. verify(value, "0123456789 ") /= 0) then
          call fatal_error(error, exit_usage, "--at needs a step number 1, 2, ... (got '"//value//"')")
          return
        end if
      case ("--lang")
        args%options%lang = lang_from_name(value)
        if (args%options%lang == 0) then
          call fatal_error(error, exit_usage, "--lang must be en or ru (got '"//value//"')")
          return
        end if
      case ("--set")
        call add_override(args%options%overrides, value, error)
        if (allocated(error)) return
      case ("diff")
        if (i == 1) then
          call parse_diff_args(args, error)
          return
        end if
        call fatal_error(error, exit_usage, "diff must come first: "//diff_usage)
        return
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
    if (.not. allocated(args%deck)) then
      call fatal_error(error, exit_usage, "no deck given")
    else if (allocated(args%options%pairs) .and. args%options%format /= format_svg) then
      call fatal_error(error, exit_usage, "--pairs needs --format svg")
    else if (args%options%at_step > 0 .and. args%options%format /= format_svg) then
      call fatal_error(error, exit_usage, "--at needs --format svg")
    end if
  end subroutine parse_args

  !> The arguments of `kinetostat diff A B [--rtol R] [--atol A] [--quiet]` (errors: exit 2).
  subroutine parse_diff_args(args, error)
    type(cli_args_t), intent(inout) :: args
    type(error_t), allocatable, intent(out) :: error
    integer :: i, n, eq, ios
    character(len=:), allocatable :: arg, name, value
    character(len=4096) :: files(2)
    integer :: n_files
    real(wp) :: x
    n = command_argument_count()
    n_files = 0
    i = 1
    do while (i < n)
      i = i + 1
      arg = argument(i)
      eq = index(arg, "=")
      if (len(arg) > 2 .and. arg(1:min(2, len(arg))) == "--" .and. eq > 0) then
        name = arg(1:eq - 1)
        value = arg(eq + 1:)
      else
        name = arg
        value = ""
        if (name == "--rtol" .or. name == "--atol") then
          if (i == n) then
            call fatal_error(error, exit_input, "diff: "//name//" needs a value; "//diff_usage)
            return
          end if
          i = i + 1
          value = argument(i)
        end if
      end if
      select case (name)
      case ("-h", "--help")
        args%help = .true.
      case ("-q", "--quiet")
        args%quiet = .true.
      case ("--rtol", "--atol")
        read (value, *, iostat=ios) x
        if (ios /= 0 .or. .not. (x >= 0.0_wp .and. x < huge(x))) then
          call fatal_error(error, exit_input, "diff: "//name//" must be a number >= 0 (got '"//value//"')")
          return
        end if
        if (name == "--rtol") then
          args%diff_options%rtol = x
        else
          args%diff_options%atol = x
        end if
      case default
        if (len(arg) > 1 .and. arg(1:1) == "-") then
          call fatal_error(error, exit_input, "diff: unknown option '"//arg//"'; "//diff_usage)
          return
        end if
        n_files = n_files + 1
        if (n_files > 2) then
          call fatal_error(error, exit_input, "diff: more than two files given ('"//arg//"'); "//diff_usage)
          return
        end if
        if (len(arg) > len(files(1))) then
          call fatal_error(error, exit_input, "diff: file name too long")
          return
        end if
        files(n_files) = arg
      end select
    end do
    if (args%help) return
    if (n_files /= 2) then
      call fatal_error(error, exit_input, "diff: needs two files; "//diff_usage)
      return
    end if
    args%diff_files = [character(len=max(len_trim(files(1)), len_trim(files(2)))) :: files(1), files(2)]
  end subroutine parse_diff_args

  !> `kinetostat diff A B`: the report on stdout; exit 0 same, 1 different, 2 trouble.
  subroutine run_diff(args, exit_code)
    type(cli_args_t), intent(in) :: args
    integer, intent(out) :: exit_code
    type(deck_source_t) :: a, b
    type(column_t), allocatable :: catalog(:)
    type(text_buffer_t) :: report
    type(error_t), allocatable :: error
    integer :: status
    call read_output_file(trim(args%diff_files(1)), a, error)
    if (.not. allocated(error)) call read_output_file(trim(args%diff_files(2)), b, error)
    if (.not. allocated(error)) then
      call known_columns(catalog)
      call diff_outputs(a%path, a%lines, b%path, b%lines, catalog, args%diff_options, report, status, error)
    end if
    if (.not. allocated(error) .and. .not. args%quiet) call write_output_stdout(report, error)
    if (allocated(error)) then
      write (error_unit, '(a)') "kinetostat: error: "//error%message
      exit_code = exit_input
    else
      exit_code = status
    end if
    flush (error_unit)
  end subroutine run_diff

  !> A file to compare, read into memory as lines.
  subroutine read_output_file(path, source, error)
    character(*), intent(in) :: path
    type(deck_source_t), intent(out) :: source
    type(error_t), allocatable, intent(out) :: error
    logical :: exists
    inquire (file=path, exist=exists)
    if (.not. exists) then
      call fatal_error(error, exit_input, path//": no such file")
      return
    end if
    call load_deck(path, source, error)
    if (allocated(error)) error%message = path//": cannot read the file"
  end subroutine read_output_file

  function argument(i) result(arg)
    integer, intent(in) :: i
    character(len=:), allocatable :: arg
    integer :: length
    call get_command_argument(i, length=length)
    allocate (character(len=length) :: arg)
    if (length > 0) call get_command_argument(i, arg)
  end function argument

end module kinetostat_cli
