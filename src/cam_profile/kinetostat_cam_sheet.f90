!> The sheet of a disc cam (`--format svg`/`dxf` of `&cam_profile`), as the course's sheet of
!> the cam synthesis, on A3 landscape with the ГОСТ frame and title block (Масштаб = the
!> profile's scale):
!> - the phases of the law over the turn (φ_у rise, φ_д far dwell, φ_в return, φ_б near
!>   dwell; in English rise, dwell, return) and, one under the other on the same cam-angle
!>   axis, the motion diagrams: the displacement s(φ) (an arm's angle ψ), the first analogue
!>   s' = ds/dφ with the velocity v = s'·|ω| on a second scale, the second analogue s'' with
!>   the acceleration a = s''·ω², and the pressure angle ϑ(φ) with its limits on the rise and
!>   on the return (a flat face: the profile's radius of curvature ρ(φ) with ρ_min);
!> - the cam at a ГОСТ 2.302 scale: the actual profile (thick; in the DXF one closed POLYLINE on
!>   layer PROFILE, for CAD), the pitch curve (dashed; a roller's), the base circle r_0 and the
!>   pitch circle, the offset circle, the phases' rays from the centre O, the sense of rotation
!>   ω, and the follower at one position (--at K; else where the pressure angle is largest, a
!>   flat face where it touches farthest off its axis) with the normal at the contact and the
!>   pressure angle;
!> - the sizes: r_0 (r_base), the pitch circle (r_prime), the offset or the arm, the roller,
!>   the largest pressure angles against their limits (a flat face: the face width and ρ_min).
!> The curves are drawn through the law at every output step divided into equal parts of 1 deg
!> at most; the profile's vertices at the output steps are the CSV's x_profile, y_profile. The
!> cam is the group "cam": sheet point = data-origin + data-scale * (x, -y), (x, y) in the cam
!> frame (m), data-scale in mm per m; data-subdivision = vertices per output step.
module kinetostat_cam_sheet
  use kinetostat_kinds, only: wp, pi, rad_to_deg, deg_to_rad
  use kinetostat_text, only: int_str
  use kinetostat_format, only: short_number, fixed_number, full_number
  use kinetostat_step_table, only: step_table_t
  use kinetostat_labels, only: unit_word => unit_symbol
  use kinetostat_vec2, only: rotate, perp
  use kinetostat_svg, only: coord
  use kinetostat_scales, only: drawing_scale_t, standard_drawing_scale, nice_step
  use kinetostat_sheet, only: sheet_t, paper_t, iso_paper, layer_links, layer_guides, layer_forces, layer_text, &
    layer_charts, layer_profile, layer_frame, anchor_middle
  use kinetostat_title_block, only: block_width, block_height
  use kinetostat_design_sheet, only: words, open_design_sheet, sheet_of, chart_t, put_chart, put_angle, put_table, dot
  use kinetostat_cam_profile, only: cam_design_t, cam_point_t, cam_sizes_t, cam_point, motion_at, cam_extremes, &
    segment_at, segment_limit, follower_flat, follower_roller, follower_oscillating
  implicit none
  private
  public :: draw_cam_sheet, cam_sheet_step

  !> Largest angle between two points of a drawn curve, deg.
  real(wp), parameter :: finest = 1.0_wp
  character(*), parameter :: ink = "#000000", curve_colour = "#1f77b4", limit_colour = "#d62728", &
    grey = "#7f7f7f", dash_dot = "6 1.5 1 1.5"

  !> The law and the geometry at the drawn angles.
  type :: cam_curves_t
    !> Cam angle, deg; s (m, an arm's in deg), s', s'', pressure angle (deg), rho (m).
    real(wp), allocatable :: phi(:), s(:), ds(:), d2s(:), theta(:), rho(:)
    !> Pitch and actual profile points (2, n), cam frame, m.
    real(wp), allocatable :: pitch(:, :), profile(:, :)
  end type cam_curves_t

contains

  !> The output step at which the follower is drawn: `at` when given, else the step of the
  !> largest |pressure angle| (a flat face: of the largest |s'|, the contact farthest off the
  !> axis).
  pure integer function cam_sheet_step(design, table, at) result(k)
    type(cam_design_t), intent(in) :: design
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: at
    if (at > 0) then
      k = at
    else if (design%follower == follower_flat) then
      k = maxloc(abs(table%rows(table%column_index("ds"), :)), dim=1)
    else
      k = maxloc(abs(table%rows(table%column_index("theta"), :)), dim=1)
    end if
  end function cam_sheet_step

  !> The sheet of the sized cam `design` whose output rows are every `step` deg (n of them).
  pure subroutine draw_cam_sheet(design, step, table, lang, k, sheet)
    !> The cam, sized (r_prime, r_base set).
    type(cam_design_t), intent(in) :: design
    !> The output step, deg.
    real(wp), intent(in) :: step
    !> The run's results (the rows, the deck, the student).
    type(step_table_t), intent(in) :: table
    !> lang_en or lang_ru.
    integer, intent(in) :: lang
    !> The row where the follower is drawn.
    integer, intent(in) :: k
    !> The sheet made.
    type(sheet_t), intent(out) :: sheet
    type(cam_curves_t) :: c
    type(paper_t) :: paper
    type(drawing_scale_t) :: drawing_scale
    real(wp) :: inner(4), column(4), region(4), box(4), fit, origin(2), scale, top, h, w
    integer :: sub, n, j
    character(len=:), allocatable :: follower_text

    sub = max(1, ceiling(step / finest - 1.0e-9_wp))
    n = nint(360.0_wp / step) * sub
    call cam_curves(design, n, c)
    paper = iso_paper("A3", .true.)
    inner = paper%inside()
    ! the diagrams in a column 165 mm wide on the left; the cam right of it, above its sizes
    ! (over the title block)
    column = [inner(1) + 174.0_wp, 27.0_wp, inner(3) - 3.0_wp, inner(4) - block_height - 4.0_wp]
    region = [column(1) + 2.0_wp, column(2) + 2.0_wp, column(3) - 2.0_wp, column(4) - 38.0_wp]
    box = cam_extent(design, c, table%rows(1, k))
    fit = min((region(3) - region(1) - 16.0_wp) / (box(3) - box(1)), (region(4) - region(2) - 16.0_wp) / &
      (box(4) - box(2))) / 1000.0_wp
    drawing_scale = standard_drawing_scale(fit)
    scale = drawing_scale%ratio * 1000.0_wp
    origin = anint([0.5_wp * (region(1) + region(3)) - scale * 0.5_wp * (box(1) + box(3)), &
      0.5_wp * (region(2) + region(4)) + scale * 0.5_wp * (box(2) + box(4))] * 100.0_wp) / 100.0_wp

    select case (design%follower)
    case (follower_flat)
      follower_text = words("translating flat-faced follower", &
        "поступательный толкатель с плоской тарелкой", lang)
    case (follower_roller)
      follower_text = words("translating roller follower", &
        "поступательный роликовый толкатель", lang)
    case default
      follower_text = words("oscillating roller follower", "роликовое коромысло", lang)
    end select
    call open_design_sheet(sheet, paper, lang, table, words("Disc cam: laws of motion, profile", &
      "Кулачковый механизм: законы движения, профиль", lang), drawing_scale%text, &
      words("Disc cam for a law of motion", "Профилирование дискового кулачка", lang)//": "// &
      follower_text, &
      size_line(design, lang)//"; ω = "// &
      short_number(design%omega)//" "//unit_word("rad/s", lang)//"; "//words("follower at", "толкатель при", lang)// &
      " phi = "//fixed_number(table%rows(1, k), 1)//" "//unit_word("deg", lang)//"; "//words("scale", "масштаб", lang)// &
      " "//drawing_scale%text, &
      sheet_of(table)//"the cam's motion diagrams and its profile at "//drawing_scale%text// &
      ". Group cam: sheet point = data-origin + data-scale * (x, -y), (x, y) in the cam frame (m), data-scale in "// &
      "mm per m; the path of class profile is the actual profile through data-subdivision points per output "// &
      "step, its vertex j * data-subdivision the CSV's row j + 1.")

    ! the diagrams, one under the other, under the strip of the phases
    w = 165.0_wp
    top = 27.0_wp
    call put_phases(sheet, design, inner(1) + 3.0_wp + 19.0_wp, top, w - 42.0_wp, lang)
    top = top + 8.0_wp
    h = (inner(4) - 3.0_wp - top - 3.0_wp * 3.0_wp) / 4.0_wp
    do j = 1, 4
      call put_diagram(sheet, design, c, j, inner(1) + 3.0_wp, top + (j - 1) * (h + 3.0_wp), w, h, lang)
    end do

    call draw_cam(sheet, design, c, sub, k, origin, scale, drawing_scale%text, region, lang)
    call put_sizes(sheet, design, [inner(3) - block_width, column(4) - 34.0_wp, column(3), column(4)], lang)
  end subroutine draw_cam_sheet

  !> The law and the geometry at n equal steps of the turn (0 .. 360 deg less one step).
  pure subroutine cam_curves(design, n, c)
    type(cam_design_t), intent(in) :: design
    integer, intent(in) :: n
    type(cam_curves_t), intent(out) :: c
    type(cam_point_t) :: q
    real(wp) :: phi
    integer :: j
    allocate (c%phi(0:n), c%s(0:n), c%ds(0:n), c%d2s(0:n), c%theta(0:n), c%rho(0:n), c%pitch(2, 0:n), &
      c%profile(2, 0:n))
    do j = 0, n
      phi = 360.0_wp * real(j, wp) / real(n, wp)
      c%phi(j) = phi
      call motion_at(design, phi * deg_to_rad, c%s(j), c%ds(j), c%d2s(j))
      q = cam_point(design, phi * deg_to_rad, c%s(j), c%ds(j), c%d2s(j))
      c%theta(j) = q%theta * rad_to_deg
      c%rho(j) = q%rho
      c%pitch(:, j) = q%pitch
      c%profile(:, j) = q%profile
    end do
  end subroutine cam_curves

  !> The strip of the phases over the cam-angle axis of the diagrams (x0 .. x0 + w).
  pure subroutine put_phases(sheet, design, x0, y0, w, lang)
    type(sheet_t), intent(inout) :: sheet
    type(cam_design_t), intent(in) :: design
    real(wp), intent(in) :: x0, y0, w
    integer, intent(in) :: lang
    real(wp) :: a, b
    integer :: i
    call sheet%set_layer(layer_charts)
    call sheet%line(x0, y0 + 6.0_wp, x0 + w, y0 + 6.0_wp, stroke=ink, width=0.25_wp)
    do i = 1, size(design%seg)
      a = x0 + w * design%seg(i)%phi0 * rad_to_deg / 360.0_wp
      b = a + w * design%seg(i)%beta * rad_to_deg / 360.0_wp
      call sheet%line(a, y0 + 3.5_wp, a, y0 + 6.0_wp, stroke=ink, width=0.25_wp)
      if (i == size(design%seg)) call sheet%line(b, y0 + 3.5_wp, b, y0 + 6.0_wp, stroke=ink, width=0.25_wp)
      call sheet%text(0.5_wp * (a + b), y0 + 4.0_wp, phase_name(design, i, lang)//" = "// &
        short_number(design%seg(i)%beta * rad_to_deg)//"°", "small", anchor_middle)
    end do
  end subroutine put_phases

  !> The course's name of phase i: rise φ_у, return φ_в, a dwell after a rise φ_д (far), else
  !> φ_б (near); in English the words.
  pure function phase_name(design, i, lang) result(text)
    type(cam_design_t), intent(in) :: design
    integer, intent(in) :: i, lang
    character(len=:), allocatable :: text
    logical :: high
    if (design%seg(i)%lift > 0.0_wp) then
      text = words("rise", "phi_у", lang)
    else if (design%seg(i)%lift < 0.0_wp) then
      text = words("return", "phi_в", lang)
    else
      high = design%seg(i)%s0 > 0.0_wp
      text = words("dwell", merge("phi_д", "phi_б", high), lang)
    end if
  end function phase_name

  !> Diagram j in the panel (x0, y0, w, h): 1 the displacement, 2 the first analogue with the
  !> velocity, 3 the second with the acceleration, 4 the pressure angle with its limits (a
  !> flat face: the radius of curvature with rho_min).
  pure subroutine put_diagram(sheet, design, c, j, x0, y0, w, h, lang)
    type(sheet_t), intent(inout) :: sheet
    type(cam_design_t), intent(in) :: design
    type(cam_curves_t), intent(in) :: c
    integer, intent(in) :: j
    real(wp), intent(in) :: x0, y0, w, h
    integer, intent(in) :: lang
    type(chart_t) :: chart
    real(wp), allocatable :: y(:), levels(:, :)
    real(wp) :: factor, om, t
    character(len=:), allocatable :: heading, ylabel, right_label, mm, deg
    logical :: arm
    integer :: i, m
    arm = design%follower == follower_oscillating
    om = abs(design%omega)
    mm = unit_word("mm", lang)
    deg = unit_word("deg", lang)
    allocate (levels(2, 0), y(lbound(c%s, 1):ubound(c%s, 1)))
    factor = 1.0_wp
    select case (j)
    case (1)
      if (arm) then
        y(:) = c%s * rad_to_deg
        heading = words("Angle of the arm ψ(φ)", "Угол поворота коромысла ψ(φ)", lang)
        ylabel = "ψ, "//deg
      else
        y(:) = c%s * 1000.0_wp
        heading = words("Displacement of the follower s(φ)", "Перемещение толкателя s(φ)", lang)
        ylabel = "s, "//mm
      end if
    case (2)
      if (arm) then
        y(:) = c%ds
        factor = om
        ylabel = "ψ′"
        right_label = "ω_2, "//unit_word("rad/s", lang)
      else
        y(:) = c%ds * 1000.0_wp
        factor = om / 1000.0_wp
        ylabel = "s′, "//mm
        right_label = "v, "//unit_word("m/s", lang)
      end if
      heading = words("First analogue s′ = ds/dφ and the velocity", &
        "Аналог скорости s′(φ) и скорость", lang)
    case (3)
      if (arm) then
        y(:) = c%d2s
        factor = om**2
        ylabel = "ψ″"
        right_label = "ε_2, "//unit_word("rad/s^2", lang)
      else
        y(:) = c%d2s * 1000.0_wp
        factor = om**2 / 1000.0_wp
        ylabel = "s″, "//mm
        right_label = "a, "//unit_word("m/s^2", lang)
      end if
      heading = words("Second analogue s″ = d²s/dφ² and the acceleration", &
        "Аналог ускорения s″(φ) и ускорение", lang)
    case default
      if (design%follower == follower_flat) then
        y(:) = c%rho * 1000.0_wp
        heading = words("Radius of curvature of the profile ρ(φ) and ρ_min", &
          "Радиус кривизны профиля ρ(φ) и ρ_min", lang)
        ylabel = "ρ, "//mm
        levels = reshape([0.0_wp, design%rho_min * 1000.0_wp, 360.0_wp, design%rho_min * 1000.0_wp], [2, 2])
      else
        y(:) = c%theta
        heading = words("Pressure angle ϑ(φ) and its limits", &
          "Угол давления ϑ(φ) и допустимые углы", lang)
        ylabel = "ϑ, "//deg
        m = size(design%seg)
        deallocate (levels)
        allocate (levels(2, 4 * m))
        do i = 1, m
          t = segment_limit(design, i) * rad_to_deg
          levels(:, 4 * i - 3) = [design%seg(i)%phi0 * rad_to_deg, t]
          levels(:, 4 * i - 2) = [(design%seg(i)%phi0 + design%seg(i)%beta) * rad_to_deg, t]
          levels(:, 4 * i - 1) = [design%seg(i)%phi0 * rad_to_deg, -t]
          levels(:, 4 * i) = [(design%seg(i)%phi0 + design%seg(i)%beta) * rad_to_deg, -t]
        end do
      end if
    end select
    call sheet%set_layer(layer_charts)
    if (j == 2 .or. j == 3) then
      call put_chart(sheet, chart, x0, y0, w, h, heading, 0.0_wp, 360.0_wp, 30.0_wp, [y, 0.0_wp], &
        "φ, "//deg, ylabel, factor, right_label)
    else
      call put_chart(sheet, chart, x0, y0, w, h, heading, 0.0_wp, 360.0_wp, 30.0_wp, [y, levels(2, :), 0.0_wp], &
        "φ, "//deg, ylabel, right_room=.true.)
    end if
    ! the phases' boundaries
    do i = 2, size(design%seg)
      t = chart%sx(design%seg(i)%phi0 * rad_to_deg)
      call sheet%line(t, chart%top, t, chart%top + chart%height, stroke=grey, width=0.15_wp, dash="1 1")
    end do
    ! the limits, dashed, then the curve
    do i = 1, size(levels, 2) / 2
      call sheet%line(chart%sx(levels(1, 2 * i - 1)), chart%sy(levels(2, 2 * i - 1)), chart%sx(levels(1, 2 * i)), &
        chart%sy(levels(2, 2 * i)), stroke=limit_colour, width=0.3_wp, dash="2 1")
    end do
    call sheet%polyline([(chart%sx(c%phi(i)), i = 0, size(c%phi) - 1)], [(chart%sy(y(i)), i = lbound(y, 1), ubound(y, 1))], &
      stroke=curve_colour, width=0.4_wp)
  end subroutine put_diagram

  !> The extent of the cam's drawing (cam frame, m): x from, y from, x to, y to.
  pure function cam_extent(design, c, phi) result(b)
    type(cam_design_t), intent(in) :: design
    type(cam_curves_t), intent(in) :: c
    !> The follower's cam angle, deg.
    real(wp), intent(in) :: phi
    real(wp) :: b(4), pts(2, 6)
    real(wp) :: r_out
    integer :: j
    r_out = maxval(norm2(c%pitch, dim=1)) + design%roller_radius
    b = [-r_out, -r_out, r_out, r_out]
    call follower_points(design, phi, pts)
    do j = 1, 3
      b = [min(b(1), pts(1, j)), min(b(2), pts(2, j)), max(b(3), pts(1, j)), max(b(4), pts(2, j))]
    end do
  end function cam_extent

  !> The follower at cam angle phi (deg) in the cam frame, m: 1 the pitch point (roller
  !> centre; the flat face on its axis), 2 the contact, 3 the far end of the stem (the arm's
  !> pivot), 4 the unit direction of motion, 5 the axis outward (the arm: pivot to roller),
  !> 6 the guide's middle (the pivot).
  pure subroutine follower_points(design, phi, pts)
    type(cam_design_t), intent(in) :: design
    real(wp), intent(in) :: phi
    real(wp), intent(out) :: pts(2, 6)
    real(wp) :: s, ds, d2s, turn, length
    type(cam_point_t) :: q
    call motion_at(design, phi * deg_to_rad, s, ds, d2s)
    q = cam_point(design, phi * deg_to_rad, s, ds, d2s)
    turn = -sign(1.0_wp, design%omega) * phi * deg_to_rad
    pts(:, 1) = q%pitch
    pts(:, 2) = q%profile
    length = 0.55_wp * design%r_prime + 2.0_wp * design%roller_radius
    if (design%follower == follower_oscillating) then
      pts(:, 3) = rotate(design%pivot, turn)
      pts(:, 5) = (pts(:, 1) - pts(:, 3)) / norm2(pts(:, 1) - pts(:, 3))
      pts(:, 4) = perp(pts(:, 5))
      pts(:, 6) = pts(:, 3)
    else
      pts(:, 5) = rotate([0.0_wp, 1.0_wp], turn)
      pts(:, 4) = pts(:, 5)
      pts(:, 3) = pts(:, 1) + length * pts(:, 5)
      pts(:, 6) = pts(:, 1) + 0.7_wp * length * pts(:, 5)
    end if
  end subroutine follower_points

  !> The cam: profile, pitch curve, circles, phases, the follower at row k, the sense of rotation.
  pure subroutine draw_cam(sheet, design, c, sub, k, origin, scale, scale_text, region, lang)
    type(sheet_t), intent(inout) :: sheet
    type(cam_design_t), intent(in) :: design
    type(cam_curves_t), intent(in) :: c
    integer, intent(in) :: sub, k
    real(wp), intent(in) :: origin(2), scale, region(4)
    character(*), intent(in) :: scale_text
    integer, intent(in) :: lang
    real(wp) :: o(2), pts(2, 6), b(2), e(2), d(2), v(2), nrm(2), r, a0, a1, bounds(4), phi0, reach
    real(wp), allocatable :: x(:), y(:)
    integer :: j, n, i
    logical :: roller
    roller = design%follower /= follower_flat
    n = size(c%phi) - 1
    o = at(origin, [0.0_wp, 0.0_wp])
    bounds = region
    call follower_points(design, c%phi((k - 1) * sub), pts)

    call sheet%group("cam")
    call sheet%attach("data-origin", coord(origin(1))//" "//coord(origin(2)))
    call sheet%attach("data-scale", full_number(scale))
    call sheet%attach("data-rotation", "0")
    call sheet%attach("data-drawing-scale", scale_text)
    call sheet%attach("data-subdivision", int_str(sub))

    ! centre lines, circles
    call sheet%set_layer(layer_guides)
    reach = maxval(norm2(c%pitch, dim=1)) * scale + 5.0_wp
    call sheet%line(o(1) - reach, o(2), o(1) + reach, o(2), stroke=ink, width=0.18_wp, dash=dash_dot)
    call sheet%line(o(1), o(2) - reach, o(1), o(2) + reach, stroke=ink, width=0.18_wp, dash=dash_dot)
    call sheet%arc(o(1), o(2), design%r_base * scale, 0.0_wp, 360.0_wp, stroke="#2ca02c", width=0.25_wp)
    if (roller) then
      call sheet%arc(o(1), o(2), design%r_prime * scale, 0.0_wp, 360.0_wp, stroke=ink, width=0.18_wp)
      sheet%items(sheet%count)%dash = dash_dot
    end if
    if (design%follower == follower_roller .and. design%offset /= 0.0_wp) call sheet%arc(o(1), o(2), &
      abs(design%offset) * scale, 0.0_wp, 360.0_wp, stroke=grey, width=0.18_wp)
    ! the phases' rays: the follower's axis at each phase's start, turned back with the cam
    do i = 1, size(design%seg)
      phi0 = design%seg(i)%phi0
      d = rotate([0.0_wp, 1.0_wp], -sign(1.0_wp, design%omega) * phi0)
      if (design%follower == follower_oscillating) d = pitch_at(phi0 * rad_to_deg) / norm2(pitch_at(phi0 * &
        rad_to_deg))
      e = at(origin, d * (maxval(norm2(c%pitch, dim=1)) + design%roller_radius + 0.1_wp * design%r_prime))
      call sheet%line(o(1), o(2), e(1), e(2), stroke=grey, width=0.18_wp)
    end do
    ! the pitch curve (a roller's) and the actual profile
    call sheet%set_layer(layer_links)
    if (roller) then
      x = [(at_x(c%pitch(:, j)), j = 0, n - 1)]
      y = [(at_y(c%pitch(:, j)), j = 0, n - 1)]
      call sheet%polygon(x, y, stroke=grey, width=0.25_wp, fill="none")
      sheet%items(sheet%count)%dash = "3 1.5"
    end if
    call sheet%set_layer(layer_profile)
    x = [(at_x(c%profile(:, j)), j = 0, n - 1)]
    y = [(at_y(c%profile(:, j)), j = 0, n - 1)]
    call sheet%polygon(x, y, stroke=ink, width=0.6_wp, fill="none")
    call sheet%attach("data-profile", "actual")
    ! the cam's sense of rotation: an arrowed arc outside the pitch curve, lower right
    call sheet%set_layer(layer_forces)
    r = (maxval(norm2(c%pitch, dim=1)) + design%roller_radius) * scale + 4.0_wp
    a0 = 290.0_wp
    a1 = 330.0_wp
    if (design%omega < 0.0_wp) then
      a0 = 330.0_wp
      a1 = 290.0_wp
    end if
    call sheet%arc(o(1), o(2), r, 290.0_wp, 40.0_wp, stroke=ink, width=0.3_wp)
    b = o + r * [cos(a1 * deg_to_rad), -sin(a1 * deg_to_rad)]
    e = o + r * [cos((a1 - sign(5.0_wp, a1 - a0)) * deg_to_rad), -sin((a1 - sign(5.0_wp, a1 - a0)) * deg_to_rad)]
    call sheet%arrow(e(1), e(2), b(1), b(2), ink, 0.3_wp, 2.5_wp)

    ! the follower
    call sheet%set_layer(layer_links)
    b = at(origin, pts(:, 1))
    e = at(origin, pts(:, 3))
    if (design%follower == follower_oscillating) then
      call sheet%line(e(1), e(2), b(1), b(2), stroke=ink, width=0.6_wp)
      call pivot_symbol(sheet, e)
    else
      d = at(origin, pts(:, 1) + design%roller_radius * pts(:, 5))
      call sheet%line(d(1), d(2), e(1), e(2), stroke=ink, width=0.6_wp)
      call guide_symbol(sheet, at(origin, pts(:, 6)), [pts(1, 5), -pts(2, 5)])
    end if
    if (roller) then
      call sheet%arc(b(1), b(2), design%roller_radius * scale, 0.0_wp, 360.0_wp, stroke=ink, width=0.5_wp)
      call dot(sheet, b, ink, 0.4_wp)
    else
      ! the flat face: across the axis, as wide as the contact travels and a margin
      v = [pts(2, 5), -pts(1, 5)]
      d = at(origin, pts(:, 1) + (maxval(abs(c%ds)) + 0.1_wp * design%r_base) * v)
      e = at(origin, pts(:, 1) - (maxval(abs(c%ds)) + 0.1_wp * design%r_base) * v)
      call sheet%line(d(1), d(2), e(1), e(2), stroke=ink, width=0.7_wp)
    end if
    ! the normal at the contact and the pressure angle between it and the direction of motion
    call sheet%set_layer(layer_forces)
    e = at(origin, pts(:, 2))
    call dot(sheet, e, limit_colour, 0.5_wp)
    nrm = pts(:, 1) - pts(:, 2)
    if (norm2(nrm) > 0.0_wp) then
      nrm = nrm / norm2(nrm)
    else
      nrm = pts(:, 4)
    end if
    if (roller) then
      d = at(origin, pts(:, 1) + nrm * (design%roller_radius + 0.3_wp * design%r_prime))
      call sheet%line(e(1), e(2), d(1), d(2), stroke=limit_colour, width=0.3_wp)
      d = at(origin, pts(:, 1) + pts(:, 4) * (design%roller_radius + 0.3_wp * design%r_prime))
      call sheet%line(b(1), b(2), d(1), d(2), stroke=limit_colour, width=0.3_wp, dash="2 1")
      a0 = atan2(pts(2, 4), pts(1, 4)) * rad_to_deg
      a1 = atan2(nrm(2), nrm(1)) * rad_to_deg
      if (abs(modulo(a1 - a0 + 180.0_wp, 360.0_wp) - 180.0_wp) > 0.05_wp) call put_angle(sheet, b(1), b(2), &
        design%roller_radius * scale + 6.0_wp, a0, modulo(a1 - a0 + 180.0_wp, 360.0_wp) - 180.0_wp, limit_colour)
    end if

    ! names
    call sheet%set_layer(layer_text)
    call dot(sheet, o, ink, 0.6_wp)
    call sheet%attach("data-point", "O")
    call sheet%place_label("O", "label", o(1), o(2), 0.75_wp * pi, bounds)
    call sheet%place_label("omega", "label", o(1) + r * cos(310.0_wp * deg_to_rad), o(2) - r * sin(310.0_wp * &
      deg_to_rad), -0.25_wp * pi, bounds)
    e = at(origin, rotate([design%r_base, 0.0_wp], -0.25_wp * pi))
    if (.not. roller) then
      call sheet%place_label(words("r_base", "r_0", lang), "label", e(1), e(2), 0.25_wp * pi, bounds, colour="#2ca02c")
    else
      call sheet%place_label(words("r_base", "r_0 - r_р", lang), "small", e(1), e(2), 0.25_wp * pi, bounds, &
        colour="#2ca02c")
      e = at(origin, rotate([design%r_prime, 0.0_wp], -0.35_wp * pi))
      call sheet%place_label(words("r_prime", "r_0", lang), "label", e(1), e(2), -0.35_wp * pi, bounds)
    end if
    if (roller) then
      b = at(origin, pts(:, 1))
      call sheet%place_label(words("B", "B", lang), "label", b(1), b(2), -0.25_wp * pi, bounds)
      call sheet%attach("data-point", "B")
      if (k >= 1) call sheet%place_label(words("theta", "ϑ", lang)//" = "//fixed_number(abs(c%theta((k - 1) * &
        sub)), 1)//"°", "label", b(1) + (design%roller_radius * scale + 8.0_wp) * cos(0.5_wp * (a0 + a1) * &
        deg_to_rad), b(2) - (design%roller_radius * scale + 8.0_wp) * sin(0.5_wp * (a0 + a1) * deg_to_rad), &
        -0.5_wp * pi, bounds, colour=limit_colour)
    end if
    ! the phases' names between their rays
    do i = 1, size(design%seg)
      phi0 = (design%seg(i)%phi0 + 0.5_wp * design%seg(i)%beta)
      d = rotate([0.0_wp, 1.0_wp], -sign(1.0_wp, design%omega) * phi0)
      if (design%follower == follower_oscillating) d = pitch_at(phi0 * rad_to_deg) / norm2(pitch_at(phi0 * &
        rad_to_deg))
      e = at(origin, d * (maxval(norm2(c%pitch, dim=1)) + design%roller_radius + 0.06_wp * design%r_prime))
      call sheet%place_label(phase_name(design, i, lang), "small", e(1), e(2), atan2(-(e(2) - o(2)), e(1) - o(1)), &
        bounds)
    end do
    call sheet%end_group()
  contains
    pure function at(og, q) result(s)
      real(wp), intent(in) :: og(2), q(2)
      real(wp) :: s(2)
      s = og + scale * [q(1), -q(2)]
    end function at
    pure real(wp) function at_x(q)
      real(wp), intent(in) :: q(2)
      at_x = origin(1) + scale * q(1)
    end function at_x
    pure real(wp) function at_y(q)
      real(wp), intent(in) :: q(2)
      at_y = origin(2) - scale * q(2)
    end function at_y
    !> The pitch point at cam angle phi (deg), cam frame.
    pure function pitch_at(phi) result(q)
      real(wp), intent(in) :: phi
      real(wp) :: q(2), s, ds, d2s
      type(cam_point_t) :: p
      call motion_at(design, phi * deg_to_rad, s, ds, d2s)
      p = cam_point(design, phi * deg_to_rad, s, ds, d2s)
      q = p%pitch
    end function pitch_at
  end subroutine draw_cam

  !> A fixed pivot at s (sheet mm): a circle on a hatched base.
  pure subroutine pivot_symbol(sheet, s)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: s(2)
    integer :: i
    call sheet%line(s(1), s(2), s(1) - 3.0_wp, s(2) + 5.0_wp, stroke=ink, width=0.35_wp)
    call sheet%line(s(1), s(2), s(1) + 3.0_wp, s(2) + 5.0_wp, stroke=ink, width=0.35_wp)
    call sheet%line(s(1) - 5.0_wp, s(2) + 5.0_wp, s(1) + 5.0_wp, s(2) + 5.0_wp, stroke=ink, width=0.35_wp)
    do i = 0, 4
      call sheet%line(s(1) - 4.0_wp + 2.0_wp * i, s(2) + 5.0_wp, s(1) - 5.5_wp + 2.0_wp * i, s(2) + 6.5_wp, &
        stroke=ink, width=0.2_wp)
    end do
    call sheet%circle(s(1), s(2), 1.2_wp, stroke=ink, width=0.35_wp, fill="#ffffff")
  end subroutine pivot_symbol

  !> A translating follower's guide at s (sheet mm) along the sheet direction d: two short
  !> walls either side of the stem, hatched outward.
  pure subroutine guide_symbol(sheet, s, d)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: s(2), d(2)
    real(wp) :: n(2), a(2), b(2)
    integer :: side, i
    n = [-d(2), d(1)]
    do side = -1, 1, 2
      a = s + side * 2.0_wp * n - 5.0_wp * d
      b = s + side * 2.0_wp * n + 5.0_wp * d
      call sheet%line(a(1), a(2), b(1), b(2), stroke=ink, width=0.35_wp)
      do i = 0, 4
        a = s + side * 2.0_wp * n + (-4.0_wp + 2.0_wp * i) * d
        call sheet%line(a(1), a(2), a(1) + side * 1.5_wp * n(1) + 1.5_wp * d(1), a(2) + side * 1.5_wp * n(2) + &
          1.5_wp * d(2), stroke=ink, width=0.2_wp)
      end do
    end do
  end subroutine guide_symbol

  !> The cam's size in words: r_base and r_prime (ru: the course's r_0, the pitch profile's
  !> least radius, and r_0 - r_р).
  pure function size_line(design, lang) result(text)
    type(cam_design_t), intent(in) :: design
    integer, intent(in) :: lang
    character(len=:), allocatable :: text, mm
    mm = " "//unit_word("mm", lang)
    if (design%follower == follower_flat) then
      text = words("r_base", "r_0", lang)//" = "//fixed_number(design%r_base * 1000.0_wp, 3)//mm
    else
      text = words("r_prime = ", "r_0 = ", lang)//fixed_number(design%r_prime * 1000.0_wp, 3)//mm//", "// &
        words("r_base = ", "r_0 - r_р = ", lang)//fixed_number(design%r_base * 1000.0_wp, 3)//mm
    end if
  end function size_line

  !> The cam's sizes under its drawing, in `box`.
  pure subroutine put_sizes(sheet, design, box, lang)
    type(sheet_t), intent(inout) :: sheet
    type(cam_design_t), intent(in) :: design
    real(wp), intent(in) :: box(4)
    integer, intent(in) :: lang
    type(cam_sizes_t) :: x
    character(len=64) :: cells(6, 2)
    character(len=:), allocatable :: mm, deg
    integer :: rows
    x = cam_extremes(design)
    mm = ", "//unit_word("mm", lang)
    deg = ", "//unit_word("deg", lang)
    cells = ""
    cells(1, :) = [character(len=64) :: words("size", "размер", lang), ""]
    if (design%follower == follower_flat) then
      cells(2, :) = [character(len=64) :: words("r_base (base circle)", "r_0 (начальная шайба)", lang)//mm, &
        fixed_number(design%r_base * 1000.0_wp, 3)]
      cells(3, :) = [character(len=64) :: words("face width", "ширина тарелки", lang)//mm, &
        fixed_number(x%face_width * 1000.0_wp, 3)]
      cells(4, :) = [character(len=64) :: "ρ_min"//mm, fixed_number(x%rho_min * 1000.0_wp, 3)]
      rows = 4
    else
      ! the course's r_0: the least radius of the pitch (centre) profile
      cells(2, :) = [character(len=64) :: words("r_prime (pitch circle)", "r_0 (центровой профиль)", lang)//mm, &
        fixed_number(design%r_prime * 1000.0_wp, 3)]
      cells(3, :) = [character(len=64) :: words("r_base (base circle)", "r_0 - r_р (профиль)", lang)//mm, &
        fixed_number(design%r_base * 1000.0_wp, 3)]
      cells(4, :) = [character(len=64) :: words("roller r_r", "ролик r_р", lang)//mm, &
        fixed_number(design%roller_radius * 1000.0_wp, 3)]
      cells(5, :) = [character(len=64) :: words("theta max, rise / limit", "ϑ наиб. удаления / доп.", lang)//deg, &
        fixed_number(x%theta_rise * rad_to_deg, 2)//" / "//fixed_number(design%limit_rise * rad_to_deg, 1)]
      cells(6, :) = [character(len=64) :: words("theta max, return / limit", "ϑ наиб. возвращения / доп.", &
        lang)// &
        deg, fixed_number(x%theta_return * rad_to_deg, 2)//" / "//fixed_number(design%limit_return * rad_to_deg, 1)]
      rows = 6
    end if
    call sheet%set_layer(layer_frame)
    call put_table(sheet, box(1), box(2), [70.0_wp, 40.0_wp], 5.0_wp, cells(1:rows, :))
    if (design%follower == follower_roller) then
      call sheet%text(box(1) + 114.0_wp, box(2) + 7.5_wp, "e = "//fixed_number(design%offset * 1000.0_wp, 3)//" "// &
        unit_word("mm", lang), "small")
    else if (design%follower == follower_oscillating) then
      call sheet%text(box(1) + 114.0_wp, box(2) + 7.5_wp, words("arm", "коромысло", lang)//" "// &
        fixed_number(design%arm * 1000.0_wp, 1)//" "//unit_word("mm", lang), "small")
      call sheet%text(box(1) + 114.0_wp, box(2) + 11.7_wp, "ψ_0 = "//fixed_number(design%psi0 * rad_to_deg, 2)// &
        "°", "small")
    end if
  end subroutine put_sizes

end module kinetostat_cam_sheet
