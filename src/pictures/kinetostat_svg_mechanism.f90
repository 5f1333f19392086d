!> SVG of the mechanism at one step (`--format svg --at K`), drawn to scale like a
!> course-project force-plan sheet: frame pivots (ground symbol) and guides (hatched),
!> links as bars or plates, sliders as blocks, joints, centres of mass, and an arrow for
!> every force of the sketch (pair forces, loads, weights, inertia forces, one force scale),
!> each labelled with its value ("F21 = 2716 N"), moments as arcs; a length scale bar, a
!> force scale bar and a list of the forces. The drawing comes from the mechanism's
!> drawing (kinetostat_drawing: the topology of kinetostat_sketch, positions from the
!> kinematics columns, forces from the mechanism's force_plan); this module only draws it.
module kinetostat_svg_mechanism
  use kinetostat_kinds, only: wp, pi, rad_to_deg, version_string
  use kinetostat_text, only: int_str
  use kinetostat_format, only: short_number, fixed_number
  use kinetostat_step_table, only: step_table_t
  use kinetostat_text_buffer, only: text_buffer_t
  use kinetostat_svg, only: svg_open, svg_close, svg_line, svg_path, svg_polyline_d, svg_circle, svg_rect, &
    svg_text, svg_arrow, svg_polygon, coord
  use kinetostat_svg_writer, only: nice_step
  use kinetostat_label_place, only: label_boxes_t, title_attributes, text_chars
  use kinetostat_labels, only: word => label, unit_word => unit_symbol
  use kinetostat_title_block, only: put_title_block, title_block_height
  use kinetostat_drawing, only: drawing_t, drawing_body_t, point_pivot, point_com, point_plain, body_bar, body_block, &
    body_cylinder, body_rod, force_pair, force_load, &
    force_gravity, force_inertia, force_kind_names
  implicit none
  private
  public :: write_svg_mechanism

  !> Sheet width (A4), mm.
  real(wp), parameter :: page_width = 210.0_wp
  !> Sheet height (A4), mm.
  real(wp), parameter :: page_height = 297.0_wp
  !> The drawing's area: left, top, width, height, mm.
  real(wp), parameter :: area(4) = [12.0_wp, 36.0_wp, 186.0_wp, 175.0_wp]
  !> Room kept around the mechanism for arrows and labels, mm.
  real(wp), parameter :: arrow_room = 30.0_wp
  !> Length of the largest force arrow, mm.
  real(wp), parameter :: longest_arrow = 28.0_wp
  !> Font size of the class "label", mm (as in kinetostat_svg's style sheet).
  real(wp), parameter :: label_size = 2.8_wp
  !> Font size of the class "num", mm.
  real(wp), parameter :: num_size = 2.2_wp
  !> Font size of the class "small", mm (the list of forces).
  real(wp), parameter :: list_size = 2.4_wp
  !> Length of the axes of the mechanism's frame on the sheet, mm.
  real(wp), parameter :: axis_length = 14.0_wp
  !> Colours of the force kinds (pair, load, weight, inertia).
  character(*), parameter :: kind_colours(*) = [character(len=7) :: "#d62728", "#2ca02c", "#8c564b", "#1f77b4"]

  !> The order the bodies are drawn in (later ones over earlier ones).
  integer, parameter :: body_order(*) = [body_bar, body_rod, body_cylinder, body_block]

contains

  !> The sheet of the mechanism at row `k` of `table`, drawn from `drawing`, its words in
  !> language `lang`.
  pure subroutine write_svg_mechanism(title, table, k, drawing, lang, out)
    !> Title of the mechanism.
    character(*), intent(in) :: title
    !> The results.
    type(step_table_t), intent(in) :: table
    !> Row drawn (1-based).
    integer, intent(in) :: k
    !> The mechanism's sketch at that row.
    type(drawing_t), intent(in) :: drawing
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> Where the lines go.
    type(text_buffer_t), intent(inout) :: out
    real(wp), allocatable :: px(:), py(:), obst_x(:), obst_y(:), hx(:), hy(:)
    real(wp) :: len_scale, force_scale, ox, oy, cx, cy, xmin, xmax, ymin, ymax, fmax, q(2), tx, ty, t(2)
    real(wp) :: bar_len, bar_value, bounds(4), origin(2), axis_tip(2, 2), u2(2), sheet_height
    character(len=:), allocatable :: line, text
    type(label_boxes_t) :: boxes
    logical :: leader
    integer :: i, j, n, nf, nm, pass

    n = 0
    if (allocated(drawing%points)) n = size(drawing%points)
    nf = 0
    if (allocated(drawing%forces)) nf = size(drawing%forces)
    nm = 0
    if (allocated(drawing%moments)) nm = size(drawing%moments)

    ! the mechanism turned by view_angle, its box (the origin of its frame included), one
    ! length scale for both axes
    allocate (px(n), py(n))
    do i = 1, n
      q = turn(drawing%points(i)%p, drawing%view_angle)
      px(i) = q(1)
      py(i) = q(2)
    end do
    xmin = 0.0_wp
    xmax = 0.0_wp
    ymin = 0.0_wp
    ymax = 0.0_wp
    if (n > 0) then
      xmin = min(xmin, minval(px))
      xmax = max(xmax, maxval(px))
      ymin = min(ymin, minval(py))
      ymax = max(ymax, maxval(py))
    end if
    do i = 1, size(drawing%guides)
      associate (g => drawing%guides(i))
        do j = -1, 1, 2
          q = turn(g%p + j * g%half_length * [cos(g%angle), sin(g%angle)], drawing%view_angle)
          xmin = min(xmin, q(1))
          xmax = max(xmax, q(1))
          ymin = min(ymin, q(2))
          ymax = max(ymax, q(2))
        end do
      end associate
    end do
    if (xmax - xmin <= 0.0_wp .and. ymax - ymin <= 0.0_wp) then
      xmin = 0.0_wp
      xmax = 1.0_wp
      ymin = 0.0_wp
      ymax = 1.0_wp
    end if
    len_scale = min((area(3) - 2.0_wp * arrow_room) / max(xmax - xmin, 1.0e-9_wp), &
      (area(4) - 2.0_wp * arrow_room) / max(ymax - ymin, 1.0e-9_wp))
    cx = area(1) + 0.5_wp * area(3)
    cy = area(2) + 0.5_wp * area(4)
    ox = cx - len_scale * 0.5_wp * (xmin + xmax)
    oy = cy + len_scale * 0.5_wp * (ymin + ymax)
    px = ox + len_scale * px
    py = oy - len_scale * py
    fmax = 0.0_wp
    do i = 1, nf
      fmax = max(fmax, hypot(drawing%forces(i)%f(1), drawing%forces(i)%f(2)))
    end do
    force_scale = 0.0_wp
    if (fmax > 0.0_wp) force_scale = longest_arrow / fmax
    bounds = [area(1), area(2), area(1) + area(3), area(2) + area(4)]

    sheet_height = page_height
    if (allocated(table%student_stamp)) sheet_height = page_height + title_block_height
    call svg_open(out, page_width, sheet_height, title//" - "//table%deck//" - "//table%row_name//" "// &
      int_str(table%run_row(k)), "kinetostat --format svg --at "//int_str(table%run_row(k))//" sheet of "// &
      table%deck//": the mechanism to scale with every force of the step as an arrow (one force scale).")
    call out%put(svg_text(area(1), 15.0_wp, title, title_attributes(title, "title", 3.3_wp, 188.0_wp)))
    line = word("deck", lang)//": "//table%deck
    if (allocated(table%subtitle)) line = line//"   "//table%subtitle
    call out%put(svg_text(area(1), 20.5_wp, line, title_attributes(line, "subtitle", 3.0_wp, 188.0_wp)))
    line = word(table%row_name, lang)//" "//int_str(table%run_row(k))//" "//word("of", lang)//" "// &
      int_str(table%run_rows())
    if (table%input_column > 0) line = line//": "//table%columns(table%input_column)%name//" = "// &
      short_number(table%rows(table%input_column, k))//" "//unit_word(table%columns(table%input_column)%unit, lang)
    if (allocated(drawing%view_note)) line = line//"; "//word(drawing%view_note, lang)
    line = line//"; "//version_string
    call out%put(svg_text(area(1), 25.5_wp, line, 'class="small"'))
    call out%put(svg_rect(area(1) - 2.0_wp, area(2) - 2.0_wp, area(3) + 4.0_wp, area(4) + 4.0_wp, 'class="panel"'))

    ! obstacles of the labels: segments (ends in pairs) of every line drawn
    allocate (obst_x(0), obst_y(0))

    ! guides (hatched on one side)
    do i = 1, size(drawing%guides)
      call put_guide(out, drawing, i, ox, oy, len_scale, obst_x, obst_y)
    end do
    ! the axes of the mechanism's frame at its origin
    origin = [ox, oy]
    do j = 1, 2
      t = turn(merge([1.0_wp, 0.0_wp], [0.0_wp, 1.0_wp], j == 1), drawing%view_angle)
      axis_tip(:, j) = origin + axis_length * [t(1), -t(2)]
      call out%put(svg_line(origin(1), origin(2), axis_tip(1, j), axis_tip(2, j), 'stroke="#555555" stroke-width="0.2"'))
      call out%put(svg_arrow(axis_tip(1, j) - 2.0_wp * t(1), axis_tip(2, j) + 2.0_wp * t(2), axis_tip(1, j), &
        axis_tip(2, j), "#555555", 0.2_wp, 2.0_wp))
      call add_segment(obst_x, obst_y, origin, axis_tip(:, j))
    end do
    ! bodies in drawing order: bars through their points (the centre of mass included) and
    ! plates as the convex hull of their points; rods, and the hydraulic cylinders over them
    ! (a tube from the pivot along the axis); blocks
    do pass = 1, size(body_order)
      do i = 1, size(drawing%bodies)
        associate (b => drawing%bodies(i))
          if (b%kind /= body_order(pass)) cycle
          select case (b%kind)
          case (body_bar)
            if (size(b%points) < 2) cycle
            call convex_hull(px(b%points), py(b%points), hx, hy)
            if (size(hx) <= 2 .or. polygon_area(hx, hy) < 1.0_wp) then
              ! a bar (points on one line): a light band with a dark outline between its ends
              call line_ends(px(b%points), py(b%points), hx, hy)
              call out%put(svg_path(svg_polyline_d(hx, hy), 'fill="none" stroke="#000000" '// &
                'stroke-width="2.2" stroke-linecap="round" stroke-linejoin="round"'))
              call out%put(svg_path(svg_polyline_d(hx, hy), 'fill="none" stroke="#e8e8e8" '// &
                'stroke-width="1.4" stroke-linecap="round" stroke-linejoin="round"'))
            else
              call out%put(svg_polygon(hx, hy, 'class="link"'))
            end if
            do j = 1, size(hx)
              call add_segment(obst_x, obst_y, [hx(j), hy(j)], [hx(modulo(j, size(hx)) + 1), hy(modulo(j, size(hx)) + 1)])
            end do
          case (body_rod)
            call axis_ends(b, b%reach(1), b%reach(2), q, t)
            call out%put(svg_line(q(1), q(2), t(1), t(2), 'stroke="#000000" stroke-width="1.5" stroke-linecap="round"'))
            call out%put(svg_line(q(1), q(2), t(1), t(2), 'stroke="#e8e8e8" stroke-width="0.8" stroke-linecap="round"'))
            call add_segment(obst_x, obst_y, q, t)
          case (body_cylinder)
            call axis_ends(b, 0.0_wp, b%length, q, t)
            call put_tube(out, q, t, 2.3_wp)
            call add_segment(obst_x, obst_y, q, t)
            if (hypot(t(1) - q(1), t(2) - q(2)) > 0.0_wp) then
              u2 = [q(2) - t(2), t(1) - q(1)] * 2.3_wp / hypot(t(1) - q(1), t(2) - q(2))
              call add_segment(obst_x, obst_y, q + u2, t + u2)
              call add_segment(obst_x, obst_y, q - u2, t - u2)
            end if
          case (body_block)
            call put_block(out, px(b%points(1)), py(b%points(1)), b%angle + drawing%view_angle)
            call add_segment(obst_x, obst_y, [px(b%points(1)) - 4.0_wp, py(b%points(1))], &
              [px(b%points(1)) + 4.0_wp, py(b%points(1))])
          case default
            continue
          end select
        end associate
      end do
    end do
    ! joints, pivots, centres of mass
    do i = 1, n
      select case (drawing%points(i)%kind)
      case (point_pivot)
        call put_pivot(out, px(i), py(i))
        call out%put(svg_circle(px(i), py(i), 1.1_wp, 'class="joint"'))
        call add_segment(obst_x, obst_y, [px(i) - 4.0_wp, py(i) + 4.5_wp], [px(i) + 4.0_wp, py(i) + 4.5_wp])
        call add_segment(obst_x, obst_y, [px(i), py(i)], [px(i), py(i) + 4.0_wp])
      case (point_com)
        call out%put(svg_circle(px(i), py(i), 0.9_wp, 'class="com"'))
        call add_segment(obst_x, obst_y, [px(i), py(i)], [px(i), py(i)])
      case (point_plain)
        cycle
      case default
        call out%put(svg_circle(px(i), py(i), 1.1_wp, 'class="joint"'))
        call add_segment(obst_x, obst_y, [px(i), py(i)], [px(i), py(i)])
      end select
    end do
    ! forces: arrows from their points, one scale
    do i = 1, nf
      associate (f => drawing%forces(i))
        if (force_scale <= 0.0_wp .or. hypot(f%f(1), f%f(2)) * force_scale < 0.3_wp) cycle
        call force_ends(f%at, f%f, q, t)
        call out%put(svg_arrow(q(1), q(2), t(1), t(2), kind_colours(f%kind), 0.45_wp, 2.4_wp))
        call add_segment(obst_x, obst_y, q, t)
      end associate
    end do
    ! moments: arcs around their points
    do i = 1, nm
      call put_moment(out, drawing, i, ox, oy, len_scale)
      q = turn(drawing%moments(i)%at, drawing%view_angle)
      q = [ox + len_scale * q(1), oy - len_scale * q(2)]
      do j = 0, 7
        call add_segment(obst_x, obst_y, q + 5.0_wp * [cos(j * pi / 4), sin(j * pi / 4)], &
          q + 5.0_wp * [cos((j + 1) * pi / 4), sin((j + 1) * pi / 4)])
      end do
    end do

    ! labels, none over another: point names, link numbers, the axes, force values along
    ! their arrows, moments beside their arcs
    do i = 1, n
      if (drawing%points(i)%kind == point_plain) cycle
      text = trim(drawing%points(i)%name)
      call boxes%place(text, label_size, px(i), py(i), 0.75_wp * pi, obst_x, obst_y, bounds, tx, ty, leader)
      call put_label(out, text, tx, ty, px(i), py(i), leader, 'class="label"', label_size)
    end do
    do i = 1, size(drawing%bodies)
      associate (b => drawing%bodies(i))
        if (size(b%points) == 0) cycle
        text = trim(b%name)
        if (b%kind == body_block) then
          q = [px(b%points(1)), py(b%points(1))]
        else if (size(b%points) >= 2) then
          q = [sum(px(b%points)), sum(py(b%points))] / size(b%points)
        else
          cycle
        end if
        call boxes%place(text, label_size, q(1), q(2), 0.25_wp * pi, obst_x, obst_y, bounds, tx, ty, leader)
        call put_label(out, text, tx, ty, q(1), q(2), leader, 'class="label" font-style="italic"', label_size)
      end associate
    end do
    do j = 1, 2
      text = merge("x", "y", j == 1)
      call boxes%place(text, label_size, axis_tip(1, j), axis_tip(2, j), atan2(axis_tip(2, j) - origin(2), &
        axis_tip(1, j) - origin(1)), obst_x, obst_y, bounds, tx, ty, leader, tail=origin)
      call put_label(out, text, tx, ty, axis_tip(1, j), axis_tip(2, j), leader, 'class="label" font-style="italic"', &
        label_size)
    end do
    do i = 1, nf
      associate (f => drawing%forces(i))
        if (force_scale <= 0.0_wp .or. hypot(f%f(1), f%f(2)) * force_scale < 0.3_wp) cycle
        call force_ends(f%at, f%f, q, t)
        text = trim(f%name)//" = "//short_number(hypot(f%f(1), f%f(2)))//" "//unit_word("N", lang)
        call boxes%place(text, num_size, t(1), t(2), atan2(t(2) - q(2), t(1) - q(1)), obst_x, obst_y, bounds, &
          tx, ty, leader, tail=q)
        call put_label(out, text, tx, ty, t(1), t(2), leader, 'class="num" style="fill: '//kind_colours(f%kind)//'"', &
          num_size)
      end associate
    end do
    do i = 1, nm
      associate (m => drawing%moments(i))
        if (m%value == 0.0_wp) cycle
        q = turn(m%at, drawing%view_angle)
        q = [ox + len_scale * q(1), oy - len_scale * q(2)]
        text = trim(m%name)//" = "//short_number(abs(m%value))//" "//unit_word("N*m", lang)
        call boxes%place(text, num_size, q(1) + 5.0_wp, q(2) + 5.0_wp, 0.25_wp * pi, obst_x, obst_y, bounds, &
          tx, ty, leader)
        call put_label(out, text, tx, ty, q(1) + 3.5_wp, q(2) + 3.5_wp, leader, 'class="num" style="fill: '// &
          kind_colours(m%kind)//'"', num_size)
      end associate
    end do

    ! scales and legend under the drawing
    ty = area(2) + area(4) + 8.0_wp
    bar_value = nice_step(40.0_wp / len_scale, 1, .false.)
    if (bar_value * len_scale > 45.0_wp) bar_value = bar_value / 2.0_wp
    bar_len = bar_value * len_scale
    call put_scale(out, area(1), ty, bar_len, word("lengths", lang)//": "//short_number(bar_value)//" "// &
      unit_word("m", lang))
    if (force_scale > 0.0_wp) then
      bar_value = nice_step(0.8_wp * fmax, 1, .false.)
      if (bar_value * force_scale > 40.0_wp) bar_value = bar_value / 2.0_wp
      call put_scale(out, area(1) + 70.0_wp, ty, bar_value * force_scale, word("forces", lang)//": "// &
        short_number(bar_value)//" "//unit_word("N", lang))
    end if
    do i = 1, size(kind_colours)
      tx = area(1) + 128.0_wp + 15.0_wp * modulo(i - 1, 2) * 2.0_wp
      call out%put(svg_line(tx, ty - 3.0_wp + 4.0_wp * ((i - 1) / 2), tx + 5.0_wp, ty - 3.0_wp + 4.0_wp * ((i - 1) / 2), &
        'stroke="'//kind_colours(i)//'" stroke-width="0.8"'))
      call out%put(svg_text(tx + 6.5_wp, ty - 2.1_wp + 4.0_wp * ((i - 1) / 2), word(trim(force_kind_names(i)), lang), &
        'class="small"'))
    end do
    call put_force_list(out, drawing, area(1), ty + 9.0_wp, lang)
    call put_title_block(out, table, lang, page_width, sheet_height, word("Mechanism with its forces", lang)// &
      ", "//word(table%row_name, lang)//" "//int_str(table%run_row(k)))
    call svg_close(out)
  contains
    !> Page points (mm) of the axis of a cylinder or rod `b` at s0 and s1 m from its anchor.
    pure subroutine axis_ends(b, s0, s1, e0, e1)
      type(drawing_body_t), intent(in) :: b
      real(wp), intent(in) :: s0, s1
      real(wp), intent(out) :: e0(2), e1(2)
      real(wp) :: w(2)
      w = turn(b%anchor + s0 * [cos(b%angle), sin(b%angle)], drawing%view_angle)
      e0 = [ox + len_scale * w(1), oy - len_scale * w(2)]
      w = turn(b%anchor + s1 * [cos(b%angle), sin(b%angle)], drawing%view_angle)
      e1 = [ox + len_scale * w(1), oy - len_scale * w(2)]
    end subroutine axis_ends
    !> Tail and tip (page, mm) of the arrow of force `f` (N) at `at` (m).
    pure subroutine force_ends(at, f, tail, tip)
      real(wp), intent(in) :: at(2), f(2)
      real(wp), intent(out) :: tail(2), tip(2)
      real(wp) :: w(2)
      tail = turn(at, drawing%view_angle)
      tail = [ox + len_scale * tail(1), oy - len_scale * tail(2)]
      w = turn(f, drawing%view_angle)
      tip = [tail(1) + force_scale * w(1), tail(2) - force_scale * w(2)]
    end subroutine force_ends
  end subroutine write_svg_mechanism

  !> A label whose baseline centre is (tx, ty), with a thin leader line from the point
  !> (px, py) to the nearest point of its box when `leader`.
  pure subroutine put_label(out, text, tx, ty, px, py, leader, attributes, font_size)
    type(text_buffer_t), intent(inout) :: out
    character(*), intent(in) :: text, attributes
    real(wp), intent(in) :: tx, ty, px, py, font_size
    logical, intent(in) :: leader
    real(wp) :: hw, b(4), e(2)
    if (leader) then
      hw = 0.3_wp * font_size * text_chars(text)
      b = [tx - hw, ty - 0.8_wp * font_size, tx + hw, ty + 0.2_wp * font_size]
      e = [max(b(1), min(b(3), px)), max(b(2), min(b(4), py))]
      call out%put(svg_line(px, py, e(1), e(2), 'stroke="#777777" stroke-width="0.15"'))
    end if
    call out%put(svg_text(tx, ty, text, attributes//' text-anchor="middle"'))
  end subroutine put_label

  !> A hydraulic cylinder's tube from a to b (page, mm), `half` mm each side of its axis,
  !> closed at a (the pivot's end), open at b where the rod leaves it.
  pure subroutine put_tube(out, a, b, half)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: a(2), b(2), half
    real(wp) :: u(2), n(2), length
    length = hypot(b(1) - a(1), b(2) - a(2))
    if (length <= 0.0_wp) return
    u = (b - a) / length
    n = [-u(2), u(1)] * half
    call out%put(svg_polygon([a(1) + n(1), b(1) + n(1), b(1) - n(1), a(1) - n(1)], &
      [a(2) + n(2), b(2) + n(2), b(2) - n(2), a(2) - n(2)], 'class="link"'))
    call out%put(svg_line(b(1) + 0.6_wp * n(1), b(2) + 0.6_wp * n(2), b(1) - 0.6_wp * n(1), b(2) - 0.6_wp * n(2), &
      'class="frame"'))
  end subroutine put_tube

  !> Append the segment a-b (page, mm) to the obstacles of the labels.
  pure subroutine add_segment(obst_x, obst_y, a, b)
    real(wp), allocatable, intent(inout) :: obst_x(:), obst_y(:)
    real(wp), intent(in) :: a(2), b(2)
    obst_x = [obst_x, a(1), b(1)]
    obst_y = [obst_y, a(2), b(2)]
  end subroutine add_segment

  !> Convex hull of the points (x, y), counterclockwise in page coordinates (monotone
  !> chain); coinciding points once. Fewer than three points are returned as they are.
  pure subroutine convex_hull(x, y, hx, hy)
    real(wp), intent(in) :: x(:), y(:)
    real(wp), allocatable, intent(out) :: hx(:), hy(:)
    integer, allocatable :: order(:), hull(:)
    integer :: i, j, n, m, lower_size
    n = size(x)
    allocate (order(n))
    order = [(i, i = 1, n)]
    do i = 2, n
      j = i
      do while (j > 1)
        if (x(order(j - 1)) < x(order(j)) .or. (x(order(j - 1)) == x(order(j)) .and. y(order(j - 1)) <= y(order(j)))) exit
        order([j - 1, j]) = order([j, j - 1])
        j = j - 1
      end do
    end do
    if (n < 3) then
      hx = x(order)
      hy = y(order)
      return
    end if
    allocate (hull(2 * n))
    m = 0
    do i = 1, n
      call push(hull, m, order(i), 2)
    end do
    lower_size = m + 1
    do i = n - 1, 1, -1
      call push(hull, m, order(i), lower_size)
    end do
    m = m - 1
    hx = x(hull(1:m))
    hy = y(hull(1:m))
  contains
    !> Point p onto hull(1:m), after dropping the points (above the first `keep` - 1) that
    !> would not make a left turn.
    pure subroutine push(hull, m, p, keep)
      integer, intent(inout) :: hull(:), m
      integer, intent(in) :: p, keep
      do while (m >= keep)
        if (cross(hull(m - 1), hull(m), p) > 0.0_wp) exit
        m = m - 1
      end do
      m = m + 1
      hull(m) = p
    end subroutine push
    pure real(wp) function cross(a, b, c)
      integer, intent(in) :: a, b, c
      cross = (x(b) - x(a)) * (y(c) - y(a)) - (y(b) - y(a)) * (x(c) - x(a))
    end function cross
  end subroutine convex_hull

  !> The two points of (x, y) farthest apart (the ends of a bar whose points lie on one line).
  pure subroutine line_ends(x, y, ex, ey)
    real(wp), intent(in) :: x(:), y(:)
    real(wp), allocatable, intent(out) :: ex(:), ey(:)
    integer :: i, j, a, b
    real(wp) :: best
    a = 1
    b = 1
    best = -1.0_wp
    do i = 1, size(x)
      do j = i + 1, size(x)
        if (hypot(x(j) - x(i), y(j) - y(i)) > best) then
          best = hypot(x(j) - x(i), y(j) - y(i))
          a = i
          b = j
        end if
      end do
    end do
    ex = [x(a), x(b)]
    ey = [y(a), y(b)]
  end subroutine line_ends

  !> Area of the polygon through the points, mm^2 (shoelace formula).
  pure real(wp) function polygon_area(x, y)
    real(wp), intent(in) :: x(:), y(:)
    integer :: n
    n = size(x)
    polygon_area = 0.5_wp * abs(sum(x * cshift(y, 1) - cshift(x, 1) * y))
    if (n < 3) polygon_area = 0.0_wp
  end function polygon_area

  !> Vector `v` turned counterclockwise by `angle` (rad).
  pure function turn(v, angle) result(w)
    real(wp), intent(in) :: v(2), angle
    real(wp) :: w(2)
    w = [cos(angle) * v(1) - sin(angle) * v(2), sin(angle) * v(1) + cos(angle) * v(2)]
  end function turn

  !> A scale bar of `length` mm at (x, y) with its label.
  pure subroutine put_scale(out, x, y, length, label)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: x, y, length
    character(*), intent(in) :: label
    call out%put(svg_line(x, y, x + length, y, 'class="scale"'))
    call out%put(svg_line(x, y - 1.0_wp, x, y + 1.0_wp, 'class="scale"'))
    call out%put(svg_line(x + length, y - 1.0_wp, x + length, y + 1.0_wp, 'class="scale"'))
    call out%put(svg_text(x + length + 1.5_wp, y + 0.9_wp, label, 'class="small"'))
  end subroutine put_scale

  !> The ground symbol of a frame pivot at (x, y): a triangle below it on a hatched base.
  pure subroutine put_pivot(out, x, y)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: x, y
    integer :: i
    call out%put(svg_polygon([x, x - 2.4_wp, x + 2.4_wp], [y, y + 4.0_wp, y + 4.0_wp], 'class="link"'))
    call out%put(svg_line(x - 4.0_wp, y + 4.0_wp, x + 4.0_wp, y + 4.0_wp, 'class="frame"'))
    do i = 0, 4
      call out%put(svg_line(x - 3.5_wp + 1.8_wp * i, y + 4.0_wp, x - 4.7_wp + 1.8_wp * i, y + 5.5_wp, 'class="hatch"'))
    end do
  end subroutine put_pivot

  !> Guide `i` of the sketch: a line with hatching on its right side.
  pure subroutine put_guide(out, drawing, i, ox, oy, len_scale, obst_x, obst_y)
    type(text_buffer_t), intent(inout) :: out
    type(drawing_t), intent(in) :: drawing
    integer, intent(in) :: i
    real(wp), intent(in) :: ox, oy, len_scale
    !> Obstacles of the labels (the guide's line is appended).
    real(wp), allocatable, intent(inout) :: obst_x(:), obst_y(:)
    real(wp) :: a(2), b(2), u(2), nrm(2), length, s
    integer :: j, count
    associate (g => drawing%guides(i))
      a = turn(g%p - g%half_length * [cos(g%angle), sin(g%angle)], drawing%view_angle)
      b = turn(g%p + g%half_length * [cos(g%angle), sin(g%angle)], drawing%view_angle)
    end associate
    a = [ox + len_scale * a(1), oy - len_scale * a(2)]
    b = [ox + len_scale * b(1), oy - len_scale * b(2)]
    length = hypot(b(1) - a(1), b(2) - a(2))
    if (length <= 0.0_wp) return
    u = (b - a) / length
    nrm = [-u(2), u(1)]
    ! hatch on the side away from the blocks: offset the line by half a block height
    a = a + 2.6_wp * nrm
    b = b + 2.6_wp * nrm
    call out%put(svg_line(a(1), a(2), b(1), b(2), 'class="frame"'))
    call add_segment(obst_x, obst_y, a + 0.75_wp * nrm, b + 0.75_wp * nrm)
    count = int(length / 2.0_wp)
    do j = 0, count
      s = 1.0_wp + 2.0_wp * j
      if (s > length) exit
      call out%put(svg_line(a(1) + s * u(1), a(2) + s * u(2), a(1) + (s - 1.2_wp) * u(1) + 1.5_wp * nrm(1), &
        a(2) + (s - 1.2_wp) * u(2) + 1.5_wp * nrm(2), 'class="hatch"'))
    end do
  end subroutine put_guide

  !> A slider block (8 x 5 mm on the sheet) at (x, y), its long side along `angle` (rad,
  !> counterclockwise on the sheet).
  pure subroutine put_block(out, x, y, angle)
    type(text_buffer_t), intent(inout) :: out
    real(wp), intent(in) :: x, y, angle
    real(wp) :: u(2), v(2), cx(4), cy(4)
    u = [cos(angle), -sin(angle)] * 4.0_wp
    v = [sin(angle), cos(angle)] * 2.5_wp
    cx = [x - u(1) - v(1), x + u(1) - v(1), x + u(1) + v(1), x - u(1) + v(1)]
    cy = [y - u(2) - v(2), y + u(2) - v(2), y + u(2) + v(2), y - u(2) + v(2)]
    call out%put(svg_polygon(cx, cy, 'class="link"'))
  end subroutine put_block

  !> Moment `i` of the sketch: a 3/4 arc of radius 5 mm about its point, the arrowhead
  !> showing its sense (its label is placed with the others).
  pure subroutine put_moment(out, drawing, i, ox, oy, len_scale)
    type(text_buffer_t), intent(inout) :: out
    type(drawing_t), intent(in) :: drawing
    integer, intent(in) :: i
    real(wp), intent(in) :: ox, oy, len_scale
    real(wp), parameter :: r = 5.0_wp
    real(wp) :: c(2), a0, a1, sense, e(2), tan_dir(2)
    character(len=7) :: colour
    associate (m => drawing%moments(i))
      if (m%value == 0.0_wp) return
      colour = kind_colours(m%kind)
      c = turn(m%at, drawing%view_angle)
      c = [ox + len_scale * c(1), oy - len_scale * c(2)]
      sense = sign(1.0_wp, m%value)
      ! from 200 deg, sweeping 270 deg in the moment's sense (counterclockwise on the sheet = +)
      a0 = 200.0_wp * pi / 180.0_wp
      a1 = a0 + sense * 1.5_wp * pi
      e = [c(1) + r * cos(a1), c(2) - r * sin(a1)]
      call out%put(svg_path("M "//coord(c(1) + r * cos(a0))//" "//coord(c(2) - r * sin(a0))//" A "//coord(r)//" "// &
        coord(r)//" 0 1 "//merge("0", "1", sense > 0.0_wp)//" "//coord(e(1))//" "//coord(e(2)), &
        'fill="none" stroke="'//colour//'" stroke-width="0.45"'))
      tan_dir = sense * [-sin(a1), -cos(a1)]
      call out%put(svg_arrow(e(1) - 2.2_wp * tan_dir(1), e(2) - 2.2_wp * tan_dir(2), e(1), e(2), colour, 0.45_wp, &
        2.2_wp))
    end associate
  end subroutine put_moment

  !> The forces and moments of the sketch as a list (name, value, direction in the
  !> position frame) in four columns.
  pure subroutine put_force_list(out, drawing, x, y, lang)
    type(text_buffer_t), intent(inout) :: out
    type(drawing_t), intent(in) :: drawing
    real(wp), intent(in) :: x, y
    integer, intent(in) :: lang
    !> Width of the list, mm.
    real(wp), parameter :: list_width = 188.0_wp
    character(len=96), allocatable :: texts(:)
    character(len=7), allocatable :: colours(:)
    character(len=:), allocatable :: text
    real(wp) :: a, column_width
    integer :: i, j, columns, widest
    call out%put(svg_text(x, y, word("Forces of the step (angles counterclockwise from the x axis of the "// &
      "mechanism's frame)", lang), &
      'class="label" font-weight="bold"'))
    allocate (texts(0), colours(0))
    do i = 1, size(drawing%forces)
      associate (f => drawing%forces(i))
        a = modulo(atan2(f%f(2), f%f(1)) * rad_to_deg, 360.0_wp)
        if (a >= 359.95_wp) a = 0.0_wp
        text = trim(f%name)//" = "//short_number(hypot(f%f(1), f%f(2)))//" "//unit_word("N", lang)
        if (hypot(f%f(1), f%f(2)) > 0.0_wp) text = text//" "//word("at", lang)//" "//fixed_number(a, 1)//" "// &
          unit_word("deg", lang)
        texts = [character(len=96) :: texts, text]
        colours = [character(len=7) :: colours, kind_colours(f%kind)]
      end associate
    end do
    do i = 1, size(drawing%moments)
      associate (m => drawing%moments(i))
        text = trim(m%name)//" = "//short_number(m%value)//" "//unit_word("N*m", lang)
        texts = [character(len=96) :: texts, text]
        colours = [character(len=7) :: colours, kind_colours(m%kind)]
      end associate
    end do
    ! as many columns (up to four) as the widest entry allows
    widest = 1
    do i = 1, size(texts)
      widest = max(widest, text_chars(trim(texts(i))))
    end do
    columns = max(1, min(4, int(list_width / (0.6_wp * list_size * widest + 1.5_wp))))
    column_width = list_width / columns
    do j = 0, size(texts) - 1
      call out%put(svg_text(x + column_width * modulo(j, columns), y + 4.5_wp + 3.6_wp * (j / columns), &
        trim(texts(j + 1)), 'class="small" style="fill: '//colours(j + 1)//'"'))
    end do
  end subroutine put_force_list

end module kinetostat_svg_mechanism
