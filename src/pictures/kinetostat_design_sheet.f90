!> What the sheets of the design kinds (the gear pair, the planetary train, the cam) share, on
!> the drawing model: the sheet opened with the ГОСТ 2.301 frame and the ГОСТ 2.104 title block
!> and a header (the drawing's heading, the deck, the program); the sheet's own en/ru words; a
!> chart of a quantity against the cam angle (its axes, the curve, levels, a second scale on
!> the right); a linear dimension (ГОСТ 2.307: extension lines, arrows, the value along the
!> dimension line); an angle's arc; a table of values in a grid; hatch ticks on one side of a
!> curve (the forbidden side of a boundary). The sheets themselves are in the folders of their
!> kinds (they draw from their kernels).
module kinetostat_design_sheet
  use kinetostat_kinds, only: wp, pi, version_string
  use kinetostat_format, only: fixed_number
  use kinetostat_step_table, only: step_table_t
  use kinetostat_labels, only: word => label, words => in_language
  use kinetostat_typeset, only: typeset, runs_extent
  use kinetostat_sheet, only: sheet_t, paper_t, layer_text, anchor_start, anchor_middle, anchor_end
  use kinetostat_title_block, only: put_sheet_format, title_block_from_table, course_data_line
  use kinetostat_mechanism_sheet, only: fitted_size
  use kinetostat_run_sheet, only: put_axes, y_range
  implicit none
  private
  public :: words, open_design_sheet, sheet_of, chart_t, put_chart, put_dimension, put_angle, put_table, put_side_ticks, &
    text_width, dot

  !> A chart of quantities against an abscissa, placed in a panel.
  type :: chart_t
    !> The plot's rectangle on the sheet, mm.
    real(wp) :: left = 0.0_wp, top = 0.0_wp, width = 0.0_wp, height = 0.0_wp
    !> The ranges drawn.
    real(wp) :: xlo = 0.0_wp, xhi = 1.0_wp, ylo = 0.0_wp, yhi = 1.0_wp
  contains
    !> A value's place on the sheet.
    procedure :: sx => chart_x
    procedure :: sy => chart_y
  end type chart_t

contains

  !> Open `sheet` on `paper` with the frame, the title block (the drawing's name, its scale,
  !> the student's fields of the run) and the header: `heading` (typeset), the deck and its
  !> title, and `line` (typeset) with the program's version.
  pure subroutine open_design_sheet(sheet, paper, lang, table, drawing_name, scale, heading, line, description)
    type(sheet_t), intent(out) :: sheet
    type(paper_t), intent(in) :: paper
    integer, intent(in) :: lang
    !> The run's results (the deck, its title, the student).
    type(step_table_t), intent(in) :: table
    !> The title block's name of the drawing and its scale ("" when none).
    character(*), intent(in) :: drawing_name, scale
    !> The header's first line and its third (before the version).
    character(*), intent(in) :: heading, line
    !> The SVG's description (how a program reads the drawing back).
    character(*), intent(in) :: description
    real(wp) :: inner(4), w
    character(len=:), allocatable :: deck_line
    ! (a course sheet's results come without their file: no path on the sheet)
    if (len(table%deck) > 0) then
      call sheet%open(paper, lang, drawing_name//" - "//table%deck, description)
    else
      call sheet%open(paper, lang, drawing_name, description)
    end if
    call put_sheet_format(sheet, title_block_from_table(table, drawing_name, scale))
    inner = paper%inside()
    w = inner(3) - inner(1) - 10.0_wp
    call sheet%set_layer(layer_text)
    call sheet%text(inner(1) + 5.0_wp, 12.0_wp, heading, "title", size=fitted_size(heading, 3.3_wp, w, 0.8_wp))
    if (len(table%deck) > 0) then
      deck_line = word("deck", lang)//": "//table%deck
      if (allocated(table%subtitle)) deck_line = deck_line//"   "//table%subtitle
    else
      deck_line = course_data_line(table, lang)
    end if
    if (len(deck_line) > 0) call sheet%text(inner(1) + 5.0_wp, 17.5_wp, deck_line, "subtitle", &
      size=fitted_size(deck_line, 3.0_wp, w, 0.6_wp), plain=.true.)
    call sheet%text(inner(1) + 5.0_wp, 22.5_wp, line//"; "//version_string, "small", &
      size=fitted_size(line//"; "//version_string, 2.4_wp, w, 0.6_wp))
  end subroutine open_design_sheet

  !> The start of a design sheet's description: "kinetostat sheet of DECK: ", or without
  !> the file on a course sheet ("kinetostat sheet: ").
  pure function sheet_of(table) result(text)
    type(step_table_t), intent(in) :: table
    character(len=:), allocatable :: text
    if (len(table%deck) > 0) then
      text = "kinetostat sheet of "//table%deck//": "
    else
      text = "kinetostat sheet: "
    end if
  end function sheet_of

  !> Width of `text` typeset on `sheet` at font size `size`, mm.
  pure real(wp) function text_width(sheet, text, size)
    type(sheet_t), intent(in) :: sheet
    character(*), intent(in) :: text
    real(wp), intent(in) :: size
    real(wp) :: above, below
    call runs_extent(typeset(text, sheet%lang), text_width, above, below)
    text_width = text_width * size
  end function text_width

  !> A chart in the panel (x0, y0, w, h) with its heading: axes for x in [xlo, xhi] (tick step
  !> xstep) and y over `ys` (every value of every curve and level, zero included), the axis
  !> labels; with `right_factor`, a second scale on the right (right value = y * right_factor)
  !> labelled `right_label`; `right_room` keeps its room without it (charts one under the other
  !> with the same abscissa). The curves are drawn by the caller through `chart%sx`, `chart%sy`.
  pure subroutine put_chart(sheet, chart, x0, y0, w, h, heading, xlo, xhi, xstep, ys, xlabel, ylabel, right_factor, &
    right_label, right_room)
    type(sheet_t), intent(inout) :: sheet
    type(chart_t), intent(out) :: chart
    real(wp), intent(in) :: x0, y0, w, h
    character(*), intent(in) :: heading
    real(wp), intent(in) :: xlo, xhi, xstep
    real(wp), intent(in) :: ys(:)
    character(*), intent(in) :: xlabel, ylabel
    real(wp), intent(in), optional :: right_factor
    character(*), intent(in), optional :: right_label
    logical, intent(in), optional :: right_room
    real(wp) :: ystep, v, t
    integer :: i
    call sheet%rect(x0, y0, w, h, "panel")
    call sheet%text(x0 + 2.0_wp, y0 + 4.5_wp, heading, "heading", size=min(3.2_wp, fitted_size(heading, 3.2_wp, &
      w - 4.0_wp, 0.6_wp)))
    chart%left = x0 + 19.0_wp
    chart%top = y0 + 8.0_wp
    chart%width = w - 23.0_wp
    if (present(right_factor)) chart%width = w - 42.0_wp
    if (present(right_room)) then
      if (right_room) chart%width = w - 42.0_wp
    end if
    chart%height = h - 20.0_wp
    chart%xlo = xlo
    chart%xhi = xhi
    call y_range(ys, chart%ylo, chart%yhi, ystep)
    call put_axes(sheet, chart%left, chart%top, chart%width, chart%height, xlo, xhi, xstep, chart%ylo, chart%yhi, &
      ystep, xlabel, ylabel)
    if (.not. present(right_factor)) return
    ! the second scale: the same ticks, their values times the factor
    do i = nint(chart%ylo / ystep), nint(chart%yhi / ystep)
      v = i * ystep
      t = chart%sy(v)
      call sheet%line(chart%left + chart%width, t, chart%left + chart%width + 1.0_wp, t, "axis")
      call sheet%text(chart%left + chart%width + 1.5_wp, t + 0.8_wp, tick_text(v * right_factor, ystep * &
        abs(right_factor)), "small", anchor_start)
    end do
    if (present(right_label)) call sheet%text(x0 + w - 3.0_wp, chart%top + 0.5_wp * chart%height, right_label, &
      "label", anchor_middle, rotation=-90.0_wp)
  contains
    !> A tick's value with the decimals its step needs (the fewest that write it exactly).
    pure function tick_text(value, step) result(text)
      real(wp), intent(in) :: value, step
      character(len=:), allocatable :: text
      integer :: decimals
      do decimals = 0, 6
        if (abs(step * 10.0_wp**decimals - anint(step * 10.0_wp**decimals)) <= 1.0e-6_wp * step * &
          10.0_wp**decimals) exit
      end do
      text = fixed_number(value, min(decimals, 6))
      if (abs(value) < 0.5_wp * step * 1.0e-6_wp) text = "0"
    end function tick_text
  end subroutine put_chart

  !> x on the sheet of the chart's abscissa value, mm.
  pure real(wp) function chart_x(self, x)
    class(chart_t), intent(in) :: self
    real(wp), intent(in) :: x
    chart_x = self%left + self%width * (x - self%xlo) / (self%xhi - self%xlo)
  end function chart_x

  !> y on the sheet of the chart's ordinate value, mm.
  pure real(wp) function chart_y(self, y)
    class(chart_t), intent(in) :: self
    real(wp), intent(in) :: y
    chart_y = self%top + self%height - self%height * (y - self%ylo) / (self%yhi - self%ylo)
  end function chart_y

  !> A linear dimension between the points a and b (sheet mm) on a dimension line `offset` mm
  !> to the left of a -> b (negative: right), with extension lines (from 1 mm off the points
  !> to 2 mm past the dimension line), arrowheads and `text` beside the dimension line, on its
  !> outer side, along it. ГОСТ 2.307 for a narrow one: arrowheads without room between the
  !> extension lines go outside them, and a value without room there goes on the dimension
  !> line's continuation past b (so it never lies over an extension line).
  pure subroutine put_dimension(sheet, a, b, offset, text)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: a(2), b(2), offset
    character(*), intent(in) :: text
    real(wp) :: u(2), n(2), pa(2), pb(2), length, angle, side, up(2), clear, tw, ea(2), eb(2)
    real(wp), parameter :: size = 2.8_wp
    !> Arrowheads' length and the dimension line's length past an outside arrowhead, mm.
    real(wp), parameter :: head = 2.5_wp, beyond = 4.0_wp
    character(len=*), parameter :: ink = "#000000"
    logical :: heads_out, value_out
    length = norm2(b - a)
    if (length <= 0.0_wp) return
    u = (b - a) / length
    ! left of a -> b as the sheet is seen (y down): (u_y, -u_x)
    n = [u(2), -u(1)]
    side = sign(1.0_wp, offset)
    pa = a + offset * n
    pb = b + offset * n
    tw = text_width(sheet, text, size)
    heads_out = length < 2.0_wp * head + 1.0_wp
    value_out = length < tw + 2.0_wp
    call sheet%line(a(1) + side * 1.0_wp * n(1), a(2) + side * 1.0_wp * n(2), pa(1) + side * 2.0_wp * n(1), &
      pa(2) + side * 2.0_wp * n(2), stroke=ink, width=0.18_wp)
    call sheet%line(b(1) + side * 1.0_wp * n(1), b(2) + side * 1.0_wp * n(2), pb(1) + side * 2.0_wp * n(1), &
      pb(2) + side * 2.0_wp * n(2), stroke=ink, width=0.18_wp)
    ! the dimension line: between the extension lines, on past them for outside arrowheads and
    ! under a value beyond b
    ea = pa
    eb = pb
    if (heads_out) then
      ea = pa - beyond * u
      eb = pb + beyond * u
    end if
    if (value_out) eb = pb + (merge(beyond, 0.0_wp, heads_out) + 1.0_wp + tw + 1.0_wp) * u
    call sheet%line(ea(1), ea(2), eb(1), eb(2), stroke=ink, width=0.18_wp)
    if (heads_out) then
      call sheet%arrow(pa(1) - 3.0_wp * u(1), pa(2) - 3.0_wp * u(2), pa(1), pa(2), ink, 0.18_wp, head)
      call sheet%arrow(pb(1) + 3.0_wp * u(1), pb(2) + 3.0_wp * u(2), pb(1), pb(2), ink, 0.18_wp, head)
    else
      call sheet%arrow(pa(1) + 3.0_wp * u(1), pa(2) + 3.0_wp * u(2), pa(1), pa(2), ink, 0.18_wp, head)
      call sheet%arrow(pb(1) - 3.0_wp * u(1), pb(2) - 3.0_wp * u(2), pb(1), pb(2), ink, 0.18_wp, head)
    end if
    ! the value beside the dimension line, on its outer side, along it (read from below or
    ! from the right); its glyphs clear of the line whichever way they face
    angle = atan2(u(2), u(1)) * 180.0_wp / pi
    if (angle > 90.0_wp - 1.0e-9_wp) angle = angle - 180.0_wp
    if (angle < -90.0_wp - 1.0e-9_wp) angle = angle + 180.0_wp
    up = [sin(angle * pi / 180.0_wp), -cos(angle * pi / 180.0_wp)]
    if (dot_product(up, side * n) > 0.0_wp) then
      clear = 0.8_wp + 0.45_wp * size
    else
      clear = 0.8_wp + 1.0_wp * size
    end if
    if (value_out) then
      associate (mid => pb + (merge(beyond, 0.0_wp, heads_out) + 1.0_wp + 0.5_wp * tw) * u + side * clear * n)
        call sheet%text(mid(1), mid(2), text, "label", anchor_middle, rotation=angle)
      end associate
    else
      associate (mid => 0.5_wp * (pa + pb) + side * clear * n)
        call sheet%text(mid(1), mid(2), text, "label", anchor_middle, rotation=angle)
      end associate
    end if
  end subroutine put_dimension

  !> An angle's arc about (cx, cy) of radius r from `start` sweeping `sweep` (deg,
  !> counter-clockwise as the sheet is seen), in `colour`.
  pure subroutine put_angle(sheet, cx, cy, r, start, sweep, colour)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: cx, cy, r, start, sweep
    character(*), intent(in) :: colour
    call sheet%arc(cx, cy, r, start, sweep, stroke=colour, width=0.25_wp)
  end subroutine put_angle

  !> A table at (x, y) (its upper left corner): `cells` (rows, columns) typeset in a grid of
  !> columns `widths` mm and rows `pitch` mm; the first row bold (the heading); the first
  !> column's texts from the left, the others centred.
  pure subroutine put_table(sheet, x, y, widths, pitch, cells)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: x, y, widths(:), pitch
    character(*), intent(in) :: cells(:, :)
    real(wp) :: cx
    integer :: r, c
    real(wp), parameter :: font = 2.4_wp
    do r = 0, size(cells, 1)
      call sheet%line(x, y + r * pitch, x + sum(widths), y + r * pitch, stroke="#000000", width=merge(0.35_wp, 0.18_wp, &
        r == 0 .or. r == size(cells, 1) .or. r == 1))
    end do
    cx = x
    do c = 0, size(widths)
      call sheet%line(cx, y, cx, y + size(cells, 1) * pitch, stroke="#000000", width=merge(0.35_wp, 0.18_wp, &
        c == 0 .or. c == size(widths)))
      if (c < size(widths)) cx = cx + widths(c + 1)
    end do
    do r = 1, size(cells, 1)
      cx = x
      do c = 1, size(cells, 2)
        if (len_trim(cells(r, c)) > 0) then
          if (c == 1) then
            call sheet%text(cx + 1.2_wp, y + (r - 1) * pitch + 0.5_wp * pitch + 0.6_wp, trim(cells(r, c)), "cell", &
              anchor_start, size=font, bold=(r == 1))
          else
            call sheet%text(cx + 0.5_wp * widths(c), y + (r - 1) * pitch + 0.5_wp * pitch + 0.6_wp, trim(cells(r, c)), &
              "cell", anchor_middle, size=font, bold=(r == 1))
          end if
        end if
        cx = cx + widths(c)
      end do
    end do
  end subroutine put_table

  !> Short ticks along the polyline (x, y) (sheet mm), every `spacing` mm, `length` mm long,
  !> on the side `side(k)` of segment k (+1: left of its direction as the sheet is seen, -1:
  !> right, 0: none), in `colour`: the hatching of a boundary on its forbidden side.
  pure subroutine put_side_ticks(sheet, x, y, side, spacing, length, colour)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: x(:), y(:)
    integer, intent(in) :: side(:)
    real(wp), intent(in) :: spacing, length
    character(*), intent(in) :: colour
    real(wp) :: carry, seg, s, u(2), n(2), p(2)
    integer :: k
    carry = 0.5_wp * spacing
    do k = 1, size(x) - 1
      seg = hypot(x(k + 1) - x(k), y(k + 1) - y(k))
      if (seg <= 0.0_wp) cycle
      u = [x(k + 1) - x(k), y(k + 1) - y(k)] / seg
      n = [u(2), -u(1)]
      s = carry
      do while (s <= seg)
        if (side(k) /= 0) then
          p = [x(k), y(k)] + s * u
          ! slanted 45 deg back along the curve, as a hatch
          call sheet%line(p(1), p(2), p(1) + length * (side(k) * n(1) - 0.6_wp * u(1)), &
            p(2) + length * (side(k) * n(2) - 0.6_wp * u(2)), stroke=colour, width=0.2_wp)
        end if
        s = s + spacing
      end do
      carry = s - seg
    end do
  end subroutine put_side_ticks

  !> A point marked by a small filled disc.
  pure subroutine dot(sheet, p, colour, radius)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: p(2)
    character(*), intent(in) :: colour
    real(wp), intent(in), optional :: radius
    real(wp) :: r
    r = 0.5_wp
    if (present(radius)) r = radius
    call sheet%circle(p(1), p(2), r, fill=colour)
  end subroutine dot

end module kinetostat_design_sheet
