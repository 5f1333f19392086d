!> `kinetostat sheets DECK -o DIR`: the course's drawing sheets of a linkage deck, each as SVG
!> and DXF (the one drawing model) and as PDF at true size when rsvg-convert is installed:
!> DIR/kinematics (the structure, the mechanism at the position with a trajectory, the output
!> link's diagrams, the values; on A3 and A4 two sheets: DIR/kinematics with the plan of
!> positions, the structure and the diagrams, DIR/kinematics-2 with the values and the plans of
!> velocities and accelerations), DIR/kinetostatics (the mechanism with its forces, Zhukovsky's
!> lever, the force polygons with each Assur group drawn apart, at the position --at K, by
!> default the step of the largest |effort| of the first drive) and,
!> with a steady cycle, DIR/dynamics (the machine dynamics and the flywheel); of a design deck
!> its one sheet: DIR/gears (&gear_geometry: the meshing drawing and the blocking contour),
!> DIR/planetary (&planetary_synthesis) or DIR/cam (&cam_profile). Every sheet is
!> computed before any file is written (an error writes nothing); each file is then written
!> through a temporary beside it and renamed, and the sheets of an earlier run that this deck
!> no longer makes are removed from DIR.
module kinetostat_sheets
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_usage, exit_input
  use kinetostat_text, only: int_str
  use kinetostat_deck, only: deck_source_t, load_deck, read_group_name
  use kinetostat_override, only: apply_overrides
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_output, only: write_output_file
  use kinetostat_mechanism, only: mechanism_t
  use kinetostat_summary, only: column_stats_t, column_stats
  use kinetostat_run, only: run_options_t, block_rows, run_mechanism, format_summary, format_svg, format_dxf, format_plans, &
    course_dynamics, course_none, course_kinematics, course_kinetostatics, course_design
  use kinetostat_registry, only: create_mechanism, deck_mechanism
  use kinetostat_override, only: override_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, drawing_from_sketch
  use kinetostat_kinematics_sheet, only: output_motion
  use kinetostat_sheet, only: kinematics_sheets
  implicit none
  private
  public :: write_course_sheets, sheet_names, parse_sheet_numbers

  !> The sheets' file stems, in the course's order: a linkage's three, then the design kinds'
  !> (each kind's mechanism_t%sheet_name: &gear_geometry, &planetary_synthesis, &cam_profile),
  !> and the kinematics' second sheet on A3, A4 (made with the first, numbered after it).
  character(*), parameter :: sheet_names(*) = [character(len=13) :: "kinematics", "kinetostatics", "dynamics", &
    "gears", "planetary", "cam", "kinematics-2"]
  !> The place of the kinematics' second sheet (A3, A4) in sheet_names.
  integer, parameter :: kinematics_second = 7
  !> The plan of positions: rows of its run between two positions (the traced point's
  !> trajectory is drawn through them all).
  integer, parameter :: rows_per_position = 6
  !> The files of a sheet.
  character(*), parameter :: sheet_suffixes(*) = [character(len=4) :: ".svg", ".dxf", ".pdf"]

contains

  !> Parse --sheet-numbers "1,2,3": the department's numbers of the sheets in the course's
  !> order (kinematics, on A3, A4 its second sheet, kinetostatics, dynamics), whole numbers 1..999.
  pure subroutine parse_sheet_numbers(text, numbers, error)
    character(*), intent(in) :: text
    integer, allocatable, intent(out) :: numbers(:)
    type(error_t), allocatable, intent(out) :: error
    integer :: start, k, value, ios
    character(len=:), allocatable :: part
    allocate (numbers(0))
    start = 1
    do
      k = index(text(start:), ",")
      if (k == 0) then
        part = trim(adjustl(text(start:)))
      else
        part = trim(adjustl(text(start:start + k - 2)))
      end if
      value = 0
      ios = 1
      if (len(part) > 0 .and. len(part) <= 3) then
        if (verify(part, "0123456789") == 0) read (part, *, iostat=ios) value
      end if
      if (ios /= 0 .or. value < 1) then
        call fatal_error(error, exit_usage, "--sheet-numbers needs whole numbers 1..999 separated by commas, "// &
          "one per sheet (kinematics, on A3, A4 kinematics-2, kinetostatics, dynamics), got '"//text//"'")
        return
      end if
      numbers = [numbers, value]
      if (k == 0) exit
      start = start + k
    end do
  end subroutine parse_sheet_numbers

  !> Compute the sheets of the deck at `path` with `options` (language, student, --set,
  !> paper, designation, --at) and write them into the directory `dir`; `numbers` the
  !> department's sheet numbers (empty: 1..N of N).
  subroutine write_course_sheets(path, options, dir, numbers, error)
    character(*), intent(in) :: path
    type(run_options_t), intent(in) :: options
    character(*), intent(in) :: dir
    integer, intent(in) :: numbers(:)
    type(error_t), allocatable, intent(out) :: error
    type(step_table_t) :: table
    type(run_options_t) :: o
    type(text_buffer_t) :: scratch
    !> The files of the sheets (at most two a sheet before the PDFs) and their names.
    type(text_buffer_t) :: files(2 * size(sheet_names))
    character(len=64) :: names(2 * size(sheet_names))
    logical :: made(size(sheet_names)), dynamics
    integer :: k_at, i, n, s, count_made, n_files, design
    character(len=256) :: message
    character(len=:), allocatable :: group
    type(deck_source_t) :: source
    class(mechanism_t), allocatable :: mech
    integer :: stat

    call load_deck(path, source, error)
    if (allocated(error)) return
    call read_group_name(source, group, error)
    if (allocated(error)) return
    ! a design kind names its one sheet (an unknown kind: run_one says so)
    design = 0
    call create_mechanism(group, mech)
    if (allocated(mech)) then
      if (allocated(mech%sheet_name)) design = sheet_index(mech%sheet_name)
    end if
    made = .false.
    k_at = 0
    if (design > 3) then
      made(design) = .true.
    else
      ! the run once: its effort's extreme step (the default --at) and whether it has a cycle
      o = options
      o%format = format_summary
      o%at_step = 0
      ! its table is read row by row: one block of the default size, whatever the maintainers'
      ! KINETOSTAT_BLOCK_ROWS (the sheets do not depend on it)
      o%block_rows = block_rows
      call run_one(path, o, table, scratch, error)
      if (allocated(error)) return
      k_at = options%at_step
      if (k_at == 0) k_at = effort_step(table)
      dynamics = table%column_index("dT") > 0
      made(1) = .true.
      made(2) = .true.
      made(3) = dynamics
      ! (A3, A4: the kinematics on two sheets)
      made(kinematics_second) = kinematics_sheets(options%paper) == 2
    end if
    count_made = count(made)
    if (size(numbers) > 0 .and. size(numbers) /= count_made) then
      call fatal_error(error, exit_usage, "--sheet-numbers: "//path//" makes "//int_str(count_made)//" sheets, "// &
        "give as many numbers (got "//int_str(size(numbers))//")")
      return
    end if
    n_files = 0
    n = 0
    do s = 1, size(sheet_names)
      if (.not. made(s) .or. s == kinematics_second) cycle
      n = n + 1
      o = options
      o%sheet_count = count_made
      o%sheet_number = n
      if (size(numbers) > 0) o%sheet_number = numbers(n)
      o%course_sheet = course_none
      select case (s)
      case (1)
        o%at_step = 0
        o%course_at = k_at
        call solve_positions(path, group, o, error)
        if (allocated(error)) return
        o%kinematics = .true.
        o%course_sheet = course_kinematics
        call add_svg_and_dxf(sheet_names(s), format_svg)
        if (made(kinematics_second)) then
          ! (A3, A4: the second sheet, the next number)
          n = n + 1
          o%sheet_number = n
          if (size(numbers) > 0) o%sheet_number = numbers(n)
          o%course_part = 2
          call add_svg_and_dxf(sheet_names(kinematics_second), format_svg)
        end if
      case (2)
        o%at_step = k_at
        o%course_sheet = course_kinetostatics
        call add_svg_and_dxf(sheet_names(s), format_plans)
      case (4:)
        ! a design's sheet (the gear pair, the planetary train, the cam; --at: the cam's position)
        o%course_sheet = course_design
        call add_svg_and_dxf(sheet_names(s), format_svg)
      case default
        ! the dynamics sheet (3)
        o%at_step = 0
        o%course_sheet = course_dynamics
        call add_svg_and_dxf(sheet_names(s), format_svg)
      end select
      if (allocated(error)) return
    end do

    ! every sheet is made: into DIR (created when missing)
    call execute_command_line("mkdir -p -- "//quoted(dir), exitstat=stat, cmdstat=i, cmdmsg=message)
    if (i /= 0 .or. stat /= 0) then
      call fatal_error(error, exit_input, "sheets: -o "//dir//": cannot create the directory")
      return
    end if
    do i = 1, n_files
      call write_output_file(dir//"/"//trim(names(i)), files(i), error)
      if (allocated(error)) return
    end do
    ! the PDFs at true size (the SVG's width and height are in mm)
    call execute_command_line("command -v rsvg-convert >/dev/null 2>&1", exitstat=stat, cmdstat=i)
    do s = 1, size(sheet_names)
      if (.not. made(s)) cycle
      if (i == 0 .and. stat == 0) then
        call execute_command_line("rsvg-convert -f pdf -o "//quoted(dir//"/."//trim(sheet_names(s))//".pdf.tmp")// &
          " "//quoted(dir//"/"//trim(sheet_names(s))//".svg")//" && mv -f -- "// &
          quoted(dir//"/."//trim(sheet_names(s))//".pdf.tmp")//" "//quoted(dir//"/"//trim(sheet_names(s))//".pdf"), &
          exitstat=stat)
        if (stat /= 0) then
          call fatal_error(error, exit_input, "sheets: rsvg-convert could not write "//dir//"/"// &
            trim(sheet_names(s))//".pdf")
          return
        end if
      end if
    end do
    ! the sheets this deck does not make, left by an earlier run
    do s = 1, size(sheet_names)
      if (made(s)) cycle
      do i = 1, size(sheet_suffixes)
        call remove_file(dir//"/"//trim(sheet_names(s))//trim(sheet_suffixes(i)), error)
        if (allocated(error)) return
      end do
    end do
  contains
    !> Run the deck with `o` and keep its text as file `name`.
    subroutine add_file(name)
      character(*), intent(in) :: name
      type(step_table_t) :: t
      if (allocated(error)) return
      n_files = n_files + 1
      call run_one(path, o, t, files(n_files), error)
      if (allocated(error)) return
      names(n_files) = name
    end subroutine add_file

    !> The sheet `stem` drawn as `svg_format` (svg; plans: the graphical method's sheet) into
    !> stem.svg, then as DXF into stem.dxf (a plans sheet's DXF: --format dxf --plans).
    subroutine add_svg_and_dxf(stem, svg_format)
      character(*), intent(in) :: stem
      integer, intent(in) :: svg_format
      o%format = svg_format
      call add_file(trim(stem)//".svg")
      o%format = format_dxf
      if (svg_format == format_plans) o%plans = .true.
      call add_file(trim(stem)//".dxf")
    end subroutine add_svg_and_dxf
  end subroutine write_course_sheets

  !> The plan of positions of the kinematics sheet into options%course_plan: the output
  !> link's extreme position (the smallest s of a slider, ψ of a rocker) found by Newton's
  !> method on its velocity from the deck's step nearest to it (v = 0: phi <- phi - v
  !> omega1/a), then the run of the deck from that input angle at equal steps,
  !> rows_per_position a position, over one turn (two with a cycle of 720 deg). A kind whose
  !> input angle cannot be set (&pr3050) gets none. --point and --output-link are checked
  !> here (exit 2 naming the option).
  subroutine solve_positions(path, group, options, error)
    character(*), intent(in) :: path, group
    type(run_options_t), intent(inout) :: options
    type(error_t), allocatable, intent(out) :: error
    type(run_options_t) :: o
    type(step_table_t) :: base, probe
    type(text_buffer_t) :: scratch
    class(mechanism_t), allocatable :: mech
    type(sketch_t) :: topo
    type(drawing_t) :: drawing
    type(error_t), allocatable :: err
    real(wp), allocatable :: s(:), v(:), a(:)
    character(len=:), allocatable :: point, known, start_name, step_name, input
    logical :: slider
    integer :: link, link_number, c_in, c_omega, turns, n_rows, it, c, ios, every
    real(wp) :: phi, c0, sgn, step, phi_low, phi_high, d_low, d_high, stroke
    real(wp), allocatable :: s_base(:)
    character(len=:), allocatable :: pivot

    o = options
    o%format = format_summary
    o%kinematics = .true.
    o%at_step = 0
    o%course_sheet = course_none
    ! these runs' tables are read row by row: one block of the default size, whatever the
    ! maintainers' KINETOSTAT_BLOCK_ROWS (the sheets do not depend on it)
    o%block_rows = block_rows
    call run_one(path, o, base, scratch, error, mech)
    if (allocated(error)) return
    call mech%sketch(topo)
    if (.not. topo%available) return
    call drawing_from_sketch(topo, base, 1, drawing, err)
    if (allocated(err)) return
    call mech%force_plan(base, 1, drawing, err)
    if (allocated(err)) return
    call output_motion(topo, drawing, base, 1, options%course_output_link, link, slider, point, s, v, a, err)
    if (allocated(err)) then
      if (options%course_output_link > 0) call move_alloc(err, error)
      return
    end if
    if (allocated(options%course_point)) then
      if (base%column_index("x_"//options%course_point) == 0) then
        known = ""
        do c = 1, size(base%columns)
          if (index(base%columns(c)%name, "x_") /= 1) cycle
          if (len(known) > 0) known = known//", "
          known = known//base%columns(c)%name(3:)
        end do
        call fatal_error(error, exit_input, "--point "//options%course_point//": "//path//" has no point "// &
          options%course_point//" (points: "//known//")")
        return
      end if
    end if
    ! the deck's input angle and how to set it
    c_in = base%input_column
    if (c_in == 0) return
    input = base%columns(c_in)%name
    if (index(input, "phi") /= 1) return
    c_omega = base%column_index("omega"//input(4:))
    if (c_omega == 0) return
    select case (group)
    case ("pr3207", "assur", "sixbar")
      start_name = "phi_start"
      step_name = "dphi"
    case ("linkage")
      start_name = "drive(1)%start"
      step_name = "drive(1)%step"
    case default
      return
    end select
    known = trim(topo%links(link)%name)
    read (known, *, iostat=ios) link_number
    if (ios /= 0) return
    ! the input link's pivot (a slider's dead centres are told apart by the distance from it)
    pivot = ""
    do c = 1, size(topo%links)
      if (trim(topo%links(c)%name) /= input(4:) .or. .not. allocated(topo%pivots)) cycle
      do it = 1, size(topo%links(c)%points)
        if (any(topo%pivots == topo%links(c)%points(it))) then
          pivot = trim(topo%links(c)%points(it))
          exit
        end if
      end do
    end do
    turns = 1
    if (base%column_index("dT") > 0 .and. base%row_count() > 1) then
      if (maxval(base%rows(c_in, 1:base%row_count())) - minval(base%rows(c_in, 1:base%row_count())) > 540.0_wp) then
        turns = 2
      end if
    end if
    every = rows_per_position
    ! a &sixbar deck's load is a table of one value a step: its runs keep the deck's steps
    if (group == "sixbar") then
      every = (base%run_rows() - 1) / (turns * options%course_positions)
      if (every < 1 .or. every * turns * options%course_positions /= base%run_rows() - 1) return
    end if
    n_rows = turns * options%course_positions * every + 1
    step = 360.0_wp / real(options%course_positions * every, wp)
    ! the deck's angle against the table's: a run from the deck's angle 0
    c0 = 0.0_wp
    sgn = 1.0_wp
    call run_at(0.0_wp, probe)
    if (.not. allocated(probe%rows) .or. probe%row_count() < 2) return
    c0 = probe%rows(c_in, 1)
    sgn = sign(1.0_wp, probe%rows(c_in, 2) - c0)
    ! the two extremes: the deck's steps of the smallest and the largest s, then Newton on
    ! v = 0 from each
    if (size(s) < 1) return
    s_base = s
    phi_low = extreme(minloc(s_base, dim=1), d_low)
    phi_high = extreme(maxloc(s_base, dim=1), d_high)
    ! position 0 begins the working stroke, the longer one in crank angle (a quick-return
    ! mechanism's); strokes of equal angle (within 0.5 deg: a central slider-crank, an engine)
    ! begin at the extreme farther from the input link's pivot (a slider's top dead centre)
    stroke = modulo((phi_high - phi_low) * sgn, 360.0_wp)
    if (stroke > 180.5_wp) then
      phi = phi_low
    else if (stroke < 179.5_wp) then
      phi = phi_high
    else if (d_high >= d_low) then
      phi = phi_high
    else
      phi = phi_low
    end if
    call run_at(phi, probe)
    if (.not. allocated(probe%rows)) return
    allocate (options%course_plan, source=probe)
    options%course_every = every
  contains
    !> The input angle (deg) of the output link's extreme nearest the base run's row `r`:
    !> Newton's method on its velocity, phi <- phi - v omega1 / a (the row's angle when it
    !> does not converge near it); `far` the output point's distance from the input link's
    !> pivot there (m; 0 for a rocker).
    real(wp) function extreme(r, far) result(angle)
      integer, intent(in) :: r
      real(wp), intent(out) :: far
      integer :: i, cx, cy, px, py
      real(wp) :: step_angle
      angle = base%rows(c_in, r)
      far = 0.0_wp
      do i = 1, 12
        call run_at(angle, probe)
        if (.not. allocated(probe%rows)) return
        call output_motion(topo, drawing, probe, 1, link_number, link, slider, point, s, v, a, err)
        if (allocated(err)) return
        if (abs(a(1)) <= tiny(1.0_wp) .or. abs(probe%rows(c_omega, 1)) <= tiny(1.0_wp)) exit
        step_angle = -v(1) * probe%rows(c_omega, 1) / a(1) * 180.0_wp / acos(-1.0_wp)
        if (abs(step_angle) > 360.0_wp / real(options%course_positions, wp)) then
          angle = base%rows(c_in, r)
          exit
        end if
        angle = angle + step_angle
        if (abs(step_angle) < 1.0e-10_wp) exit
      end do
      call run_at(angle, probe)
      if (.not. allocated(probe%rows) .or. .not. slider .or. len(pivot) == 0) return
      cx = probe%column_index("x_"//point)
      cy = probe%column_index("y_"//point)
      px = probe%column_index("x_"//pivot)
      py = probe%column_index("y_"//pivot)
      if (min(cx, cy, px, py) > 0) far = norm2([probe%rows(cx, 1) - probe%rows(px, 1), &
        probe%rows(cy, 1) - probe%rows(py, 1)])
    end function extreme

    !> The run of the deck from the table's input angle `angle` (deg) at the plan's steps;
    !> a run that fails leaves `t` without rows (no plan).
    subroutine run_at(angle, t)
      real(wp), intent(in) :: angle
      type(step_table_t), intent(out) :: t
      type(run_options_t) :: p
      type(override_t), allocatable :: extra(:)
      type(text_buffer_t) :: text
      type(error_t), allocatable :: e
      real(wp) :: deck_angle
      integer :: n_extra
      deck_angle = (angle - c0) * sgn
      n_extra = 3
      if (group == "sixbar") n_extra = 4
      allocate (extra(n_extra))
      extra(1)%name = start_name
      extra(1)%value = real_text(deck_angle)
      extra(2)%name = step_name
      extra(2)%value = real_text(step)
      extra(3)%name = "n"
      extra(3)%value = int_str(n_rows)
      if (group == "sixbar") then
        extra(4)%name = "start_at_extreme"
        extra(4)%value = ".false."
      end if
      p = o
      if (allocated(p%overrides)) then
        p%overrides = [p%overrides, extra]
      else
        p%overrides = extra
      end if
      call run_one(path, p, t, text, e)
      if (allocated(e)) then
        if (allocated(t%rows)) deallocate (t%rows)
      end if
    end subroutine run_at
  end subroutine solve_positions

  !> A real in namelist syntax, all its digits.
  pure function real_text(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=32) :: buffer
    write (buffer, "(es25.17)") x
    text = trim(adjustl(buffer))
  end function real_text

  !> One run of the deck into `out` (no spool: the sheets are small); `mech` the mechanism
  !> run (its deck read).
  subroutine run_one(path, options, table, out, error, mech_out)
    character(*), intent(in) :: path
    type(run_options_t), intent(in) :: options
    type(step_table_t), intent(out) :: table
    type(text_buffer_t), intent(inout) :: out
    type(error_t), allocatable, intent(out) :: error
    class(mechanism_t), allocatable, intent(out), optional :: mech_out
    character(len=:), allocatable :: group
    class(mechanism_t), allocatable :: mech
    type(deck_source_t) :: source, patched
    call load_deck(path, source, error)
    if (allocated(error)) return
    call deck_mechanism(source, group, mech, error)
    if (allocated(error)) return
    if ((.not. mech%force_sheet .and. .not. allocated(mech%sheet_name)) .or. group == "gears" .or. &
        group == "cam") then
      call fatal_error(error, exit_usage, "sheets: "//source%path//" is &"//group//": the course sheets are drawn "// &
        "for linkages (pr3207, pr3050, sixbar, assur, linkage) and the designs (gear_geometry, "// &
        "planetary_synthesis, cam_profile)")
      return
    end if
    if (allocated(options%overrides)) then
      call apply_overrides(source, options%overrides, patched, error)
      if (allocated(error)) return
      call run_mechanism(mech, group, patched, options, table, out, error)
    else
      call run_mechanism(mech, group, source, options, table, out, error)
    end if
    if (present(mech_out)) call move_alloc(mech, mech_out)
  end subroutine run_one

  !> The place of the sheet called `name` in sheet_names (0: none).
  pure integer function sheet_index(name) result(k)
    character(*), intent(in) :: name
    do k = 1, size(sheet_names)
      if (trim(sheet_names(k)) == name) return
    end do
    k = 0
  end function sheet_index

  !> The step of the largest |effort| of the first drive at constant speed: the table's
  !> driver column; with a steady cycle (the columns J_red, dJ_red, M_red, dT and the true
  !> omega1), whose driver column is the constant M_d of the true motion, the effort of the
  !> force analysis before the flywheel, M1 = omega_m^2/2 dJ_red - M_red (omega_m = (omega_max
  !> + omega_min)/2: the drive's moment at the constant mean speed, which equals the driver
  !> column of a run with dynamics = 'reduced'). The first step without a driver column.
  pure integer function effort_step(table) result(k)
    type(step_table_t), intent(in) :: table
    type(column_stats_t) :: s
    integer :: c, cj, cm, cw, n
    real(wp) :: omega_m
    real(wp), allocatable :: effort(:)
    k = 1
    cj = table%column_index("dJ_red")
    cm = table%column_index("M_red")
    cw = table%column_index("omega1")
    if (cj > 0 .and. cm > 0 .and. cw > 0 .and. table%column_index("dT") > 0) then
      ! (a steady cycle is one block: its rows are all held)
      n = table%row_count()
      omega_m = 0.5_wp * (maxval(table%rows(cw, 1:n)) + minval(table%rows(cw, 1:n)))
      allocate (effort(n))
      effort(:) = 0.5_wp * omega_m**2 * table%rows(cj, 1:n) - table%rows(cm, 1:n)
      if (n > 0) k = table%run_row(maxloc(abs(effort), dim=1))
      return
    end if
    if (.not. allocated(table%driver)) return
    c = table%column_index(table%driver)
    if (c == 0) return
    s = column_stats(table, c)
    if (abs(s%max) >= abs(s%min)) then
      k = s%max_row
    else
      k = s%min_row
    end if
    k = max(1, k)
  end function effort_step

  !> A path quoted for the shell (single quotes; a quote inside as '\'').
  pure function quoted(text) result(q)
    character(*), intent(in) :: text
    character(len=:), allocatable :: q
    integer :: i
    q = "'"
    do i = 1, len(text)
      if (text(i:i) == "'") then
        q = q//"'\''"
      else
        q = q//text(i:i)
      end if
    end do
    q = q//"'"
  end function quoted

  !> Remove a file if it exists (an old sheet); an error when it stays.
  subroutine remove_file(path, error)
    character(*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: error
    integer :: unit, ios
    logical :: there
    inquire (file=path, exist=there)
    if (.not. there) return
    open (newunit=unit, file=path, status="old", iostat=ios)
    if (ios == 0) close (unit, status="delete", iostat=ios)
    if (ios /= 0) call fatal_error(error, exit_input, "sheets: cannot remove the earlier sheet "//path)
  end subroutine remove_file

end module kinetostat_sheets
