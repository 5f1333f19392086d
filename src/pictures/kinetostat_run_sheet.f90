!> The sheet of a run (`--format svg`, `--format dxf` without --at) on the drawing model, with
!> the ГОСТ 2.301 frame and the title block:
!> - the hodograph of every pair force: the tip of the force vector over the cycle in the
!>   tables' frame (x = F cos(FG), y = F sin(FG)), the origin marked, the points numbered by
!>   step (point k = step k, like fig. 9 of the 1991 manual), a scale bar in N; one panel
!>   per pair (`--pairs` selects);
!> - the driving moment (or force) against the input angle, with its mean over the cycle;
!> - the magnitudes of the pair forces against the input angle, with a legend;
!> - with a dynamics stage, the machine dynamics: J_red, M_red with M_d, ΔT, ω1 with its
!>   mean and extremes, Wittenbauer's ΔT(J_red);
!> - with --shaking, the shaking force F_shake (the resultant of the inertia forces, not a
!>   pair force: its own block) as a hodograph and the shaking moment M_shake against the
!>   input angle;
!> - a note when the input step is too coarse next to a load that switches (the curves are
!>   chords between steps; the coarse-step warning of the run).
!> A table without an input angle (gear stages) gets one panel per row with the pair forces
!> drawn as vectors from the origin instead (a vector under 1 mm is named in a note).
!> Paper: A4 portrait when the hodographs and the charts fit; A3 landscape in two columns
!> when the dynamics or the shaking blocks come too. Every series goes through
!> `plotted_indices`, the one place a long run is reduced to the points drawn. Same table ->
!> same entities.
module kinetostat_run_sheet
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp, deg_to_rad, version_string
  use kinetostat_error, only: error_t, fatal_error, exit_usage
  use kinetostat_text, only: int_str, upper, next_item
  use kinetostat_format, only: fixed_number, short_number, full_number
  use kinetostat_step_table, only: step_table_t, col_force, col_force_angle, col_moment
  use kinetostat_summary, only: coarse_step_warning, coarse_step_limit, column_stats, column_stats_t
  use kinetostat_row_keeper, only: bucket_extremes, all_rows_limit, sheet_buckets
  use kinetostat_svg, only: coord, palette_colour
  use kinetostat_labels, only: word => label, unit_word => unit_symbol
  use kinetostat_scales, only: nice_step, scale_number
  use kinetostat_typeset, only: typeset, runs_extent, char_count, unit_text
  use kinetostat_sheet, only: sheet_t, paper_t, iso_paper, layer_text, layer_charts, layer_scales, anchor_middle, &
    anchor_end
  use kinetostat_title_block, only: put_sheet_format, title_block_from_table, block_height
  implicit none
  private
  public :: write_run_sheet, pair_force_t, find_pair_forces, select_pair_forces, nice_step, cycle_mean, &
    plotted_indices, put_axes, y_range, wrapped, note_length

  !> Gap between panels, mm.
  real(wp), parameter :: gap = 3.5_wp
  !> Smallest and largest height of the charts row, mm.
  real(wp), parameter :: chart_height = 62.0_wp, chart_max_height = 100.0_wp
  !> Width of the driving-effort chart (the magnitudes chart takes the rest), mm.
  real(wp), parameter :: driver_chart_width = 80.0_wp
  !> Height of a chart of the machine dynamics, mm.
  real(wp), parameter :: dynamics_chart_height = 62.0_wp
  !> Height of the machine dynamics block: its heading and three rows of charts, mm.
  real(wp), parameter :: dynamics_block_height = 10.0_wp + 3.0_wp * (dynamics_chart_height + gap)
  !> Height of the shaking block: its heading and one row of panels, mm.
  real(wp), parameter :: shaking_block_height = 8.0_wp + 66.0_wp
  !> Most numbered points in one hodograph (beyond it every m-th step is numbered).
  integer, parameter :: max_point_labels = 24
  !> Font size of the class "small", mm.
  real(wp), parameter :: small_size = 2.4_wp
  !> Two points nearer than this share one number label ("1,13"), mm.
  real(wp), parameter :: label_merge_distance = 1.0_wp
  !> Bytes of a line of a note, at most.
  integer, parameter :: note_length = 400
  !> The name of the shaking force's column (--shaking).
  character(*), parameter :: shaking_force = "F_shake"

  !> A pair force of the table: its magnitude and angle columns.
  type :: pair_force_t
    !> Name ("F16").
    character(len=:), allocatable :: name
    !> Column of the magnitude, N.
    integer :: magnitude = 0
    !> Column of the angle, deg (counterclockwise from the x axis of the tables).
    integer :: angle = 0
  end type pair_force_t

