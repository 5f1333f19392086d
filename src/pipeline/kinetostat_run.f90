!> The one run pipeline of every mechanism: read the deck -> solve every step into a step
!> table -> guard (nothing non-finite reaches an output) -> write the chosen format into a
!> buffer. The caller writes the buffer out only when all of this succeeded.
module kinetostat_run
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp
  use kinetostat_selfcheck, only: selfcheck_tolerance
  use kinetostat_error, only: error_t, fatal_error, exit_geometry, exit_input, out_of_memory
  use kinetostat_text, only: int_str, printable
  use kinetostat_format, only: trimmed_es
  use kinetostat_step_table, only: step_table_t, student_t, echo_cursor_t, echo_real_kind, echo_array_kind
  use kinetostat_run_tally, only: run_tally_t, merge_tally
  use kinetostat_deck, only: deck_source_t, release_deck_text
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_csv_writer, only: write_csv
  use kinetostat_json_writer, only: write_json
  use kinetostat_npy_writer, only: write_npy
  use kinetostat_run_sheet, only: write_run_sheet
  use kinetostat_mechanism_sheet, only: write_mechanism_sheet
  use kinetostat_sheet, only: sheet_t, iso_paper
  use kinetostat_dynamics_sheet, only: draw_dynamics_sheet
  use kinetostat_kinematics_sheet, only: draw_kinematics_sheet
  use kinetostat_sheet_svg, only: write_sheet_svg
  use kinetostat_sheet_dxf, only: write_sheet_dxf
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, drawing_from_sketch
  use kinetostat_plans_base, only: plans_t
  use kinetostat_plans, only: build_plans
  use kinetostat_plans_structure, only: structure_lines_of
  use kinetostat_escape, only: table_text
  use kinetostat_plans_sheet, only: plans_sheet_t, plans_sheet
  use kinetostat_plans_json, only: write_plans_json
  use kinetostat_plans_draw, only: draw_plans_sheet
  use kinetostat_error, only: exit_usage
  use kinetostat_labels, only: lang_en, lang_ru
  use kinetostat_override, only: override_t, mark_overrides
  use kinetostat_summary, only: coarse_step_warning, summary_header, summary_row, tally_rows, column_stats_t, &
    column_stats, drive_work, summarized
  use kinetostat_table_writer, only: write_table_head, write_table_rows, write_table_tail, write_shaking_rows
  use kinetostat_spool, only: spool_t
  use kinetostat_bodies, only: mass_model_t
  use kinetostat_shaking, only: add_shaking
  use kinetostat_point_motion, only: add_point_motion
  use kinetostat_row_keeper, only: row_keeper_t
  use kinetostat_kinds, only: deg_to_rad
  implicit none
  private
  public :: run_options_t, run_mechanism, guard_finite, progress_i, block_rows
  public :: format_table, format_csv, format_json, format_svg, format_summary, format_plans, format_dxf, &
    format_deck, format_npy, format_from_name, format_names, course_none, course_dynamics, &
    course_kinematics, course_kinetostatics, course_design

  !> Course sheets (kinetostat sheets): none (the format's own drawing), the dynamics sheet.
  integer, parameter :: course_none = 0, course_dynamics = 1, course_kinematics = 2, course_kinetostatics = 3, &
    course_design = 4

  !> Output format: the legacy fixed-format table.
  integer, parameter :: format_table = 1
  !> Output format: CSV.
  integer, parameter :: format_csv = 2
  !> Output format: one JSON object.
  integer, parameter :: format_json = 3
  !> Output format: one SVG sheet (hodographs and diagrams, or the mechanism at a step).
  integer, parameter :: format_svg = 4
  !> Output format: a CSV header and one summary row (extremes, means, work).
  integer, parameter :: format_summary = 5
  !> Output format: the graphical method's plans of step --at K (an SVG sheet).
  integer, parameter :: format_plans = 6
  !> Output format: the mechanism of step --at K as an ASCII DXF drawing.
  integer, parameter :: format_dxf = 7
  !> Output format: the matching analysis deck of a design kind (mechanism_t%analysis_deck).
  integer, parameter :: format_deck = 8
  !> Output format: the CSV's columns as a NumPy .npy file (binary).
  integer, parameter :: format_npy = 9
  !> The formats' names as --format takes them, in the order of their codes.
  character(*), parameter :: format_keys(*) = [character(len=7) :: "table", "csv", "json", "svg", "summary", &
    "plans", "dxf", "deck", "npy"]
  !> Names of the formats, for messages and --help.
  character(*), parameter :: format_names = "table, csv, json, svg, summary, plans, dxf, deck, npy"

  !> Steps solved and written at a time: a run holds the rows of one block (and at most the
  !> spool's bound of output text), whatever its number of steps.
  integer, parameter :: block_rows = 8192

  abstract interface
    !> Told after every block of a run: rows done so far of the run's total.
    subroutine progress_i(done, total)
      implicit none
      !> Rows done.
      integer, intent(in) :: done
      !> Rows of the run.
      integer, intent(in) :: total
    end subroutine progress_i
  end interface

  !> How to run and what to write.
  type :: run_options_t
    !> format_table, format_csv or format_json.
    integer :: format = format_table
    !> Language of the legacy table (lang_en, lang_ru).
    integer :: lang = lang_en
    !> The --set overrides (already written into the deck; marked in the outputs).
    type(override_t), allocatable :: overrides(:)
    !> CSV and JSON add the kinematics columns (positions, link angles and speeds,
    !> accelerations of the centres of mass, force components).
    logical :: kinematics = .false.
    !> Pair forces also in the moving axes of the link each acts on (--frame link).
    logical :: link_frame = .false.
    !> Add the shaking force and moment and the total force and moment on the frame
    !> (--shaking; kinetostat_shaking).
    logical :: shaking = .false.
    !> SVG: the pair forces to draw, comma-separated ("" for all).
    character(len=:), allocatable :: pairs
    !> SVG: draw the mechanism at this row (0: the sheet of hodographs and diagrams).
    integer :: at_step = 0
    !> JSON with --at: the graphical method's plans of that row instead of the rows.
    logical :: plans = .false.
    !> With --at (format_plans): the structural analysis of the mechanism drawn at that row
    !> instead of its plans (`kinetostat structure` of a deck without an analysis of its own).
    logical :: structure = .false.
    !> The student's header (legacy table and sheets); unallocated when not asked for.
    type(student_t), allocatable :: student
    !> Rows per block (0: block_rows); the output does not depend on it (tests vary it).
    integer :: block_rows = 0
    !> Values of an echoed array written between drains of the output (0: the step table's
    !> echo_chunk_values); the output does not depend on it (tests vary it).
    integer :: echo_chunk = 0
    !> --allow-selfcheck-failure: a failed self-check is a warning and the output is
    !> written (by default it is a computation error, exit 3, and nothing is written).
    logical :: allow_selfcheck_failure = .false.
    !> The caller reads the run's output, tallies and warnings, not its rows (a plain run,
    !> a sweep's variant): with --format summary (no --shaking, --plans or --frame link) the
    !> columns no summary shows (the pair forces' angles) need not be computed.
    logical :: rows_unread = .false.
    !> kinetostat sheets: the course sheet drawn by --format svg/dxf (course_none: the run's
    !> own sheet), its paper ("A1" .. "A4", landscape), the title block's designation
    !> (графа 2 and 26), the sheet's number and the number of sheets (0: 1 of 1).
    integer :: course_sheet = course_none
    character(len=2) :: paper = "A1"
    character(len=:), allocatable :: designation
    integer :: sheet_number = 0, sheet_count = 0
    !> The kinematics sheet's position (a row of the run; the sheet keeps every row).
    integer :: course_at = 1
    !> The kinematics sheet's plan of positions: the number of positions (--positions, 8 or
    !> 12), the traced point (--point; "": the coupler's centre of mass), the output link
    !> (--output-link; 0: the last link of the last group), and the run at the positions'
    !> angles that kinetostat sheets solved (course_every rows a position; none: no plan).
    integer :: course_positions = 12
    character(len=:), allocatable :: course_point
    integer :: course_output_link = 0
    integer :: course_every = 1
    type(step_table_t), allocatable :: course_plan
    !> The kinematics sheet on A4 (portrait, two sheets): which one, 1 or 2.
    integer :: course_part = 1
  end type run_options_t

contains

  !> Output format code from its name; 0 when unknown.
  pure integer function format_from_name(name)
    !> Name given with --format.
    character(*), intent(in) :: name
    format_from_name = findloc(format_keys, name, dim=1)
  end function format_from_name

  !> Run one deck through a mechanism, in blocks of rows: each block is solved, checked,
  !> tallied (summary and self-check figures) and written after the previous one; with a
  !> `spool`, text beyond its bound goes to its temporary file as the run goes. On success
  !> `out` holds the output (all of it, or what the spool did not take: the caller commits
  !> the spool) and `table` the run's figures (self-check, warnings) with its last block.
  subroutine run_mechanism(mech, group, source, options, table, out, error, spool, progress)
    !> The mechanism named by the deck's first group.
    class(mechanism_t), intent(inout) :: mech
    !> Namelist group name (mechanism kind).
    character(*), intent(in) :: group
    !> The deck, read into memory; its text is released once read (the path stays).
    type(deck_source_t), intent(inout) :: source
    !> Format and language.
    type(run_options_t), intent(in) :: options
    !> The results.
    type(step_table_t), intent(out) :: table
    !> The output text.
    type(text_buffer_t), intent(inout) :: out
    !> Input, geometry or overflow error.
    type(error_t), allocatable, intent(out) :: error
    !> Where text beyond the memory bound goes (discarded on error).
    type(spool_t), intent(inout), optional :: spool
    !> Told after every block.
    procedure(progress_i), optional :: progress
    type(text_buffer_t) :: later
    type(spool_t) :: later_spool
    !> The legacy table's shaking block (--shaking), printed after the layout's sections.
    type(text_buffer_t) :: shaking
    type(spool_t) :: shaking_spool
    !> Where the writer is in the lines before the rows (the INPUT DATA echo).
    type(echo_cursor_t) :: head
    !> The moving links and frame pairs (--shaking).
    type(mass_model_t) :: model
    !> The mechanism's topology for the points' velocities and accelerations (--kinematics).
    type(sketch_t) :: motion_topo
    !> The rows a drawing needs (--at K, the SVG sheet), kept as the blocks go.
    type(row_keeper_t) :: keeper
    logical :: drawn, whole_run
    type(sheet_t) :: sheet
    character(len=:), allocatable :: pairs_asked
    integer :: first, rows, k_at
    !> The kinematics sheet's mechanism at its position and its plans.
    type(drawing_t) :: course_drawing
    type(plans_t) :: course_plans

    rows = block_rows
    if (options%block_rows > 0) then
      rows = options%block_rows
    else
      call block_rows_asked(rows, error)
      if (allocated(error)) return
    end if
    call mech%read_deck(source, error)
    if (allocated(error)) return
    if ((options%format == format_svg .or. options%format == format_dxf) .and. .not. mech%force_sheet) then
      if (allocated(options%pairs)) then
        if (len(options%pairs) > 0) then
          call fatal_error(error, exit_usage, "--pairs: "//source%path//" is &"//group//", a design: its "// &
            "sheet has no pair forces to choose")
          return
        end if
      end if
    end if
    if (options%shaking) then
      call mech%mass_model(model)
      if (.not. model%available) then
        call fatal_error(error, exit_usage, "--shaking: only linkage mechanisms (pr3207, pr3050, sixbar, assur, "// &
          "linkage) report the shaking force; "//source%path//" is &"//group)
        return
      end if
    end if
    call release_deck_text(source)
    table%mechanism = group
    table%deck = source%path
    if (allocated(options%student)) table%student = options%student
    table%row_name = "step"
    table%driver = "M1"
    if (allocated(options%designation)) table%designation = options%designation
    if (options%sheet_number > 0) table%sheet_number = options%sheet_number
    if (options%sheet_count > 0) table%sheet_count = options%sheet_count
    table%kinematics_shown = options%kinematics
    table%kinematics_wanted = options%kinematics .or. options%link_frame .or. options%format == format_svg .or. &
      options%plans .or. options%format == format_plans .or. options%format == format_dxf .or. options%shaking
    table%force_angles_wanted = .not. (options%rows_unread .and. options%format == format_summary .and. &
      .not. (options%shaking .or. options%plans .or. options%link_frame .or. options%kinematics))
    ! CSV, npy and JSON show the rows and the self-check: no column's figures over the run
    table%summaries_wanted = .not. (any(options%format == [format_csv, format_npy]) .or. &
      (options%format == format_json .and. .not. options%plans))
    pairs_asked = ""
    if (allocated(options%pairs)) pairs_asked = options%pairs
    head%chunk = options%echo_chunk
    ! a drawing of forces (the SVG sheet, --at K) keeps only the rows it draws, block by
    ! block; the analysis deck and a design's sheet (the cam's profile) need every row at once
    drawn = mech%force_sheet .and. (any(options%format == [format_svg, format_plans, format_dxf]) .or. options%plans)
    whole_run = options%format == format_deck .or. &
      (.not. mech%force_sheet .and. any(options%format == [format_svg, format_dxf]))
    first = 1
    do
      if (.not. whole_run) then
        table%block_first = first
        table%block_last = first + rows - 1
      end if
      call run_block(error)
      if (allocated(error)) exit
      if (present(progress)) call progress(table%row_offset + table%row_count(), table%total_rows)
      if (table%last_block()) exit
      first = table%row_offset + table%row_count() + 1
    end do
    if (allocated(error) .and. present(spool)) call spool%discard()
    if (allocated(error)) call later_spool%discard()
    if (allocated(error)) call shaking_spool%discard()
  contains
    !> The kinematics sheet's traced point asked (--point; "" none).
    function point_name() result(name)
      character(len=:), allocatable :: name
      name = ""
      if (allocated(options%course_point)) name = options%course_point
    end function point_name

    !> Solve, check, tally and write the next block.
    subroutine run_block(error)
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: warning
      table%block_tally = run_tally_t()
      call mech%solve(table, error)
      if (allocated(error)) then
        if (index(error%message, "out of memory:") == 1) error%message = table%deck//": &"//group//": "// &
          error%message
        return
      end if
      ! a mechanism without blocks (gears) gives all its rows at once
      if (table%total_rows == 0) table%total_rows = table%row_count()
      call table%finish_columns()
      if (allocated(table%no_room)) then
        call fatal_error(error, exit_input, table%deck//": &"//group//": out of memory: no room for "// &
          table%no_room)
        return
      end if
      if (options%kinematics) then
        ! the points' velocities and accelerations (every linkage, from its sketch)
        if (table%first_block()) call mech%sketch(motion_topo)
        call add_point_motion(motion_topo, table, error)
        if (allocated(error)) return
        call table%finish_columns()
      end if
      if (options%shaking) then
        call add_shaking(table, model, error)
        if (allocated(error)) return
      end if
      call guard_rows(table, error)
      if (allocated(error)) return
      if (table%first_block()) then
        call start_output(error)
        if (allocated(error)) return
      end if
      call tally_block(table)
      if (table%last_block()) then
        ! the kind's own summary and warnings from the run's figures
        call mech%finish_run(table)
        call guard_inputs(table, error)
        if (allocated(error)) return
        call guard_summary(table, options%kinematics, error)
        if (allocated(error)) return
        call judge_selfcheck(table, options%allow_selfcheck_failure, error)
        if (allocated(error)) return
        call coarse_step_warning(table, warning)
        if (allocated(warning)) call table%add_warning(warning)
      end if
      select case (options%format)
      case (format_csv)
        ! the spool takes the rows as they are formatted (when there is one)
        call write_csv(table, out, spool)
      case (format_npy)
        call write_npy(table, out, error)
        if (allocated(error)) return
      case (format_summary)
        if (table%last_block()) then
          call out%put(summary_header(table, options%kinematics))
          call out%put(summary_row(table, options%kinematics))
        end if
      case (format_json)
        if (options%plans) then
          call keep_drawn_rows(error)
          if (allocated(error)) return
          if (table%last_block()) call write_at_step(mech, table, options, out, error)
          if (allocated(error)) return
        else
          do
            call write_json(mech%title(options%lang), table, out, head, spool)
            if (head%done) exit
            call drain_head(error)
            if (allocated(error)) return
          end do
        end if
      case (format_plans)
        call keep_drawn_rows(error)
        if (allocated(error)) return
        if (table%last_block()) call write_at_step(mech, table, options, out, error)
        if (allocated(error)) return
      case (format_deck)
        call mech%analysis_deck(table, out, error)
        if (allocated(error)) return
      case (format_svg, format_dxf)
        call guard_drawable(table, error)
        if (allocated(error)) return
        call keep_drawn_rows(error)
        if (allocated(error)) return
        if (.not. table%last_block()) then
          continue
        else if (mech%force_sheet .and. options%at_step > 0) then
          call write_at_step(mech, table, options, out, error)
        else
          if (options%course_sheet == course_kinematics) then
            call drawn_sketch(mech, table, "the kinematics sheet draws linkages only", motion_topo, error)
            if (allocated(error)) return
            k_at = findloc(table%row_numbers, options%course_at, dim=1)
            if (k_at == 0) k_at = minloc(abs(table%row_numbers - options%course_at), dim=1)
            call drawing_from_sketch(motion_topo, table, k_at, course_drawing, error)
            if (allocated(error)) return
            call mech%force_plan(table, k_at, course_drawing, error)
            if (allocated(error)) return
            call build_plans(motion_topo, course_drawing, table, k_at, course_plans)
            if (allocated(options%course_plan)) then
              call draw_kinematics_sheet(mech%course_name(options%lang), table, motion_topo, course_drawing, k_at, &
                iso_paper(options%paper, .true.), options%lang, sheet, options%course_plan, options%course_every, &
                options%course_positions, point_name(), options%course_output_link, course_plans, options%course_part)
            else
              call draw_kinematics_sheet(mech%course_name(options%lang), table, motion_topo, course_drawing, k_at, &
                iso_paper(options%paper, .true.), options%lang, sheet, every=1, n_positions=options%course_positions, &
                point_asked=point_name(), output_link=options%course_output_link, plans=course_plans, &
                part=options%course_part)
            end if
          else if (options%course_sheet == course_dynamics) then
            call draw_dynamics_sheet(mech%course_name(options%lang), table, iso_paper(options%paper, .true.), options%lang, &
                                     sheet)
          else if (mech%force_sheet) then
            call write_run_sheet(mech%title(options%lang), table, pairs_asked, options%lang, sheet, error)
          else if (options%at_step > 0 .and. table%single_record) then
            call fatal_error(error, exit_usage, "--at: "//table%deck//" is &"//group//", one "//table%row_name// &
              ": its sheet has no steps to choose")
          else
            ! a design's sheet (the gear pair, the planetary train, the cam); on a course sheet
            ! (kinetostat sheets) from the results without their file: the sheet names none
            if (options%course_sheet == course_design) then
              call mech%design_sheet(without_file(table), options%lang, options%at_step, sheet, error)
            else
              call mech%design_sheet(table, options%lang, options%at_step, sheet, error)
            end if
          end if
          if (allocated(error)) return
          if (options%format == format_dxf) then
            call write_sheet_dxf(sheet, out)
          else
            call write_sheet_svg(sheet, out)
          end if
        end if
        if (allocated(error)) return
      case default
        call write_table_rows(mech, table, options%lang, out, later, spool)
        if (options%shaking) call write_shaking_rows(table, options%lang, shaking)
        if (table%last_block()) then
          if (present(spool)) then
            call spool%absorb(out, later_spool, later, error)
            if (allocated(error)) return
            call spool%absorb(out, shaking_spool, shaking, error)
            if (allocated(error)) return
          else
            if (later%length > 0) call out%append(later%data(1:later%length))
            if (shaking%length > 0) call out%append(shaking%data(1:shaking%length))
          end if
          call write_table_tail(table, options%lang, out)
        end if
      end select
      call check_text_room(error)
      if (allocated(error)) return
      if (.not. present(spool)) return
      if (allocated(spool%failure)) then
        ! a failed write of the spool while the rows were formatted (spool_t%take)
        call move_alloc(spool%failure, error)
        return
      end if
      call spool%drain(out, error)
      if (allocated(error)) return
      call later_spool%drain(later, error)
      if (allocated(error)) return
      call shaking_spool%drain(shaking, error)
    end subroutine run_block

    !> A drawing's rows: after the first block, what to keep (--at K: the row, and the
    !> travel of the points on guides; the SVG sheet: the extremes of long runs); after every
    !> block, the rows kept; after the last, the kept rows become the table's.
    subroutine keep_drawn_rows(error)
      type(error_t), allocatable, intent(out) :: error
      if (.not. drawn) return
      if (table%first_block()) then
        if (options%at_step > 0) then
          call aim_at_step(error)
          if (allocated(error)) return
        else
          call keeper%keep_buckets()
        end if
      end if
      call keeper%add(table, error)
      if (.not. allocated(error) .and. table%last_block()) call keeper%take(table, error)
      if (allocated(error)) error%message = table%deck//": &"//table%mechanism//": "//error%message
    end subroutine keep_drawn_rows

    !> --at K: K must be a row of the run; the rows kept are K's and those of the extreme
    !> positions of every point on a guide of the mechanism's sketch (its travel).
    subroutine aim_at_step(error)
      type(error_t), allocatable, intent(out) :: error
      type(sketch_t) :: topo
      integer, allocatable :: cx(:), cy(:)
      real(wp), allocatable :: u(:, :)
      integer :: i, n
      n = table%run_rows()
      if (options%at_step > n) then
        call fatal_error(error, exit_usage, "--at "//int_str(options%at_step)//": "//table%deck//" has "// &
          int_str(n)//" "//table%row_name//"s (1.."//int_str(n)//")")
        return
      end if
      call mech%sketch(topo)
      n = 0
      if (topo%available .and. allocated(topo%guides)) n = size(topo%guides)
      allocate (cx(n), cy(n), u(2, n))
      do i = 1, n
        cx(i) = table%column_index("x_"//trim(topo%guides(i)%point))
        cy(i) = table%column_index("y_"//trim(topo%guides(i)%point))
        u(:, i) = [cos(topo%guides(i)%angle * deg_to_rad), sin(topo%guides(i)%angle * deg_to_rad)]
      end do
      call keeper%keep_at(options%at_step, cx, cy, u)
    end subroutine aim_at_step

    !> Before the first rows: --frame link's check, the --set marks, the table's head.
    subroutine start_output(error)
      type(error_t), allocatable, intent(out) :: error
      if (options%link_frame) then
        if (.not. any(table%columns%link_axes)) then
          call fatal_error(error, exit_usage, "--frame link: only the generic engine (&assur) reports reactions "// &
            "in link axes; "//table%deck//" is &"//group)
          return
        end if
        table%link_frame = .true.
      end if
      if (allocated(options%overrides)) then
        if (size(options%overrides) > 0) call mark_overrides(table, options%overrides)
      end if
      if (options%format /= format_table) return
      do
        call write_table_head(mech, table, options%lang, out, head)
        if (head%done) exit
        call drain_head(error)
        if (allocated(error)) return
      end do
    end subroutine start_output

    !> Between parts of the head: the text so far to the spool (when over its bound).
    subroutine drain_head(error)
      type(error_t), allocatable, intent(out) :: error
      call check_text_room(error)
      if (allocated(error)) return
      if (present(spool)) call spool%drain(out, error)
    end subroutine drain_head

    !> The output's text could not grow (out of memory): the run stops (exit 2).
    subroutine check_text_room(error)
      type(error_t), allocatable, intent(out) :: error
      integer :: bytes
      bytes = max(out%lost, later%lost, shaking%lost)
      if (bytes > 0) call out_of_memory(error, table%deck//": the output's text", int(bytes, int64))
    end subroutine check_text_room
  end subroutine run_mechanism

  !> The results `table` without their file (a course sheet names none: what it shows is
  !> the mechanism, not where its deck was kept); a design's results are one record.
  pure function without_file(table) result(course)
    type(step_table_t), intent(in) :: table
    type(step_table_t) :: course
    course = table
    course%deck = ""
  end function without_file

  !> The block just solved into the run's tally (table%run_tally), the one place where the
  !> blocks of a run meet: the figures the kind noted for the block (self-check maxima, drive
  !> deviation, peaks, integrals, flags: merge_tally) and per column the extremes, sums and
  !> trapezoid sums of its rows in row order (tally_rows). Whatever the blocks, the run's
  !> figures are those of one block of every row, bit for bit (test/cli/test_block_rows.sh).
  subroutine tally_block(table)
    !> The results: the block's rows and figures; the run's tally is updated.
    type(step_table_t), intent(inout) :: table
    call merge_tally(table%run_tally, table%block_tally)
    call tally_rows(table)
  end subroutine tally_block

  !> Rows per block: the maintainers' knob KINETOSTAT_BLOCK_ROWS (a whole number >= 1; the
  !> output does not depend on it: test/cli/test_block_rows.sh), else `rows` as given.
  !> Any other value is an input error (exit 2) naming the variable.
  subroutine block_rows_asked(rows, error)
    !> Rows per block (left as it is when the variable is unset or empty).
    integer, intent(inout) :: rows
    !> The variable's value is not a whole number >= 1.
    type(error_t), allocatable, intent(out) :: error
    character(len=32) :: text
    integer :: length, status, value, ios
    call get_environment_variable("KINETOSTAT_BLOCK_ROWS", text, length, status)
    if (status == 1 .or. length == 0) return
    value = 0
    ios = 1
    if (status == 0 .and. verify(trim(text), "0123456789") == 0) read (text, '(i32)', iostat=ios) value
    if (ios /= 0 .or. value < 1) then
      call fatal_error(error, exit_input, "KINETOSTAT_BLOCK_ROWS: expected a whole number of rows >= 1 (got '"// &
        printable(trim(text(1:min(length, len(text)))))//"')")
      return
    end if
    rows = value
  end subroutine block_rows_asked

  !> The mechanism at row options%at_step, drawn from its sketch.
  subroutine write_at_step(mech, table, options, out, error)
    class(mechanism_t), intent(in) :: mech
    type(step_table_t), intent(in) :: table
    type(run_options_t), intent(in) :: options
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    type(sketch_t) :: topo
    type(drawing_t) :: drawing
    type(plans_t) :: plans
    type(plans_sheet_t) :: plans_geometry
    type(sheet_t) :: sheet
    character(len=160), allocatable :: lines(:)
    integer :: k, i
    ! a kind without a drawing of its mechanism (a design kind keeps no rows for one)
    call drawn_sketch(mech, table, "--at: this mechanism is not drawn (only linkages are); --format svg "// &
      "without --at shows its forces", topo, error)
    if (allocated(error)) return
    ! the table holds the rows the drawing needs (kinetostat_row_keeper): find row --at K
    k = 0
    if (allocated(table%row_numbers)) k = findloc(table%row_numbers, options%at_step, dim=1)
    if (k == 0) then
      call fatal_error(error, exit_usage, "--at "//int_str(options%at_step)//": "//table%deck//" has "// &
        int_str(table%run_rows())//" "//table%row_name//"s (1.."//int_str(table%run_rows())//")")
      return
    end if
    call drawing_from_sketch(topo, table, k, drawing, error)
    if (allocated(error)) return
    call mech%force_plan(table, k, drawing, error)
    if (allocated(error)) return
    if (options%structure) then
      call structure_lines_of(topo, drawing, table, k, options%lang, lines)
      ! the Russian analysis in the course's words alone (as a &linkage deck's own)
      if (options%lang /= lang_ru) then
        call out%put(" DECK: "//table_text(table%deck))
        if (allocated(table%subtitle)) then
          if (len_trim(table%subtitle) > 0) call out%put(" TITLE: "//table_text(trim(table%subtitle)))
        end if
      end if
      do i = 1, size(lines)
        call out%put(" "//trim(lines(i)))
      end do
      return
    end if
    if (options%plans .or. options%format == format_plans) then
      ! the graphical method: as numbers (json), or its sheet (plans: SVG; dxf)
      call build_plans(topo, drawing, table, k, plans)
      if (options%course_sheet == course_kinetostatics) then
        call plans_sheet(topo, drawing, plans, plans_geometry, options%paper)
      else
        call plans_sheet(topo, drawing, plans, plans_geometry)
      end if
      if (options%format == format_json) then
        call write_plans_json(mech%title(options%lang), plans, plans_geometry, table, k, out)
        return
      end if
      if (options%course_sheet == course_kinetostatics) then
        call draw_plans_sheet(mech%course_name(options%lang), table, k, drawing, plans, plans_geometry, options%lang, &
          sheet)
      else
        call draw_plans_sheet(mech%title(options%lang), table, k, drawing, plans, plans_geometry, options%lang, sheet)
      end if
    else
      call write_mechanism_sheet(mech%title(options%lang), table, k, drawing, options%lang, sheet)
    end if
    if (options%format == format_dxf) then
      call write_sheet_dxf(sheet, out)
    else
      call write_sheet_svg(sheet, out)
    end if
  end subroutine write_at_step

  !> Nothing that is not finite may reach an output: a non-finite result is a geometry
  !> error (exit 3) naming the step, its input angle and the quantity.
  pure subroutine guard_finite(table, error)
    !> The results (all rows).
    type(step_table_t), intent(in) :: table
    !> The error, if any value is not finite.
    type(error_t), allocatable, intent(out) :: error
    call guard_rows(table, error)
    if (allocated(error)) return
    call guard_inputs(table, error)
  end subroutine guard_finite

  !> guard_finite for the rows now in the table (a block of the run).
  pure subroutine guard_rows(table, error)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> The error, if any value is not finite.
    type(error_t), allocatable, intent(out) :: error
    integer :: k, c
    if (all_finite(table%rows(1:size(table%columns), 1:table%row_count()))) return
    do k = 1, table%row_count()
      do c = 1, size(table%columns)
        if (ieee_is_finite(table%rows(c, k))) cycle
        call fatal_error(error, exit_geometry, table%deck//": &"//table%mechanism//": "// &
          row_text(table, k)//": "//table%columns(c)%name// &
          " is not finite (overflow: the deck's magnitudes are out of the representable range)")
        return
      end do
    end do
  end subroutine guard_rows

  !> Whether every value is finite: no value has all its exponent bits set (an infinity or
  !> a NaN), found in one pass of integer operations the compiler vectorizes (a test a
  !> value, with its branch, costs a summary run's rows more than their tallies).
  pure logical function all_finite(x) result(finite)
    !> The values.
    real(wp), intent(in) :: x(:, :)
    !> The exponent's bits of a real(wp) (IEEE binary64).
    integer(int64), parameter :: exponent_bits = shiftl(2047_int64, 52)
    !> Negative once a value's exponent bits are all set: iand(not(bits), exponent_bits) is 0
    !> for that value alone, and 0 - 1 sets the sign bit.
    integer(int64) :: flags
    integer :: i, j
    flags = 0_int64
    do j = 1, size(x, 2)
      do i = 1, size(x, 1)
        flags = ior(flags, iand(not(transfer(x(i, j), 0_int64)), exponent_bits) - 1_int64)
      end do
    end do
    finite = flags >= 0_int64
  end function all_finite

  !> guard_finite for the derived input values of the echo and the self-check figures.
  pure subroutine guard_inputs(table, error)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> The error, if any value is not finite.
    type(error_t), allocatable, intent(out) :: error
    integer :: i
    do i = 1, table%echo_count
      if (table%echo(i)%kind /= echo_real_kind .and. table%echo(i)%kind /= echo_array_kind) cycle
      if (all(ieee_is_finite(table%echo(i)%values))) cycle
      call fatal_error(error, exit_geometry, table%deck//": &"//table%mechanism//": derived input value "// &
        table%echo(i)%name//" is not finite (overflow: the deck's magnitudes are out of the representable range)")
      return
    end do
    if (table%has_selfcheck) then
      if (.not. ieee_is_finite(table%run_tally%residual%value)) then
        call fatal_error(error, exit_geometry, table%deck//": &"//table%mechanism//": "// &
          selfcheck_where(table, table%run_tally%residual%row)//"the self-check's equilibrium residual is not finite "// &
          "(overflow: the deck's magnitudes are out of the representable range)")
      else if (.not. ieee_is_finite(table%run_tally%mismatch%value)) then
        call fatal_error(error, exit_geometry, table%deck//": &"//table%mechanism//": "// &
          selfcheck_where(table, table%run_tally%mismatch%row)//"the self-check's "//table%driver//" mismatch is not "// &
          "finite (overflow: the deck's magnitudes are out of the representable range)")
      end if
    end if
  end subroutine guard_inputs

  !> "step 12: " (the row of a self-check figure; "" when not known).
  pure function selfcheck_where(table, row) result(text)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> Row of the run (0: not known).
    integer, intent(in) :: row
    character(len=:), allocatable :: text
    text = ""
    if (row > 0) text = table%row_name//" "//int_str(row)//": "
  end function selfcheck_where

  !> A self-check above selfcheck_tolerance means the numbers are wrong (a bug, or input
  !> beyond the precision of the arithmetic, such as an angle of 1e20 deg): a computation
  !> error (exit 3) naming the figure and the step, so that nothing is written; with
  !> `allowed` (--allow-selfcheck-failure) a warning of the run instead (in the JSON's
  !> warnings too) and the output is written.
  pure subroutine judge_selfcheck(table, allowed, error)
    !> The results (all rows).
    type(step_table_t), intent(inout) :: table
    !> Whether a failed self-check is only a warning.
    logical, intent(in) :: allowed
    !> The error, when the self-check failed and that is not allowed.
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: what
    character(len=:), allocatable :: residual_text, mismatch_text, limit_text
    if (.not. table%has_selfcheck .or. table%run_tally%rows == 0) return
    if (table%run_tally%residual%value <= selfcheck_tolerance .and. table%run_tally%mismatch%value <= selfcheck_tolerance) return
    residual_text = trimmed_es(table%run_tally%residual%value, 2)
    mismatch_text = trimmed_es(table%run_tally%mismatch%value, 2)
    limit_text = trimmed_es(selfcheck_tolerance, 1)
    if (table%run_tally%residual%value > selfcheck_tolerance) then
      what = selfcheck_where(table, table%run_tally%residual%row)//"equilibrium residual "//residual_text
    else
      what = selfcheck_where(table, table%run_tally%mismatch%row)//table%driver//" mismatch vs the power balance "// &
        mismatch_text
    end if
    what = "self-check failed at "//what//" (limit "//limit_text//"; max equilibrium residual "// &
      residual_text//", max "//table%driver//" mismatch "//mismatch_text//")"
    if (allowed) then
      call table%add_warning(what//": the results are not trustworthy (written because of "// &
        "--allow-selfcheck-failure)")
    else
      call fatal_error(error, exit_geometry, table%deck//": &"//table%mechanism//": "//what// &
        ": the results are wrong (a bug, or input beyond the precision of the arithmetic, e.g. a huge "// &
        "angle); nothing written (--allow-selfcheck-failure writes them with a warning)")
    end if
  end subroutine judge_selfcheck

  !> guard_finite for the figures of the run's summary (the SUMMARY block of the table,
  !> --format summary, a sweep's rows): each summarized column's mean (of those the run
  !> tallies) and the driver's work. The means are averages of finite values and kept in
  !> range (see column_stats); only a work beyond the largest real is left, an error (exit
  !> 3) naming it.
  pure subroutine guard_summary(table, kinematics, error)
    !> The results (all rows tallied).
    type(step_table_t), intent(in) :: table
    !> Whether the kinematics columns are summarized too.
    logical, intent(in) :: kinematics
    !> The error, if a figure is not finite.
    type(error_t), allocatable, intent(out) :: error
    type(column_stats_t) :: s
    real(wp) :: work
    logical :: known
    integer :: c
    if (table%run_tally%rows == 0) return
    do c = 1, size(table%columns)
      if (.not. (summarized(table, c, kinematics) .and. table%tallied(c))) cycle
      s = column_stats(table, c)
      if (ieee_is_finite(s%mean)) cycle
      call fatal_error(error, exit_geometry, table%deck//": &"//table%mechanism//": the mean of "// &
        table%columns(c)%name//" over the run is not finite (overflow: the deck's magnitudes are out of the "// &
        "representable range)")
      return
    end do
    call drive_work(table, work, known)
    if (known .and. .not. ieee_is_finite(work)) then
      call fatal_error(error, exit_geometry, table%deck//": &"//table%mechanism//": the work of "// &
        table%driver//" over the run is not finite (overflow: the deck's magnitudes are out of the "// &
        "representable range)")
    end if
  end subroutine guard_summary

  !> The SVG maps every value to the page through ranges, tick steps and means (sums of
  !> products of two values); a value beyond `drawable_limit` in magnitude would overflow
  !> them: a geometry error (exit 3) naming the step and the column, before anything is drawn.
  pure subroutine guard_drawable(table, error)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> The error, if a value cannot be drawn.
    type(error_t), allocatable, intent(out) :: error
    !> Largest magnitude drawn (its products and sums over 10^6 rows stay finite).
    real(wp), parameter :: drawable_limit = 1.0e150_wp
    integer :: k, c
    do k = 1, table%row_count()
      do c = 1, size(table%columns)
        if (abs(table%rows(c, k)) <= drawable_limit) cycle
        call fatal_error(error, exit_geometry, table%deck//": &"//table%mechanism//": "// &
          row_text(table, k)//": "//table%columns(c)%name//" is too large to draw (magnitude above 1e150)")
        return
      end do
    end do
  end subroutine guard_drawable

  !> The mechanism's sketch, or a usage error (exit 1) naming the deck, its group and `why`
  !> when the kind has no drawing of its mechanism.
  subroutine drawn_sketch(mech, table, why, topo, error)
    class(mechanism_t), intent(in) :: mech
    !> The results (their deck and group named).
    type(step_table_t), intent(in) :: table
    !> What cannot be done without a drawing.
    character(*), intent(in) :: why
    type(sketch_t), intent(out) :: topo
    type(error_t), allocatable, intent(out) :: error
    call mech%sketch(topo)
    if (.not. topo%available) call fatal_error(error, exit_usage, table%deck//": &"//table%mechanism//": "//why)
  end subroutine drawn_sketch

  !> "step k (phi1 = x deg)" or "stage k".
  pure function row_text(table, k) result(text)
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    character(len=32) :: buf
    real(wp) :: x
    integer :: n
    text = table%row_name//" "//int_str(table%row_offset + k)
    if (table%input_column > 0) then
      x = table%rows(table%input_column, k)
      if (ieee_is_finite(x)) then
        write (buf, '(g0.10)') x
        buf = adjustl(buf)
        if (index(buf, ".") > 0 .and. scan(buf, "eE") == 0) then
          n = len_trim(buf)
          do while (buf(n:n) == "0")
            buf(n:n) = " "
            n = n - 1
          end do
          if (buf(n:n) == ".") buf(n:n) = " "
        end if
        text = text//" ("//table%columns(table%input_column)%name//" = "//trim(adjustl(buf))//" "// &
          table%columns(table%input_column)%unit//")"
      end if
    end if
  end function row_text

end module kinetostat_run
