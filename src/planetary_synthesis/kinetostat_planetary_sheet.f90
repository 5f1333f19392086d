!> The sheet of a single-row planetary train (`--format svg`/`dxf` of `&planetary_synthesis`),
!> on A3 landscape with the ГОСТ frame and title block:
!> - the kinematic scheme (ГОСТ 2.770) in the axial section: the input shaft with the sun 1,
!>   the planets 2 on the carrier H, the ring 3 fixed to the frame (hatched), the output shaft
!>   of the carrier; the gears' pitch radii to scale when the deck gives the module m (a ГОСТ
!>   2.302 scale in Масштаб), else proportional to the teeth (no scale);
!> - beside it, on the same radii, the picture of linear speeds (Смирнов's): the sun's line
!>   through the pitch point A, the planet's through A and the ring's pitch point C (its
!>   instant centre), the carrier's through the planet's centre B, and the ratio they give,
!>   u_1H = ω_1/ω_H = (v_A/r_1)/(v_B/r_B);
!> - the train seen along its axis: the sun, the k planets equally spaced with their tip
!>   circles (the neighbours' clearance), the ring, the carrier's circle and arms;
!> - the tooth numbers, the ratio and every condition of the choice with its numbers.
module kinetostat_planetary_sheet
  use kinetostat_kinds, only: wp, pi
  use kinetostat_text, only: int_str
  use kinetostat_format, only: short_number, fixed_number
  use kinetostat_step_table, only: step_table_t
  use kinetostat_labels, only: unit_word => unit_symbol
  use kinetostat_scales, only: drawing_scale_t, standard_drawing_scale
  use kinetostat_sheet, only: sheet_t, paper_t, iso_paper, layer_links, layer_guides, layer_forces, layer_text, &
    layer_frame, layer_vplan, anchor_middle, anchor_start
  use kinetostat_title_block, only: block_width, block_height
  use kinetostat_design_sheet, only: words, open_design_sheet, sheet_of, put_table, dot
  use kinetostat_planetary_synthesis, only: planetary_spec_t, planetary_train_t, train_conditions
  implicit none
  private
  public :: draw_planetary_sheet

  character(*), parameter :: ink = "#000000", grey = "#7f7f7f", dash_dot = "6 1.5 1 1.5", sun_colour = "#1f77b4", &
    planet_colour = "#2ca02c", carrier_colour = "#d62728"

contains

  !> The sheet of the train (z1, z2, z3) with k planets chosen for `spec`; `m` the module (mm)
  !> or 0 when the deck gives none.
  pure subroutine draw_planetary_sheet(spec, z1, z2, z3, k, m, table, lang, sheet)
    type(planetary_spec_t), intent(in) :: spec
    integer, intent(in) :: z1, z2, z3, k
    real(wp), intent(in) :: m
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: lang
    type(sheet_t), intent(out) :: sheet
    type(paper_t) :: paper
    type(drawing_scale_t) :: drawing_scale
    type(planetary_train_t) :: t
    real(wp) :: inner(4), scheme(4), front(4), unit, r(3), fit, scale, axis_y, x_sun, rh
    character(len=:), allocatable :: scale_text, mm, scale_line

    t = train_conditions(spec, z1, z2, z3)
    paper = iso_paper("A3", .true.)
    inner = paper%inside()
    ! the axial scheme with the speeds beside it on the left, the view along the axis right
    scheme = [inner(1) + 6.0_wp, 30.0_wp, inner(1) + 200.0_wp, 196.0_wp]
    front = [inner(3) - block_width, 30.0_wp, inner(3) - 3.0_wp, inner(4) - block_height - 4.0_wp]
    unit = m
    if (unit <= 0.0_wp) unit = 1.0_wp
    r = 0.5_wp * unit * [real(z1, wp), real(z2, wp), real(z3, wp)]
    rh = r(1) + r(2)
    ! one scale for both views: the ring and its housing within each region
    fit = min((scheme(4) - scheme(2) - 12.0_wp) / (2.3_wp * r(3)), (front(3) - front(1) - 20.0_wp) / (2.3_wp * r(3)), &
      (front(4) - front(2) - 20.0_wp) / (2.3_wp * r(3)))
    if (m > 0.0_wp) then
      drawing_scale = standard_drawing_scale(fit)
      scale = drawing_scale%ratio
      scale_text = drawing_scale%text
    else
      scale = fit
      scale_text = ""
    end if
    mm = " "//unit_word("mm", lang)
    if (m > 0.0_wp) then
      scale_line = "m = "//short_number(m)//mm//"; "//words("scale ", "масштаб ", lang)//scale_text
    else
      scale_line = words("no scale: radii as the teeth", &
        "без масштаба: радиусы по числам зубьев", lang)
    end if

    call open_design_sheet(sheet, paper, lang, table, words("Planetary train: scheme, speeds", &
      "Планетарная передача: схема, скорости", lang), scale_text, &
      words("Single-row planetary train: the tooth numbers for u_1H = ", &
      "Однорядная планетарная передача: подбор чисел зубьев для u_1H = ", lang) &
        //short_number(spec%u), &
      "z_1 = "//int_str(z1)//", z_2 = "//int_str(z2)//", z_3 = "//int_str(z3)//", k = "//int_str(k)// &
      ", u_1H = "//fixed_number(t%u_actual, 4)//"; "//scale_line, &
      sheet_of(table)//"the planetary train's kinematic scheme, its picture of linear "// &
      "speeds, its view along the axis and the conditions of its tooth numbers.")

    axis_y = 0.5_wp * (scheme(2) + scheme(4))
    x_sun = scheme(1) + 62.0_wp
    call draw_scheme(sheet, r, k, scale, axis_y, x_sun, scheme, lang)
    call draw_speeds(sheet, r, scale, axis_y, scheme(1) + 130.0_wp, scheme, lang)
    call draw_front(sheet, r, unit, k, scale, [0.5_wp * (front(1) + front(3)), 0.5_wp * (front(2) + front(4))], &
      front, lang)
    call draw_conditions(sheet, spec, t, k, [inner(1) + 6.0_wp, 202.0_wp, inner(3) - block_width - 8.0_wp, &
      inner(4) - 3.0_wp], lang)
  end subroutine draw_planetary_sheet

  !> The kinematic scheme in the axial section: the axis horizontal at axis_y, the gears' plane
  !> at x_sun; radii r (sun, planet, ring) times `scale`.
  pure subroutine draw_scheme(sheet, r, k, scale, axis_y, x_sun, box, lang)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: r(3), scale, axis_y, x_sun, box(4)
    integer, intent(in) :: k, lang
    real(wp) :: y1, yh, y2a, y3, rim, xc, x_in, x_out, side
    integer :: s, i
    rim = 3.0_wp
    x_in = box(1) + 6.0_wp
    x_out = x_sun + 58.0_wp
    xc = x_sun + 22.0_wp
    call sheet%set_layer(layer_guides)
    call sheet%line(x_in - 4.0_wp, axis_y, x_out + 6.0_wp, axis_y, stroke=ink, width=0.18_wp, dash=dash_dot)
    call sheet%set_layer(layer_links)
    ! the input shaft and the sun
    call sheet%line(x_in, axis_y, x_sun, axis_y, stroke=sun_colour, width=0.7_wp)
    y1 = r(1) * scale
    call sheet%line(x_sun, axis_y - y1, x_sun, axis_y + y1, stroke=sun_colour, width=0.7_wp)
    do s = -1, 1, 2
      call sheet%line(x_sun - rim, axis_y + s * y1, x_sun + rim, axis_y + s * y1, stroke=sun_colour, width=0.7_wp)
    end do
    call bearing(sheet, x_in + 12.0_wp, axis_y)
    ! the planets on their axles, the carrier and the output shaft
    yh = (r(1) + r(2)) * scale
    y2a = r(2) * scale
    y3 = r(3) * scale
    do s = -1, 1, 2
      if (s == 1 .and. k < 2) cycle
      side = real(s, wp)
      call sheet%line(x_sun, axis_y - side * (yh - y2a), x_sun, axis_y - side * (yh + y2a), stroke=planet_colour, &
        width=0.7_wp)
      call sheet%line(x_sun - rim, axis_y - side * (yh - y2a), x_sun + rim, axis_y - side * (yh - y2a), &
        stroke=planet_colour, width=0.7_wp)
      call sheet%line(x_sun - rim, axis_y - side * (yh + y2a), x_sun + rim, axis_y - side * (yh + y2a), &
        stroke=planet_colour, width=0.7_wp)
      ! the planet's axle (a revolute pair on the carrier) and the carrier's arm
      call sheet%line(x_sun, axis_y - side * yh, xc, axis_y - side * yh, stroke=carrier_colour, width=0.7_wp)
      call sheet%line(xc, axis_y - side * yh, xc, axis_y, stroke=carrier_colour, width=0.7_wp)
      ! the ring, fixed: from the frame's wall down to its pitch radius
      call sheet%line(x_sun, axis_y - side * y3, x_sun, axis_y - side * (y3 + 8.0_wp), stroke=ink, width=0.7_wp)
      call sheet%line(x_sun - rim, axis_y - side * y3, x_sun + rim, axis_y - side * y3, stroke=ink, width=0.7_wp)
      call sheet%line(x_sun - 10.0_wp, axis_y - side * (y3 + 8.0_wp), x_sun + 10.0_wp, axis_y - side * (y3 + 8.0_wp), &
        stroke=ink, width=0.5_wp)
      do i = 0, 9
        call sheet%line(x_sun - 9.0_wp + 2.0_wp * i, axis_y - side * (y3 + 8.0_wp), x_sun - 7.5_wp + 2.0_wp * i, &
          axis_y - side * (y3 + 9.5_wp), stroke=ink, width=0.2_wp)
      end do
    end do
    call sheet%line(xc, axis_y, x_out, axis_y, stroke=carrier_colour, width=0.7_wp)
    call bearing(sheet, x_out - 12.0_wp, axis_y)
    ! the links' numbers and tooth numbers
    call sheet%set_layer(layer_text)
    call sheet%place_label("1", "label", x_sun - 4.0_wp, axis_y - 0.5_wp * y1, pi, box, italic=.true.)
    call sheet%place_label("2", "label", x_sun - 4.0_wp, axis_y - yh, pi, box, italic=.true.)
    call sheet%place_label("3", "label", x_sun - 4.0_wp, axis_y - y3 - 4.0_wp, pi, box, italic=.true.)
    call sheet%place_label("H", "label", xc + 3.0_wp, axis_y - 0.5_wp * yh, 0.0_wp, box, italic=.true.)
    call sheet%place_label("omega1", "label", x_in + 4.0_wp, axis_y, -0.5_wp * pi, box, colour=sun_colour)
    call sheet%place_label("omega_H", "label", x_out - 4.0_wp, axis_y, -0.5_wp * pi, box, colour=carrier_colour)
    call sheet%text(box(1), box(4) - 1.0_wp, words("Kinematic scheme (ГОСТ 2.770)", &
      "Кинематическая схема", lang), &
      "heading")
  end subroutine draw_scheme

  !> A shaft's bearing in the frame at (x, y): two short walls across the shaft, hatched.
  pure subroutine bearing(sheet, x, y)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: x, y
    integer :: s, i
    do s = -1, 1, 2
      call sheet%line(x - 3.0_wp, y + s * 2.0_wp, x + 3.0_wp, y + s * 2.0_wp, stroke=ink, width=0.35_wp)
      do i = 0, 3
        call sheet%line(x - 2.5_wp + 2.0_wp * i, y + s * 2.0_wp, x - 1.0_wp + 2.0_wp * i, y + s * 3.5_wp, stroke=ink, &
          width=0.2_wp)
      end do
    end do
  end subroutine bearing

  !> The picture of linear speeds on the radii of the scheme: its radius axis at x0, the speeds
  !> to the right (v_A drawn 40 mm).
  pure subroutine draw_speeds(sheet, r, scale, axis_y, x0, box, lang)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: r(3), scale, axis_y, x0, box(4)
    integer, intent(in) :: lang
    real(wp) :: ya, yb, yc, la
    real(wp), parameter :: length = 40.0_wp
    ya = axis_y - r(1) * scale
    yb = axis_y - (r(1) + r(2)) * scale
    yc = axis_y - r(3) * scale
    la = length
    call sheet%set_layer(layer_vplan)
    ! the radius axis and the radii of A, B, C (dotted, from the scheme)
    call sheet%line(x0, axis_y + 3.0_wp, x0, yc - 4.0_wp, stroke=ink, width=0.3_wp)
    call sheet%line(x0, ya, x0 + la + 4.0_wp, ya, stroke=grey, width=0.15_wp, dash="1 1")
    call sheet%line(x0, yb, x0 + 0.5_wp * la + 4.0_wp, yb, stroke=grey, width=0.15_wp, dash="1 1")
    call sheet%line(x0, yc, x0 + 8.0_wp, yc, stroke=grey, width=0.15_wp, dash="1 1")
    ! the speeds of A and B
    call sheet%arrow(x0, ya, x0 + la, ya, ink, 0.35_wp, 2.5_wp)
    call sheet%arrow(x0, yb, x0 + 0.5_wp * la, yb, ink, 0.35_wp, 2.5_wp)
    ! the lines of the sun (O a), the planet (c a), the carrier (O b)
    call sheet%line(x0, axis_y, x0 + la, ya, stroke=sun_colour, width=0.5_wp)
    call sheet%line(x0, yc, x0 + la, ya, stroke=planet_colour, width=0.5_wp)
    call sheet%line(x0, axis_y, x0 + 0.5_wp * la, yb, stroke=carrier_colour, width=0.5_wp)
    call dot(sheet, [x0, axis_y], ink, 0.5_wp)
    call dot(sheet, [x0 + la, ya], ink, 0.5_wp)
    call dot(sheet, [x0 + 0.5_wp * la, yb], ink, 0.5_wp)
    call dot(sheet, [x0, yc], ink, 0.5_wp)
    call sheet%set_layer(layer_text)
    call sheet%place_label("O", "label", x0, axis_y, 0.75_wp * pi, box)
    call sheet%place_label("a", "label", x0 + la, ya, 0.0_wp, box)
    call sheet%place_label("b", "label", x0 + 0.5_wp * la, yb, 0.0_wp, box)
    call sheet%place_label("c", "label", x0, yc, pi, box)
    call sheet%place_label("A", "label", x0, ya, pi, box)
    call sheet%place_label("B", "label", x0, yb, pi, box)
    call sheet%place_label("1", "small", x0 + 0.5_wp * la, 0.5_wp * (axis_y + ya), 0.0_wp, box, colour=sun_colour, &
      italic=.true.)
    call sheet%place_label("H", "small", x0 + 0.25_wp * la, 0.5_wp * (axis_y + yb), pi, box, colour=carrier_colour, &
      italic=.true.)
    call sheet%place_label("2", "small", x0 + 0.5_wp * la, 0.5_wp * (ya + yc), 0.0_wp, box, colour=planet_colour, &
      italic=.true.)
    call sheet%text(x0 - 4.0_wp, box(4) - 1.0_wp, words("Linear speeds", &
      "Картина линейных скоростей", lang), "heading")
    ! the ratio as the picture gives it: the slopes of the sun's and the carrier's lines
    call sheet%text(x0 - 4.0_wp, box(4) - 7.0_wp, "u_1H = ω_1/ω_H = (v_A/r_1)/(v_B/r_B) = "// &
      fixed_number((la / (axis_y - ya)) / (0.5_wp * la / (axis_y - yb)), 4), "small")
  end subroutine draw_speeds

  !> The train seen along its axis about `c` (sheet mm): sun, planets with their tip circles,
  !> ring, carrier.
  pure subroutine draw_front(sheet, r, unit, k, scale, c, box, lang)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: r(3), unit, scale, c(2), box(4)
    integer, intent(in) :: k, lang
    real(wp) :: rh, a, p(2)
    integer :: i
    rh = (r(1) + r(2)) * scale
    call sheet%set_layer(layer_guides)
    call sheet%line(c(1) - (r(3) * scale + 8.0_wp), c(2), c(1) + r(3) * scale + 8.0_wp, c(2), stroke=ink, &
      width=0.18_wp, dash=dash_dot)
    call sheet%line(c(1), c(2) - (r(3) * scale + 8.0_wp), c(1), c(2) + r(3) * scale + 8.0_wp, stroke=ink, &
      width=0.18_wp, dash=dash_dot)
    call sheet%arc(c(1), c(2), rh, 0.0_wp, 360.0_wp, stroke=carrier_colour, width=0.2_wp)
    sheet%items(sheet%count)%dash = dash_dot
    call sheet%set_layer(layer_links)
    call sheet%arc(c(1), c(2), r(1) * scale, 0.0_wp, 360.0_wp, stroke=sun_colour, width=0.5_wp)
    call sheet%arc(c(1), c(2), r(3) * scale, 0.0_wp, 360.0_wp, stroke=ink, width=0.5_wp)
    call sheet%arc(c(1), c(2), r(3) * scale + 5.0_wp, 0.0_wp, 360.0_wp, stroke=ink, width=0.5_wp)
    do i = 0, k - 1
      a = 0.5_wp * pi + 2.0_wp * pi * real(i, wp) / real(k, wp)
      p = c + rh * [cos(a), -sin(a)]
      call sheet%arc(p(1), p(2), r(2) * scale, 0.0_wp, 360.0_wp, stroke=planet_colour, width=0.5_wp)
      ! the tip circle (ha* = 1): the neighbours' clearance
      call sheet%arc(p(1), p(2), (r(2) + unit) * scale, 0.0_wp, 360.0_wp, stroke=planet_colour, width=0.15_wp)
      sheet%items(sheet%count)%dash = "1.5 1"
      call sheet%line(c(1), c(2), p(1), p(2), stroke=carrier_colour, width=0.5_wp)
      call dot(sheet, p, carrier_colour, 0.6_wp)
    end do
    call dot(sheet, c, ink, 0.6_wp)
    call sheet%set_layer(layer_text)
    a = 0.5_wp * pi + pi / real(max(k, 1), wp)
    call sheet%place_label("z_1", "small", c(1) + 0.6_wp * r(1) * scale * cos(a + 0.3_wp), &
      c(2) - 0.6_wp * r(1) * scale * sin(a + 0.3_wp), a, box, colour=sun_colour)
    p = c + rh * [cos(0.5_wp * pi), -sin(0.5_wp * pi)]
    call sheet%place_label("z_2", "small", p(1), p(2), 0.0_wp, box, colour=planet_colour)
    call sheet%place_label("z_3", "small", c(1) + (r(3) * scale + 2.5_wp) * cos(a), c(2) - (r(3) * scale + 2.5_wp) * &
      sin(a), a, box)
    call sheet%text(box(1), box(2) + 4.0_wp, words("Along the axis: k = ", "Вид вдоль оси: k = ", lang)//int_str(k), &
      "heading")
  end subroutine draw_front

  !> The tooth numbers, the ratio and the conditions in a table, in `box`.
  pure subroutine draw_conditions(sheet, spec, t, k, box, lang)
    type(sheet_t), intent(inout) :: sheet
    type(planetary_spec_t), intent(in) :: spec
    type(planetary_train_t), intent(in) :: t
    integer, intent(in) :: k, lang
    real(wp), intent(in) :: box(4)
    character(len=80) :: cells(7, 3)
    character(len=:), allocatable :: yes
    yes = words("met", "выполнено", lang)
    cells(1, :) = [character(len=80) :: words("condition", "условие", lang), words("with the numbers", &
      "с числами", lang), ""]
    cells(2, :) = [character(len=80) :: words("coaxiality", "соосность", lang), "z_3 = z_1 + 2 z_2: "// &
      int_str(t%z3)//" = "//int_str(t%z1)//" + "//int_str(2 * t%z2), verdict(t%met(1))]
    cells(3, :) = [character(len=80) :: words("assembly", "сборка", lang), "(z_1 + z_3)/k = "//int_str(t%z1 + t%z3)// &
      "/"//int_str(k)//" = "//short_number(t%assembly_number), verdict(t%met(2))]
    if (k == 1) then
      cells(4, :) = [character(len=80) :: words("neighbours", "соседство", lang), "k = 1", verdict(t%met(3))]
    else
      ! sin(pi/k) by its value on a Russian sheet (no Latin words there)
      cells(4, :) = [character(len=80) :: words("neighbours", "соседство", lang), "(z_1 + z_2)"// &
        words(" sin(π/k)", "·"//fixed_number(sin(pi / real(k, wp)), 4), lang)//" = "// &
        fixed_number(t%neighbour_margin + real(t%z2 + 2, wp), 2)//" > z_2 + 2 = "//int_str(t%z2 + 2), &
        verdict(t%met(3))]
    end if
    cells(5, :) = [character(len=80) :: words("least teeth", "наименьшие числа зубьев", lang), &
      "z_1, z_2 ≥ "// &
      int_str(spec%z_min)//", z_3 ≥ "//int_str(spec%z_ring_min), verdict(t%met(4) .and. t%met(5))]
    cells(6, :) = [character(len=80) :: words("ratio", "передаточное отношение", lang), &
      "u_1H = 1 + z_3/z_1 = "// &
      fixed_number(t%u_actual, 4)//"; |u_1H - u| = "//fixed_number(abs(t%u_actual - spec%u), 4)//" ≤ "// &
      fixed_number(spec%u_tolerance * spec%u, 4), verdict(t%met(6))]
    cells(7, :) = [character(len=80) :: words("smallest ring", "наименьшее колесо 3", lang), "z_3 = "// &
      int_str(t%z3)//" ≥ "//int_str(spec%z_ring_min)//", u = "//short_number(spec%u)//" ± "// &
      short_number(100.0_wp * spec%u_tolerance)//" %", ""]
    call sheet%set_layer(layer_frame)
    call put_table(sheet, box(1), box(2) + 6.0_wp, [46.0_wp, 118.0_wp, 24.0_wp], 5.5_wp, cells)
    call sheet%set_layer(layer_text)
    call sheet%text(box(1), box(2) + 3.5_wp, words("Conditions of the tooth numbers", &
      "Условия подбора чисел зубьев", lang), "heading")
  contains
    pure function verdict(ok) result(text)
      logical, intent(in) :: ok
      character(len=:), allocatable :: text
      if (ok) then
        text = yes
      else
        text = words("broken", "нарушено", lang)
      end if
    end function verdict
  end subroutine draw_conditions

end module kinetostat_planetary_sheet