contains

  !> The sheet of a run. `pairs` is the --pairs list ("F16,F36"; "" for every pair force).
  pure subroutine write_run_sheet(title, table, pairs, lang, sheet, error)
    !> Title of the mechanism.
    character(*), intent(in) :: title
    !> Finite results.
    type(step_table_t), intent(in) :: table
    !> Comma-separated pair names, or "".
    character(*), intent(in) :: pairs
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> The sheet made.
    type(sheet_t), intent(out) :: sheet
    !> Usage error: a name in `pairs` that is no pair force of the table.
    type(error_t), allocatable, intent(out) :: error
    type(pair_force_t), allocatable :: every_pair(:), chosen(:)
    type(paper_t) :: paper
    character(len=note_length), allocatable :: note(:)
    integer :: columns, rows, n_panels, i
    real(wp) :: panel_w, panel_h, y, x0, y0, chart_h, inner(4), col(4), col2(4), top, run_h, width, reserved
    logical :: dynamics, shaking, two_columns

    allocate (every_pair(0)) ! defined before the call (gcc's -Wmaybe-uninitialized on the descriptor)
    call find_pair_forces(table, every_pair)
    call select_pair_forces(table, every_pair, pairs, chosen, error)
    if (allocated(error)) return
    dynamics = table%column_index("dT") > 0 .and. table%input_column > 0
    shaking = table%column_index(shaking_force) > 0 .and. table%column_index("M_shake") > 0 .and. &
      table%input_column > 0

    if (table%input_column > 0) then
      n_panels = size(chosen)
    else
      n_panels = table%row_count()
    end if
    ! A4 portrait; A3 portrait with the shaking block under the charts; A3 landscape in two
    ! columns with the dynamics (and the shaking block under the charts)
    two_columns = dynamics
    if (dynamics) then
      paper = iso_paper("A3", .true.)
    else if (shaking) then
      paper = iso_paper("A3", .false.)
    else
      paper = iso_paper("A4", .false.)
    end if
    inner = paper%inside()
    if (two_columns) then
      col = [inner(1) + 3.0_wp, inner(2), inner(1) + 195.0_wp, inner(4) - 2.0_wp]
      col2 = [col(3) + 6.0_wp, inner(2), inner(3) - 3.0_wp, inner(4) - block_height - 3.0_wp]
    else
      col = [inner(1) + 3.0_wp, inner(2), inner(3) - 3.0_wp, inner(4) - block_height - 3.0_wp]
    end if
    width = col(3) - col(1)
    call coarse_note(table, lang, width, note)
    top = 27.0_wp + 3.2_wp * size(note)
    ! the panels: about 60 mm wide, smaller when the charts would not fit under them
    reserved = 0.0_wp
    if (shaking) reserved = shaking_block_height + gap
    columns = max(3, nint(width / 62.0_wp))
    ! a table of stages: as large as the column allows, up to three across
    if (table%input_column == 0) columns = min(3, max(1, n_panels))
    do
      call panel_grid(columns, width, panel_w, panel_h)
      rows = (n_panels + columns - 1) / columns
      y = top + 12.0_wp + rows * (panel_h + gap)
      if (table%input_column == 0) panel_h = min(panel_h, 150.0_wp)
      y = top + 12.0_wp + rows * (panel_h + gap)
      if (table%input_column == 0 .or. y + chart_height + reserved <= col(4) .or. columns >= 6) exit
      columns = columns + 1
    end do
    run_h = col(4) - y - 2.0_wp - reserved
    chart_h = min(chart_max_height, max(chart_height, run_h))
    if (table%input_column == 0) chart_h = 0.0_wp

    call sheet%open(paper, lang, title//" - "//table%deck, &
      "kinetostat sheet of "//table%deck//". Hodograph paths (class hodograph, data-force = the "// &
      "pair): page point = data-origin + data-scale * (Fx, -Fy), in mm, data-scale in mm per N; point k of a "// &
      "path is step k of the CSV.")
    call put_sheet_format(sheet, title_block_from_table(table, word("Hodographs and diagrams", lang), ""))
    call sheet%set_layer(layer_text)
    call put_header(sheet, title, table, lang, col(1), inner(3) - inner(1) - 6.0_wp, note)

    call sheet%set_layer(layer_charts)
    if (table%input_column > 0) then
      call sheet%text(col(1), top + 5.0_wp, word("Hodographs of the pair forces", lang), "heading")
      call sheet%text(col(1), top + 9.0_wp, word("Tip of each force vector over the cycle, in the frame of the "// &
        "tables (x right, y up); point k = step k; O = zero force.", lang), "small", &
        size=min(small_size, fitting_size(word("Tip of each force vector over the cycle, in the frame of the "// &
        "tables (x right, y up); point k = step k; O = zero force.", lang), width)))
      do i = 1, size(chosen)
        call panel_origin(i, columns, panel_w, panel_h, col(1), top + 12.0_wp, x0, y0)
        call put_hodograph(sheet, table, chosen(i), x0, y0, panel_w, panel_h, lang, chosen(i)%name)
      end do
      if (size(chosen) == 0) call sheet%text(col(1), top + 17.0_wp, &
        word("This table has no pair force with an angle column: no hodographs.", lang), "note")
      y = top + 12.0_wp + rows * (panel_h + gap)
      call put_driver_chart(sheet, table, col(1), y, driver_chart_width, chart_h, lang)
      call put_magnitude_chart(sheet, table, chosen, col(1) + driver_chart_width + gap, y, &
        width - driver_chart_width - gap, chart_h, lang)
      y = y + chart_h + gap
      if (dynamics) call put_dynamics_charts(sheet, table, col2(1), top, col2(3) - col2(1), lang)
      if (shaking) call put_shaking(sheet, table, col(1), y, width, lang)
    else
      call sheet%text(col(1), top + 5.0_wp, word("Pair forces of every " // table%row_name // " as vectors", lang), &
        "heading")
      call sheet%text(col(1), top + 9.0_wp, word("The rows of this table are " // table%row_name // &
        "s, not steps of a cycle: no hodographs and no diagrams against an input angle.", lang), "small")
      do i = 1, table%row_count()
        call panel_origin(i, columns, panel_w, panel_h, col(1), top + 12.0_wp, x0, y0)
        call put_vector_panel(sheet, table, chosen, i, x0, y0, panel_w, panel_h, lang)
      end do
    end if
  end subroutine write_run_sheet

  !> Size of a panel of a grid of `columns` panels across `width` mm.
  pure subroutine panel_grid(columns, width, panel_w, panel_h)
    integer, intent(in) :: columns
    real(wp), intent(in) :: width
    real(wp), intent(out) :: panel_w, panel_h
    panel_w = (width - (columns - 1) * gap) / columns
    panel_h = panel_w + 4.0_wp
  end subroutine panel_grid

  !> Top-left corner of panel `i` (1-based, row by row) of a grid starting at (left, top).
  pure subroutine panel_origin(i, columns, panel_w, panel_h, left, top, x0, y0)
    integer, intent(in) :: i, columns
    real(wp), intent(in) :: panel_w, panel_h, left, top
    real(wp), intent(out) :: x0, y0
    x0 = left + modulo(i - 1, columns) * (panel_w + gap)
    y0 = top + ((i - 1) / columns) * (panel_h + gap)
  end subroutine panel_origin

  !> Title, deck, row range and program lines at the top of the sheet, and the notes.
  pure subroutine put_header(sheet, title, table, lang, x, width, note)
    type(sheet_t), intent(inout) :: sheet
    character(*), intent(in) :: title
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    real(wp), intent(in) :: x, width
    character(*), intent(in) :: note(:)
    character(len=:), allocatable :: line
    integer :: n, i
    call sheet%text(x, 12.0_wp, title, "title", size=min(3.3_wp, fitting_size(title, width) * 0.6_wp / 0.8_wp), &
      plain=.true.)
    line = word("deck", lang)//": "//table%deck
    if (allocated(table%subtitle)) line = line//"   "//table%subtitle
    call sheet%text(x, 17.5_wp, line, "subtitle", size=min(3.0_wp, fitting_size(line, width)), plain=.true.)
    n = table%run_rows()
    if (n /= 1) then
      line = int_str(n)//" "//word(table%row_name//"s", lang)
    else
      line = int_str(n)//" "//word(table%row_name, lang)
    end if
    if (table%input_column > 0 .and. n > 0) then
      associate (c => table%columns(table%input_column))
        line = line//", "//c%name//" = "//short_number(table%rows(table%input_column, 1))
        if (n > 1) line = line//" ... "//short_number(table%rows(table%input_column, table%row_count()))
        line = line//" "//unit_word(c%unit, lang)
      end associate
    end if
    line = line//"; "//version_string
    call sheet%text(x, 22.5_wp, line, "small")
    do i = 1, size(note)
      call sheet%text(x, 27.0_wp + 3.2_wp * (i - 1), trim(note(i)), "note", colour="#b22222")
    end do
  end subroutine put_header

  !> The sheet's note when the run's input step is too coarse next to a switching load (the
  !> coarse-step warning): its lines, `width` mm wide at most; none otherwise.
  pure subroutine coarse_note(table, lang, width, lines)
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    real(wp), intent(in) :: width
    character(len=note_length), allocatable, intent(out) :: lines(:)
    character(len=:), allocatable :: warning, text
    call coarse_step_warning(table, warning)
    if (.not. allocated(warning)) then
      allocate (lines(0))
      return
    end if
    text = word("The input step", lang)//" "//scale_number(table%run_tally%largest_step)//" "//unit_word("deg", lang)//" "// &
      word("is coarser than", lang)//" "//scale_number(coarse_step_limit)//" "//unit_word("deg", lang)//" "// &
      word("next to a load that switches on or off", lang)//": "//word("the curves join the steps by chords and "// &
      "may miss the true peaks and the true mean; rerun with a finer step", lang)//"."
    call wrapped(text, int(width / (0.6_wp * 2.6_wp)), lines)
  end subroutine coarse_note

  !> `text` cut at blanks into lines of at most `most` characters (UTF-8 characters).
  pure subroutine wrapped(text, most, lines)
    character(*), intent(in) :: text
    integer, intent(in) :: most
    character(len=note_length), allocatable, intent(out) :: lines(:)
    character(len=note_length), allocatable :: found(:)
    integer :: start, cut, i
    allocate (found(0))
    start = 1
    do while (start <= len(text))
      cut = len(text)
      if (char_count(text(start:)) > most) then
        cut = start
        do i = start, len(text)
          if (char_count(text(start:i)) > most) exit
          if (text(i:i) == " ") cut = i
        end do
        if (cut == start) cut = i - 1
      end if
      found = [character(len=note_length) :: found, text(start:cut)]
      start = cut + 1
    end do
    lines = found
  end subroutine wrapped

  !> A text as it is written on a sheet (its units typographic), for measuring it.
  pure function unit_text_of(text) result(out)
    character(*), intent(in) :: text
    character(len=:), allocatable :: out
    out = unit_text(text)
  end function unit_text_of

  !> The font size (mm) at which `text` at 0.6 x size per character fills `width` mm.
  pure real(wp) function fitting_size(text, width)
    character(*), intent(in) :: text
    real(wp), intent(in) :: width
    real(wp) :: w, above, below
    call runs_extent(typeset(text, 1), w, above, below)
    fitting_size = huge(1.0_wp)
    if (w > 0.0_wp) fitting_size = floor(width / w * 100.0_wp) / 100.0_wp
  end function fitting_size

  !> Every pair force of the table: a force column (col_force) followed by its angle column
  !> (col_force_angle, named as the force with "G" appended), in column order; the shaking
  !> force (--shaking) is no pair force.
  pure subroutine find_pair_forces(table, pairs)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> The pair forces.
    type(pair_force_t), allocatable, intent(out) :: pairs(:)
    integer :: c, a
    allocate (pairs(0))
    do c = 1, size(table%columns)
      if (table%columns(c)%kind /= col_force) cycle
      if (table%columns(c)%name == shaking_force) cycle
      a = table%column_index(table%columns(c)%name//"G")
      if (a == 0) cycle
      if (table%columns(a)%kind /= col_force_angle) cycle
      call push_pair(pairs, table%columns(c)%name, c, a)
    end do
  end subroutine find_pair_forces

  !> The pair forces named in `list` (comma-separated, any case, in the list's order); all of
  !> them when `list` is blank. A name that is not a pair force is a usage error naming the
  !> deck and the pair forces there are; the shaking force's name is taken (its own block
  !> shows it).
  pure subroutine select_pair_forces(table, pairs, list, chosen, error)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> Every pair force of the table.
    type(pair_force_t), intent(in) :: pairs(:)
    !> The --pairs list, or "".
    character(*), intent(in) :: list
    !> The selection.
    type(pair_force_t), allocatable, intent(out) :: chosen(:)
    !> Usage error.
    type(error_t), allocatable, intent(out) :: error
    character(len=:), allocatable :: name, known
    integer :: start, i, k
    allocate (chosen(0))
    if (len_trim(list) == 0) then
      do i = 1, size(pairs)
        call push_pair(chosen, pairs(i)%name, pairs(i)%magnitude, pairs(i)%angle)
      end do
      return
    end if
    start = 1
    do while (start > 0)
      call next_item(list, start, name)
      k = 0
      do i = 1, size(pairs)
        if (upper(pairs(i)%name) == upper(name)) k = i
      end do
      if (k == 0 .and. .not. (upper(name) == upper(shaking_force) .and. table%column_index(shaking_force) > 0)) then
        known = ""
        do i = 1, size(pairs)
          if (i > 1) known = known//", "
          known = known//pairs(i)%name
        end do
        if (size(pairs) == 0) known = "none"
        call fatal_error(error, exit_usage, "--pairs: '"//name//"' is not a pair force of "//table%deck// &
          " (pair forces: "//known//")")
        return
      end if
      if (k > 0) call push_pair(chosen, pairs(k)%name, pairs(k)%magnitude, pairs(k)%angle)
    end do
  end subroutine select_pair_forces

  !> Append a pair force to a list (element by element: gfortran loses deferred-length
  !> character components in array constructors of derived types).
  pure subroutine push_pair(list, name, magnitude, angle)
    type(pair_force_t), allocatable, intent(inout) :: list(:)
    character(*), intent(in) :: name
    integer, intent(in) :: magnitude, angle
    type(pair_force_t), allocatable :: grown(:)
    integer :: i
    allocate (grown(size(list) + 1))
    do i = 1, size(list)
      grown(i)%name = list(i)%name
      grown(i)%magnitude = list(i)%magnitude
      grown(i)%angle = list(i)%angle
    end do
    grown(size(grown))%name = name
    grown(size(grown))%magnitude = magnitude
    grown(size(grown))%angle = angle
    call move_alloc(grown, list)
  end subroutine push_pair

  !> Components of pair `p` at every row, N: x = F cos(FG), y = F sin(FG).
  pure subroutine pair_components(table, p, fx, fy)
    type(step_table_t), intent(in) :: table
    type(pair_force_t), intent(in) :: p
    real(wp), allocatable, intent(out) :: fx(:), fy(:)
    fx = table%rows(p%magnitude, :) * cos(table%rows(p%angle, :) * deg_to_rad)
    fy = table%rows(p%magnitude, :) * sin(table%rows(p%angle, :) * deg_to_rad)
  end subroutine pair_components

  !> Mean of y over the range of x (trapezoidal rule: the work of a driving moment over the
  !> cycle divided by the angle turned); the plain mean when x does not advance.
  pure real(wp) function cycle_mean(x, y)
    !> Input coordinate at every row.
    real(wp), intent(in) :: x(:)
    !> Values.
    real(wp), intent(in) :: y(:)
    integer :: n
    n = size(x)
    cycle_mean = 0.0_wp
    if (n == 0) return
    if (n == 1 .or. x(n) == x(1)) then
      cycle_mean = sum(y) / n
      return
    end if
    cycle_mean = sum((x(2:n) - x(1:n - 1)) * (y(2:n) + y(1:n - 1))) / (2.0_wp * (x(n) - x(1)))
  end function cycle_mean

  !> Decimals of tick labels at a step of `step`.
  pure integer function tick_decimals(step)
    real(wp), intent(in) :: step
    tick_decimals = max(0, -floor(log10(step) + 1.0e-9_wp))
  end function tick_decimals

  !> A scale bar: a nice force near a quarter of `extent` (N), drawn `scale` mm per N at
  !> (x, y) with end ticks and its value.
  pure subroutine put_scale_bar(sheet, x, y, extent, scale, lang)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: x, y, extent, scale
    integer, intent(in) :: lang
    real(wp) :: value, length
    value = nice_step(extent, 4, .false.)
    if (value * scale > 40.0_wp) value = value / 2.0_wp
    length = value * scale
    call sheet%set_layer(layer_scales)
    call sheet%line(x, y, x + length, y, "scale")
    call sheet%line(x, y - 1.0_wp, x, y + 1.0_wp, "scale")
    call sheet%line(x + length, y - 1.0_wp, x + length, y + 1.0_wp, "scale")
    call sheet%text(x + length + 1.5_wp, y + 0.9_wp, short_number(value)//" "//unit_word("N", lang), "small")
    call sheet%set_layer(layer_charts)
  end subroutine put_scale_bar

  !> Map data points (N) into the rectangle (ax, ay, aw, ah) at one scale for both axes,
  !> the origin (0, 0) included and centred with the data; the origin's page point is
  !> rounded to the coordinate grid so that every page point is exactly origin + scale * F.
  pure subroutine fit_points(fx, fy, ax, ay, aw, ah, ox, oy, scale, extent)
    real(wp), intent(in) :: fx(:), fy(:), ax, ay, aw, ah
    !> Page point of the origin, mm.
    real(wp), intent(out) :: ox, oy
    !> mm per N (0 when every point is the origin).
    real(wp), intent(out) :: scale
    !> Largest extent of the data box, N.
    real(wp), intent(out) :: extent
    real(wp) :: xmin, xmax, ymin, ymax, dx, dy, tiny
    xmin = min(0.0_wp, minval(fx))
    xmax = max(0.0_wp, maxval(fx))
    ymin = min(0.0_wp, minval(fy))
    ymax = max(0.0_wp, maxval(fy))
    dx = xmax - xmin
    dy = ymax - ymin
    extent = max(dx, dy)
    ox = ax + 0.5_wp * aw
    oy = ay + 0.5_wp * ah
    scale = 0.0_wp
    if (extent <= 0.0_wp) return
    tiny = 1.0e-6_wp * extent
    scale = min(aw / max(dx, tiny), ah / max(dy, tiny))
    ox = anint((ax + 0.5_wp * aw - scale * 0.5_wp * (xmin + xmax)) * 100.0_wp) / 100.0_wp
    oy = anint((ay + 0.5_wp * ah + scale * 0.5_wp * (ymin + ymax)) * 100.0_wp) / 100.0_wp
  end subroutine fit_points

  !> The rows a series is drawn through, in order: every row of a run of up to all_rows_limit
  !> (4096) rows; of a longer one the smallest and largest value of each column of `values`
  !> per bucket of the run's rows (kinetostat_row_keeper's bucket_extremes: at most 4096
  !> points, every peak survives). The one place where a series is turned into plotted points.
  pure subroutine plotted_indices(table, values, keep)
    !> The table the series comes from (its rows are the run's rows, or a drawing's selection).
    type(step_table_t), intent(in) :: table
    !> One column per drawn coordinate, one row per row of the table.
    real(wp), intent(in) :: values(:, :)
    !> The rows kept, increasing.
    integer, allocatable, intent(out) :: keep(:)
    integer :: k
    if (.not. thinned_run(table)) then
      keep = [(k, k=1, size(values, 1))]
    else
      call bucket_extremes(values, [(table%run_row(k), k=1, size(values, 1))], table%run_rows(), &
        sheet_buckets / size(values, 2), keep)
    end if
  end subroutine plotted_indices

  !> Whether the table's curves go through a part of its run's rows (plotted_indices).
  pure logical function thinned_run(table)
    type(step_table_t), intent(in) :: table
    thinned_run = table%run_rows() > all_rows_limit
  end function thinned_run

  !> The origin of a force diagram: light axes across the plot area and a small circle; its
  !> labels "x", "y", "O" are placed with the step numbers.
  pure subroutine put_origin(sheet, ox, oy, ax, ay, aw, ah)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: ox, oy, ax, ay, aw, ah
    call sheet%line(ax, oy, ax + aw, oy, "faint")
    call sheet%line(ox, ay, ox, ay + ah, "faint")
    call sheet%circle(ox, oy, 0.7_wp, "origin")
  end subroutine put_origin

  !> The labels of an origin: x at the end of its axis, y at the top of its own, O by the
  !> origin, inside `bounds`.
  pure subroutine put_origin_labels(sheet, ox, oy, ax, ay, aw, bounds)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: ox, oy, ax, ay, aw, bounds(4)
    call sheet%place_label("x", "small", ax + aw, oy, -0.75_wp * 3.141592653589793_wp, bounds)
    call sheet%place_label("y", "small", ox, ay, -0.25_wp * 3.141592653589793_wp, bounds)
    call sheet%place_label("O", "small", ox, oy, 0.75_wp * 3.141592653589793_wp, bounds)
  end subroutine put_origin_labels

  !> One hodograph panel with its top-left corner at (x0, y0), titled `heading`.
  pure subroutine put_hodograph(sheet, table, p, x0, y0, w, h, lang, heading)
    type(sheet_t), intent(inout) :: sheet
    type(step_table_t), intent(in) :: table
    type(pair_force_t), intent(in) :: p
    real(wp), intent(in) :: x0, y0, w, h
    integer, intent(in) :: lang
    character(*), intent(in) :: heading
    real(wp), allocatable :: fx(:), fy(:), px(:), py(:)
    real(wp) :: ax, ay, aw, ah, ox, oy, scale, extent, bounds(4)
    integer :: k, n
    integer, allocatable :: keep(:)
    logical :: thinned
    n = table%row_count()
    call pair_components(table, p, fx, fy)
    ! a long run: the curve through its extremes, without rays, dots and step numbers
    call plotted_indices(table, reshape([fx, fy], [n, 2]), keep)
    thinned = thinned_run(table)
    fx = fx(keep)
    fy = fy(keep)
    call sheet%rect(x0, y0, w, h, "panel")
    call sheet%text(x0 + 2.0_wp, y0 + 4.5_wp, heading, "label", bold=.true.)
    call sheet%text(x0 + w - 2.0_wp, y0 + 4.5_wp, word("max", lang)//" "// &
      short_number(maxval(table%rows(p%magnitude, :)))//" "//unit_word("N", lang), "small", anchor_end)
    ax = x0 + 5.0_wp
    ay = y0 + 9.0_wp
    aw = w - 10.0_wp
    ah = h - 19.0_wp
    bounds = [x0 + 0.8_wp, y0 + 6.0_wp, x0 + w - 0.8_wp, y0 + h - 7.0_wp]
    call fit_points(fx, fy, ax, ay, aw, ah, ox, oy, scale, extent)
    call put_origin(sheet, ox, oy, ax - 3.0_wp, ay - 3.0_wp, aw + 6.0_wp, ah + 6.0_wp)
    if (scale <= 0.0_wp) then
      call sheet%text(x0 + 0.5_wp * w, y0 + h - 4.0_wp, p%name//" = 0 "//word("at every step", lang), "note", &
        anchor_middle)
      call put_origin_labels(sheet, ox, oy, ax - 3.0_wp, ay - 3.0_wp, aw + 6.0_wp, bounds)
      return
    end if
    px = ox + scale * fx
    py = oy - scale * fy
    call put_scale_bar(sheet, x0 + 3.0_wp, y0 + h - 4.0_wp, extent, scale, lang)
    if (thinned) then
      call sheet%polyline(px, py, "hodograph")
      call hodograph_data(sheet)
      call sheet%attach("data-steps", int_str(table%run_rows()))
      call sheet%attach("data-thinned", int_str(size(keep)))
      call sheet%text(x0 + w - 2.0_wp, y0 + h - 8.0_wp, int_str(size(keep))//" "//word("of", lang)//" "// &
        int_str(table%run_rows())//" "//word("points drawn", lang), "small", anchor_end)
      call put_origin_labels(sheet, ox, oy, ax - 3.0_wp, ay - 3.0_wp, aw + 6.0_wp, bounds)
      return
    end if
    do k = 1, n
      call sheet%line(ox, oy, px(k), py(k), "ray")
    end do
    call sheet%polyline(px, py, "hodograph")
    call hodograph_data(sheet)
    do k = 1, n
      call sheet%circle(px(k), py(k), 0.45_wp, "point")
    end do
    call put_origin_labels(sheet, ox, oy, ax - 3.0_wp, ay - 3.0_wp, aw + 6.0_wp, bounds)
    call put_point_numbers(sheet, px, py, bounds)
  contains
    !> The data attributes of the hodograph's path.
    pure subroutine hodograph_data(sheet)
      type(sheet_t), intent(inout) :: sheet
      call sheet%attach("data-force", p%name)
      call sheet%attach("data-origin", coord(ox)//" "//coord(oy))
      call sheet%attach("data-scale", full_number(scale))
    end subroutine hodograph_data
  end subroutine put_hodograph

  !> Step numbers beside the points: points closer than label_merge_distance share one
  !> label ("1,13", "1-13" for a run); with many steps only every m-th step is numbered.
  !> Each label goes to a free place near its point off the drawn lines, inside `bounds`.
  pure subroutine put_point_numbers(sheet, px, py, bounds)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: px(:), py(:), bounds(4)
    integer, allocatable :: owner(:), members(:)
    real(wp) :: cx, cy
    character(len=:), allocatable :: text
    integer :: n, k, j, every
    n = size(px)
    if (n == 0) return
    every = (n + max_point_labels - 1) / max_point_labels
    allocate (owner(n))
    owner = 0
    do k = 1, n
      if (modulo(k - 1, every) /= 0 .and. k /= n) cycle
      owner(k) = k
      do j = 1, k - 1
        if (owner(j) /= j) cycle
        if (hypot(px(k) - px(j), py(k) - py(j)) < label_merge_distance) then
          owner(k) = j
          exit
        end if
      end do
    end do
    cx = sum(px) / n
    cy = sum(py) / n
    do k = 1, n
      if (owner(k) /= k) cycle
      members = pack([(j, j=1, n)], owner == k)
      text = run_list(members)
      ! many coinciding steps: the first two and the last ("1,17..361")
      if (len(text) > 16 .and. size(members) > 3) text = int_str(members(1))//","//int_str(members(2))//".."// &
        int_str(members(size(members)))
      call sheet%place_label(text, "num", px(k), py(k), atan2(py(k) - cy, px(k) - cx), bounds)
    end do
  end subroutine put_point_numbers

  !> "1,13", "1-13", "2,5-7": sorted step numbers, runs of three or more as a range.
  pure function run_list(members) result(text)
    integer, intent(in) :: members(:)
    character(len=:), allocatable :: text
    integer :: i, j
    text = ""
    i = 1
    do while (i <= size(members))
      j = i
      do while (j < size(members))
        if (members(j + 1) /= members(j) + 1) exit
        j = j + 1
      end do
      if (len(text) > 0) text = text//","
      if (j - i >= 2) then
        text = text//int_str(members(i))//"-"//int_str(members(j))
        i = j + 1
      else
        text = text//int_str(members(i))
        i = i + 1
      end if
    end do
  end function run_list

  !> Axes of a chart: the plot rectangle, grid and tick labels for x in [xlo, xhi] and y in
  !> [ylo, yhi], and the axis labels.
  pure subroutine put_axes(sheet, left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, xlabel, ylabel)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep
    character(*), intent(in) :: xlabel, ylabel
    real(wp) :: v, t
    integer :: i, decimals
    decimals = tick_decimals(xstep)
    do i = ceiling(xlo / xstep - 1.0e-9_wp), floor(xhi / xstep + 1.0e-9_wp)
      v = i * xstep
      t = left + pw * (v - xlo) / (xhi - xlo)
      call sheet%line(t, top, t, top + ph, "grid")
      call sheet%line(t, top + ph, t, top + ph + 1.0_wp, "axis")
      call sheet%text(t, top + ph + 3.8_wp, fixed_number(v, decimals), "small", anchor_middle)
    end do
    decimals = tick_decimals(ystep)
    do i = nint(ylo / ystep), nint(yhi / ystep)
      v = i * ystep
      t = top + ph - ph * (v - ylo) / (yhi - ylo)
      call sheet%line(left, t, left + pw, t, "grid")
      call sheet%line(left - 1.0_wp, t, left, t, "axis")
      call sheet%text(left - 1.5_wp, t + 0.8_wp, fixed_number(v, decimals), "small", anchor_end)
    end do
    if (ylo < 0.0_wp .and. yhi > 0.0_wp) then
      t = top + ph - ph * (0.0_wp - ylo) / (yhi - ylo)
      call sheet%line(left, t, left + pw, t, "faint")
    end if
    call sheet%rect(left, top, pw, ph, "axis")
    call sheet%text(left + 0.5_wp * pw, top + ph + 8.0_wp, xlabel, "label", anchor_middle)
    call sheet%text(left - 12.0_wp, top + 0.5_wp * ph, ylabel, "label", anchor_middle, rotation=-90.0_wp)
  end subroutine put_axes

  !> Range and tick step of a chart's y axis over `values`, zero included.
  pure subroutine y_range(values, lo, hi, step)
    real(wp), intent(in) :: values(:)
    real(wp), intent(out) :: lo, hi, step
    real(wp) :: vmin, vmax
    vmin = min(0.0_wp, minval(values))
    vmax = max(0.0_wp, maxval(values))
    if (vmax - vmin <= 0.0_wp) vmax = vmin + 1.0_wp
    step = nice_step(vmax - vmin, 5, .false.)
    lo = step * floor(vmin / step + 1.0e-9_wp)
    hi = step * ceiling(vmax / step - 1.0e-9_wp)
  end subroutine y_range

  !> Range and tick step of a chart's x axis (the input coordinate): the data's range.
  pure subroutine x_range(values, degrees, lo, hi, step)
    real(wp), intent(in) :: values(:)
    logical, intent(in) :: degrees
    real(wp), intent(out) :: lo, hi, step
    lo = minval(values)
    hi = maxval(values)
    if (hi - lo <= 0.0_wp) then
      lo = lo - 1.0_wp
      hi = hi + 1.0_wp
    end if
    step = nice_step(hi - lo, 6, degrees)
  end subroutine x_range

  !> One data series of a chart: a line and a dot at every row (a long run: the line through
  !> its plotted points, no dots); `dotted` false for a dashed second curve.
  pure subroutine put_series(sheet, table, x, y, colour, dash, dotted)
    type(sheet_t), intent(inout) :: sheet
    !> The table the series comes from (one point per row).
    type(step_table_t), intent(in) :: table
    real(wp), intent(in) :: x(:), y(:)
    character(*), intent(in) :: colour, dash
    logical, intent(in) :: dotted
    integer :: k
    integer, allocatable :: keep(:)
    call plotted_indices(table, reshape(y, [size(y), 1]), keep)
    call sheet%polyline(x(keep), y(keep), stroke=colour, width=0.4_wp, dash=dash)
    if (thinned_run(table) .or. .not. dotted) return
    do k = 1, size(x)
      call sheet%circle(x(k), y(k), 0.45_wp, fill=colour)
    end do
  end subroutine put_series

  !> The driving moment (or force) of the table against its input coordinate, with its mean.
  pure subroutine put_driver_chart(sheet, table, x0, y0, w, h, lang)
    type(sheet_t), intent(inout) :: sheet
    type(step_table_t), intent(in) :: table
    real(wp), intent(in) :: x0, y0, w, h
    integer, intent(in) :: lang
    real(wp), allocatable :: x(:), y(:)
    real(wp) :: left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, mean, t
    type(column_stats_t) :: stats
    character(len=:), allocatable :: what
    integer :: c, ci
    ci = table%input_column
    c = 0
    if (allocated(table%driver)) c = table%column_index(table%driver)
    call sheet%rect(x0, y0, w, h, "panel")
    if (c == 0 .or. table%row_count() == 0) then
      call sheet%text(x0 + 2.0_wp, y0 + 5.0_wp, word("Driving effort", lang), "heading")
      call sheet%text(x0 + 2.0_wp, y0 + 12.0_wp, word("This table has no driving moment or force column.", lang), &
        "note")
      return
    end if
    what = word("Driving force", lang)
    if (table%columns(c)%kind == col_moment) what = word("Driving moment", lang)
    call sheet%text(x0 + 2.0_wp, y0 + 5.0_wp, what//" "//table%columns(c)%name//" "//word("against", lang)// &
      " "//table%columns(ci)%name, "heading")
    left = x0 + 17.0_wp
    top = y0 + 9.0_wp
    pw = w - 21.0_wp
    ph = h - 22.0_wp
    call x_range(table%rows(ci, :), table%columns(ci)%unit == "deg", xlo, xhi, xstep)
    if (table%row_count() < table%run_rows()) then
      ! the rows held are a selection of a long run's: its mean as the run's summary has it
      stats = column_stats(table, c)
      mean = stats%mean
    else
      mean = cycle_mean(table%rows(ci, :), table%rows(c, :))
    end if
    ! roundoff of a mean that is zero (a conservative cycle): printed as 0, not -5.53E-16
    if (abs(mean) <= 1.0e-12_wp * maxval(abs(table%rows(c, :)))) mean = 0.0_wp
    call y_range([table%rows(c, :), mean], ylo, yhi, ystep)
    call put_axes(sheet, left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, &
      table%columns(ci)%name//", "//unit_word(table%columns(ci)%unit, lang), &
      table%columns(c)%name//", "//unit_word(table%columns(c)%unit, lang))
    x = left + pw * (table%rows(ci, :) - xlo) / (xhi - xlo)
    y = top + ph - ph * (table%rows(c, :) - ylo) / (yhi - ylo)
    call put_series(sheet, table, x, y, "#1f77b4", "", .true.)
    t = top + ph - ph * (mean - ylo) / (yhi - ylo)
    call sheet%line(left, t, left + pw, t, "mean")
    what = word("mean", lang)//" "//short_number(mean)//" "//unit_word(table%columns(c)%unit, lang)
    call sheet%text(x0 + w - 1.5_wp, y0 + h - 2.2_wp, what, "small", anchor_end)
    t = x0 + w - 1.5_wp - 0.6_wp * small_size * char_count(unit_text_of(what)) - 1.0_wp
    call sheet%line(t - 6.0_wp, y0 + h - 3.0_wp, t, y0 + h - 3.0_wp, "mean")
  end subroutine put_driver_chart

  !> The machine dynamics of a steady cycle (the course's dynamics drawing) in a column at
  !> (x0, y0), `width` mm wide: J_red, M_red with M_d, ΔT, ω1 with ω_m and the δ band against
  !> the input angle, and Wittenbauer's curve ΔT against J_red.
  pure subroutine put_dynamics_charts(sheet, table, x0, y0, width, lang)
    type(sheet_t), intent(inout) :: sheet
    type(step_table_t), intent(in) :: table
    !> Top left of the block, mm; its width.
    real(wp), intent(in) :: x0, y0, width
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    real(wp) :: w, top
    integer :: ci
    character(len=:), allocatable :: deg, nm, kgm2, input
    ci = table%input_column
    w = 0.5_wp * (width - gap)
    deg = unit_word("deg", lang)
    nm = unit_word("N*m", lang)
    kgm2 = unit_word("kg*m^2", lang)
    input = table%columns(ci)%name//", "//deg
    call sheet%text(x0, y0 + 4.0_wp, word("Machine dynamics (reduced to the input link)", lang), "heading")
    call sheet%text(x0, y0 + 8.0_wp, word("Steady cycle", lang)//": M_d = "//short_number(table%dynamics%m_d)// &
      " "//nm//", "//word("flywheel", lang)//" J_fw = "//short_number(table%dynamics%j_flywheel)//" "//kgm2// &
      " ("//word("textbook", lang)//" "//short_number(table%dynamics%j_flywheel_textbook)//"), delta = "// &
      short_number(table%dynamics%delta), "small")
    top = y0 + 10.0_wp
    call chart(sheet, table%rows(ci, :), table%rows(table%column_index("J_red"), :), x0, top, &
      word("Reduced moment of inertia J_red", lang), input, "J_red, "//kgm2, [real(wp) ::])
    if (table%dynamics%drive_table .and. allocated(table%driver)) then
      ! a driving-moment table: M_d(phi) = the balancing moment's column, dashed
      call chart(sheet, table%rows(ci, :), table%rows(table%column_index("M_red"), :), x0 + w + gap, top, &
        word("Reduced moment M_red and M_d (dashed)", lang), input, "M_red, "//nm, [real(wp) ::], &
        table%rows(table%column_index(table%driver), :))
    else
      call chart(sheet, table%rows(ci, :), table%rows(table%column_index("M_red"), :), x0 + w + gap, top, &
        word("Reduced moment M_red and M_d (dashed)", lang), input, "M_red, "//nm, [table%dynamics%m_d])
    end if
    top = top + dynamics_chart_height + gap
    call chart(sheet, table%rows(ci, :), table%rows(table%column_index("dT"), :), x0, top, &
      word("Change of kinetic energy dT", lang), input, "dT, "//unit_word("J", lang), [real(wp) ::])
    call chart(sheet, table%rows(ci, :), table%rows(table%column_index("omega1"), :), x0 + w + gap, top, &
      word("Speed omega1 (dashed: mean, max, min)", lang), input, "omega1, "//unit_word("rad/s", lang), &
      [table%dynamics%omega_mean, table%dynamics%omega_max, table%dynamics%omega_min])
    top = top + dynamics_chart_height + gap
    call chart(sheet, table%rows(table%column_index("J_red"), :), table%rows(table%column_index("dT"), :), x0, top, &
      word("Wittenbauer's curve: dT against J_red", lang), "J_red, "//kgm2, "dT, "//unit_word("J", lang), [real(wp) ::])
  contains
    !> One chart of y against x with dashed horizontal lines at `levels` (the y range holds them)
    !> or a dashed second curve `dashed` over the same x.
    pure subroutine chart(sheet, xv, yv, x0, y0, heading, xlabel, ylabel, levels, dashed)
      type(sheet_t), intent(inout) :: sheet
      real(wp), intent(in) :: xv(:), yv(:), x0, y0
      character(*), intent(in) :: heading, xlabel, ylabel
      real(wp), intent(in) :: levels(:)
      real(wp), intent(in), optional :: dashed(:)
      real(wp) :: left, pt, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, t, vmin, vmax
      integer :: i
      call sheet%rect(x0, y0, w, dynamics_chart_height, "panel")
      call sheet%text(x0 + 2.0_wp, y0 + 5.0_wp, heading, "heading", size=min(3.2_wp, fitting_size(heading, w - 4.0_wp)))
      left = x0 + 17.0_wp
      pt = y0 + 9.0_wp
      pw = w - 21.0_wp
      ph = dynamics_chart_height - 22.0_wp
      call x_range(xv, index(xlabel, ", "//deg) > 0, xlo, xhi, xstep)
      if (size(levels) > 0) then
        ! a speed band: the range of the data and the levels, zero not forced in
        vmin = min(minval(yv), minval(levels))
        vmax = max(maxval(yv), maxval(levels))
        call x_range([vmin, vmax], .false., ylo, yhi, ystep)
        if (vmin > 0.0_wp .and. vmax > 0.0_wp .and. table%dynamics%m_d /= levels(1)) then
          ylo = ystep * floor(vmin / ystep + 1.0e-9_wp)
          yhi = ystep * ceiling(vmax / ystep - 1.0e-9_wp)
        else
          call y_range([yv, levels], ylo, yhi, ystep)
        end if
      else if (present(dashed)) then
        call y_range([yv, dashed], ylo, yhi, ystep)
      else
        call y_range(yv, ylo, yhi, ystep)
      end if
      call put_axes(sheet, left, pt, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, xlabel, ylabel)
      call put_series(sheet, table, left + pw * (xv - xlo) / (xhi - xlo), pt + ph - ph * (yv - ylo) / (yhi - ylo), &
        "#1f77b4", "", .true.)
      ! a dashed line without the dots of the data series
      if (present(dashed)) call put_series(sheet, table, left + pw * (xv - xlo) / (xhi - xlo), &
        pt + ph - ph * (dashed - ylo) / (yhi - ylo), "#333333", "2,1", .false.)
      do i = 1, size(levels)
        t = pt + ph - ph * (levels(i) - ylo) / (yhi - ylo)
        call sheet%line(left, t, left + pw, t, "mean")
      end do
    end subroutine chart
  end subroutine put_dynamics_charts

  !> The shaking block (--shaking) at (x0, y0), `width` mm wide: the hodograph of the shaking
  !> force F_shake (the resultant of the inertia forces) and the shaking moment M_shake (about
  !> the origin of the tables' frame) against the input angle.
  pure subroutine put_shaking(sheet, table, x0, y0, width, lang)
    type(sheet_t), intent(inout) :: sheet
    type(step_table_t), intent(in) :: table
    real(wp), intent(in) :: x0, y0, width
    integer, intent(in) :: lang
    type(pair_force_t) :: f
    real(wp) :: left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, panel, h
    integer :: ci, c
    ci = table%input_column
    c = table%column_index("M_shake")
    call sheet%text(x0, y0 + 4.0_wp, word("Shaking force and moment (the resultant of the inertia forces)", lang), &
      "heading")
    h = shaking_block_height - 8.0_wp
    panel = h - 4.0_wp
    f%name = shaking_force
    f%magnitude = table%column_index(shaking_force)
    f%angle = table%column_index(shaking_force//"G")
    call put_hodograph(sheet, table, f, x0, y0 + 8.0_wp, panel, h, lang, shaking_force)
    call sheet%rect(x0 + panel + gap, y0 + 8.0_wp, width - panel - gap, h, "panel")
    call sheet%text(x0 + panel + gap + 2.0_wp, y0 + 13.0_wp, word("Shaking moment", lang)//" M_shake "// &
      word("against", lang)//" "//table%columns(ci)%name, "heading")
    left = x0 + panel + gap + 17.0_wp
    top = y0 + 17.0_wp
    pw = width - panel - gap - 21.0_wp
    ph = h - 22.0_wp
    call x_range(table%rows(ci, :), table%columns(ci)%unit == "deg", xlo, xhi, xstep)
    call y_range(table%rows(c, :), ylo, yhi, ystep)
    call put_axes(sheet, left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, &
      table%columns(ci)%name//", "//unit_word(table%columns(ci)%unit, lang), "M_shake, "//unit_word("N*m", lang))
    call put_series(sheet, table, left + pw * (table%rows(ci, :) - xlo) / (xhi - xlo), &
      top + ph - ph * (table%rows(c, :) - ylo) / (yhi - ylo), "#9467bd", "", .true.)
  end subroutine put_shaking

  !> The magnitudes of the chosen pair forces against the input coordinate, with a legend.
  pure subroutine put_magnitude_chart(sheet, table, pairs, x0, y0, w, h, lang)
    type(sheet_t), intent(inout) :: sheet
    type(step_table_t), intent(in) :: table
    type(pair_force_t), intent(in) :: pairs(:)
    real(wp), intent(in) :: x0, y0, w, h
    integer, intent(in) :: lang
    real(wp), allocatable :: x(:), y(:), magnitudes(:)
    real(wp) :: left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, legend_x, row, dy
    character(len=7) :: colour
    character(len=:), allocatable :: dash
    integer :: ci, i
    ci = table%input_column
    call sheet%rect(x0, y0, w, h, "panel")
    call sheet%text(x0 + 2.0_wp, y0 + 5.0_wp, word("Magnitudes of the pair forces against", lang)//" "// &
      table%columns(ci)%name, "heading")
    if (size(pairs) == 0 .or. table%row_count() == 0) then
      call sheet%text(x0 + 2.0_wp, y0 + 12.0_wp, word("No pair forces to show.", lang), "note")
      return
    end if
    left = x0 + 17.0_wp
    top = y0 + 9.0_wp
    pw = w - 21.0_wp - 16.0_wp
    ph = h - 22.0_wp
    call x_range(table%rows(ci, :), table%columns(ci)%unit == "deg", xlo, xhi, xstep)
    allocate (magnitudes(0))
    do i = 1, size(pairs)
      magnitudes = [magnitudes, table%rows(pairs(i)%magnitude, :)]
    end do
    call y_range(magnitudes, ylo, yhi, ystep)
    call put_axes(sheet, left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, &
      table%columns(ci)%name//", "//unit_word(table%columns(ci)%unit, lang), word("force", lang)//", "// &
      unit_word("N", lang))
    x = left + pw * (table%rows(ci, :) - xlo) / (xhi - xlo)
    legend_x = left + pw + 3.0_wp
    dy = min(4.0_wp, ph / size(pairs))
    do i = 1, size(pairs)
      call palette_colour(i, colour, dash)
      y = top + ph - ph * (table%rows(pairs(i)%magnitude, :) - ylo) / (yhi - ylo)
      call put_series(sheet, table, x, y, colour, dash, .true.)
      row = top + 1.5_wp + (i - 1) * dy
      call sheet%line(legend_x, row, legend_x + 5.0_wp, row, stroke=colour, width=0.6_wp, dash=dash)
      call sheet%text(legend_x + 6.5_wp, row + 0.9_wp, pairs(i)%name, "small")
    end do
  end subroutine put_magnitude_chart

  !> One row (gear stage) as a vector diagram: every pair force of 1 mm or more as an arrow
  !> from the origin, at one scale, named at its tip, with a scale bar; the shorter ones named
  !> in a note.
  pure subroutine put_vector_panel(sheet, table, pairs, k, x0, y0, w, h, lang)
    type(sheet_t), intent(inout) :: sheet
    type(step_table_t), intent(in) :: table
    type(pair_force_t), intent(in) :: pairs(:)
    integer, intent(in) :: k
    real(wp), intent(in) :: x0, y0, w, h
    integer, intent(in) :: lang
    real(wp), allocatable :: fx(:), fy(:)
    real(wp) :: ax, ay, aw, ah, ox, oy, scale, extent, tx, ty, d, bounds(4)
    character(len=7) :: colour
    character(len=:), allocatable :: dash, text, short
    integer :: i, j, n
    call sheet%rect(x0, y0, w, h, "panel")
    call sheet%text(x0 + 2.0_wp, y0 + 4.5_wp, word(table%row_name, lang)//" "//int_str(k), "label", bold=.true.)
    allocate (fx(0), fy(0))
    do i = 1, size(pairs)
      fx = [fx, table%rows(pairs(i)%magnitude, k) * cos(table%rows(pairs(i)%angle, k) * deg_to_rad)]
      fy = [fy, table%rows(pairs(i)%magnitude, k) * sin(table%rows(pairs(i)%angle, k) * deg_to_rad)]
    end do
    ax = x0 + 6.0_wp
    ay = y0 + 9.0_wp
    aw = w - 12.0_wp
    ah = h - 20.0_wp
    bounds = [x0 + 1.0_wp, y0 + 6.0_wp, x0 + w - 1.0_wp, y0 + h - 7.0_wp]
    n = size(pairs)
    if (n == 0) then
      scale = 0.0_wp
    else
      call fit_points(fx, fy, ax, ay, aw, ah, ox, oy, scale, extent)
    end if
    if (scale <= 0.0_wp) then
      call sheet%text(x0 + 0.5_wp * w, y0 + 0.5_wp * h, word("no pair force", lang), "note", anchor_middle)
      return
    end if
    call put_origin(sheet, ox, oy, ax - 4.0_wp, ay - 4.0_wp, aw + 8.0_wp, ah + 8.0_wp)
    short = ""
    do i = 1, n
      d = hypot(fx(i), fy(i))
      if (d == 0.0_wp) cycle
      if (d * scale < 1.0_wp) then
        if (len(short) > 0) short = short//", "
        short = short//pairs(i)%name
        cycle
      end if
      ! a vector equal to an earlier one is named in that one's label
      if (any([(hypot(fx(j) - fx(i), fy(j) - fy(i)) * scale < 0.5_wp .and. &
        hypot(fx(j), fy(j)) * scale >= 1.0_wp, j=1, i - 1)])) cycle
      call palette_colour(i, colour, dash)
      call sheet%arrow(ox, oy, ox + scale * fx(i), oy - scale * fy(i), colour, 0.4_wp, 2.0_wp)
    end do
    call put_scale_bar(sheet, x0 + 3.0_wp, y0 + h - 4.0_wp, extent, scale, lang)
    call put_origin_labels(sheet, ox, oy, ax - 4.0_wp, ay - 4.0_wp, aw + 8.0_wp, bounds)
    call sheet%set_layer(layer_text)
    do i = 1, n
      d = hypot(fx(i), fy(i))
      if (d * scale < 1.0_wp) cycle
      if (any([(hypot(fx(j) - fx(i), fy(j) - fy(i)) * scale < 0.5_wp .and. &
        hypot(fx(j), fy(j)) * scale >= 1.0_wp, j=1, i - 1)])) cycle
      call palette_colour(i, colour, dash)
      tx = ox + scale * fx(i)
      ty = oy - scale * fy(i)
      text = ""
      do j = i, n
        if (hypot(fx(j) - fx(i), fy(j) - fy(i)) * scale < 0.5_wp) text = text//pairs(j)%name//" = "
      end do
      text = text//short_number(table%rows(pairs(i)%magnitude, k))//" "//unit_word("N", lang)
      call sheet%place_label(text, "num", tx, ty, atan2(-fy(i), fx(i)), bounds, tail=[ox, oy], colour=colour)
    end do
    if (len(short) > 0) call sheet%text(x0 + 2.0_wp, y0 + h - 8.5_wp, word("under 1 mm, not drawn", lang)//": "// &
      short, "note", size=min(2.6_wp, fitting_size(word("under 1 mm, not drawn", lang)//": "//short, w - 4.0_wp)))
    call sheet%set_layer(layer_charts)
  end subroutine put_vector_panel

end module kinetostat_run_sheet
