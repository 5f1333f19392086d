!> The sheet of a spur gear pair with profile shift (`--format svg`/`dxf` of `&gear_geometry`),
!> as the course's sheet of the gear synthesis: on A3 landscape (A2 or A1 when A3 would draw the
!> module smaller than 4 mm), with the ГОСТ frame and title block (Масштаб = the drawing's
!> scale):
!> - the meshing drawing (картина зацепления) at a ГОСТ 2.302 scale, the centre line upright,
!>   gear 1 below: seven teeth of each gear about the pitch point P (all of them when a gear has
!>   ten or fewer), cut by the generating rack (kinetostat_gear_teeth: involute flanks, root fillets,
!>   an undercut as cut); the pitch, base, working pitch, tip and root circles (r, r_b, r_w,
!>   r_a, r_f) over the teeth drawn; the centres O1, O2 and the centre distance a_w as a
!>   dimension; the common tangent at P and the line of action N1N2 with the working pressure
!>   angle α_w, the active length B1B2 (thick), the base pitch p_b laid off from B1 and from B2
!>   (the zones of one and two pairs in mesh); the profiles through B1 and B2 and the arcs of
!>   contact a1b1, a2b2 on the working pitch circles; the senses of rotation ω1, ω2 (gear 1
!>   driving);
!> - the blocking contour of (z1, z2) in the plane (x1, x2): the lines of undercut, pointed
!>   teeth, ε_α = 1 and 1.2 and interference, each hatched on its forbidden side, the curve of
!>   equal specific sliding (λ1 = λ2, dashed), the chosen point;
!> - the table of the pair's dimensions and the conditions of the contour.
!> The meshing drawing is the group "meshing": sheet point = data-origin + data-scale *
!> (q1, -q2), q = the pair's point (mm; O1 at the origin, O2 on +x) turned by data-rotation
!> (deg); every flank is a path with data-flank = its gear and lies on an involute of that
!> gear's base circle (tools/synthesis_check.py involutes reads it back).
module kinetostat_gear_sheet
  use kinetostat_kinds, only: wp, pi, rad_to_deg
  use kinetostat_text, only: int_str
  use kinetostat_format, only: short_number, fixed_number, full_number
  use kinetostat_step_table, only: step_table_t
  use kinetostat_labels, only: unit_word => unit_symbol
  use kinetostat_vec2, only: rotate
  use kinetostat_svg, only: coord
  use kinetostat_scales, only: drawing_scale_t, standard_drawing_scale
  use kinetostat_sheet, only: sheet_t, paper_t, iso_paper, layer_links, layer_guides, layer_forces, layer_text, &
    layer_scales, layer_charts, layer_frame, anchor_start, anchor_middle
  use kinetostat_title_block, only: block_width, block_height
  use kinetostat_design_sheet, only: words, open_design_sheet, sheet_of, chart_t, put_chart, put_dimension, put_angle, &
    put_table, put_side_ticks, dot
  use kinetostat_gear_geometry, only: gear_pair_t, pair_geometry_t, contour_curve_t, pair_geometry, involute, &
    involute_flank, line_of_action, blocking_contour, contour_names, contour_lo, contour_hi, equal_sliding_x2
  use kinetostat_gear_teeth, only: tooth_outline_t, tooth_outline
  implicit none
  private
  public :: draw_gear_sheet

  !> Teeth drawn on each side of the tooth at the pitch point.
  integer, parameter :: teeth_each_side = 3
  !> The least module drawn, mm (else a larger paper).
  real(wp), parameter :: least_module = 4.0_wp
  !> Room kept around the meshing drawing for its labels, mm.
  real(wp), parameter :: label_room = 11.0_wp
  !> Colours: the line of action, the arcs of contact, the base circles, the working circles.
  character(*), parameter :: action_colour = "#d62728", arc_colour = "#ff7f0e", base_colour = "#2ca02c", &
    working_colour = "#1f77b4", ink = "#000000", grey = "#7f7f7f"
  !> Dash-dot of axes and pitch circles (ГОСТ 2.303), mm.
  character(*), parameter :: dash_dot = "6 1.5 1 1.5"

  !> Where the meshing drawing sits: the pair's frame on the sheet.
  type :: mesh_view_t
    real(wp) :: origin(2) = 0.0_wp
    !> Sheet mm per mm of the pair.
    real(wp) :: scale = 1.0_wp
    type(drawing_scale_t) :: drawing_scale
  end type mesh_view_t

