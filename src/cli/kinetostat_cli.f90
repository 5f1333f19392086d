!> Command line: argument parsing, the run of one deck through the pipeline, checked output
!> (stdout or an atomically replaced file), and the only place where an error becomes a
!> `kinetostat: error: ...` line on stderr and an exit code.
module kinetostat_cli
  use, intrinsic :: iso_fortran_env, only: error_unit, int64
  use kinetostat_kinds, only: wp, version_string
  use kinetostat_error, only: error_t, fatal_error, exit_success, exit_usage, exit_input, exit_warning
  use kinetostat_deck_repeats, only: deck_repeats
  use kinetostat_deck, only: deck_source_t, load_deck, read_group_name, set_max_deck_size, deck_source_from_text
  use kinetostat_override, only: first_override_line, override_t, parse_override, apply_overrides
  use kinetostat_sweep, only: vary_t, parse_vary, run_sweep, variant_result_t, allow_selfcheck_failure_in_sweep, &
    sweep_header, sweep_npy
  use kinetostat_summary, only: override_fields
  use kinetostat_escape, only: csv_field
  use kinetostat_posix, only: stderr_is_terminal, cpu_count, guard_signals, output_is_terminal
  use kinetostat_text, only: int_str, printable, joined
  use kinetostat_run, only: format_summary, format_npy
  use kinetostat_step_table, only: step_table_t, student_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_output, only: write_output_file, write_output_stdout
  use kinetostat_spool, only: spool_t
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_labels, only: lang_from_name, lang_en, unit_symbol
  use kinetostat_run, only: run_options_t, run_mechanism, format_from_name, format_names, format_svg, format_json, &
    format_plans, format_dxf
  use kinetostat_registry, only: create_mechanism, deck_mechanism, known_kinds, known_columns
  use kinetostat_step_table, only: column_t
  use kinetostat_diff, only: diff_options_t, diff_outputs
  use kinetostat_linkage_layout, only: linkage_structure_text
  use kinetostat_convert, only: convert_deck
  use kinetostat_gear_geometry_layout, only: gear_contour_text
  use kinetostat_assur_presets, only: assur_preset, preset_names
  use kinetostat_assur_layout, only: assur_mechanism_t
  use kinetostat_linkage_layout, only: linkage_mechanism_t
  use kinetostat_linkage_balance, only: linkage_balance
  use kinetostat_assur_balance, only: assur_balance, balance_method_names, balance_full, balance_words
  use kinetostat_deck, only: deck_line_count, deck_line
  use kinetostat_step_table, only: column_tally_t
  use kinetostat_kinds, only: wp
  use kinetostat_format, only: short_number
  use kinetostat_cli_options, only: synopsis_lines, usage_text, value_options, find_option, find_command, &
    command_takes, frame_names
  use kinetostat_sheets, only: write_course_sheets, parse_sheet_numbers
  !$ use omp_lib, only: omp_set_num_threads
  implicit none
  private
  public :: run_cli

  !> Help text after the synopsis (cli_options writes that; the kinds, presets and formats
  !> are appended from the registry and the pipeline).
  character(*), parameter :: help_lines(*) = [character(len=92) :: &
    "template KIND  a commented deck to start from (KIND: a mechanism, or a preset of the", &
    "            generic engine)", &
    "diff A B    compare two outputs (below)", &
    "balance DECK  a linkage deck with counterweights added (docs/shaking.md); before/after", &
    "            figures on stderr; --method (default full), --fraction: partial, default 0.5;", &
    "            --lang ru: the report in Russian", &
    "structure DECK  structural analysis of a linkage deck (&linkage, &assur, &pr3207, &pr3050,", &
    "            &sixbar)", &
    "convert DECK --to linkage  the deck translated into a &linkage deck (its comments kept", &
    "            where they map); stdout or -o FILE (docs/linkage.md)", &
    "contour DECK  the blocking contour of a &gear_geometry deck's pair as CSV: curve,x1,x2", &
    "sheets DECK -o DIR  the course's sheets (kinetostatics; dynamics with a steady cycle) as", &
    "            SVG, DXF and PDF (rsvg-convert) in DIR (docs/course.md)", &
    "", &
    "DECK is a Fortran namelist file; its first group names the mechanism; - reads it", &
    "from standard input (so does a pipe given as a path, e.g. /dev/stdin).", &
    "--set NAME=VALUE  set a deck variable as if the deck ended with NAME = VALUE", &
    "            (repeatable; l_ab=0.12, f5c(3)=0, 'dyad(2)%l2=0.45'); marked (--set)", &
    "-o FILE, --output FILE  write to FILE (atomically: nothing is left behind on error)", &
    "--format    table (default, the legacy printout), csv (full precision), json, svg", &
    "            (a sheet of force hodographs and diagrams; a design's own sheet: the gear", &
    "            pair's meshing, the train's scheme, the cam; see docs/pictures.md), dxf (the", &
    "            same sheet for CAD programs), summary (a CSV header and one row: max, min,", &
    "            where, mean per column, work; a design's values themselves), deck (a", &
    "            design's analysis deck: &gears, &cam), or npy (the CSV's columns as a NumPy", &
    "            .npy file: -o FILE, never to a terminal)", &
    "--pairs     with svg or dxf: only these pair forces, e.g. --pairs F16,F36", &
    "--at K      with svg: the mechanism drawn at step K with every force of the step (a", &
    "            cam's sheet: its follower at row K)", &
    "--at K      with plans: the graphical method's sheet of step K (plans of velocities and", &
    "            accelerations, force polygons, Zhukovsky's lever)", &
    "--student NAME --group G --variant N   the header line of the 1991 programs (date, time,", &
    "            surname, group, variant) on the legacy table and a title block on the sheets", &
    "--at K      with dxf: the mechanism at step K (the svg sheet) as an ASCII DXF for CAD", &
    "--plans     with json and --at K: the graphical method at step K (plans of velocities and", &
    "            accelerations, force polygons, Zhukovsky's lever) as numbers; with dxf", &
    "            and --at K: its sheet (--format plans) as a DXF drawing", &
    "--lang      language of the table's labels: en (default) or ru (the 1991 printouts)", &
    "--kinematics  csv and json add positions of joints and centres of mass, link angles,", &
    "            angular speeds and accelerations, accelerations of the centres of mass and", &
    "            the x, y components of the pair forces (the table is unchanged)", &
    "--shaking   linkages: add the shaking force F_shake (magnitude, x, y) and moment M_shake", &
    "            and the total force and moment on the frame F_frame_x, F_frame_y, M_frame", &
    "            (docs/shaking.md)", &
    "--frame     global (default) or link: &assur decks also report every pair force as", &
    "            <F>_along, <F>_across in the axes of the link it acts on (the table prints", &
    "            them instead of magnitudes and angles)", &
    "-q, --quiet no warnings on stderr (errors are still reported); diff: no report", &
    "sweep       one summary row per variant of the grid of every --vary (COUNT values", &
    "            from FROM to TO), the first --vary slowest; --part K/N runs block K of N", &
    "            (the parts' outputs concatenated in order are the whole sweep's); --jobs N", &
    "            runs its variants in N processes (default: one per processor), same bytes;", &
    "            --keep-going writes every variant, a failed one with its message in the", &
    "            last column error, and exits 2 when any failed", &
    "--max-deck-size BYTES  the largest deck read (default 268435456, 256 MiB); a longer", &
    "            file, or endless input such as /dev/zero, is an input error", &
    "--allow-selfcheck-failure  a self-check above its limit is a warning and the output is", &
    "            written (by default it is an error, exit 3, and nothing is written)", &
    "--strict    a run that warns (a self-check failure allowed, a dead position between", &
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
    "  CSV columns are matched by name in any order; a column on one side only is listed and", &
    "  is a difference (exit 1); --common compares the shared columns only.", &
    "", &
    "Exit codes: 0 ok, 1 usage, 2 input or output error, 3 geometry error, a result that", &
    "is not finite or a failed self-check (the step is named), 4 warnings with --strict", &
    "(output written)."]

  !> Parsed command line.
  type :: cli_args_t
    character(len=:), allocatable :: deck
    character(len=:), allocatable :: out_file
    character(len=:), allocatable :: template_kind
    type(run_options_t) :: options
    logical :: quiet = .false.
    !> --strict: a run that warned exits with exit_warning (its output is still written).
    logical :: strict = .false.
    !> sweep --keep-going: a failing variant gets a row with its error instead of failing the
    !> sweep.
    logical :: keep_going = .false.
    !> The sweep subcommand was given.
    logical :: sweep = .false.
    !> The structure subcommand was given (`kinetostat structure DECK`).
    logical :: structure = .false.
    !> The contour subcommand was given (`kinetostat contour DECK`).
    logical :: contour = .false.
    !> The convert subcommand was given (`kinetostat convert DECK --to linkage`).
    logical :: convert = .false.
    !> Its target model (--to).
    character(len=:), allocatable :: convert_to
    !> The --vary axes of a sweep.
    type(vary_t), allocatable :: varies(:)
    !> --part K/N of a sweep: this process runs block K of N.
    integer :: part = 1
    !> N of --part K/N.
    integer :: parts = 1
    !> --jobs N of a sweep: processes to run its variants in (0: one per processor).
    integer :: jobs = 0
    !> Whether --format was given.
    logical :: format_given = .false.
    logical :: help = .false.
    logical :: version = .false.
    !> `kinetostat diff A B`: the two files.
    character(len=:), allocatable :: diff_files(:)
    !> Tolerances of `diff`.
    type(diff_options_t) :: diff_options
    !> The balance subcommand was given.
    logical :: balance = .false.
    !> balance --method (balance_full, ...).
    integer :: balance_method = balance_full
    !> balance --fraction (partial method), 0..1.
    real(wp) :: fraction = 0.5_wp
    !> Whether --fraction was given.
    logical :: fraction_given = .false.
    !> The sheets subcommand was given (`kinetostat sheets DECK -o DIR`).
    logical :: sheets = .false.
    !> sheets --sheet-numbers (empty: 1..N of N).
    integer, allocatable :: sheet_numbers(:)
    !> Options only the sheets subcommand takes were given.
    logical :: sheet_options = .false.
  end type cli_args_t


  !> The progress line of a single run: whether to show it (stderr a terminal, no --quiet).
  logical :: progress_wanted = .false.
  !> The deck it names.
  character(len=:), allocatable :: progress_deck
  !> When the run started, clock ticks.
  integer(int64) :: progress_start = 0
  !> Clock ticks per second.
  integer(int64) :: progress_rate = 0
  !> Clock ticks before the line shows.
  integer(int64) :: progress_delay = 0

