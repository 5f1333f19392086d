!> SVG writer over the step table (`--format svg`): one self-contained sheet (A4 wide, A4
!> high unless the panels need more) with
!> - the hodograph of every pair force: the tip of the force vector over the cycle in the
!>   tables' frame (x = F cos(FG), y = F sin(FG)), the origin marked, the points numbered by
!>   step (point k = step k, like fig. 9 of the 1991 manual), a scale bar in N; one panel
!>   per pair (`--pairs` selects);
!> - the driving moment (or force) against the input angle, with its mean over the cycle;
!> - the magnitudes of the pair forces against the input angle, with a legend.
!> A table without an input angle (gear stages) gets one panel per row with the pair forces
!> drawn as vectors from the origin instead. Same table -> same bytes.
module kinetostat_svg_writer
  use, intrinsic :: iso_fortran_env, only: int64
  use kinetostat_kinds, only: wp, deg_to_rad, version_string
  use kinetostat_error, only: error_t, fatal_error, exit_usage
  use kinetostat_text, only: int_str, upper
  use kinetostat_format, only: fixed_number, short_number, full_number
  use kinetostat_step_table, only: step_table_t, col_force, col_force_angle, col_moment
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_svg, only: svg_open, svg_close, svg_line, svg_path, svg_polyline_d, svg_circle, svg_rect, &
    svg_text, svg_arrow, coord, palette_colour, xml_escape
  use kinetostat_label_place, only: label_boxes_t, title_attributes, anchor_start, anchor_end
  use kinetostat_labels, only: word => label, unit_word => unit_symbol
  use kinetostat_title_block, only: put_title_block, title_block_height
  implicit none
  private
  public :: write_svg, pair_force_t, find_pair_forces, select_pair_forces, nice_step, cycle_mean

  !> Sheet width (A4), mm.
  real(wp), parameter :: page_width = 210.0_wp
  !> Smallest sheet height (A4), mm.
  real(wp), parameter :: page_height = 297.0_wp
  !> Margin on every side, mm.
  real(wp), parameter :: margin = 10.0_wp
  !> Gap between panels, mm.
  real(wp), parameter :: gap = 3.5_wp
  !> Smallest height of the charts row, mm (they grow into what is left of an A4 sheet).
  real(wp), parameter :: chart_height = 78.0_wp
  !> Largest height of the charts row, mm.
  real(wp), parameter :: chart_max_height = 100.0_wp
  !> Width of the driving-effort chart (the magnitudes chart takes the rest), mm.
  real(wp), parameter :: driver_chart_width = 82.0_wp
  !> Height of a chart of the machine dynamics, mm.
  real(wp), parameter :: dynamics_chart_height = 62.0_wp
  !> Height of the machine dynamics block: its heading and three rows of charts, mm.
  real(wp), parameter :: dynamics_block_height = 10.0_wp + 3.0_wp * (dynamics_chart_height + gap)
  !> Most numbered points in one hodograph (beyond it every m-th step is numbered).
  integer, parameter :: max_point_labels = 24
  !> Points a curve is drawn through at most: a longer run is thinned to what the sheet can
  !> show (thin_indices keeps every stretch's extremes); the numbers are not changed.
  integer, parameter :: max_drawn_points = 2000
  !> Font size of the class "num", mm (kinetostat_svg's style sheet).
  real(wp), parameter :: num_size = 2.2_wp
  !> Font size of the class "small", mm.
  real(wp), parameter :: small_size = 2.4_wp
  !> Two points nearer than this share one number label ("1,13"), mm.
  real(wp), parameter :: label_merge_distance = 1.0_wp

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
  pure subroutine write_svg(title, table, pairs, lang, out, error)
    !> Title of the mechanism.
    character(*), intent(in) :: title
    !> Finite results.
    type(step_table_t), intent(in) :: table
    !> Comma-separated pair names, or "".
    character(*), intent(in) :: pairs
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    !> Usage error: a name in `pairs` that is no pair force of the table.
    type(error_t), allocatable, intent(out) :: error
    type(pair_force_t), allocatable :: every_pair(:), chosen(:)
    integer :: columns, rows, n_panels, i
    real(wp) :: panel_w, panel_h, y, height, x0, y0, chart_h

    allocate (every_pair(0)) ! defined before the call (gcc's -Wmaybe-uninitialized on the descriptor)
    call find_pair_forces(table, every_pair)
    call select_pair_forces(table, every_pair, pairs, chosen, error)
    if (allocated(error)) return

    if (table%input_column > 0) then
      n_panels = size(chosen)
    else
      n_panels = table%row_count()
    end if
    call panel_grid(n_panels, columns, panel_w, panel_h)
    rows = (n_panels + columns - 1) / columns
    y = 39.0_wp + rows * (panel_h + gap)
    chart_h = min(chart_max_height, max(chart_height, page_height - margin - y - 2.0_wp))
    if (table%input_column > 0) y = y + 2.0_wp + chart_h
    if (table%column_index("dT") > 0) y = y + dynamics_block_height
    height = max(page_height, y + margin)
    if (allocated(table%student_stamp)) height = height + title_block_height

    call svg_open(out, page_width, height, title//" - "//table%deck, &
      "kinetostat --format svg sheet of "//table%deck//". Hodograph paths (class hodograph, data-force = the "// &
      "pair): page point = data-origin + data-scale * (Fx, -Fy), in mm, data-scale in mm per N; point k of a "// &
      "path is step k of the CSV.")
    call put_header(out, title, table, lang)

    if (table%input_column > 0) then
      call out%put(svg_text(margin, 32.0_wp, word("Hodographs of the pair forces", lang), 'class="heading"'))
      call out%put(svg_text(margin, 36.0_wp, word("Tip of each force vector over the cycle, in the frame of the "// &
        "tables (x right, y up); point k = step k; O = zero force.", lang), 'class="small"'))
      do i = 1, size(chosen)
        call panel_origin(i, columns, panel_w, panel_h, x0, y0)
        call put_hodograph(out, table, chosen(i), x0, y0, panel_w, panel_h, lang)
      end do
      if (size(chosen) == 0) call out%put(svg_text(margin, 44.0_wp, &
        word("This table has no pair force with an angle column: no hodographs.", lang), 'class="note"'))
      y = 39.0_wp + rows * (panel_h + gap) + 2.0_wp
      call put_driver_chart(out, table, margin, y, driver_chart_width, chart_h, lang)
      call put_magnitude_chart(out, table, chosen, margin + driver_chart_width + gap, y, &
        page_width - 2.0_wp * margin - driver_chart_width - gap, chart_h, lang)
      if (table%column_index("dT") > 0) call put_dynamics_charts(out, table, y + chart_h + gap, lang)
    else
      call out%put(svg_text(margin, 32.0_wp, word("Pair forces of every " // table%row_name // " as vectors", lang), &
        'class="heading"'))
      call out%put(svg_text(margin, 36.0_wp, word("The rows of this table are " // table%row_name // &
        "s, not steps of a cycle: no hodographs and no diagrams against an input angle.", lang), 'class="small"'))
      do i = 1, table%row_count()
        call panel_origin(i, columns, panel_w, panel_h, x0, y0)
        call put_vector_panel(out, table, chosen, i, x0, y0, panel_w, panel_h, lang)
      end do
    end if
    call put_title_block(out, table, lang, page_width, height, word("Hodographs and diagrams", lang))
    call svg_close(out)
  end subroutine write_svg

  !> Columns and size of the panel grid for `n` panels: 3 across up to 6 panels, 4 across
  !> beyond (so that up to 8 panels and the charts fit on one A4 sheet).
  pure subroutine panel_grid(n, columns, width, height)
    integer, intent(in) :: n
    integer, intent(out) :: columns
    real(wp), intent(out) :: width, height
    if (n <= 6) then
      columns = 3
    else
      columns = 4
    end if
    width = (page_width - 2.0_wp * margin - (columns - 1) * gap) / columns
    height = width + 4.0_wp
  end subroutine panel_grid

  !> Top-left corner of panel `i` (1-based, row by row).
  pure subroutine panel_origin(i, columns, width, height, x0, y0)
    integer, intent(in) :: i, columns
    real(wp), intent(in) :: width, height
    real(wp), intent(out) :: x0, y0
    x0 = margin + modulo(i - 1, columns) * (width + gap)
    y0 = 39.0_wp + ((i - 1) / columns) * (height + gap)
  end subroutine panel_origin

  !> Title, deck, row range and program lines at the top of the sheet.
  pure subroutine put_header(out, title, table, lang)
    type(text_buffer_t), intent(inout) :: out
    character(*), intent(in) :: title
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    character(len=:), allocatable :: line
    integer :: n
    call out%put(svg_text(margin, 15.0_wp, title, title_attributes(title, "title", 3.3_wp, 188.0_wp)))
    line = word("deck", lang)//": "//table%deck
    if (allocated(table%subtitle)) line = line//"   "//table%subtitle
    call out%put(svg_text(margin, 20.5_wp, line, title_attributes(line, "subtitle", 3.0_wp, 188.0_wp)))
    n = table%row_count()
    if (n /= 1) then
      line = int_str(n)//" "//word(table%row_name//"s", lang)
    else
      line = int_str(n)//" "//word(table%row_name, lang)
    end if
    if (table%input_column > 0 .and. n > 0) then
      associate (c => table%columns(table%input_column))
        line = line//", "//c%name//" = "//short_number(table%rows(table%input_column, 1))
        if (n > 1) line = line//" ... "//short_number(table%rows(table%input_column, n))
        line = line//" "//unit_word(c%unit, lang)
      end associate
    end if
    line = line//"; "//version_string
    call out%put(svg_text(margin, 25.0_wp, line, 'class="small"'))
  end subroutine put_header

  !> Every pair force of the table: a force column (col_force) followed by its angle column
  !> (col_force_angle, named as the force with "G" appended), in column order.
  pure subroutine find_pair_forces(table, pairs)
    !> The results.
    type(step_table_t), intent(in) :: table
    !> The pair forces.
    type(pair_force_t), allocatable, intent(out) :: pairs(:)
    integer :: c, a
    allocate (pairs(0))
    do c = 1, size(table%columns)
      if (table%columns(c)%kind /= col_force) cycle
      a = table%column_index(table%columns(c)%name//"G")
      if (a == 0) cycle
      if (table%columns(a)%kind /= col_force_angle) cycle
      call push_pair(pairs, table%columns(c)%name, c, a)
    end do
  end subroutine find_pair_forces

  !> The pair forces named in `list` (comma-separated, any case, in the list's order); all of
  !> them when `list` is blank. A name that is not a pair force is a usage error naming the
  !> deck and the pair forces there are.
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
    integer :: start, comma, i, k
    allocate (chosen(0))
    if (len_trim(list) == 0) then
      do i = 1, size(pairs)
        call push_pair(chosen, pairs(i)%name, pairs(i)%magnitude, pairs(i)%angle)
      end do
      return
    end if
    start = 1
    do
      comma = index(list(start:), ",")
      if (comma == 0) then
        name = trim(adjustl(list(start:)))
      else
        name = trim(adjustl(list(start:start + comma - 2)))
      end if
      k = 0
      do i = 1, size(pairs)
        if (upper(pairs(i)%name) == upper(name)) k = i
      end do
      if (k == 0) then
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
      call push_pair(chosen, pairs(k)%name, pairs(k)%magnitude, pairs(k)%angle)
      if (comma == 0) exit
      start = start + comma
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

  !> A "nice" tick or scale-bar step (1, 2 or 5 times a power of ten) near span/count;
  !> angles in degrees spanning 30 deg or more step by 15, 30, 45, 60, 90 or 180 deg.
  pure real(wp) function nice_step(span, count, degrees)
    !> Span to divide, in the quantity's unit (> 0).
    real(wp), intent(in) :: span
    !> About how many steps.
    integer, intent(in) :: count
    !> Whether the quantity is an angle in degrees.
    logical, intent(in) :: degrees
    real(wp), parameter :: angle_steps(*) = [15.0_wp, 30.0_wp, 45.0_wp, 60.0_wp, 90.0_wp, 180.0_wp]
    real(wp) :: raw, p, m
    integer :: i
    raw = span / count
    if (degrees .and. span >= 30.0_wp .and. span <= 2160.0_wp) then
      do i = 1, size(angle_steps)
        nice_step = angle_steps(i)
        if (angle_steps(i) >= raw) return
      end do
      return
    end if
    p = 10.0_wp**floor(log10(raw))
    m = raw / p
    if (m <= 1.0_wp) then
      nice_step = p
    else if (m <= 2.0_wp) then
      nice_step = 2.0_wp * p
    else if (m <= 5.0_wp) then
      nice_step = 5.0_wp * p
    else
      nice_step = 10.0_wp * p
    end if
  end function nice_step

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
  pure subroutine put_scale_bar(out, x, y, extent, scale, lang)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: x, y, extent, scale
    integer, intent(in) :: lang
    real(wp) :: value, length
    value = nice_step(extent, 4, .false.)
    if (value * scale > 40.0_wp) value = value / 2.0_wp
    length = value * scale
    call out%put(svg_line(x, y, x + length, y, 'class="scale"'))
    call out%put(svg_line(x, y - 1.0_wp, x, y + 1.0_wp, 'class="scale"'))
    call out%put(svg_line(x + length, y - 1.0_wp, x + length, y + 1.0_wp, 'class="scale"'))
    call out%put(svg_text(x + length + 1.5_wp, y + 0.9_wp, short_number(value)//" "//unit_word("N", lang), &
      'class="small"'))
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

  !> Rows of a long run that a curve is drawn through, in order, at most `limit`: the run
  !> cut into equal stretches, of each its first and last row and the rows of the smallest
  !> and largest value of every column of `values` (so the curve keeps its extremes and its
  !> bounding box). All rows when there are no more than `limit`.
  pure subroutine thin_indices(values, limit, keep)
    !> One column per drawn coordinate, one row per step.
    real(wp), intent(in) :: values(:, :)
    !> Most rows kept (>= 2 + 2 * columns).
    integer, intent(in) :: limit
    !> The rows kept, increasing.
    integer, allocatable, intent(out) :: keep(:)
    logical, allocatable :: taken(:)
    integer :: n, stretches, s, first, last, c
    n = size(values, 1)
    allocate (taken(n), source=.false.)
    if (n <= limit) then
      taken = .true.
    else
      stretches = max(1, limit / (2 + 2 * size(values, 2)))
      do s = 1, stretches
        first = 1 + int((int(s - 1, int64) * n) / stretches)
        last = int((int(s, int64) * n) / stretches)
        if (last < first) cycle
        taken(first) = .true.
        taken(last) = .true.
        do c = 1, size(values, 2)
          taken(first - 1 + minloc(values(first:last, c), dim=1)) = .true.
          taken(first - 1 + maxloc(values(first:last, c), dim=1)) = .true.
        end do
      end do
    end if
    keep = pack([(s, s=1, n)], taken)
  end subroutine thin_indices

  !> The origin of a force diagram: light axes across the plot area, a small circle and "O".
  !> The boxes of its three labels are taken in `boxes` (the point numbers go elsewhere);
  !> "y" moves to the left of its axis when "x" has its place.
  pure subroutine put_origin(out, ox, oy, ax, ay, aw, ah, boxes)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: ox, oy, ax, ay, aw, ah
    type(label_boxes_t), intent(out) :: boxes
    type(label_boxes_t) :: y_right
    call out%put(svg_line(ax, oy, ax + aw, oy, 'class="faint"'))
    call out%put(svg_line(ox, ay, ox, ay + ah, 'class="faint"'))
    call out%put(svg_text(ax + aw - 0.3_wp, oy - 0.8_wp, "x", 'class="small" text-anchor="end"'))
    call boxes%reserve(ax + aw - 0.3_wp, oy - 0.8_wp, "x", small_size, anchor_end)
    call y_right%reserve(ox + 0.8_wp, ay + 2.0_wp, "y", small_size, anchor_start)
    if (boxes%is_free(y_right%box(:, 1))) then
      call out%put(svg_text(ox + 0.8_wp, ay + 2.0_wp, "y", 'class="small"'))
      call boxes%reserve(ox + 0.8_wp, ay + 2.0_wp, "y", small_size, anchor_start)
    else
      call out%put(svg_text(ox - 0.8_wp, ay + 2.0_wp, "y", 'class="small" text-anchor="end"'))
      call boxes%reserve(ox - 0.8_wp, ay + 2.0_wp, "y", small_size, anchor_end)
    end if
    call out%put(svg_circle(ox, oy, 0.7_wp, 'class="origin"'))
    call out%put(svg_text(ox - 1.0_wp, oy + 2.6_wp, "O", 'class="small" text-anchor="end"'))
    call boxes%reserve(ox - 1.0_wp, oy + 2.6_wp, "O", small_size, anchor_end)
  end subroutine put_origin

  !> One hodograph panel with its top-left corner at (x0, y0).
  pure subroutine put_hodograph(out, table, p, x0, y0, w, h, lang)
    type(text_buffer_t), intent(inout) :: out
    type(step_table_t), intent(in) :: table
    type(pair_force_t), intent(in) :: p
    real(wp), intent(in) :: x0, y0, w, h
    integer, intent(in) :: lang
    type(label_boxes_t) :: boxes
    real(wp), allocatable :: fx(:), fy(:), px(:), py(:)
    real(wp) :: ax, ay, aw, ah, ox, oy, scale, extent
    integer :: k, n
    integer, allocatable :: keep(:)
    logical :: thinned
    n = table%row_count()
    call pair_components(table, p, fx, fy)
    ! a long run: the curve through its extremes, without rays, dots and step numbers
    thinned = n > max_drawn_points
    if (thinned) then
      call thin_indices(reshape([fx, fy], [n, 2]), max_drawn_points, keep)
      fx = fx(keep)
      fy = fy(keep)
    end if
    call out%put(svg_rect(x0, y0, w, h, 'class="panel"'))
    call out%put(svg_text(x0 + 2.0_wp, y0 + 4.5_wp, p%name, 'class="label" font-weight="bold"'))
    call out%put(svg_text(x0 + w - 2.0_wp, y0 + 4.5_wp, word("max", lang)//" "// &
      short_number(maxval(table%rows(p%magnitude, :)))//" "//unit_word("N", lang), 'class="small" text-anchor="end"'))
    ax = x0 + 5.0_wp
    ay = y0 + 9.0_wp
    aw = w - 10.0_wp
    ah = h - 19.0_wp
    call fit_points(fx, fy, ax, ay, aw, ah, ox, oy, scale, extent)
    call put_origin(out, ox, oy, ax - 3.0_wp, ay - 3.0_wp, aw + 6.0_wp, ah + 6.0_wp, boxes)
    if (scale <= 0.0_wp) then
      call out%put(svg_text(x0 + 0.5_wp * w, y0 + h - 4.0_wp, p%name//" = 0 "//word("at every step", lang), &
        'class="note" text-anchor="middle"'))
      return
    end if
    px = ox + scale * fx
    py = oy - scale * fy
    if (thinned) then
      call out%put(svg_path(svg_polyline_d(px, py), 'class="hodograph" data-force="'//xml_escape(p%name)// &
        '" data-origin="'//coord(ox)//" "//coord(oy)//'" data-scale="'//full_number(scale)// &
        '" data-steps="'//int_str(n)//'" data-thinned="'//int_str(size(keep))//'"'))
      call out%put(svg_text(x0 + w - 2.0_wp, y0 + h - 8.0_wp, int_str(size(keep))//" of "//int_str(n)// &
        " points drawn", 'class="small" text-anchor="end"'))
      call put_scale_bar(out, x0 + 3.0_wp, y0 + h - 4.0_wp, extent, scale, lang)
      return
    end if
    do k = 1, n
      call out%put(svg_line(ox, oy, px(k), py(k), 'class="ray"'))
    end do
    call out%put(svg_path(svg_polyline_d(px, py), 'class="hodograph" data-force="'//xml_escape(p%name)// &
      '" data-origin="'//coord(ox)//" "//coord(oy)//'" data-scale="'//full_number(scale)//'"'))
    do k = 1, n
      call out%put(svg_circle(px(k), py(k), 0.45_wp, 'class="point"'))
    end do
    call put_point_numbers(out, px, py, ox, oy, x0 + 1.0_wp, y0 + 6.0_wp, w - 2.0_wp, h - 13.0_wp, boxes)
    call put_scale_bar(out, x0 + 3.0_wp, y0 + h - 4.0_wp, extent, scale, lang)
  end subroutine put_hodograph

  !> Step numbers beside the points: points closer than label_merge_distance share one
  !> label ("1,13", "1-13" for a run); with many steps only every m-th step is numbered.
  !> Each label goes to a free place near its point (kinetostat_label_place) away from the
  !> curve and the origin, inside the box (bx, by, bw, bh); one placed away from its point
  !> gets a leader line.
  pure subroutine put_point_numbers(out, px, py, ox, oy, bx, by, bw, bh, boxes)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: px(:), py(:), ox, oy, bx, by, bw, bh
    !> Boxes already taken; the new labels' are added.
    type(label_boxes_t), intent(inout) :: boxes
    integer, allocatable :: owner(:), members(:)
    real(wp), allocatable :: seg_x(:), seg_y(:)
    real(wp) :: cx, cy, tx, ty, hw, e(2)
    logical :: leader
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
    ! obstacles: the curve's segments and the origin
    seg_x = [ox, ox]
    seg_y = [oy, oy]
    if (n == 1) then
      seg_x = [seg_x, px(1), px(1)]
      seg_y = [seg_y, py(1), py(1)]
    end if
    do k = 1, n - 1
      seg_x = [seg_x, px(k), px(k + 1)]
      seg_y = [seg_y, py(k), py(k + 1)]
    end do
    do k = 1, n
      if (owner(k) /= k) cycle
      members = pack([(j, j=1, n)], owner == k)
      text = run_list(members)
      ! many coinciding steps: the first two and the last ("1,17..361")
      if (len(text) > 16 .and. size(members) > 3) text = int_str(members(1))//","//int_str(members(2))//".."// &
        int_str(members(size(members)))
      call boxes%place(text, num_size, px(k), py(k), atan2(py(k) - cy, px(k) - cx), seg_x, seg_y, &
        [bx, by, bx + bw, by + bh], tx, ty, leader)
      if (leader) then
        hw = 0.3_wp * num_size * len(text)
        e = [max(tx - hw, min(tx + hw, px(k))), max(ty - 0.8_wp * num_size, min(ty + 0.2_wp * num_size, py(k)))]
        call out%put(svg_line(px(k), py(k), e(1), e(2), 'stroke="#777777" stroke-width="0.12"'))
      end if
      call out%put(svg_text(tx, ty, text, 'class="num" text-anchor="middle"'))
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
  !> [ylo, yhi], and the axis labels. Returns nothing: the caller maps with chart_x/chart_y.
  pure subroutine put_axes(out, left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, xlabel, ylabel)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep
    character(*), intent(in) :: xlabel, ylabel
    real(wp) :: v, t
    integer :: i, decimals
    decimals = tick_decimals(xstep)
    do i = ceiling(xlo / xstep - 1.0e-9_wp), floor(xhi / xstep + 1.0e-9_wp)
      v = i * xstep
      t = left + pw * (v - xlo) / (xhi - xlo)
      call out%put(svg_line(t, top, t, top + ph, 'class="grid"'))
      call out%put(svg_line(t, top + ph, t, top + ph + 1.0_wp, 'class="axis"'))
      call out%put(svg_text(t, top + ph + 3.8_wp, fixed_number(v, decimals), 'class="small" text-anchor="middle"'))
    end do
    decimals = tick_decimals(ystep)
    do i = nint(ylo / ystep), nint(yhi / ystep)
      v = i * ystep
      t = top + ph - ph * (v - ylo) / (yhi - ylo)
      call out%put(svg_line(left, t, left + pw, t, 'class="grid"'))
      call out%put(svg_line(left - 1.0_wp, t, left, t, 'class="axis"'))
      call out%put(svg_text(left - 1.5_wp, t + 0.8_wp, fixed_number(v, decimals), 'class="small" text-anchor="end"'))
    end do
    if (ylo < 0.0_wp .and. yhi > 0.0_wp) then
      t = top + ph - ph * (0.0_wp - ylo) / (yhi - ylo)
      call out%put(svg_line(left, t, left + pw, t, 'class="faint"'))
    end if
    call out%put(svg_rect(left, top, pw, ph, 'class="axis"'))
    call out%put(svg_text(left + 0.5_wp * pw, top + ph + 8.0_wp, xlabel, 'class="label" text-anchor="middle"'))
    call out%put(svg_text(left - 12.0_wp, top + 0.5_wp * ph, ylabel, 'class="label" text-anchor="middle" '// &
      'transform="rotate(-90 '//coord(left - 12.0_wp)//" "//coord(top + 0.5_wp * ph)//')"'))
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

  !> One data series of a chart: a line and a dot at every row.
  pure subroutine put_series(out, x, y, colour, dash)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: x(:), y(:)
    character(*), intent(in) :: colour, dash
    character(len=:), allocatable :: style
    integer :: k
    integer, allocatable :: keep(:)
    style = 'fill="none" stroke="'//colour//'" stroke-width="0.4"'
    if (len(dash) > 0) style = style//' stroke-dasharray="'//dash//'"'
    if (size(x) > max_drawn_points) then
      ! a long run: the line through its extremes, no dots (they would merge into the line)
      call thin_indices(reshape(y, [size(y), 1]), max_drawn_points, keep)
      call out%put(svg_path(svg_polyline_d(x(keep), y(keep)), style))
      return
    end if
    call out%put(svg_path(svg_polyline_d(x, y), style))
    do k = 1, size(x)
      call out%put(svg_circle(x(k), y(k), 0.45_wp, 'fill="'//colour//'"'))
    end do
  end subroutine put_series

  !> The driving moment (or force) of the table against its input coordinate, with its mean.
  pure subroutine put_driver_chart(out, table, x0, y0, w, h, lang)
    type(text_buffer_t), intent(inout) :: out
    type(step_table_t), intent(in) :: table
    real(wp), intent(in) :: x0, y0, w, h
    integer, intent(in) :: lang
    real(wp), allocatable :: x(:), y(:)
    real(wp) :: left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, mean, t
    character(len=:), allocatable :: what
    integer :: c, ci
    ci = table%input_column
    c = 0
    if (allocated(table%driver)) c = table%column_index(table%driver)
    call out%put(svg_rect(x0, y0, w, h, 'class="panel"'))
    if (c == 0 .or. table%row_count() == 0) then
      call out%put(svg_text(x0 + 2.0_wp, y0 + 5.0_wp, word("Driving effort", lang), 'class="heading"'))
      call out%put(svg_text(x0 + 2.0_wp, y0 + 12.0_wp, word("This table has no driving moment or force column.", lang), &
        'class="note"'))
      return
    end if
    what = word("Driving force", lang)
    if (table%columns(c)%kind == col_moment) what = word("Driving moment", lang)
    call out%put(svg_text(x0 + 2.0_wp, y0 + 5.0_wp, what//" "//table%columns(c)%name//" "//word("against", lang)// &
      " "//table%columns(ci)%name, 'class="heading"'))
    left = x0 + 17.0_wp
    top = y0 + 9.0_wp
    pw = w - 21.0_wp
    ph = h - 22.0_wp
    call x_range(table%rows(ci, :), table%columns(ci)%unit == "deg", xlo, xhi, xstep)
    mean = cycle_mean(table%rows(ci, :), table%rows(c, :))
    ! roundoff of a mean that is zero (a conservative cycle): printed as 0, not -5.53E-16
    if (abs(mean) <= 1.0e-12_wp * maxval(abs(table%rows(c, :)))) mean = 0.0_wp
    call y_range([table%rows(c, :), mean], ylo, yhi, ystep)
    call put_axes(out, left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, &
      table%columns(ci)%name//", "//unit_word(table%columns(ci)%unit, lang), &
      table%columns(c)%name//", "//unit_word(table%columns(c)%unit, lang))
    x = left + pw * (table%rows(ci, :) - xlo) / (xhi - xlo)
    y = top + ph - ph * (table%rows(c, :) - ylo) / (yhi - ylo)
    call put_series(out, x, y, "#1f77b4", "")
    t = top + ph - ph * (mean - ylo) / (yhi - ylo)
    call out%put(svg_line(left, t, left + pw, t, 'class="mean"'))
    call out%put(svg_line(x0 + w - 30.0_wp, y0 + h - 3.0_wp, x0 + w - 24.0_wp, y0 + h - 3.0_wp, 'class="mean"'))
    call out%put(svg_text(x0 + w - 23.0_wp, y0 + h - 2.2_wp, word("mean", lang)//" "//short_number(mean)//" "// &
      unit_word(table%columns(c)%unit, lang), 'class="small"'))
  end subroutine put_driver_chart

  !> The machine dynamics of a steady cycle (the course's dynamics drawing): J_red, M_red with
  !> M_d, dT, omega1 with omega_m and the delta band against the input angle, and
  !> Wittenbauer's curve dT against J_red.
  pure subroutine put_dynamics_charts(out, table, y0, lang)
    type(text_buffer_t), intent(inout) :: out
    type(step_table_t), intent(in) :: table
    !> Top of the block, mm.
    real(wp), intent(in) :: y0
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    real(wp) :: w, top
    integer :: ci
    character(len=:), allocatable :: deg, nm, kgm2, input
    ci = table%input_column
    w = 0.5_wp * (page_width - 2.0_wp * margin - gap)
    deg = unit_word("deg", lang)
    nm = unit_word("N*m", lang)
    kgm2 = unit_word("kg*m^2", lang)
    input = table%columns(ci)%name//", "//deg
    call out%put(svg_text(margin, y0 + 4.0_wp, word("Machine dynamics (reduced to the input link)", lang), &
      'class="heading"'))
    call out%put(svg_text(margin, y0 + 8.0_wp, word("Steady cycle", lang)//": M_d = "//short_number(table%dynamics_value("M_d"))// &
      " "//nm//", "//word("flywheel", lang)//" J_fw = "//short_number(table%dynamics_value("J_flywheel"))//" "//kgm2//" ("// &
      word("textbook", lang)//" "//short_number(table%dynamics_value("J_flywheel_textbook"))//"), delta = "// &
      short_number(table%dynamics_value("delta")), 'class="small"'))
    top = y0 + 10.0_wp
    call chart(out, table%rows(ci, :), table%rows(table%column_index("J_red"), :), margin, top, &
      word("Reduced moment of inertia J_red", lang), input, "J_red, "//kgm2, [real(wp) ::])
    if (table%dynamics_index("M_d_scale") > 0 .and. allocated(table%driver)) then
      ! a driving-moment table: M_d(phi) = the balancing moment's column, dashed
      call chart(out, table%rows(ci, :), table%rows(table%column_index("M_red"), :), margin + w + gap, top, &
        word("Reduced moment M_red and M_d (dashed)", lang), input, "M_red, "//nm, [real(wp) ::], &
        table%rows(table%column_index(table%driver), :))
    else
      call chart(out, table%rows(ci, :), table%rows(table%column_index("M_red"), :), margin + w + gap, top, &
        word("Reduced moment M_red and M_d (dashed)", lang), input, "M_red, "//nm, [table%dynamics_value("M_d")])
    end if
    top = top + dynamics_chart_height + gap
    call chart(out, table%rows(ci, :), table%rows(table%column_index("dT"), :), margin, top, &
      word("Change of kinetic energy dT", lang), input, "dT, "//unit_word("J", lang), [real(wp) ::])
    call chart(out, table%rows(ci, :), table%rows(table%column_index("omega1"), :), margin + w + gap, top, &
      word("Speed omega1 (dashed: mean, max, min)", lang), input, "omega1, "//unit_word("rad/s", lang), &
      [table%dynamics_value("omega_mean"), table%dynamics_value("omega_max"), table%dynamics_value("omega_min")])
    top = top + dynamics_chart_height + gap
    call chart(out, table%rows(table%column_index("J_red"), :), table%rows(table%column_index("dT"), :), margin, top, &
      word("Wittenbauer's curve: dT against J_red", lang), "J_red, "//kgm2, "dT, "//unit_word("J", lang), [real(wp) ::])
  contains
    !> One chart of y against x with dashed horizontal lines at `levels` (the y range holds them)
    !> or a dashed second curve `dashed` over the same x.
    pure subroutine chart(o, xv, yv, x0, y0, heading, xlabel, ylabel, levels, dashed)
      type(text_buffer_t), intent(inout) :: o
      real(wp), intent(in) :: xv(:), yv(:), x0, y0
      character(*), intent(in) :: heading, xlabel, ylabel
      real(wp), intent(in) :: levels(:)
      real(wp), intent(in), optional :: dashed(:)
      real(wp) :: left, pt, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, t, vmin, vmax
      integer :: i
      integer, allocatable :: keep(:)
      call o%put(svg_rect(x0, y0, w, dynamics_chart_height, 'class="panel"'))
      call o%put(svg_text(x0 + 2.0_wp, y0 + 5.0_wp, heading, 'class="heading"'))
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
        if (vmin > 0.0_wp .and. vmax > 0.0_wp .and. table%dynamics_value("M_d") /= levels(1)) then
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
      call put_axes(o, left, pt, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, xlabel, ylabel)
      call put_series(o, left + pw * (xv - xlo) / (xhi - xlo), pt + ph - ph * (yv - ylo) / (yhi - ylo), &
        "#1f77b4", "")
      if (present(dashed)) then
        ! a dashed line without the dots of the data series (thinned as they are for long runs)
        if (size(xv) > max_drawn_points) then
          call thin_indices(reshape(dashed, [size(dashed), 1]), max_drawn_points, keep)
        else
          keep = [(i, i = 1, size(xv))]
        end if
        call o%put(svg_path(svg_polyline_d(left + pw * (xv(keep) - xlo) / (xhi - xlo), &
          pt + ph - ph * (dashed(keep) - ylo) / (yhi - ylo)), &
          'fill="none" stroke="#333333" stroke-width="0.4" stroke-dasharray="2,1"'))
      end if
      do i = 1, size(levels)
        t = pt + ph - ph * (levels(i) - ylo) / (yhi - ylo)
        call o%put(svg_line(left, t, left + pw, t, 'class="mean"'))
      end do
    end subroutine chart
  end subroutine put_dynamics_charts

  !> The magnitudes of the chosen pair forces against the input coordinate, with a legend.
  pure subroutine put_magnitude_chart(out, table, pairs, x0, y0, w, h, lang)
    type(text_buffer_t), intent(inout) :: out
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
    call out%put(svg_rect(x0, y0, w, h, 'class="panel"'))
    call out%put(svg_text(x0 + 2.0_wp, y0 + 5.0_wp, word("Magnitudes of the pair forces against", lang)//" "// &
      table%columns(ci)%name, 'class="heading"'))
    if (size(pairs) == 0 .or. table%row_count() == 0) then
      call out%put(svg_text(x0 + 2.0_wp, y0 + 12.0_wp, word("No pair forces to show.", lang), 'class="note"'))
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
    call put_axes(out, left, top, pw, ph, xlo, xhi, xstep, ylo, yhi, ystep, &
      table%columns(ci)%name//", "//unit_word(table%columns(ci)%unit, lang), word("force", lang)//", "// &
      unit_word("N", lang))
    x = left + pw * (table%rows(ci, :) - xlo) / (xhi - xlo)
    legend_x = left + pw + 3.0_wp
    dy = min(4.0_wp, ph / size(pairs))
    do i = 1, size(pairs)
      call palette_colour(i, colour, dash)
      y = top + ph - ph * (table%rows(pairs(i)%magnitude, :) - ylo) / (yhi - ylo)
      call put_series(out, x, y, colour, dash)
      row = top + 1.5_wp + (i - 1) * dy
      call out%put(svg_line(legend_x, row, legend_x + 5.0_wp, row, 'stroke="'//colour//'" stroke-width="0.6"'// &
        merge_dash(dash)))
      call out%put(svg_text(legend_x + 6.5_wp, row + 0.9_wp, pairs(i)%name, 'class="small"'))
    end do
  end subroutine put_magnitude_chart

  !> ' stroke-dasharray="..."' for a non-empty dash pattern, else "".
  pure function merge_dash(dash) result(text)
    character(*), intent(in) :: dash
    character(len=:), allocatable :: text
    text = ""
    if (len(dash) > 0) text = ' stroke-dasharray="'//dash//'"'
  end function merge_dash

  !> One row (gear stage) as a vector diagram: every non-zero pair force as an arrow from
  !> the origin, at one scale, named at its tip, with a scale bar.
  pure subroutine put_vector_panel(out, table, pairs, k, x0, y0, w, h, lang)
    type(text_buffer_t), intent(inout) :: out
    type(step_table_t), intent(in) :: table
    type(pair_force_t), intent(in) :: pairs(:)
    integer, intent(in) :: k
    real(wp), intent(in) :: x0, y0, w, h
    integer, intent(in) :: lang
    type(label_boxes_t) :: boxes
    real(wp), allocatable :: fx(:), fy(:), star_x(:), star_y(:)
    real(wp) :: ax, ay, aw, ah, ox, oy, scale, extent, tx, ty, d, qx, qy
    logical :: leader
    character(len=7) :: colour
    character(len=:), allocatable :: dash, text
    integer :: i, j, n
    call out%put(svg_rect(x0, y0, w, h, 'class="panel"'))
    call out%put(svg_text(x0 + 2.0_wp, y0 + 4.5_wp, word(table%row_name, lang)//" "//int_str(k), &
      'class="label" font-weight="bold"'))
    allocate (fx(0), fy(0))
    do i = 1, size(pairs)
      fx = [fx, table%rows(pairs(i)%magnitude, k) * cos(table%rows(pairs(i)%angle, k) * deg_to_rad)]
      fy = [fy, table%rows(pairs(i)%magnitude, k) * sin(table%rows(pairs(i)%angle, k) * deg_to_rad)]
    end do
    ax = x0 + 6.0_wp
    ay = y0 + 9.0_wp
    aw = w - 12.0_wp
    ah = h - 20.0_wp
    n = size(pairs)
    if (n == 0) then
      scale = 0.0_wp
    else
      call fit_points(fx, fy, ax, ay, aw, ah, ox, oy, scale, extent)
    end if
    if (scale <= 0.0_wp) then
      call out%put(svg_text(x0 + 0.5_wp * w, y0 + 0.5_wp * h, word("no pair force", lang), &
        'class="note" text-anchor="middle"'))
      return
    end if
    call put_origin(out, ox, oy, ax - 4.0_wp, ay - 4.0_wp, aw + 8.0_wp, ah + 8.0_wp, boxes)
    ! the arrows as segments origin -> tip (the obstacles of the labels)
    allocate (star_x(0), star_y(0))
    do i = 1, n
      star_x = [star_x, ox, ox + scale * fx(i)]
      star_y = [star_y, oy, oy - scale * fy(i)]
    end do
    do i = 1, n
      d = hypot(fx(i), fy(i))
      if (d * scale < 0.2_wp) cycle
      ! a vector equal to an earlier one is named in that one's label
      if (any([(hypot(fx(j) - fx(i), fy(j) - fy(i)) * scale < 0.5_wp .and. &
        hypot(fx(j), fy(j)) * scale >= 0.2_wp, j=1, i - 1)])) cycle
      call palette_colour(i, colour, dash)
      tx = ox + scale * fx(i)
      ty = oy - scale * fy(i)
      call out%put(svg_arrow(ox, oy, tx, ty, colour, 0.4_wp, 2.0_wp))
      text = ""
      do j = i, n
        if (hypot(fx(j) - fx(i), fy(j) - fy(i)) * scale < 0.5_wp) text = text//pairs(j)%name//" = "
      end do
      text = text//short_number(table%rows(pairs(i)%magnitude, k))//" "//unit_word("N", lang)
      call boxes%place(text, num_size, tx, ty, atan2(-fy(i), fx(i)), star_x, star_y, &
        [x0 + 1.0_wp, y0 + 6.0_wp, x0 + w - 1.0_wp, y0 + h - 7.0_wp], qx, qy, leader, tail=[ox, oy])
      if (leader) call out%put(svg_line(tx, ty, qx, qy - 0.3_wp * num_size, 'stroke="#777777" stroke-width="0.12"'))
      call out%put(svg_text(qx, qy, text, 'class="num" text-anchor="middle" style="fill: '//colour//'"'))
    end do
    call put_scale_bar(out, x0 + 3.0_wp, y0 + h - 4.0_wp, extent, scale, lang)
  end subroutine put_vector_panel

end module kinetostat_svg_writer