contains

  !> The sheet of the pair `p` with geometry `g` (the run's shifts), its words in `lang`.
  pure subroutine draw_gear_sheet(p, g, table, lang, sheet)
    !> The pair.
    type(gear_pair_t), intent(in) :: p
    !> Its geometry.
    type(pair_geometry_t), intent(in) :: g
    !> The run's results (the deck, the student's fields).
    type(step_table_t), intent(in) :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> The sheet made.
    type(sheet_t), intent(out) :: sheet
    type(tooth_outline_t) :: tooth(2)
    type(paper_t) :: paper
    type(mesh_view_t) :: view
    real(wp) :: phase(2), centre(2, 2), span(2, 2), box(4), region(4), column(4), inner(4), fit, side
    integer :: first(2), last(2), i, candidate
    character(len=2), parameter :: papers(3) = ["A3", "A2", "A1"]

    tooth(1) = tooth_outline(p, g, 1)
    tooth(2) = tooth_outline(p, g, 2)
    ! the tooth whose flank passes through P: gear 1's clockwise flank, gear 2's too (about O2)
    phase(1) = tooth(1)%base_half - involute(g%alpha_w)
    phase(2) = pi + tooth(2)%base_half - involute(g%alpha_w)
    centre(:, 1) = [0.0_wp, 0.0_wp]
    centre(:, 2) = [g%a_w, 0.0_wp]
    do i = 1, 2
      associate (z => merge(p%z1, p%z2, i == 1))
        ! a gear of few teeth whole (no gap of one to three teeth)
        if (z <= 2 * teeth_each_side + 4) then
          first(i) = 0
          last(i) = z - 1
          span(:, i) = [0.0_wp, 2.0_wp * pi]
        else
          first(i) = -teeth_each_side
          last(i) = teeth_each_side
          span(:, i) = phase(i) + [real(first(i), wp) - 0.5_wp, real(last(i), wp) + 0.5_wp] * tooth(i)%pitch_angle
        end if
      end associate
    end do
    box = extent()

    ! the paper: A3 landscape, larger when A3 draws the module below least_module
    do candidate = 1, size(papers)
      paper = iso_paper(papers(candidate), .true.)
      call layout(paper, region, column)
      fit = min((region(3) - region(1) - 2.0_wp * label_room) / (box(3) - box(1)), &
        (region(4) - region(2) - 2.0_wp * label_room) / (box(4) - box(2)))
      view%drawing_scale = standard_drawing_scale(fit)
      if (view%drawing_scale%ratio * p%m >= least_module) exit
    end do
    view%scale = view%drawing_scale%ratio
    view%origin = [0.5_wp * (region(1) + region(3)) - view%scale * 0.5_wp * (box(1) + box(3)), &
      0.5_wp * (region(2) + region(4)) + view%scale * 0.5_wp * (box(2) + box(4))]
    view%origin = anint(view%origin * 100.0_wp) / 100.0_wp
    inner = paper%inside()

    call open_design_sheet(sheet, paper, lang, table, words("Gear pair: meshing, blocking contour", &
      "Зубчатая передача: зацепление, блокирующий контур", lang), &
      view%drawing_scale%text, &
      words("Involute spur gear pair with profile shift: the meshing and the blocking contour", &
      "Эвольвентная зубчатая передача со смещением: "// &
      "картина зацепления и блокирующий контур", lang), &
      "z1 = "//int_str(p%z1)//", z2 = "//int_str(p%z2)//", m = "//short_number(p%m)//" "//unit_word("mm", lang)// &
      ", x1 = "//fixed_number(g%x(1), 4)//", x2 = "//fixed_number(g%x(2), 4)//"; "// &
      words("scale", "масштаб", lang)//" "//view%drawing_scale%text, &
      sheet_of(table)//"the meshing drawing of the gear pair at "//view%drawing_scale%text// &
      ", the blocking contour and the dimensions. Group meshing: sheet point = data-origin + data-scale * "// &
      "(q1, -q2), q = the pair's point (mm; O1 at the origin, O2 on +x) turned by data-rotation (deg); paths "// &
      "with data-flank = N are flanks of gear N, on involutes of its base circle.")
    call draw_meshing(sheet, p, g, tooth, phase, centre, first, last, span, view, region, lang)
    ! the right column: the contour (its plot square) with the legend beside it, the tables under
    side = min(0.56_wp * (column(4) - column(2)), column(3) - column(1) - 64.0_wp)
    call draw_contour_panel(sheet, p, g, [column(1), column(2), column(1) + side + 3.0_wp, column(2) + side], lang)
    call draw_legend(sheet, g, [column(1) + side + 6.0_wp, column(2), column(3), column(2) + side], lang)
    call draw_dimension_table(sheet, p, g, [column(1), column(2) + side + 4.0_wp, column(3), column(4)], lang)
  contains
    !> The drawing's extent in the turned frame q = (-y, x): q1 from, q2 from, q1 to, q2 to.
    pure function extent() result(b)
      real(wp) :: b(4), a, q(2), pts(2, 5)
      integer :: k, j
      b = [huge(1.0_wp), huge(1.0_wp), -huge(1.0_wp), -huge(1.0_wp)]
      do j = 1, 2
        call grow(b, turned(centre(:, j)))
        do k = 0, 90
          a = span(1, j) + (span(2, j) - span(1, j)) * k / 90.0_wp
          call grow(b, turned(centre(:, j) + tooth(j)%ra * [cos(a), sin(a)]))
        end do
      end do
      pts = line_of_action(g)
      do k = 1, 2
        q = turned(pts(:, k))
        call grow(b, q)
      end do
    end function extent
    pure subroutine grow(b, q)
      real(wp), intent(inout) :: b(4)
      real(wp), intent(in) :: q(2)
      b = [min(b(1), q(1)), min(b(2), q(2)), max(b(3), q(1)), max(b(4), q(2))]
    end subroutine grow
    !> The meshing's region and the right column (contour, table) on `paper`: the column as
    !> wide as the title block, above it.
    pure subroutine layout(paper, region, column)
      type(paper_t), intent(in) :: paper
      real(wp), intent(out) :: region(4), column(4)
      real(wp) :: b(4)
      b = paper%inside()
      column = [b(3) - block_width, 27.0_wp, b(3) - 3.0_wp, b(4) - block_height - 4.0_wp]
      region = [b(1) + 3.0_wp, 26.0_wp, column(1) - 6.0_wp, b(4) - 3.0_wp]
    end subroutine layout
  end subroutine draw_gear_sheet

  !> A point of the pair's frame (mm) turned into the drawing's frame: q = (-y, x).
  pure function turned(v) result(q)
    real(wp), intent(in) :: v(2)
    real(wp) :: q(2)
    q = [-v(2), v(1)]
  end function turned

  !> A point of the pair's frame (mm) on the sheet, mm.
  pure function on_sheet(view, v) result(s)
    type(mesh_view_t), intent(in) :: view
    real(wp), intent(in) :: v(2)
    real(wp) :: s(2)
    s = view%origin + view%scale * [-v(2), -v(1)]
  end function on_sheet

  !> The meshing drawing.
  pure subroutine draw_meshing(sheet, p, g, tooth, phase, centre, first, last, span, view, region, lang)
    type(sheet_t), intent(inout) :: sheet
    type(gear_pair_t), intent(in) :: p
    type(pair_geometry_t), intent(in) :: g
    type(tooth_outline_t), intent(in) :: tooth(2)
    real(wp), intent(in) :: phase(2), centre(2, 2), span(2, 2)
    integer, intent(in) :: first(2), last(2)
    type(mesh_view_t), intent(in) :: view
    real(wp), intent(in) :: region(4)
    integer, intent(in) :: lang
    real(wp) :: pts(2, 5), u(2), rw(2), radii(5), rho(2, 2), theta(2, 2), q(2), a(2), b(2), pb, ticks(2, 2), x_dim
    real(wp) :: label_bounds(4), far
    integer :: i, k, c
    character(len=8) :: circle_names(5)
    character(len=1) :: n

    pts = line_of_action(g)
    u = (pts(:, 2) - pts(:, 1)) / g%g
    rw = 0.5_wp * g%dw
    pb = g%base_pitch
    label_bounds = region

    call sheet%group("meshing")
    call sheet%attach("data-origin", coord(view%origin(1))//" "//coord(view%origin(2)))
    call sheet%attach("data-scale", full_number(view%scale))
    call sheet%attach("data-rotation", "90")
    call sheet%attach("data-drawing-scale", view%drawing_scale%text)
    call sheet%attach("data-a-w", full_number(g%a_w))

    ! the circles over the teeth drawn (pitch and working circles dash-dot)
    call sheet%set_layer(layer_guides)
    do i = 1, 2
      radii = [0.5_wp * g%df(i), 0.5_wp * g%db(i), 0.5_wp * g%d(i), rw(i), 0.5_wp * g%da(i)]
      do c = 1, 5
        select case (c)
        case (2)
          call circle_arc(sheet, i, radii(c), base_colour, 0.25_wp, "")
        case (3)
          call circle_arc(sheet, i, radii(c), ink, 0.18_wp, dash_dot)
        case (4)
          call circle_arc(sheet, i, radii(c), working_colour, 0.25_wp, dash_dot)
        case default
          call circle_arc(sheet, i, radii(c), ink, 0.18_wp, "")
        end select
      end do
    end do
    ! the centre line (beyond both centres) and the common tangent at P, dash-dot
    far = 6.0_wp
    if (span(2, 1) - span(1, 1) >= 2.0_wp * pi) far = tooth(1)%ra * view%scale + 4.0_wp
    a = on_sheet(view, centre(:, 1))
    b = on_sheet(view, centre(:, 2))
    call sheet%line(a(1), a(2) + far, b(1), b(2) - 6.0_wp, stroke=ink, width=0.18_wp, dash=dash_dot)
    do i = 1, 2
      a = on_sheet(view, centre(:, i))
      call sheet%line(a(1) - 4.0_wp, a(2), a(1) + 4.0_wp, a(2), stroke=ink, width=0.18_wp)
    end do
    a = on_sheet(view, pts(:, 3))
    call sheet%line(a(1) - 0.35_wp * g%g * view%scale - 6.0_wp, a(2), a(1) + 0.35_wp * g%g * view%scale + 6.0_wp, a(2), &
      stroke=ink, width=0.18_wp, dash=dash_dot)

    ! the teeth
    call sheet%set_layer(layer_links)
    do i = 1, 2
      do k = first(i), last(i)
        call draw_tooth(sheet, i, phase(i) + real(k, wp) * tooth(i)%pitch_angle)
      end do
    end do

    ! the profiles at the start (through B1) and the end (through B2) of contact, the arcs of
    ! contact on the working circles; rho(point, gear): the point's distance from N1 (gear 1)
    ! or N2 (gear 2)
    call sheet%set_layer(layer_forces)
    rho(1, :) = [max(0.0_wp, g%rho_low(1)), g%g - g%rho_low(1)]
    rho(2, :) = [g%rho_tip(1), max(0.0_wp, g%g - g%rho_tip(1))]
    do i = 1, 2
      do k = 1, 2
        if (i == 1) then
          theta(k, i) = g%alpha_w - rho(k, i) / tooth(i)%rb
        else
          theta(k, i) = pi + g%alpha_w - rho(k, i) / tooth(i)%rb
        end if
        call polyline_of(sheet, involute_flank(tooth(i)%rb, tooth(i)%rb, tooth(i)%ra, 24), centre(:, i), theta(k, i), grey, &
          0.2_wp, "1.5 1")
      end do
      q = sheet_centre(i)
      call sheet%arc(q(1), q(2), rw(i) * view%scale, (theta(2, i) + involute(g%alpha_w)) * rad_to_deg + 90.0_wp, &
        (theta(1, i) - theta(2, i)) * rad_to_deg, stroke=arc_colour, width=0.8_wp)
    end do
    ! the line of action N1N2, its active part B1B2, the base pitch from B1 and from B2
    a = on_sheet(view, pts(:, 1))
    b = on_sheet(view, pts(:, 2))
    call sheet%line(a(1), a(2), b(1), b(2), stroke=action_colour, width=0.3_wp)
    a = on_sheet(view, pts(:, 4))
    b = on_sheet(view, pts(:, 5))
    call sheet%line(a(1), a(2), b(1), b(2), stroke=action_colour, width=0.8_wp)
    ticks(:, 1) = pts(:, 4) + pb * u
    ticks(:, 2) = pts(:, 5) - pb * u
    ! the ticks across the line: its direction on the sheet is (-u_y, -u_x)
    a = [u(1), -u(2)]
    do k = 1, 2
      q = on_sheet(view, ticks(:, k))
      call sheet%line(q(1) - 1.8_wp * a(1), q(2) - 1.8_wp * a(2), q(1) + 1.8_wp * a(1), q(2) + 1.8_wp * a(2), &
        stroke=action_colour, width=0.3_wp)
    end do
    ! the working pressure angle at P: from the common tangent to the line of action
    a = on_sheet(view, pts(:, 3))
    call put_angle(sheet, a(1), a(2), 9.0_wp, 0.0_wp, g%alpha_w * rad_to_deg, ink)
    call put_angle(sheet, a(1), a(2), 9.0_wp, 180.0_wp, g%alpha_w * rad_to_deg, ink)
    ! the senses of rotation: gear 1 clockwise (driving: contact from B1 to B2), gear 2 against it
    do i = 1, 2
      call rotation_arrow(sheet, i)
    end do

    ! the centre distance
    call sheet%set_layer(layer_scales)
    a = on_sheet(view, centre(:, 1))
    b = on_sheet(view, centre(:, 2))
    x_dim = view%origin(1) + view%scale * max(tooth(1)%ra, tooth(2)%ra * sin(min(0.5_wp * pi, &
      0.5_wp * (span(2, 2) - span(1, 2))))) + 7.0_wp
    x_dim = min(x_dim, region(3) - 8.0_wp)
    call put_dimension(sheet, a, b, -(x_dim - a(1)), "a_w = "//fixed_number(g%a_w, 3))

    ! the points and their names
    call sheet%set_layer(layer_text)
    call named_point(sheet, on_sheet(view, centre(:, 1)), "O1", pi * 0.75_wp)
    call named_point(sheet, on_sheet(view, centre(:, 2)), "O2", pi * 0.75_wp)
    call named_point(sheet, on_sheet(view, pts(:, 3)), "P", 0.9_wp * pi)
    call named_point(sheet, on_sheet(view, pts(:, 1)), "N1", pi)
    call named_point(sheet, on_sheet(view, pts(:, 2)), "N2", 0.0_wp)
    call named_point(sheet, on_sheet(view, pts(:, 4)), "B1", 0.5_wp * pi)
    call named_point(sheet, on_sheet(view, pts(:, 5)), "B2", -0.5_wp * pi)
    do i = 1, 2
      n = achar(iachar("0") + i)
      call named_point(sheet, sheet_at(centre(:, i), rw(i), theta(1, i) + involute(g%alpha_w)), "a"//n, &
        merge(0.5_wp * pi, -0.5_wp * pi, i == 1))
      call named_point(sheet, sheet_at(centre(:, i), rw(i), theta(2, i) + involute(g%alpha_w)), "b"//n, &
        merge(0.5_wp * pi, -0.5_wp * pi, i == 1))
    end do
    a = on_sheet(view, pts(:, 3))
    call sheet%place_label("alpha_w", "label", a(1) + 12.0_wp * cos(0.5_wp * g%alpha_w), a(2) - 12.0_wp * &
      sin(0.5_wp * g%alpha_w), 0.0_wp, label_bounds)
    a = on_sheet(view, pts(:, 4) + 0.5_wp * pb * u)
    call sheet%place_label("p_b", "label", a(1), a(2), -0.5_wp * pi, label_bounds, colour=action_colour)
    a = on_sheet(view, pts(:, 5) - 0.5_wp * pb * u)
    call sheet%place_label("p_b", "label", a(1), a(2), 0.5_wp * pi, label_bounds, colour=action_colour)
    ! the circles' names, each at the end of its arc (or low on a whole circle)
    do i = 1, 2
      n = achar(iachar("0") + i)
      circle_names = [character(len=8) :: "r_f"//n, "r_b"//n, "r_"//n, "r_w"//n, "r_a"//n]
      radii = [0.5_wp * g%df(i), 0.5_wp * g%db(i), 0.5_wp * g%d(i), rw(i), 0.5_wp * g%da(i)]
      do c = 1, 5
        call circle_label(sheet, i, c, radii(c), trim(circle_names(c)))
      end do
    end do
    call sheet%end_group()
  contains
    !> The sheet point of gear i's centre.
    pure function sheet_centre(i) result(s)
      integer, intent(in) :: i
      real(wp) :: s(2)
      s = on_sheet(view, centre(:, i))
    end function sheet_centre
    !> The sheet point at radius r and angle a (pair's frame) about the centre c.
    pure function sheet_at(c, r, a) result(s)
      real(wp), intent(in) :: c(2), r, a
      real(wp) :: s(2)
      s = on_sheet(view, c + r * [cos(a), sin(a)])
    end function sheet_at
    !> A circle of gear i over its span, as an arc (a whole circle when the span is).
    pure subroutine circle_arc(sheet, i, r, colour, width, dash)
      type(sheet_t), intent(inout) :: sheet
      integer, intent(in) :: i
      real(wp), intent(in) :: r, width
      character(*), intent(in) :: colour, dash
      real(wp) :: s(2)
      s = sheet_centre(i)
      if (span(2, i) - span(1, i) >= 2.0_wp * pi) then
        ! a whole circle as a closed arc: a line labels keep off, not a disc
        call sheet%arc(s(1), s(2), r * view%scale, 0.0_wp, 360.0_wp, stroke=colour, width=width)
        if (len(dash) > 0) sheet%items(sheet%count)%dash = dash
      else
        call sheet%arc(s(1), s(2), r * view%scale, span(1, i) * rad_to_deg + 90.0_wp, (span(2, i) - span(1, i)) * &
          rad_to_deg, stroke=colour, width=width)
        if (len(dash) > 0) sheet%items(sheet%count)%dash = dash
      end if
    end subroutine circle_arc
    !> Points (2, n) of the frame of a tooth or a profile (mm), turned by `angle` about `c`, as
    !> a polyline.
    pure subroutine polyline_of(sheet, xy, c, angle, colour, width, dash)
      type(sheet_t), intent(inout) :: sheet
      real(wp), intent(in) :: xy(:, :), c(2), angle
      character(*), intent(in) :: colour, dash
      real(wp), intent(in) :: width
      real(wp) :: sx(size(xy, 2)), sy(size(xy, 2)), s(2)
      integer :: j
      do j = 1, size(xy, 2)
        s = on_sheet(view, c + rotate(xy(:, j), angle))
        sx(j) = s(1)
        sy(j) = s(2)
      end do
      if (len(dash) > 0) then
        call sheet%polyline(sx, sy, stroke=colour, width=width, dash=dash)
      else
        call sheet%polyline(sx, sy, stroke=colour, width=width)
      end if
    end subroutine polyline_of
    !> Tooth of gear i whose axis is at `axis` (rad, pair's frame about its centre): both sides'
    !> root arcs, fillets and flanks, and the tip land.
    pure subroutine draw_tooth(sheet, i, axis)
      type(sheet_t), intent(inout) :: sheet
      integer, intent(in) :: i
      real(wp), intent(in) :: axis
      real(wp) :: s(2), mirror(2, 2)
      integer :: side
      s = sheet_centre(i)
      associate (t => tooth(i))
        do side = 1, -1, -2
          mirror = reshape([1.0_wp, 0.0_wp, 0.0_wp, real(side, wp)], [2, 2])
          ! the root arc from the space's middle to the fillet
          call sheet%arc(s(1), s(2), t%rf * view%scale, (axis + side * 0.5_wp * t%pitch_angle) * rad_to_deg + 90.0_wp, &
            side * (t%root_end - 0.5_wp * t%pitch_angle) * rad_to_deg, stroke=ink, width=0.5_wp)
          call polyline_of(sheet, matmul(mirror, t%fillet), centre(:, i), axis, ink, 0.5_wp, "")
          call polyline_of(sheet, matmul(mirror, t%flank), centre(:, i), axis, ink, 0.5_wp, "")
          call sheet%attach("data-flank", int_str(i))
        end do
        if (t%tip_half > 0.0_wp) call sheet%arc(s(1), s(2), t%ra * view%scale, (axis - t%tip_half) * rad_to_deg + &
          90.0_wp, 2.0_wp * t%tip_half * rad_to_deg, stroke=ink, width=0.5_wp)
      end associate
    end subroutine draw_tooth
    !> The sense of rotation of gear i: an arrowed arc inside the root circle, left of the centre.
    pure subroutine rotation_arrow(sheet, i)
      type(sheet_t), intent(inout) :: sheet
      integer, intent(in) :: i
      real(wp) :: s(2), r, a0, a1, tip(2), tail(2)
      character(len=1) :: n
      n = achar(iachar("0") + i)
      s = sheet_centre(i)
      r = min(0.45_wp * tooth(i)%rf * view%scale, 12.0_wp)
      ! gear 1 turns clockwise (sheet angles falling), gear 2 counter-clockwise
      if (i == 1) then
        a0 = 235.0_wp
        a1 = 175.0_wp
      else
        a0 = 125.0_wp
        a1 = 185.0_wp
      end if
      call sheet%arc(s(1), s(2), r, min(a0, a1), abs(a1 - a0), stroke=ink, width=0.25_wp)
      tip = s + r * [cos(a1 * pi / 180.0_wp), -sin(a1 * pi / 180.0_wp)]
      tail = s + r * [cos((a1 + sign(6.0_wp, a0 - a1)) * pi / 180.0_wp), -sin((a1 + sign(6.0_wp, a0 - a1)) * pi / 180.0_wp)]
      call sheet%arrow(tail(1), tail(2), tip(1), tip(2), ink, 0.25_wp, 2.2_wp)
      call sheet%place_label("omega"//n, "label", s(1) + r * cos(a0 * pi / 180.0_wp) - 1.0_wp, &
        s(2) - r * sin(a0 * pi / 180.0_wp), pi, label_bounds)
    end subroutine rotation_arrow
    !> A point marked and named.
    pure subroutine named_point(sheet, s, name, base)
      type(sheet_t), intent(inout) :: sheet
      real(wp), intent(in) :: s(2), base
      character(*), intent(in) :: name
      call dot(sheet, s, ink, 0.55_wp)
      call sheet%attach("data-point", name)
      call sheet%place_label(name, "label", s(1), s(2), base, label_bounds)
    end subroutine named_point
    !> The name of circle c of gear i, at radius r: near an end of the arc (alternately), or
    !> low on a whole circle, placed towards the gear's centre.
    pure subroutine circle_label(sheet, i, c, r, name)
      type(sheet_t), intent(inout) :: sheet
      integer, intent(in) :: i, c
      real(wp), intent(in) :: r
      character(*), intent(in) :: name
      real(wp) :: a, s(2), o(2), toward
      if (span(2, i) - span(1, i) >= 2.0_wp * pi) then
        a = pi + (real(c, wp) - 3.0_wp) * 0.32_wp
      else if (mod(c, 2) == 1) then
        a = span(1, i) + (0.15_wp + 0.1_wp * c) * tooth(i)%pitch_angle
      else
        a = span(2, i) - (0.15_wp + 0.1_wp * c) * tooth(i)%pitch_angle
      end if
      s = sheet_at(centre(:, i), r, a)
      o = sheet_centre(i) - s
      toward = atan2(-o(2), o(1))
      call sheet%place_label(name, "label", s(1), s(2), toward, label_bounds, size=2.4_wp)
    end subroutine circle_label
  end subroutine draw_meshing

  !> The blocking contour of the pair's (z1, z2) in the panel `box` (x0, y0, x1, y1), with the
  !> chosen point (x1, x2) of `g`.
  pure subroutine draw_contour_panel(sheet, p, g, box, lang)
    type(sheet_t), intent(inout) :: sheet
    type(gear_pair_t), intent(in) :: p
    type(pair_geometry_t), intent(in) :: g
    real(wp), intent(in) :: box(4)
    integer, intent(in) :: lang
    type(contour_curve_t), allocatable :: curves(:)
    type(chart_t) :: chart
    real(wp), allocatable :: sx(:), sy(:), ex(:), ey(:)
    integer, allocatable :: side(:)
    real(wp) :: x2, mid(2), chosen(2), bounds(4)
    integer :: c, k, piece, k0, k1, n
    logical :: found
    character(len=7), parameter :: colours(8) = [character(len=7) :: "#d62728", "#d62728", "#ff7f0e", "#ff7f0e", &
      "#1f77b4", "#1f77b4", "#9467bd", "#9467bd"]

    allocate (curves(size(contour_names)))
    call blocking_contour(p, curves)
    call sheet%set_layer(layer_charts)
    call put_chart(sheet, chart, box(1), box(2), box(3) - box(1), box(4) - box(2), words("Blocking contour of z1 = "// &
      int_str(p%z1)//", z2 = "//int_str(p%z2), "Блокирующий контур для z1 = "//int_str(p%z1)//", z2 = "// &
      int_str(p%z2), lang), contour_lo, contour_hi, 0.5_wp, [contour_lo, contour_hi], "x_1", "x_2")
    bounds = [chart%left + 1.0_wp, chart%top + 1.0_wp, chart%left + chart%width - 1.0_wp, chart%top + chart%height - &
      1.0_wp]
    ! the curve of equal largest specific sliding (dashed)
    allocate (ex(0), ey(0))
    do k = 0, 60
      call equal_sliding_x2(p, contour_lo + (contour_hi - contour_lo) * k / 60.0_wp, x2, found)
      if (found .and. x2 >= contour_lo .and. x2 <= contour_hi) then
        ex = [ex, chart%sx(contour_lo + (contour_hi - contour_lo) * k / 60.0_wp)]
        ey = [ey, chart%sy(x2)]
      else if (size(ex) > 1) then
        exit
      else
        deallocate (ex, ey)
        allocate (ex(0), ey(0))
      end if
    end do
    if (size(ex) > 1) call sheet%polyline(ex, ey, stroke="#555555", width=0.3_wp, dash="3 1.5")
    ! the boundaries, hatched on their forbidden side
    do c = 1, size(curves)
      n = size(curves(c)%x1)
      if (n < 2) cycle
      do piece = 1, size(curves(c)%piece_start)
        k0 = curves(c)%piece_start(piece)
        k1 = n
        if (piece < size(curves(c)%piece_start)) k1 = curves(c)%piece_start(piece + 1) - 1
        if (k1 - k0 < 1) cycle
        sx = [(chart%sx(curves(c)%x1(k)), k = k0, k1)]
        sy = [(chart%sy(curves(c)%x2(k)), k = k0, k1)]
        call sheet%polyline(sx, sy, stroke=colours(c), width=0.45_wp)
        allocate (side(k1 - k0))
        do k = k0, k1 - 1
          side(k - k0 + 1) = forbidden_side(c, [curves(c)%x1(k), curves(c)%x2(k)], [curves(c)%x1(k + 1), &
            curves(c)%x2(k + 1)])
        end do
        call put_side_ticks(sheet, sx, sy, side, 2.0_wp, 1.3_wp, colours(c))
        deallocate (side)
      end do
    end do
    ! the chosen point and the curves' names
    chosen = [chart%sx(g%x(1)), chart%sy(g%x(2))]
    if (all(g%x >= contour_lo .and. g%x <= contour_hi)) call dot(sheet, chosen, ink, 0.9_wp)
    if (size(ex) > 1) call sheet%place_label("λ_1 = λ_2", "small", ex(size(ex) / 3 + 1), ey(size(ey) / 3 + 1), &
      0.0_wp, bounds, colour="#555555")
    do c = 1, size(curves)
      n = size(curves(c)%x1)
      if (n < 2) cycle
      k = max(1, nint(0.62_wp * n))
      mid = [chart%sx(curves(c)%x1(k)), chart%sy(curves(c)%x2(k))]
      call sheet%place_label(curve_name(c), "small", mid(1), mid(2), 0.25_wp * pi, bounds, colour=colours(c))
    end do
  contains
    !> The name of curve c on the chart.
    pure function curve_name(c) result(text)
      integer, intent(in) :: c
      character(len=:), allocatable :: text
      character(len=1) :: n
      n = achar(iachar("1") + mod(c - 1, 2))
      select case (c)
      case (1, 2)
        text = words("undercut "//n, "подрезание "//n, lang)
      case (3, 4)
        text = "s_a"//n//" = "//short_number(p%sa_min_star)//"m"
      case (5)
        text = "eps_alpha = 1"
      case (6)
        text = "eps_alpha = 1.2"
      case default
        text = words("interference "//n, "интерференция "//n, lang)
      end select
    end function curve_name
    !> The forbidden side of the segment a -> b of curve c as the sheet shows it (+1 left,
    !> -1 right): where the condition fails, a little off the segment's middle.
    pure integer function forbidden_side(c, a, b)
      integer, intent(in) :: c
      real(wp), intent(in) :: a(2), b(2)
      real(wp) :: m(2), d(2), nrm(2), h
      d = b - a
      h = norm2(d)
      forbidden_side = 0
      if (h <= 0.0_wp) return
      m = 0.5_wp * (a + b)
      ! left of a -> b on the sheet is right of it in the (x1, x2) plane (the sheet's y is down)
      nrm = [d(2), -d(1)] / h
      h = 0.01_wp * (contour_hi - contour_lo)
      if (broken(c, m + h * nrm) .and. .not. broken(c, m - h * nrm)) then
        forbidden_side = 1
      else if (broken(c, m - h * nrm) .and. .not. broken(c, m + h * nrm)) then
        forbidden_side = -1
      end if
    end function forbidden_side
    !> Whether the condition of curve c is broken at (x1, x2).
    pure logical function broken(c, x)
      integer, intent(in) :: c
      real(wp), intent(in) :: x(2)
      type(pair_geometry_t) :: q
      q = pair_geometry(p, x(1), x(2))
      broken = .true.
      if (.not. q%valid) return
      select case (c)
      case (1, 2)
        broken = q%undercut(c)
      case (3, 4)
        broken = q%pointed(c - 2)
      case (5)
        broken = q%eps_alpha < 1.0_wp
      case (6)
        broken = q%eps_alpha < 1.2_wp
      case default
        broken = q%interference(c - 6)
      end select
    end function broken
  end subroutine draw_contour_panel

  !> The legend of the meshing drawing's lines and its graphical checks, in `box`.
  pure subroutine draw_legend(sheet, g, box, lang)
    type(sheet_t), intent(inout) :: sheet
    type(pair_geometry_t), intent(in) :: g
    real(wp), intent(in) :: box(4)
    integer, intent(in) :: lang
    real(wp) :: y, pts(2, 5)
    integer :: k
    character(len=7), parameter :: colours(5) = [character(len=7) :: action_colour, action_colour, arc_colour, &
      base_colour, working_colour]
    real(wp), parameter :: widths(5) = [0.3_wp, 0.8_wp, 0.8_wp, 0.25_wp, 0.25_wp]
    character(len=64) :: names(5)
    names(1) = words("line of action N1N2", "линия зацепления N1N2", lang)
    names(2) = words("active length B1B2", "активная линия B1B2", lang)
    names(3) = words("arcs of contact a1b1, a2b2", "дуги зацепления a1b1, a2b2", lang)
    names(4) = words("base circles r_b", "основные окружности r_b", lang)
    names(5) = words("working circles r_w", "начальные окружности r_w", lang)
    call sheet%set_layer(layer_text)
    call sheet%text(box(1), box(2) + 4.0_wp, words("Meshing drawing", "Картина зацепления", lang), "heading")
    y = box(2) + 10.0_wp
    do k = 1, size(names)
      call sheet%line(box(1), y - 0.9_wp, box(1) + 6.0_wp, y - 0.9_wp, stroke=colours(k), width=widths(k))
      if (k == 5) sheet%items(sheet%count)%dash = dash_dot
      call sheet%text(box(1) + 7.5_wp, y, trim(names(k)), "small")
      y = y + 4.2_wp
    end do
    call sheet%line(box(1), y - 0.9_wp, box(1) + 6.0_wp, y - 0.9_wp, stroke=ink, width=0.18_wp)
    sheet%items(sheet%count)%dash = dash_dot
    call sheet%text(box(1) + 7.5_wp, y, words("pitch circles r", "делительные окружности r", lang), "small")
    y = y + 7.0_wp
    ! the graphical checks of the contact ratio
    pts = line_of_action(g)
    call sheet%text(box(1), y, "eps_alpha = B1B2 / p_b", "small")
    call sheet%text(box(1), y + 4.2_wp, "= "//fixed_number(norm2(pts(:, 5) - pts(:, 4)), 3)// &
      " / "//fixed_number(g%base_pitch, 3)//" = "//fixed_number(g%eps_alpha, 3), "small")
    call sheet%text(box(1), y + 9.4_wp, "a1b1 / p_w = a2b2 / p_w = eps_alpha", "small")
    call sheet%text(box(1), y + 14.6_wp, words("ω1: gear 1 drives", "ω1: колесо 1 ведущее", lang), "small")
    ! the blocking contour's signs
    y = y + 26.0_wp
    call sheet%text(box(1), y, words("Blocking contour", "Блокирующий контур", lang), "heading")
    call dot(sheet, [box(1) + 1.5_wp, y + 5.1_wp], ink, 0.9_wp)
    call sheet%text(box(1) + 4.0_wp, y + 6.0_wp, "x_1 = "//fixed_number(g%x(1), 4)//", x_2 = "// &
      fixed_number(g%x(2), 4), "small")
    call sheet%line(box(1), y + 9.3_wp, box(1) + 6.0_wp, y + 9.3_wp, stroke="#555555", width=0.3_wp, dash="3 1.5")
    call sheet%text(box(1) + 7.5_wp, y + 10.2_wp, words("λ_1 = λ_2: equal largest sliding", &
      "λ_1 = λ_2: равные удельные скольжения", lang), "small")
    call sheet%text(box(1), y + 14.4_wp, words("hatched: the side where the", "штриховка: со стороны", &
      lang), "small")
    call sheet%text(box(1), y + 18.0_wp, words("condition is broken", "нарушения условия", lang), "small")
  end subroutine draw_legend

  !> The table of the pair's dimensions and its conditions in `box`.
  pure subroutine draw_dimension_table(sheet, p, g, box, lang)
    type(sheet_t), intent(inout) :: sheet
    type(gear_pair_t), intent(in) :: p
    type(pair_geometry_t), intent(in) :: g
    real(wp), intent(in) :: box(4)
    integer, intent(in) :: lang
    character(len=64) :: cells(12, 3), pair_cells(8, 2), flags(4)
    character(len=:), allocatable :: mm
    real(wp) :: pitch, y
    integer :: i, n_flags
    mm = ", "//unit_word("mm", lang)
    pitch = min(4.6_wp, (box(4) - box(2) - 10.0_wp) / 12.0_wp)
    cells(1, :) = [character(len=64) :: words("gear", "колесо", lang), "1", "2"]
    cells(2, :) = [character(len=64) :: "z", int_str(p%z1), int_str(p%z2)]
    cells(3, :) = [character(len=64) :: "x", fixed_number(g%x(1), 4), fixed_number(g%x(2), 4)]
    cells(4, :) = [character(len=64) :: "x_min", fixed_number(g%x_min(1), 4), fixed_number(g%x_min(2), 4)]
    cells(5, :) = [character(len=64) :: "d"//mm, fixed_number(g%d(1), 3), fixed_number(g%d(2), 3)]
    cells(6, :) = [character(len=64) :: "d_b"//mm, fixed_number(g%db(1), 3), fixed_number(g%db(2), 3)]
    cells(7, :) = [character(len=64) :: "d_w"//mm, fixed_number(g%dw(1), 3), fixed_number(g%dw(2), 3)]
    cells(8, :) = [character(len=64) :: "d_a"//mm, fixed_number(g%da(1), 3), fixed_number(g%da(2), 3)]
    cells(9, :) = [character(len=64) :: "d_f"//mm, fixed_number(g%df(1), 3), fixed_number(g%df(2), 3)]
    cells(10, :) = [character(len=64) :: "s"//mm, fixed_number(g%s(1), 3), fixed_number(g%s(2), 3)]
    cells(11, :) = [character(len=64) :: "s_a"//mm, fixed_number(g%sa(1), 3), fixed_number(g%sa(2), 3)]
    cells(12, :) = [character(len=64) :: "λ", sliding(g%sliding(1)), sliding(g%sliding(2))]
    call sheet%set_layer(layer_frame)
    call put_table(sheet, box(1), box(2), [24.0_wp, 24.0_wp, 24.0_wp], pitch, cells)
    pair_cells(1, :) = [character(len=64) :: words("pair", "передача", lang), ""]
    pair_cells(2, :) = [character(len=64) :: "m"//mm, short_number(p%m)]
    pair_cells(3, :) = [character(len=64) :: "alpha, "//unit_word("deg", lang), short_number(p%alpha * rad_to_deg)]
    pair_cells(4, :) = [character(len=64) :: "alpha_w, "//unit_word("deg", lang), fixed_number(g%alpha_w * rad_to_deg, &
      4)]
    pair_cells(5, :) = [character(len=64) :: "a_w"//mm, fixed_number(g%a_w, 3)]
    pair_cells(6, :) = [character(len=64) :: "y", fixed_number(g%y, 4)]
    pair_cells(7, :) = [character(len=64) :: "Δy", fixed_number(g%delta_y, 4)]
    pair_cells(8, :) = [character(len=64) :: "eps_alpha", fixed_number(g%eps_alpha, 4)]
    call put_table(sheet, box(1) + 78.0_wp, box(2), [26.0_wp, 24.0_wp], pitch, pair_cells)
    ! the conditions of the blocking contour, in words
    n_flags = 0
    do i = 1, 2
      if (g%undercut(i)) call add(flags, n_flags, words("gear "//int_str(i)//" undercut", "подрезание колеса "// &
        int_str(i), lang))
      if (g%pointed(i)) call add(flags, n_flags, words("gear "//int_str(i)//" pointed", "заострение колеса "// &
        int_str(i), lang))
      if (g%interference(i)) call add(flags, n_flags, words("interference on gear "//int_str(i), &
        "интерференция колеса "//int_str(i), lang))
    end do
    y = box(2) + 8.0_wp * pitch + 5.0_wp
    call sheet%set_layer(layer_text)
    if (n_flags == 0 .and. g%eps_alpha >= 1.2_wp) then
      call sheet%text(box(1) + 78.0_wp, y, words("Inside the blocking contour:", &
        "Внутри блокирующего контура:", lang), "small")
      call sheet%text(box(1) + 78.0_wp, y + 3.6_wp, words("no undercut, no pointed teeth,", &
        "нет подрезания, заострения,", lang), "small")
      call sheet%text(box(1) + 78.0_wp, y + 7.2_wp, words("no interference, eps_alpha ≥ 1.2", &
        "интерференции; eps_alpha ≥ 1.2", lang), "small")
    else
      call sheet%text(box(1) + 78.0_wp, y, words("Outside the blocking contour:", &
        "Вне блокирующего контура:", lang), "small", colour="#b22222")
      do i = 1, n_flags
        call sheet%text(box(1) + 78.0_wp, y + 3.6_wp * i, trim(flags(i)), "small", colour="#b22222")
      end do
      if (g%eps_alpha < 1.2_wp) call sheet%text(box(1) + 78.0_wp, y + 3.6_wp * (n_flags + 1), "eps_alpha = "// &
        fixed_number(g%eps_alpha, 3)//" < 1.2", "small", colour="#b22222")
    end if
  contains
    pure subroutine add(list, n, text)
      character(len=64), intent(inout) :: list(:)
      integer, intent(inout) :: n
      character(*), intent(in) :: text
      if (n >= size(list)) return
      n = n + 1
      list(n) = text
    end subroutine add
    !> A largest specific sliding: infinite where the active path reaches a base circle.
    pure function sliding(value) result(text)
      real(wp), intent(in) :: value
      character(len=:), allocatable :: text
      if (value >= 1.0e29_wp) then
        text = "∞"
      else
        text = fixed_number(value, 3)
      end if
    end function sliding
  end subroutine draw_dimension_table

end module kinetostat_gear_sheet