contains

  !> Run the program for the current command line; returns the exit code.
  subroutine run_cli(exit_code)
    !> Exit code of the spec.
    integer, intent(out) :: exit_code
    type(cli_args_t) :: args
    type(error_t), allocatable :: error
    type(step_table_t) :: table
    type(text_buffer_t) :: out
    type(spool_t) :: spool
    integer :: warnings, failed_variants
    logical :: ran, committed

    ran = .false.
    committed = .false.
    warnings = 0
    failed_variants = 0
    call guard_signals()
    call serial_unless_asked()
    call parse_args(args, error)
    if (.not. allocated(error) .and. allocated(args%diff_files) .and. .not. args%help) then
      call run_diff(args, exit_code)
      return
    end if
    if (.not. allocated(error)) then
      if (args%help) then
        call out%put("kinetostat - kinetostatic force analysis of planar mechanisms")
        call out%put("")
        call out%put_lines(synopsis_lines(len(help_lines)))
        call out%put("")
        call out%put_lines(help_lines)
        call out%put("Kinds: "//known_kinds())
        call out%put("Presets (template): "//preset_names)
        call out%put("Formats: "//format_names)
      else if (args%version) then
        call out%put(version_string)
      else if (allocated(args%template_kind)) then
        call write_template(args%template_kind, out, error)
      else if (args%sweep) then
        call sweep_deck(args, out, warnings, failed_variants, error)
      else if (args%structure) then
        call structure_of_deck(args, out, error)
      else if (args%contour) then
        call contour_of_deck(args, out, error)
      else if (args%convert) then
        call convert_of_deck(args, out, error)
      else if (args%balance) then
        call balance_deck(args, out, error)
      else if (args%sheets) then
        call write_course_sheets(args%deck, args%options, args%out_file, args%sheet_numbers, error)
        committed = .true.
      else
        progress_wanted = stderr_is_terminal() .and. .not. args%quiet
        progress_deck = args%deck
        call system_clock(progress_start, progress_rate)
        progress_delay = progress_delay_seconds() * progress_rate
        if (allocated(args%out_file)) call spool%aim(args%out_file)
        args%options%rows_unread = .true.
        call run_deck(args%deck, args%options, table, out, error, spool)
        call progress_line("")
        ran = .not. allocated(error)
        if (ran) call spool%commit(out, error)
        committed = .true.
      end if
    end if
    if (.not. allocated(error) .and. .not. committed) then
      if (allocated(args%out_file)) then
        call write_output_file(args%out_file, out, error)
      else
        call write_output_stdout(out, error)
      end if
    end if
    if (ran .and. .not. allocated(error)) call warn(table, args%quiet, warnings)

    if (allocated(error)) then
      write (error_unit, '(a)') "kinetostat: error: "//printable(error%message)
      if (error%code == exit_usage) write (error_unit, '(a)') usage_text()
      exit_code = error%code
    else if (failed_variants > 0) then
      exit_code = exit_input
    else if (args%strict .and. warnings > 0) then
      exit_code = exit_warning
    else
      exit_code = exit_success
    end if
    flush (error_unit)
  end subroutine run_cli

  !> Steps run in parallel only when OMP_NUM_THREADS asks for it ("when
  !> OMP_NUM_THREADS > 1"); unset, a run uses one thread (OpenMP's own default would take
  !> every processor, doubling the CPU time of a run for little gain in its wall time).
  subroutine serial_unless_asked()
    integer :: length, status
    call get_environment_variable("OMP_NUM_THREADS", length=length, status=status)
    !$ if (status /= 0 .or. length == 0) call omp_set_num_threads(1)
  end subroutine serial_unless_asked

  !> Read the deck's first group, create that mechanism, run it into `out` and `spool`.
  subroutine run_deck(path, options, table, out, error, spool)
    character(*), intent(in) :: path
    type(run_options_t), intent(in) :: options
    type(step_table_t), intent(out) :: table
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    !> Where the output goes beyond the memory bound.
    type(spool_t), intent(inout) :: spool
    character(len=:), allocatable :: group
    class(mechanism_t), allocatable :: mech
    type(deck_source_t) :: source
    type(deck_source_t) :: patched
    !> Warnings for variables given more than once.
    character(len=512), allocatable :: repeats(:)
    allocate (repeats(0))
    call load_deck(path, source, error)
    if (allocated(error)) return
    call deck_mechanism(source, group, mech, error)
    if (allocated(error)) return
    ! variables the deck as written assigns twice (--set replaces a value on purpose); found
    ! before the run, which may release the deck's text
    repeats = deck_repeats(source)
    if (.not. allocated(options%overrides)) then
      call run_mechanism(mech, group, source, options, table, out, error, spool, show_progress)
      if (.not. allocated(error)) call add_warnings(repeats, table)
      return
    end if
    call apply_overrides(source, options%overrides, patched, error)
    if (allocated(error)) return
    call run_mechanism(mech, group, patched, options, table, out, error, spool, show_progress)
    if (allocated(error)) then
      if (error%code == exit_input) call blame_override(source, group, options%overrides, error)
    else
      call add_warnings(repeats, table)
    end if
  end subroutine run_deck

  !> The remarks into the run's warnings.
  pure subroutine add_warnings(remarks, table)
    !> One warning a line (blank-padded).
    character(*), intent(in) :: remarks(:)
    !> The run's results (the warnings are added).
    type(step_table_t), intent(inout) :: table
    integer :: i
    do i = 1, size(remarks)
      call table%add_warning(trim(remarks(i)))
    end do
  end subroutine add_warnings

  !> The limit of --max-deck-size BYTES (a whole number from 1 to huge(1), the largest deck
  !> a build with default integers can hold): set for every deck read.
  subroutine parse_deck_size(arg, error)
    !> The option's value.
    character(*), intent(in) :: arg
    type(error_t), allocatable, intent(out) :: error
    integer(int64) :: bytes
    integer :: ios
    ios = 1
    if (len(arg) > 0 .and. len(arg) < 19 .and. verify(arg, "0123456789") == 0) read (arg, *, iostat=ios) bytes
    if (ios == 0) then
      if (bytes < 1 .or. bytes > huge(1)) ios = 1
    end if
    if (ios /= 0) then
      call fatal_error(error, exit_usage, "--max-deck-size must be a whole number of bytes from 1 to "// &
        int_str(huge(1))//" (got '"//printable(arg)//"')")
      return
    end if
    call set_max_deck_size(bytes)
  end subroutine parse_deck_size

  !> K and N of "--part K/N" (1 <= K <= N).
  subroutine parse_part(arg, part, parts, error)
    character(*), intent(in) :: arg
    integer, intent(out) :: part, parts
    type(error_t), allocatable, intent(out) :: error
    integer :: slash, ios
    part = 1
    parts = 1
    slash = index(arg, "/")
    ios = 1
    if (slash > 1 .and. verify(arg(1:slash - 1), "0123456789") == 0 .and. verify(arg(slash + 1:), "0123456789") == 0 &
        .and. len(arg) > slash .and. len(arg) < 16) then
      read (arg(1:slash - 1), *, iostat=ios) part
      if (ios == 0) read (arg(slash + 1:), *, iostat=ios) parts
    end if
    if (ios /= 0 .or. part < 1 .or. part > parts) then
      call fatal_error(error, exit_usage, "--part must be K/N with 1 <= K <= N (got '"//arg//"')")
      part = 1
      parts = 1
    end if
  end subroutine parse_part

  !> After a block of a run: from one second after the start on, the progress line
  !> "kinetostat: DECK: step K of N" (stderr a terminal and no --quiet only).
  subroutine show_progress(done, total)
    !> Rows done.
    integer, intent(in) :: done
    !> Rows of the run.
    integer, intent(in) :: total
    integer(int64) :: now
    if (.not. progress_wanted .or. progress_rate <= 0) return
    call system_clock(now)
    if (now - progress_start < progress_delay) return
    call progress_line("kinetostat: "//progress_deck//": step "//int_str(done)//" of "//int_str(total))
  end subroutine show_progress

  !> Seconds a run goes before it shows the progress line: 1, or KINETOSTAT_PROGRESS_DELAY
  !> (a whole number >= 0; the tests use 0).
  integer function progress_delay_seconds() result(seconds)
    character(len=16) :: text
    integer :: length, status, ios
    seconds = 1
    call get_environment_variable("KINETOSTAT_PROGRESS_DELAY", text, length, status)
    if (status /= 0 .or. length == 0) return
    read (text, *, iostat=ios) length
    if (ios == 0 .and. length >= 0) seconds = length
  end function progress_delay_seconds

  !> The progress line on stderr (a terminal): `text` written over the previous one from
  !> the start of the line; "" erases it (nothing when none was written).
  subroutine progress_line(text)
    character(*), intent(in) :: text
    !> Characters erased by "" (the longest line written so far).
    integer, save :: written = 0
    if (len(text) == 0) then
      if (written == 0) return
      write (error_unit, '(a)', advance='no') achar(13)//repeat(" ", written)//achar(13)
      written = 0
    else
      write (error_unit, '(a)', advance='no') achar(13)//text
      written = max(written, len(text))
    end if
    flush (error_unit)
  end subroutine progress_line

  !> Append a --vary axis.
  subroutine add_vary(varies, arg, error)
    type(vary_t), allocatable, intent(inout) :: varies(:)
    character(*), intent(in) :: arg
    type(error_t), allocatable, intent(out) :: error
    type(vary_t) :: one
    call parse_vary(arg, one, error)
    if (allocated(error)) return
    if (.not. allocated(varies)) allocate (varies(0))
    varies = [varies, one]
  end subroutine add_vary

  !> `kinetostat balance`: the &assur deck with counterweights added into `out`; the report
  !> (the counterweights, max |F_shake|, max |M_shake| and max |M1| before and after, the
  !> balanced deck's self-check) on stderr unless --quiet.
  subroutine balance_deck(args, out, error)
    type(cli_args_t), intent(in) :: args
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    type(deck_source_t) :: source, balanced
    type(assur_mechanism_t) :: mech
    type(linkage_mechanism_t) :: linkage
    type(override_t), allocatable :: overrides(:)
    type(text_buffer_t) :: report
    type(step_table_t) :: before, after
    character(len=:), allocatable :: group, shown
    !> A &pr3207, &pr3050 or &sixbar deck's &linkage translation.
    type(text_buffer_t) :: translation
    integer :: i
    call load_deck(args%deck, source, error)
    if (allocated(error)) return
    call read_group_name(source, group, error)
    if (allocated(error)) return
    shown = "&"//group
    if (group == "pr3207" .or. group == "pr3050" .or. group == "sixbar") then
      ! balanced as its &linkage translation, which the balanced deck is
      call convert_deck(source, translation, error)
      if (allocated(error)) return
      shown = source%path ! (not source%path itself: source is the result)
      call deck_source_from_text(shown, translation%data(1:translation%length), source, error=error)
      if (allocated(error)) return
      shown = "&"//group//" (its &linkage translation)"
      group = "linkage"
    end if
    if (group /= "assur" .and. group /= "linkage") then
      call fatal_error(error, exit_input, source%path//": &"//group//": balance works on the linkage decks "// &
        "(&assur and &linkage; &pr3207, &pr3050 and &sixbar through their &linkage translation): not a linkage "// &
        "of lower pairs")
      return
    end if
    if (group == "linkage") then
      call linkage%read_deck(source, error)
      if (allocated(error)) return
      call linkage_balance(linkage%deck, args%balance_method, args%fraction, args%options%lang, overrides, report, &
                           error)
    else
      call mech%read_deck(source, error)
      if (allocated(error)) return
      if (mech%deck%mech%drive_dyad > 0 .and. args%balance_method /= balance_full) then
        call fatal_error(error, exit_usage, source%path//": &assur: balance --method "// &
          trim(balance_method_names(args%balance_method))//" needs a crank that turns the mechanism; this deck is "// &
          "driven by an actuator (drive_dyad)")
        return
      end if
      call assur_balance(mech%deck, args%balance_method, args%fraction, args%options%lang, overrides, report, error)
    end if
    if (allocated(error)) then
      error%message = source%path//": "//shown//": "//error%message
      return
    end if
    call apply_overrides(source, overrides, balanced, error)
    if (allocated(error)) return
    do i = 1, deck_line_count(balanced)
      call out%put(deck_line(balanced, i))
    end do
    ! (each run releases its deck's text)
    call summary_run(source, before, error)
    if (allocated(error)) return
    call summary_run(balanced, after, error)
    if (allocated(error)) then
      error%message = "the balanced deck: "//error%message
      return
    end if
    if (args%quiet) return
    call say(report%data(1:report%length))
    call compare(words("max |F_shake|", "наибольший |F_shake| (главный вектор сил "// &
      "инерции)"), "F_shake", "N")
    call compare(words("max |M_shake|", "наибольший |M_shake| (главный момент сил "// &
      "инерции)"), "M_shake", "N*m")
    call compare(words("max |M1|     ", "наибольший |M1| (уравновешивающий момент)"), "M1", "N*m")
    call say(words("balanced deck's self-check: max residual ", "самоконтроль уравновешенного "// &
      "механизма: "// &
      "наибольшая невязка равновесия ")//short_number(after%run_tally%residual%value)//", "// &
      words("M1 against the power balance ", "M1 по сравнению с балансом "// &
        "мощностей ")//short_number(after%run_tally%mismatch%value))
  contains
    !> The deck run with the shaking columns into a summary (its tallies).
    subroutine summary_run(deck_source, table, error)
      type(deck_source_t), intent(inout) :: deck_source
      type(step_table_t), intent(out) :: table
      type(error_t), allocatable, intent(out) :: error
      class(mechanism_t), allocatable :: run_mech
      type(run_options_t) :: options
      type(text_buffer_t) :: text
      call create_mechanism(group, run_mech)
      options%format = format_summary
      options%shaking = .true.
      call run_mechanism(run_mech, group, deck_source, options, table, text, error)
    end subroutine summary_run

    !> The largest magnitude of column `name` before and after.
    subroutine compare(label, name, unit)
      character(*), intent(in) :: label, name, unit
      real(wp) :: a, b
      integer :: ca, cb
      character(len=:), allocatable :: u
      ca = before%column_index(name)
      cb = after%column_index(name)
      if (ca == 0 .or. cb == 0) return
      a = largest(before%run_tally%columns(ca))
      b = largest(after%run_tally%columns(cb))
      u = unit_symbol(unit, args%options%lang)
      if (a > 0.0_wp) then
        call say(label//words(": before ", ": до уравновешивания ")//short_number(a)//" "//u// &
          words(", after ", ", после ")//short_number(b)//" "//u//" ("//short_number(b / a)// &
          words(" of before)", " от прежнего)"))
      else
        call say(label//words(": before 0 ", ": до уравновешивания 0 ")//u// &
          words(", after ", ", после ")//short_number(b)//" "//u)
      end if
    end subroutine compare

    !> The report's wording in the language of --lang.
    pure function words(english, russian) result(text)
      character(*), intent(in) :: english, russian
      character(len=:), allocatable :: text
      text = balance_words(english, russian, args%options%lang)
    end function words

    !> Largest magnitude of a tallied column.
    real(wp) function largest(tally)
      type(column_tally_t), intent(in) :: tally
      largest = max(abs(tally%max), abs(tally%min))
    end function largest

    !> Lines of `text` on stderr, each prefixed "kinetostat: balance: ".
    subroutine say(text)
      character(*), intent(in) :: text
      integer :: start, k
      start = 1
      do k = 1, len(text)
        if (text(k:k) /= achar(10)) cycle
        write (error_unit, '(a)') "kinetostat: balance: "//text(start:k - 1)
        start = k + 1
      end do
      if (start <= len(text)) write (error_unit, '(a)') "kinetostat: balance: "//text(start:)
    end subroutine say
  end subroutine balance_deck

  !> `kinetostat sweep`: the summary CSV of every variant (one header, one row each, in
  !> grid order); warnings one line each, prefixed with the variant's overrides. The first
  !> variant (in grid order) that fails fails the sweep, naming the variant; with
  !> --keep-going every variant gets its row, a failed one its override values, empty figures
  !> and its error in the last column `error` (empty on good rows), the error on stderr too,
  !> and `failed` counts them (exit 2 after the output is written).
  subroutine sweep_deck(args, out, warnings, failed, error)
    type(cli_args_t), intent(in) :: args
    type(text_buffer_t), intent(inout) :: out
    !> Number of warnings over all variants.
    integer, intent(out) :: warnings
    !> Number of variants that failed (--keep-going).
    integer, intent(out) :: failed
    type(error_t), allocatable, intent(out) :: error
    type(deck_source_t) :: source
    type(override_t), allocatable :: sets(:)
    type(variant_result_t), allocatable :: results(:), ran(:)
    integer :: v, i, start, first, jobs, fields
    character(len=:), allocatable :: name, prefix, header, message
    warnings = 0
    failed = 0
    jobs = args%jobs
    if (jobs == 0) jobs = cpu_count()
    call load_deck(args%deck, source, error)
    if (allocated(error)) return
    call allow_selfcheck_failure_in_sweep(args%options%allow_selfcheck_failure)
    if (allocated(args%options%overrides)) then
      sets = args%options%overrides
    else
      allocate (sets(0))
    end if
    call run_sweep(source, sets, args%varies, args%part, args%parts, jobs, &
      stderr_is_terminal() .and. .not. args%quiet, first, results, error, args%options%shaking)
    if (allocated(error)) return
    if (size(results) == 0) return
    call sweep_header(source, sets, args%varies, first, results, args%options%shaking, header)
    if (len(header) == 0) header = override_fields(override_texts(results(1)), 1)
    ! a header of override names only (no variant ran): no comma after the last
    if (len(header) > 0) then
      if (header(len(header):len(header)) == ",") header = header(:len(header) - 1)
    end if
    fields = csv_field_count(header)
    do v = 1, size(results)
      name = variant_name(results(v))
      if (.not. allocated(results(v)%error)) then
        if (results(v)%header /= header) call fatal_error(results(v)%error, exit_input, source%path// &
          ": its summary has other columns than the sweep's header (the first variant of the grid that runs)")
      end if
      if (.not. allocated(results(v)%error)) cycle
      message = results(v)%error%message//" (sweep variant "//int_str(first + v - 1)//": "//name//")"
      if (.not. args%keep_going) then
        call move_alloc(results(v)%error, error)
        error%message = message
        return
      end if
      failed = failed + 1
      write (error_unit, '(a)') "kinetostat: error: "//printable(message)
      results(v)%row = override_fields(override_texts(results(v)), 2)
      results(v)%row = results(v)%row//repeat(",", max(0, fields - csv_field_count(results(v)%row) + 1))
      results(v)%row = results(v)%row//csv_field(results(v)%error%message)
      results(v)%warning_count = 0
    end do
    if (args%options%format == format_npy) then
      ! every part is an npy file of its own rows (numpy.concatenate joins them); with
      ! --keep-going a failed variant is left out (named on stderr, exit 2)
      ran = pack(results, [(.not. allocated(results(v)%error), v = 1, size(results))])
      if (size(ran) > 0) call sweep_npy(ran, out, error)
      if (allocated(error)) return
    else if (args%part == 1) then
      if (args%keep_going) then
        call out%put(header//",error")
      else
        call out%put(header)
      end if
    end if
    do v = 1, size(results)
      if (args%options%format == format_npy) then
        continue
      else if (args%keep_going .and. .not. allocated(results(v)%error)) then
        call out%put(results(v)%row//",")
      else
        call out%put(results(v)%row)
      end if
      warnings = warnings + results(v)%warning_count
      if (args%quiet .or. results(v)%warnings%length == 0 .or. allocated(results(v)%error)) cycle
      prefix = "kinetostat: warning: "//source%path//" ("//variant_name(results(v))//"): "
      start = 1
      do i = 1, results(v)%warnings%length
        if (results(v)%warnings%data(i:i) /= achar(10)) cycle
        write (error_unit, '(a)') printable(prefix//results(v)%warnings%data(start:i - 1))
        start = i + 1
      end do
    end do
  contains
    function variant_name(r) result(text)
      type(variant_result_t), intent(in) :: r
      character(len=:), allocatable :: text
      text = joined(override_texts(r), ", ")
    end function variant_name

    !> The variant's overrides as "NAME=VALUE" texts (the summary's form).
    function override_texts(r) result(texts)
      type(variant_result_t), intent(in) :: r
      character(len=:), allocatable :: texts(:)
      integer :: k, longest
      longest = 1
      do k = 1, size(r%overrides)
        longest = max(longest, len(r%overrides(k)%name) + 1 + len(r%overrides(k)%value))
      end do
      allocate (character(len=longest) :: texts(size(r%overrides)))
      do k = 1, size(r%overrides)
        texts(k) = r%overrides(k)%name//"="//r%overrides(k)%value
      end do
    end function override_texts

    !> The number of fields of a CSV line (commas outside double quotes, plus one; 0 for "").
    pure integer function csv_field_count(line) result(n)
      character(*), intent(in) :: line
      integer :: k
      logical :: quoted
      n = 0
      if (len(line) == 0) return
      n = 1
      quoted = .false.
      do k = 1, len(line)
        if (line(k:k) == '"') quoted = .not. quoted
        if (line(k:k) == "," .and. .not. quoted) n = n + 1
      end do
    end function csv_field_count
  end subroutine sweep_deck

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

  !> An input error of a run with overrides keeps the full run's own message; it is blamed on
  !> override k ("(from --set NAME=VALUE)", or "--set NAME=VALUE: ..." in place of the deck
  !> line of a value that does not read) only when the deck with that override alone gives
  !> the same error and the deck without overrides does not: a mistake of the deck itself, or
  !> one that only several overrides together make, is reported as it is.
  subroutine blame_override(source, group, overrides, error)
    !> The deck as read (without overrides).
    type(deck_source_t), intent(in) :: source
    !> Its first group.
    character(*), intent(in) :: group
    !> The overrides.
    type(override_t), intent(in) :: overrides(:)
    !> The run's error; its message names the override found to be the cause.
    type(error_t), intent(inout) :: error
    character(len=:), allocatable :: message
    integer :: k, first_line
    first_line = first_override_line(source)
    message = without_line(error%message)
    if (same_error(overrides(1:0))) return
    do k = 1, size(overrides)
      if (size(overrides) > 1) then
        if (.not. same_error(overrides(k:k))) cycle
      end if
      call name_cause()
      return
    end do
  contains
    !> Whether the deck with `some` overrides fails its reading with the run's message.
    logical function same_error(some)
      type(override_t), intent(in) :: some(:)
      type(deck_source_t) :: patched
      class(mechanism_t), allocatable :: mech
      type(error_t), allocatable :: current
      call apply_overrides(source, some, patched)
      call create_mechanism(group, mech)
      call mech%read_deck(patched, current)
      same_error = .false.
      if (allocated(current)) same_error = without_line(current%message) == message
    end function same_error

    !> The line number of a message ("deck.nml:21: ..." -> 21), 0 when it names none.
    pure integer function line_of(text) result(line)
      character(*), intent(in) :: text
      integer :: d, ios
      line = 0
      if (index(text, source%path//":") /= 1) return
      d = len(source%path) + 2
      if (d > len(text)) return
      d = d - 1 + verify(text(d:), "0123456789")
      if (d <= len(source%path) + 2 .or. text(d:d) /= ":") return
      read (text(len(source%path) + 2:d - 1), *, iostat=ios) line
      if (ios /= 0) line = 0
    end function line_of

    !> A message without the number of a line from the first override's on ("deck.nml:21:
    !> ..." -> "deck.nml: ..."): those lines move with the number of overrides.
    pure function without_line(text) result(plain)
      character(*), intent(in) :: text
      character(len=:), allocatable :: plain
      integer :: line
      plain = text
      line = line_of(text)
      if (line >= first_line) plain = source%path//text(len(source%path) + 2 + len(int_str(line)):)
    end function without_line

    !> The message with override k as its cause. A message that names the override's own
    !> line ("deck.nml:21: ...", a line the file does not have) names the override instead:
    !> "--set NAME=VALUE: ..." replaces "deck.nml:21".
    subroutine name_cause()
      character(len=:), allocatable :: given
      given = overrides(k)%name//"="//overrides(k)%value
      error%code = exit_input
      if (line_of(error%message) == first_line + k - 1) then
        error%message = "--set "//given//message(len(source%path) + 1:)
      else
        error%message = error%message//" (from --set "//given//")"
      end if
    end subroutine name_cause
  end subroutine blame_override

  !> `kinetostat structure DECK`: the structural analysis of a linkage deck: a `&linkage`
  !> deck's own; for the other linkages (PR 3207, PR 3050, the T.FTN six-bar, `&assur`) from
  !> their model - the mechanism drawn at the first step, its units those of the plans.
  subroutine structure_of_deck(args, out, error)
    type(cli_args_t), intent(in) :: args
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    type(deck_source_t) :: source
    type(run_options_t) :: options
    type(step_table_t) :: table
    !> Unaimed: the few lines stay in `out`.
    type(spool_t) :: spool
    character(len=:), allocatable :: group
    call load_deck(args%deck, source, error)
    if (allocated(error)) return
    call read_group_name(source, group, error)
    if (allocated(error)) return
    select case (group)
    case ("linkage")
      call linkage_structure_text(source, args%options%lang, out, error)
    case ("pr3207", "pr3050", "sixbar", "assur")
      options%lang = args%options%lang
      options%format = format_plans
      options%at_step = 1
      options%structure = .true.
      call run_deck(args%deck, options, table, out, error, spool)
    case default
      call fatal_error(error, exit_input, source%path//": &"//group//": structure: not a linkage of lower pairs "// &
        "(a structural analysis is made of &pr3207, &pr3050, &sixbar, &assur and &linkage decks)")
    end select
  end subroutine structure_of_deck

  !> `kinetostat convert DECK --to linkage`: the deck translated into the `&linkage` model,
  !> written as a deck (all or nothing: the caller writes `out` when no error came).
  subroutine convert_of_deck(args, out, error)
    type(cli_args_t), intent(in) :: args
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    type(deck_source_t) :: source
    call load_deck(args%deck, source, error, whole_lines=.true.)
    if (allocated(error)) return
    call convert_deck(source, out, error)
  end subroutine convert_of_deck

  !> `kinetostat contour DECK`: the blocking contour of a `&gear_geometry` deck's pair (with
  !> the --set overrides) as long-format CSV.
  subroutine contour_of_deck(args, out, error)
    type(cli_args_t), intent(in) :: args
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    type(deck_source_t) :: source, patched
    call load_group_deck(args%deck, "gear_geometry", "contour: only &gear_geometry decks have a blocking "// &
      "contour (a spur pair's z1, z2 and basic rack)", source, error)
    if (allocated(error)) return
    if (.not. allocated(args%options%overrides)) then
      call gear_contour_text(source, out, error)
      return
    end if
    call apply_overrides(source, args%options%overrides, patched)
    call gear_contour_text(patched, out, error)
    if (allocated(error)) then
      if (error%code == exit_input) call blame_override(source, "gear_geometry", args%options%overrides, error)
    end if
  end subroutine contour_of_deck

  !> The deck at `path`, which must be of group `wanted`; otherwise an input error naming the
  !> deck and its group with `why`.
  subroutine load_group_deck(path, wanted, why, source, error)
    !> Deck path.
    character(*), intent(in) :: path
    !> The group the command works on.
    character(*), intent(in) :: wanted
    !> What the command takes, for the message.
    character(*), intent(in) :: why
    !> The deck.
    type(deck_source_t), intent(out) :: source
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: group
    call load_deck(path, source, error)
    if (allocated(error)) return
    call read_group_name(source, group, error)
    if (allocated(error)) return
    if (group /= wanted) call fatal_error(error, exit_input, source%path//": &"//group//": "//why)
  end subroutine load_group_deck

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
  !> remarks, a failed self-check allowed by --allow-selfcheck-failure.
  subroutine warn(table, quiet, count)
    !> The run's results.
    type(step_table_t), intent(in) :: table
    !> --quiet: count the warnings, print none.
    logical, intent(in) :: quiet
    !> Number of warnings.
    integer, intent(out) :: count
    integer :: i
    character(len=:), allocatable :: prefix
    prefix = "kinetostat: warning: "//printable(table%deck)//": "
    count = table%warning_count()
    if (.not. quiet) then
      do i = 1, table%warning_count()
        write (error_unit, '(a)') printable(prefix//table%warnings(i)%text)
      end do
    end if
  end subroutine warn

  subroutine parse_args(args, error)
    type(cli_args_t), intent(out) :: args
    type(error_t), allocatable, intent(out) :: error
    integer :: i, k, n, ios
    character(len=:), allocatable :: arg, name, value
    !> The options given (indices of cli_options()), and by which name.
    integer, allocatable :: given(:)
    character(len=26), allocatable :: given_as(:)

    n = command_argument_count()
    if (n == 0) then
      call fatal_error(error, exit_usage, "no deck given")
      return
    end if
    allocate (given(0), given_as(0))
    i = 0
    do while (i < n)
      call next_option(i, n, value_options(), name, value)
      if (.not. allocated(value)) then
        call fatal_error(error, exit_usage, name//" needs a value")
        return
      end if
      k = find_option(name)
      if (k > 0) then
        given = [given, k]
        given_as = [character(len=26) :: given_as, name]
      end if
      if (common_flag(args, name)) cycle
      select case (name)
      case ("-V", "--version")
        args%version = .true.
      case ("--strict")
        args%strict = .true.
      case ("--keep-going")
        args%keep_going = .true.
      case ("--allow-selfcheck-failure")
        args%options%allow_selfcheck_failure = .true.
      case ("--kinematics")
        args%options%kinematics = .true.
      case ("--plans")
        args%options%plans = .true.
      case ("--student", "--group", "--variant")
        ! the fields not given are "-"; the stamp is the run's, set once all options are read
        if (.not. allocated(args%options%student)) args%options%student = student_t("-", "-", "-", "")
        if (name == "--student") args%options%student%name = value
        if (name == "--group") args%options%student%group = value
        if (name == "--variant") args%options%student%variant = value
      case ("--shaking")
        args%options%shaking = .true.
      case ("--method")
        args%balance_method = 0
        do k = 1, size(balance_method_names)
          if (value == trim(balance_method_names(k))) args%balance_method = k
        end do
        if (args%balance_method == 0) then
          call fatal_error(error, exit_usage, "--method must be full, crank or partial (got '"//value//"')")
          return
        end if
      case ("--fraction")
        block
          integer :: ios
          read (value, *, iostat=ios) args%fraction
          if (ios /= 0 .or. verify(trim(value), "0123456789.eE+-") /= 0 .or. len_trim(value) == 0) then
            call fatal_error(error, exit_usage, "--fraction needs a number in [0, 1] (got '"//value//"')")
            return
          end if
          if (.not. (args%fraction >= 0.0_wp .and. args%fraction <= 1.0_wp)) then
            call fatal_error(error, exit_usage, "--fraction must lie in [0, 1] (got '"//value//"')")
            return
          end if
        end block
        args%fraction_given = .true.
      case ("balance", "contour", "sheets", "convert", "structure")
        if (i /= 1) then
          call fatal_error(error, exit_usage, name//" must come first: "//first_word_usage(name))
          return
        end if
        args%balance = args%balance .or. name == "balance"
        args%contour = args%contour .or. name == "contour"
        args%sheets = args%sheets .or. name == "sheets"
        args%convert = args%convert .or. name == "convert"
        args%structure = args%structure .or. name == "structure"
      case ("-o", "--output")
        args%out_file = value
      case ("--format")
        args%format_given = .true.
        args%options%format = format_from_name(value)
        if (args%options%format == 0) then
          call fatal_error(error, exit_usage, "--format must be one of "//format_names//" (got '"//value//"')")
          return
        end if
      case ("--pairs")
        args%options%pairs = value
      case ("--frame")
        if (all(value /= frame_names)) then
          call fatal_error(error, exit_usage, "--frame must be global or link (got '"//value//"')")
          return
        end if
        args%options%link_frame = value == "link"
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
      case ("--vary")
        call add_vary(args%varies, value, error)
        if (allocated(error)) return
      case ("--part")
        call parse_part(value, args%part, args%parts, error)
        if (allocated(error)) return
      case ("--jobs")
        block
          integer :: ios
          read (value, *, iostat=ios) args%jobs
          if (ios /= 0 .or. args%jobs < 1 .or. verify(trim(value), "0123456789") /= 0) then
            call fatal_error(error, exit_usage, "--jobs must be a whole number >= 1 (got '"//value//"')")
            return
          end if
        end block
      case ("--max-deck-size")
        call parse_deck_size(value, error)
        if (allocated(error)) return
      case ("sweep")
        if (allocated(args%deck) .or. args%sweep .or. allocated(args%template_kind)) then
          call fatal_error(error, exit_usage, "sweep must come first: kinetostat sweep DECK --vary NAME=FROM:TO:COUNT")
          return
        end if
        args%sweep = .true.
      case ("--paper")
        args%sheet_options = .true.
        if (all(value /= ["A1", "A2", "A3", "A4"])) then
          call fatal_error(error, exit_usage, "--paper must be A1, A2, A3 or A4 (got '"//value//"')")
          return
        end if
        args%options%paper = value
      case ("--designation")
        args%sheet_options = .true.
        args%options%designation = value
      case ("--sheet-numbers")
        args%sheet_options = .true.
        call parse_sheet_numbers(value, args%sheet_numbers, error)
        if (allocated(error)) return
      case ("--positions")
        args%sheet_options = .true.
        if (value /= "8" .and. value /= "12") then
          call fatal_error(error, exit_input, "--positions must be 8 or 12 (got '"//value//"')")
          return
        end if
        read (value, *) args%options%course_positions
      case ("--point")
        args%sheet_options = .true.
        if (len_trim(value) == 0 .or. len(value) > 16 .or. verify(value, &
            "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_") /= 0) then
          call fatal_error(error, exit_input, "--point needs a point's name as in the deck's columns "// &
            "(B, S2, ...), got '"//value//"'")
          return
        end if
        args%options%course_point = value
      case ("--output-link")
        args%sheet_options = .true.
        if (len(value) == 0 .or. len(value) > 3 .or. verify(value, "0123456789") /= 0) then
          call fatal_error(error, exit_input, "--output-link needs a link's number 1..999 (got '"//value//"')")
          return
        end if
        read (value, *) args%options%course_output_link
        if (args%options%course_output_link < 1) then
          call fatal_error(error, exit_input, "--output-link needs a link's number 1..999 (got '"//value//"')")
          return
        end if
      case ("--to")
        if (value /= "linkage") then
          call fatal_error(error, exit_usage, "--to must be linkage (got '"//value//"')")
          return
        end if
        args%convert_to = value
      case ("diff")
        if (i == 1) then
          call parse_diff_args(args, error)
          return
        end if
        call fatal_error(error, exit_usage, "diff must come first: "//usage_text("diff"))
        return
      case ("template")
        if (allocated(args%deck) .or. i == n) then
          call fatal_error(error, exit_usage, "template needs exactly one KIND (known: "//known_kinds()//")")
          return
        end if
        i = i + 1
        args%template_kind = argument(i)
      case default
        ! an option of another subcommand (--rtol): check_options_belong names it
        if (k > 0) cycle
        arg = argument(i)
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
    if (args%help .or. args%version) return
    if (allocated(args%template_kind)) then
      call check_options_belong("template")
      return
    end if
    if (.not. allocated(args%sheet_numbers)) allocate (args%sheet_numbers(0))
    if (.not. allocated(args%deck)) then
      call fatal_error(error, exit_usage, "no deck given")
    else if (args%sheets .and. .not. allocated(args%out_file)) then
      call fatal_error(error, exit_usage, "sheets needs -o DIR (the directory the sheets go into)")
    else if (args%sheets .and. (args%format_given .or. args%options%kinematics .or. args%options%shaking .or. &
             args%options%plans .or. allocated(args%options%pairs))) then
      call fatal_error(error, exit_usage, "sheets takes a deck, -o DIR, --paper, --lang, --at, --designation, "// &
        "--sheet-numbers, --positions, --point, --output-link, --student, --group, --variant and --set only")
    else if (args%sheet_options .and. .not. args%sheets) then
      call fatal_error(error, exit_usage, "--paper, --designation, --sheet-numbers, --positions, --point and "// &
        "--output-link belong to the sheets "// &
        "subcommand: kinetostat sheets DECK -o DIR ...")
    else if (args%convert .and. .not. allocated(args%convert_to)) then
      call fatal_error(error, exit_usage, "convert needs --to linkage: "//usage_text("convert"))
    else if (.not. args%convert .and. allocated(args%convert_to)) then
      call fatal_error(error, exit_usage, "--to belongs to the convert subcommand: "//usage_text("convert"))
    else if (args%structure .and. (args%format_given .or. allocated(args%options%overrides) .or. &
             args%options%at_step > 0)) then
      call fatal_error(error, exit_usage, "structure takes a deck, --lang and -o only")
    else if (args%contour .and. (args%format_given .or. args%options%at_step > 0 .or. args%options%lang /= lang_en .or. &
             args%options%kinematics .or. args%options%shaking)) then
      call fatal_error(error, exit_usage, "contour takes a deck, --set and -o only")
    else if (args%sweep .and. .not. allocated(args%varies)) then
      call fatal_error(error, exit_usage, "sweep needs at least one --vary NAME=FROM:TO:COUNT")
    else if (.not. args%sweep .and. (allocated(args%varies) .or. args%parts > 1 .or. args%jobs > 0 .or. &
             args%keep_going)) then
      call fatal_error(error, exit_usage, "--vary, --part, --jobs and --keep-going belong to the sweep subcommand: "// &
        "kinetostat sweep DECK --vary ...")
    else if (args%balance .and. (args%format_given .or. args%options%shaking .or. args%options%kinematics .or. &
             allocated(args%options%overrides))) then
      call fatal_error(error, exit_usage, "balance takes a deck, -o FILE, --method, --fraction and --lang only")
    else if (.not. args%balance .and. (args%fraction_given .or. args%balance_method /= balance_full)) then
      call fatal_error(error, exit_usage, "--method and --fraction belong to the balance subcommand: "// &
        "kinetostat balance DECK ...")
    else if (args%balance .and. args%fraction_given .and. args%balance_method /= 3) then
      call fatal_error(error, exit_usage, "--fraction belongs to --method partial")
    else if (args%sweep .and. args%format_given .and. all(args%options%format /= [format_summary, format_npy])) then
      call fatal_error(error, exit_usage, "sweep writes the summary format only (--format summary, or npy)")
    else if (allocated(args%options%pairs) .and. all(args%options%format /= [format_svg, format_dxf])) then
      call fatal_error(error, exit_usage, "--pairs needs --format svg or dxf")
    else if (args%options%plans .and. (all(args%options%format /= [format_json, format_dxf]) .or. &
      args%options%at_step == 0)) then
      call fatal_error(error, exit_usage, "--plans needs --format json or dxf and --at K")
    else if (args%options%format == format_plans .and. args%options%at_step == 0) then
      call fatal_error(error, exit_usage, "--format plans needs --at K (the step whose plans are drawn)")
    else if (args%options%at_step > 0 .and. all(args%options%format /= [format_svg, format_plans, format_dxf]) &
      .and. .not. args%options%plans .and. .not. args%sheets) then
      call fatal_error(error, exit_usage, "--at needs --format svg, plans or dxf (or --format json --plans)")
    else if (args%options%format == format_npy) then
      if (binary_to_terminal(args%out_file)) call fatal_error(error, exit_usage, "--format npy writes binary data, "// &
        "not for a terminal: give -o FILE.npy or redirect standard output")
    end if
    if (allocated(error)) return
    if (args%sweep) then
      call check_options_belong("sweep")
    else if (args%balance) then
      call check_options_belong("balance")
    else if (args%structure) then
      call check_options_belong("structure")
    else if (args%contour) then
      call check_options_belong("contour")
    else if (args%convert) then
      call check_options_belong("convert")
    else if (args%sheets) then
      call check_options_belong("sheets")
    else
      call check_options_belong("")
    end if
    if (allocated(error)) return
    if (allocated(args%options%student)) args%options%student%stamp = run_stamp()
  contains
    !> Every option given must be one of the subcommand's (cli_commands; "" the run of a
    !> deck): otherwise a usage error naming it.
    subroutine check_options_belong(command)
      character(*), intent(in) :: command
      integer :: c, j
      c = find_command(command)
      do j = 1, size(given)
        if (command_takes(c, given(j))) cycle
        if (len(command) == 0) then
          call fatal_error(error, exit_usage, trim(given_as(j))//" does not go with the run of a deck")
        else
          call fatal_error(error, exit_usage, command//" does not take "//trim(given_as(j)))
        end if
        return
      end do
    end subroutine check_options_belong
  end subroutine parse_args

  !> The flags every parser takes (-h/--help, -q/--quiet): set in `args`; whether `name` was one.
  logical function common_flag(args, name)
    type(cli_args_t), intent(inout) :: args
    !> The option's name as given.
    character(*), intent(in) :: name
    common_flag = .true.
    select case (name)
    case ("-h", "--help")
      args%help = .true.
    case ("-q", "--quiet")
      args%quiet = .true.
    case default
      common_flag = .false.
    end select
  end function common_flag

  !> The usage a subcommand that must come first names when it does not.
  pure function first_word_usage(command) result(text)
    !> The subcommand's word.
    character(*), intent(in) :: command
    character(len=:), allocatable :: text
    select case (command)
    case ("balance")
      text = "kinetostat balance DECK [-o FILE] [--method M]"
    case ("contour")
      text = "kinetostat contour DECK [-o FILE]"
    case ("sheets")
      text = "kinetostat sheets DECK -o DIR"
    case ("structure")
      text = "kinetostat structure DECK [--lang ru]"
    case default
      text = usage_text(command)
    end select
  end function first_word_usage

  !> Whether binary output would reach a terminal: the file of `-o` (a terminal device, or
  !> /dev/stdout on one), or standard output when there is no `-o`.
  logical function binary_to_terminal(out_file)
    !> The path of `-o`, if given.
    character(len=:), allocatable, intent(in) :: out_file
    if (allocated(out_file)) then
      binary_to_terminal = output_is_terminal(out_file)
    else
      binary_to_terminal = output_is_terminal()
    end if
  end function binary_to_terminal

  !> Date and time of the run as the 1991 header printed them: "25.11.2026 18:31".
  function run_stamp() result(stamp)
    character(len=:), allocatable :: stamp
    integer :: v(8)
    call date_and_time(values=v)
    stamp = two(v(3))//"."//two(v(2))//"."//int_str(v(1))//" "//two(v(5))//":"//two(v(6))
  contains
    pure function two(i) result(t)
      integer, intent(in) :: i
      character(len=:), allocatable :: t
      t = int_str(i)
      if (i < 10) t = "0"//t
    end function two
  end function run_stamp

  !> The arguments of `kinetostat diff A B [--rtol R] [--atol A] [--common] [--quiet]` (errors: exit 2).
  subroutine parse_diff_args(args, error)
    type(cli_args_t), intent(inout) :: args
    type(error_t), allocatable, intent(out) :: error
    integer :: i, n, ios
    character(len=:), allocatable :: arg, name, value
    character(len=4096) :: files(2)
    integer :: n_files
    real(wp) :: x
    n = command_argument_count()
    n_files = 0
    i = 1
    do while (i < n)
      call next_option(i, n, value_options(), name, value)
      if (.not. allocated(value)) then
        call fatal_error(error, exit_input, "diff: "//name//" needs a value; "//usage_text("diff"))
        return
      end if
      if (common_flag(args, name)) cycle
      select case (name)
      case ("--common")
        args%diff_options%common = .true.
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
        if (find_option(name) > 0) then
          call fatal_error(error, exit_input, "diff does not take "//name//"; "//usage_text("diff"))
          return
        end if
        arg = argument(i)
        if (len(arg) > 1 .and. arg(1:1) == "-") then
          call fatal_error(error, exit_input, "diff: unknown option '"//arg//"'; "//usage_text("diff"))
          return
        end if
        n_files = n_files + 1
        if (n_files > 2) then
          call fatal_error(error, exit_input, "diff: more than two files given ('"//arg//"'); "//usage_text("diff"))
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
      call fatal_error(error, exit_input, "diff: needs two files; "//usage_text("diff"))
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
      call diff_outputs(a%path, a%records, b%path, b%records, catalog, args%diff_options, report, status, error)
    end if
    if (.not. allocated(error) .and. .not. args%quiet) call write_output_stdout(report, error)
    if (allocated(error)) then
      write (error_unit, '(a)') "kinetostat: error: "//printable(error%message)
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
    call load_deck(path, source, error, whole_lines=.true.)
    if (allocated(error)) error%message = path//": cannot read the file"
  end subroutine read_output_file

  !> The option at argument i+1 (i is advanced): its name and value, where `--name=value` is
  !> the same as `--name value` for the options in `takes_value`; another argument has the
  !> value "". The value is not allocated when an option of `takes_value` is the last argument.
  subroutine next_option(i, n, takes_value, name, value)
    !> The argument before the option; on return, the option's last argument.
    integer, intent(inout) :: i
    !> The number of arguments.
    integer, intent(in) :: n
    !> The options that take a value.
    character(*), intent(in) :: takes_value(:)
    !> The option's name (or the argument).
    character(len=:), allocatable, intent(out) :: name
    !> The option's value.
    character(len=:), allocatable, intent(out) :: value
    character(len=:), allocatable :: arg
    integer :: eq
    i = i + 1
    arg = argument(i)
    eq = index(arg, "=")
    if (len(arg) > 2 .and. arg(1:min(2, len(arg))) == "--" .and. eq > 0) then
      name = arg(1:eq - 1)
      value = arg(eq + 1:)
    else if (any(arg == takes_value)) then
      name = arg
      if (i == n) return
      i = i + 1
      value = argument(i)
    else
      name = arg
      value = ""
    end if
  end subroutine next_option

  function argument(i) result(arg)
    integer, intent(in) :: i
    character(len=:), allocatable :: arg
    integer :: length
    call get_command_argument(i, length=length)
    allocate (character(len=length) :: arg)
    if (length > 0) call get_command_argument(i, arg)
  end function argument

end module kinetostat_cli
