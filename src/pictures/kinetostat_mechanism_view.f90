!> The mechanism at one step drawn into a region of a sheet of the drawing model, at a
!> standard scale, in the turned frame where gravity points down the sheet (the `--at` sheet
!> draws with it; the plans sheet places the mechanism beside its plans with it):
!>
!>   call fit_mechanism_view(drawing, region, room, view)   ! ГОСТ 2.302 scale that fits
!>   call draw_mechanism(sheet, drawing, view, region, force_scale, short)
!>
!> `view` says where the position frame sits on the sheet: a point p (m, the mechanism's
!> position frame) is drawn at view%point(p) = origin + scale·(q1, -q2) with q = p turned
!> counterclockwise by view%rotation (sheet mm, y down); view%direction(v) turns a vector
!> (a velocity, a force) the same way. view%drawing_scale is the ratio and its text ("1:5"),
!> view%mu_l() = 1/scale m per mm.
!>
!> Drawn (layers LINKS, JOINTS, GUIDES, FORCES, TEXT), inside a group "mechanism" whose data
!> attributes give the view (data-origin "x y" mm, data-scale mm per m, data-rotation deg,
!> data-drawing-scale): guides on the frame hatched on one side, with a gap where a frame
!> pivot off the guide lies on its line; the axes x, y of the position frame at its origin;
!> links as bars (or plates: the convex hull of their points), hydraulic cylinders and rods,
!> slider blocks; pivots with the ground symbol; joints as circles (data-joint = the joint's
!> name), centres of mass as dots (data-point); with force_scale > 0 every force of the
!> drawing as an arrow from its point (force_scale mm per N; the colour of its kind), each
!> labelled "F21 = 2043 N", and every moment as a 3/4 arc in its sense with its value. A
!> force shorter than 1 mm at that scale is not drawn: its name is returned in `short` (the
!> sheet lists it with a note). Labels are placed by the sheet (off every line, leader lines
!> where no free place is near), inside `region`.
module kinetostat_mechanism_view
  use kinetostat_kinds, only: wp, pi, rad_to_deg
  use kinetostat_format, only: short_number, full_number
  use kinetostat_labels, only: unit_word => unit_symbol
  use kinetostat_scales, only: drawing_scale_t, standard_drawing_scale, scale_number
  use kinetostat_sheet, only: sheet_t, entity_group, layer_links, layer_joints, layer_guides, layer_forces, layer_text
  use kinetostat_svg, only: coord
  use kinetostat_drawing, only: drawing_t, drawing_body_t, point_pivot, point_com, point_plain, body_bar, &
    body_block, body_cylinder, body_rod
  implicit none
  private
  public :: mechanism_view_t, fit_mechanism_view, draw_mechanism, force_colours, shortest_drawn_force, &
    mark_other_drawing

  !> Colours of the force kinds (pair, load, weight, inertia).
  character(*), parameter :: force_colours(*) = [character(len=7) :: "#d62728", "#2ca02c", "#8c564b", "#1f77b4"]
  !> The order the bodies are drawn in (later ones over earlier ones).
  integer, parameter :: body_order(*) = [body_bar, body_rod, body_cylinder, body_block]
  !> Length of the axes of the mechanism's frame on the sheet, mm.
  real(wp), parameter :: axis_length = 14.0_wp
  !> A force drawn shorter than this is listed, not drawn, mm.
  real(wp), parameter :: shortest_drawn_force = 1.0_wp
  !> Half the gap a guide leaves around a frame pivot on its line, mm.
  real(wp), parameter :: pivot_gap = 6.0_wp

  !> Where a mechanism's position frame sits on a sheet.
  type :: mechanism_view_t
    !> Turn of the position frame on the sheet, rad (counterclockwise as the sheet is seen).
    real(wp) :: rotation = 0.0_wp
    !> Sheet mm per m of the mechanism (1000 x the drawing scale's ratio).
    real(wp) :: scale = 1000.0_wp
    !> Sheet point of the position frame's origin, mm.
    real(wp) :: origin(2) = 0.0_wp
    !> The drawing scale (ГОСТ 2.302).
    type(drawing_scale_t) :: drawing_scale
  contains
    procedure :: point => view_point
    procedure :: direction => view_direction
    procedure :: mu_l
  end type mechanism_view_t

contains

  !> Sheet point (mm) of the mechanism's point p (m, position frame).
  pure function view_point(self, p) result(s)
    class(mechanism_view_t), intent(in) :: self
    real(wp), intent(in) :: p(2)
    real(wp) :: s(2)
    s = self%origin + self%scale * self%direction(p)
  end function view_point

  !> A vector of the position frame (any unit) turned onto the sheet (y down), same length.
  pure function view_direction(self, v) result(s)
    class(mechanism_view_t), intent(in) :: self
    real(wp), intent(in) :: v(2)
    real(wp) :: s(2)
    real(wp) :: q(2)
    q = turn(v, self%rotation)
    s = [q(1), -q(2)]
  end function view_direction

  !> μl: m of the mechanism per mm of the sheet.
  pure real(wp) function mu_l(self)
    class(mechanism_view_t), intent(in) :: self
    mu_l = 1.0_wp / self%scale
  end function mu_l

  !> The view of `drawing` in `region` (x0, y0, x1, y1, mm) at the largest ГОСТ 2.302 scale
  !> at which what is drawn fits with `room` mm to spare on every side (for the labels): the
  !> mechanism's points, its guides, the origin of its frame, the ground symbols and, with
  !> `force_scale` (mm per N), the force arrows drawn (1 mm and longer) and the moments'
  !> arcs; centred. `fit`, when asked, is the ratio at which the points alone would fill the
  !> region less the room (before rounding to a standard scale).
  pure subroutine fit_mechanism_view(drawing, region, room, view, fit, force_scale)
    type(drawing_t), intent(in) :: drawing
    real(wp), intent(in) :: region(4), room
    type(mechanism_view_t), intent(out) :: view
    real(wp), intent(out), optional :: fit
    !> mm per N of the force arrows (none when absent or 0).
    real(wp), intent(in), optional :: force_scale
    real(wp) :: lo(2), hi(2), ratio, box(4), arrows
    integer :: attempt
    view%rotation = drawing%view_angle
    arrows = 0.0_wp
    if (present(force_scale)) arrows = force_scale
    ! the points alone, m
    call extent(0.0_wp, 0.0_wp, box)
    lo = box(1:2)
    hi = box(3:4)
    if (all(hi - lo <= 0.0_wp)) then
      lo = 0.0_wp
      hi = 1.0_wp
    end if
    ratio = min(max(region(3) - region(1) - 2.0_wp * room, 1.0_wp) / max(hi(1) - lo(1), 1.0e-9_wp), &
      max(region(4) - region(2) - 2.0_wp * room, 1.0_wp) / max(hi(2) - lo(2), 1.0e-9_wp)) / 1000.0_wp
    if (present(fit)) fit = ratio
    ! the largest standard scale at which the whole drawing fits
    view%drawing_scale = standard_drawing_scale(ratio)
    do attempt = 1, 60
      view%scale = 1000.0_wp * view%drawing_scale%ratio
      call extent(view%scale, arrows, box)
      if (box(3) - box(1) <= region(3) - region(1) - 2.0_wp * room .and. &
        box(4) - box(2) <= region(4) - region(2) - 2.0_wp * room) exit
      view%drawing_scale = standard_drawing_scale(view%drawing_scale%ratio * (1.0_wp - 1.0e-9_wp))
    end do
    view%scale = 1000.0_wp * view%drawing_scale%ratio
    call extent(view%scale, arrows, box)
    ! centred, on the sheet's 0.01 mm grid (box: sheet mm about the frame's origin, y down)
    view%origin = [0.5_wp * (region(1) + region(3) - box(1) - box(3)), 0.5_wp * (region(2) + region(4) - box(2) - box(4))]
    view%origin = anint(view%origin * 100.0_wp) / 100.0_wp
  contains
    !> The box of the drawing at `scale` mm per m with arrows at `per_newton` mm per N,
    !> relative to the frame's origin on the sheet (x0, y0, x1, y1; with scale 0: the
    !> points' box in m, y up).
    pure subroutine extent(scale, per_newton, b)
      real(wp), intent(in) :: scale, per_newton
      real(wp), intent(out) :: b(4)
      real(wp) :: q(2), t(2), f
      integer :: i, j
      b = 0.0_wp
      do i = 1, size(drawing%points)
        q = sheet_offset(drawing%points(i)%p, scale)
        call grow(b, q)
        ! a pivot's ground symbol below it
        if (scale > 0.0_wp .and. drawing%points(i)%kind == point_pivot) call grow(b, q + [0.0_wp, 5.5_wp])
      end do
      do i = 1, size(drawing%guides)
        associate (g => drawing%guides(i))
          do j = -1, 1, 2
            call grow(b, sheet_offset(g%p + j * g%half_length * [cos(g%angle), sin(g%angle)], scale))
          end do
        end associate
      end do
      if (scale <= 0.0_wp) return
      ! the axes of the frame
      call grow(b, axis_length * direction_of([1.0_wp, 0.0_wp]))
      call grow(b, axis_length * direction_of([0.0_wp, 1.0_wp]))
      if (per_newton <= 0.0_wp) return
      do i = 1, size(drawing%forces)
        associate (fo => drawing%forces(i))
          f = hypot(fo%f(1), fo%f(2)) * per_newton
          if (f < shortest_drawn_force) cycle
          q = sheet_offset(fo%at, scale)
          t = q + per_newton * direction_of(fo%f)
          call grow(b, t)
        end associate
      end do
      do i = 1, size(drawing%moments)
        q = sheet_offset(drawing%moments(i)%at, scale)
        call grow(b, q - 6.0_wp)
        call grow(b, q + 6.0_wp)
      end do
    end subroutine extent
    !> Offset of point p (m) from the frame's origin on the sheet at `scale` (0: p turned, m).
    pure function sheet_offset(p, scale) result(q)
      real(wp), intent(in) :: p(2), scale
      real(wp) :: q(2)
      q = turn(p, view%rotation)
      if (scale > 0.0_wp) q = scale * [q(1), -q(2)]
    end function sheet_offset
    !> A vector turned onto the sheet (y down).
    pure function direction_of(v) result(q)
      real(wp), intent(in) :: v(2)
      real(wp) :: q(2)
      q = turn(v, view%rotation)
      q = [q(1), -q(2)]
    end function direction_of
    pure subroutine grow(b, q)
      real(wp), intent(inout) :: b(4)
      real(wp), intent(in) :: q(2)
      b(1:2) = min(b(1:2), q)
      b(3:4) = max(b(3:4), q)
    end subroutine grow
  end subroutine fit_mechanism_view

  !> Draw the mechanism of `drawing` on `sheet` with `view`, its labels inside `region`
  !> (x0, y0, x1, y1, mm); forces at `force_scale` mm per N (0: no forces nor moments).
  !> `short` returns the names of the forces shorter than 1 mm at that scale (not drawn).
  !> `label_size` (mm) sets every label's font size (a small drawing: A4's course sheet).
  pure subroutine draw_mechanism(sheet, drawing, view, region, force_scale, short, label_size)
    type(sheet_t), intent(inout) :: sheet
    type(drawing_t), intent(in) :: drawing
    type(mechanism_view_t), intent(in) :: view
    real(wp), intent(in) :: region(4)
    !> mm per N.
    real(wp), intent(in) :: force_scale
    !> Names of the forces not drawn (too short), comma-separated ("" when none).
    character(len=:), allocatable, intent(out) :: short
    !> Font size of the labels, mm (default: their classes' sizes).
    real(wp), intent(in), optional :: label_size
    real(wp), allocatable :: px(:), py(:), hx(:), hy(:)
    real(wp) :: q(2), t(2), origin(2), axis_tip(2, 2), u2(2)
    character(len=:), allocatable :: text
    integer :: i, j, n, pass
    short = ""
    n = size(drawing%points)
    allocate (px(n), py(n))
    do i = 1, n
      q = view%point(drawing%points(i)%p)
      px(i) = q(1)
      py(i) = q(2)
    end do
    call sheet%group("mechanism")
    call sheet%attach("data-origin", coord(view%origin(1))//" "//coord(view%origin(2)))
    call sheet%attach("data-scale", full_number(view%scale))
    call sheet%attach("data-rotation", full_number(view%rotation * rad_to_deg))
    call sheet%attach("data-drawing-scale", view%drawing_scale%text)

    ! guides (hatched on one side)
    call sheet%set_layer(layer_guides)
    do i = 1, size(drawing%guides)
      call put_guide(sheet, drawing, i, view)
    end do
    ! the axes of the mechanism's frame at its origin
    origin = view%origin
    do j = 1, 2
      t = view%direction(merge([1.0_wp, 0.0_wp], [0.0_wp, 1.0_wp], j == 1))
      axis_tip(:, j) = origin + axis_length * t
      call sheet%line(origin(1), origin(2), axis_tip(1, j), axis_tip(2, j), stroke="#555555", width=0.2_wp)
      call sheet%arrow(axis_tip(1, j) - 2.0_wp * t(1), axis_tip(2, j) - 2.0_wp * t(2), axis_tip(1, j), axis_tip(2, j), &
        "#555555", 0.2_wp, 2.0_wp)
    end do
    ! bodies in drawing order: bars through their points (the centre of mass included) and
    ! plates as the convex hull of their points; rods, and the hydraulic cylinders over them
    ! (a tube from the pivot along the axis); blocks
    call sheet%set_layer(layer_links)
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
              call sheet%polyline(hx, hy, stroke="#000000", width=2.2_wp)
              call sheet%polyline(hx, hy, stroke="#e8e8e8", width=1.4_wp)
            else
              call sheet%polygon(hx, hy, "link")
            end if
          case (body_rod)
            call axis_ends(b, b%reach(1), b%reach(2), q, t)
            call sheet%line(q(1), q(2), t(1), t(2), stroke="#000000", width=1.5_wp)
            call sheet%line(q(1), q(2), t(1), t(2), stroke="#e8e8e8", width=0.8_wp)
          case (body_cylinder)
            call axis_ends(b, 0.0_wp, b%length, q, t)
            if (hypot(t(1) - q(1), t(2) - q(2)) > 0.0_wp) then
              u2 = [q(2) - t(2), t(1) - q(1)] * 2.3_wp / hypot(t(1) - q(1), t(2) - q(2))
              call sheet%polygon([q(1) + u2(1), t(1) + u2(1), t(1) - u2(1), q(1) - u2(1)], &
                [q(2) + u2(2), t(2) + u2(2), t(2) - u2(2), q(2) - u2(2)], "link")
              call sheet%line(t(1) + 0.6_wp * u2(1), t(2) + 0.6_wp * u2(2), t(1) - 0.6_wp * u2(1), &
                t(2) - 0.6_wp * u2(2), "frame")
            end if
          case (body_block)
            call put_block(sheet, px(b%points(1)), py(b%points(1)), b%angle + view%rotation)
          case default
            continue
          end select
        end associate
      end do
    end do
    ! joints, pivots, centres of mass
    call sheet%set_layer(layer_joints)
    do i = 1, n
      select case (drawing%points(i)%kind)
      case (point_pivot)
        call put_pivot(sheet, px(i), py(i))
        call sheet%circle(px(i), py(i), 1.1_wp, "joint")
        call sheet%attach("data-joint", trim(drawing%points(i)%name))
      case (point_com)
        call sheet%circle(px(i), py(i), 0.9_wp, "com")
        call sheet%attach("data-point", trim(drawing%points(i)%name))
      case (point_plain)
        cycle
      case default
        call sheet%circle(px(i), py(i), 1.1_wp, "joint")
        call sheet%attach("data-joint", trim(drawing%points(i)%name))
      end select
    end do
    ! forces: arrows from their points, one scale; moments: arcs around their points
    call sheet%set_layer(layer_forces)
    if (force_scale > 0.0_wp) then
      do i = 1, size(drawing%forces)
        associate (f => drawing%forces(i))
          if (hypot(f%f(1), f%f(2)) == 0.0_wp) cycle
          if (hypot(f%f(1), f%f(2)) * force_scale < shortest_drawn_force) then
            if (len(short) > 0) short = short//", "
            short = short//trim(f%name)
            cycle
          end if
          call force_ends(f%at, f%f, q, t)
          call sheet%arrow(q(1), q(2), t(1), t(2), force_colours(f%kind), 0.45_wp, 2.4_wp)
        end associate
      end do
      do i = 1, size(drawing%moments)
        call put_moment(sheet, drawing, i, view)
      end do
    end if

    ! labels, none over another nor over a line: point names, link numbers, the axes, force
    ! values beside their arrows, moments beside their arcs
    call sheet%set_layer(layer_text)
    do i = 1, n
      if (drawing%points(i)%kind == point_plain) cycle
      call sheet%place_label(trim(drawing%points(i)%name), "label", px(i), py(i), 0.75_wp * pi, region, size=label_size)
    end do
    do i = 1, size(drawing%bodies)
      associate (b => drawing%bodies(i))
        if (size(b%points) == 0) cycle
        if (b%kind == body_block) then
          q = [px(b%points(1)), py(b%points(1))]
        else if (size(b%points) >= 2) then
          q = [sum(px(b%points)), sum(py(b%points))] / size(b%points)
        else
          cycle
        end if
        call sheet%place_label(trim(b%name), "label", q(1), q(2), 0.25_wp * pi, region, italic=.true., size=label_size)
      end associate
    end do
    do j = 1, 2
      call sheet%place_label(merge("x", "y", j == 1), "label", axis_tip(1, j), axis_tip(2, j), &
        atan2(axis_tip(2, j) - origin(2), axis_tip(1, j) - origin(1)), region, tail=origin, italic=.true., size=label_size)
    end do
    if (force_scale > 0.0_wp) then
      do i = 1, size(drawing%forces)
        associate (f => drawing%forces(i))
          if (hypot(f%f(1), f%f(2)) * force_scale < shortest_drawn_force) cycle
          call force_ends(f%at, f%f, q, t)
          text = trim(f%name)//" = "//short_number(hypot(f%f(1), f%f(2)))//" "//unit_word("N", sheet%lang)
          call sheet%place_label(text, "num", t(1), t(2), atan2(t(2) - q(2), t(1) - q(1)), region, tail=q, &
            colour=force_colours(f%kind), size=label_size)
        end associate
      end do
      do i = 1, size(drawing%moments)
        associate (m => drawing%moments(i))
          if (m%value == 0.0_wp) cycle
          q = view%point(m%at)
          text = trim(m%name)//" = "//short_number(abs(m%value))//" "//unit_word("N*m", sheet%lang)
          call sheet%place_label(text, "num", q(1) + 5.0_wp, q(2) + 5.0_wp, 0.25_wp * pi, region, &
            colour=force_colours(m%kind), size=label_size)
        end associate
      end do
    end if
    call sheet%end_group()
  contains
    !> Sheet points (mm) of the axis of a cylinder or rod `b` at s0 and s1 m from its anchor.
    pure subroutine axis_ends(b, s0, s1, e0, e1)
      type(drawing_body_t), intent(in) :: b
      real(wp), intent(in) :: s0, s1
      real(wp), intent(out) :: e0(2), e1(2)
      e0 = view%point(b%anchor + s0 * [cos(b%angle), sin(b%angle)])
      e1 = view%point(b%anchor + s1 * [cos(b%angle), sin(b%angle)])
    end subroutine axis_ends
    !> Tail and tip (sheet, mm) of the arrow of force `f` (N) at `at` (m).
    pure subroutine force_ends(at, f, tail, tip)
      real(wp), intent(in) :: at(2), f(2)
      real(wp), intent(out) :: tail(2), tip(2)
      tail = view%point(at)
      tip = tail + force_scale * view%direction(f)
    end subroutine force_ends
  end subroutine draw_mechanism

  !> Renames the marks of a drawing of draw_mechanism that is not the mechanism's (a link or
  !> a group drawn apart), the sheet's entities from `first` on: its group's class becomes
  !> `group_class`, its marks data-joint and data-point become data-<mark>-joint and
  !> data-<mark>-point (machine checks read the joints of the mechanism's drawing).
  pure subroutine mark_other_drawing(sheet, first, group_class, mark)
    type(sheet_t), intent(inout) :: sheet
    !> The drawing's first entity.
    integer, intent(in) :: first
    !> The class of its group ("input-link").
    character(*), intent(in) :: group_class
    !> The word in its marks ("link").
    character(*), intent(in) :: mark
    integer :: j
    do j = first, sheet%count
      associate (item => sheet%items(j))
        if (item%kind == entity_group) item%class = group_class
        if (.not. allocated(item%data_names)) cycle
        where (item%data_names == "data-joint") item%data_names = "data-"//mark//"-joint"
        where (item%data_names == "data-point") item%data_names = "data-"//mark//"-point"
      end associate
    end do
  end subroutine mark_other_drawing

  !> Vector `v` turned counterclockwise by `angle` (rad).
  pure function turn(v, angle) result(w)
    real(wp), intent(in) :: v(2), angle
    real(wp) :: w(2)
    w = [cos(angle) * v(1) - sin(angle) * v(2), sin(angle) * v(1) + cos(angle) * v(2)]
  end function turn

  !> Convex hull of the points (x, y), counterclockwise in sheet coordinates (monotone
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
    polygon_area = 0.0_wp
    if (size(x) < 3) return
    polygon_area = 0.5_wp * abs(sum(x * cshift(y, 1) - cshift(x, 1) * y))
  end function polygon_area

  !> The ground symbol of a frame pivot at (x, y): a triangle below it on a hatched base.
  pure subroutine put_pivot(sheet, x, y)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: x, y
    integer :: i
    call sheet%polygon([x, x - 2.4_wp, x + 2.4_wp], [y, y + 4.0_wp, y + 4.0_wp], "link")
    call sheet%line(x - 4.0_wp, y + 4.0_wp, x + 4.0_wp, y + 4.0_wp, "frame")
    do i = 0, 4
      call sheet%line(x - 3.5_wp + 1.8_wp * i, y + 4.0_wp, x - 4.7_wp + 1.8_wp * i, y + 5.5_wp, "hatch")
    end do
  end subroutine put_pivot

  !> Guide `i` of the drawing: a line with hatching on one side, offset by half a block from
  !> its sliders' path, with a gap around every frame pivot that lies on that path but not
  !> at the guide's own point (a crank's bearing is not on the ram's guide).
  pure subroutine put_guide(sheet, drawing, i, view)
    type(sheet_t), intent(inout) :: sheet
    type(drawing_t), intent(in) :: drawing
    integer, intent(in) :: i
    type(mechanism_view_t), intent(in) :: view
    real(wp) :: a(2), b(2), u(2), nrm(2), length, s, t0, t1, tp, d(2)
    real(wp), allocatable :: cuts(:, :)
    integer :: j, k, count
    associate (g => drawing%guides(i))
      a = view%point(g%p - g%half_length * [cos(g%angle), sin(g%angle)])
      b = view%point(g%p + g%half_length * [cos(g%angle), sin(g%angle)])
    end associate
    length = hypot(b(1) - a(1), b(2) - a(2))
    if (length <= 0.0_wp) return
    u = (b - a) / length
    nrm = [-u(2), u(1)]
    ! the gaps: frame pivots on the sliders' path (within 3 mm of it on the sheet)
    allocate (cuts(2, 0))
    do j = 1, size(drawing%points)
      if (drawing%points(j)%kind /= point_pivot) cycle
      d = view%point(drawing%points(j)%p) - a
      tp = dot_product(d, u)
      if (abs(dot_product(d, nrm)) > 3.0_wp .or. tp < -pivot_gap .or. tp > length + pivot_gap) cycle
      cuts = reshape([cuts, [tp - pivot_gap, tp + pivot_gap]], [2, size(cuts, 2) + 1])
    end do
    ! hatch on the side away from the blocks: offset the line by half a block height
    a = a + 2.6_wp * nrm
    b = b + 2.6_wp * nrm
    t0 = 0.0_wp
    do
      ! the next piece: from t0 to the first gap after it
      t1 = length
      do k = 1, size(cuts, 2)
        if (cuts(1, k) <= t0 .and. cuts(2, k) > t0) t0 = cuts(2, k)
      end do
      do k = 1, size(cuts, 2)
        if (cuts(1, k) > t0) t1 = min(t1, cuts(1, k))
      end do
      if (t1 - t0 > 0.5_wp) then
        call sheet%line(a(1) + t0 * u(1), a(2) + t0 * u(2), a(1) + t1 * u(1), a(2) + t1 * u(2), "frame")
        count = int((t1 - t0) / 2.0_wp)
        do j = 0, count
          s = t0 + 1.0_wp + 2.0_wp * j
          if (s > t1) exit
          call sheet%line(a(1) + s * u(1), a(2) + s * u(2), a(1) + (s - 1.2_wp) * u(1) + 1.5_wp * nrm(1), &
            a(2) + (s - 1.2_wp) * u(2) + 1.5_wp * nrm(2), "hatch")
        end do
      end if
      if (t1 >= length) exit
      t0 = t1
    end do
  end subroutine put_guide

  !> A slider block (8 x 5 mm on the sheet) at (x, y), its long side along `angle` (rad,
  !> counterclockwise on the sheet).
  pure subroutine put_block(sheet, x, y, angle)
    type(sheet_t), intent(inout) :: sheet
    real(wp), intent(in) :: x, y, angle
    real(wp) :: u(2), v(2)
    u = [cos(angle), -sin(angle)] * 4.0_wp
    v = [sin(angle), cos(angle)] * 2.5_wp
    call sheet%polygon([x - u(1) - v(1), x + u(1) - v(1), x + u(1) + v(1), x - u(1) + v(1)], &
      [y - u(2) - v(2), y + u(2) - v(2), y + u(2) + v(2), y - u(2) + v(2)], "link")
  end subroutine put_block

  !> Moment `i` of the drawing: a 3/4 arc of radius 5 mm about its point, the arrowhead
  !> showing its sense (its label is placed with the others).
  pure subroutine put_moment(sheet, drawing, i, view)
    type(sheet_t), intent(inout) :: sheet
    type(drawing_t), intent(in) :: drawing
    integer, intent(in) :: i
    type(mechanism_view_t), intent(in) :: view
    real(wp), parameter :: r = 5.0_wp
    real(wp) :: c(2), a1, sense, e(2), tan_dir(2)
    associate (m => drawing%moments(i))
      if (m%value == 0.0_wp) return
      c = view%point(m%at)
      sense = sign(1.0_wp, m%value)
      ! from 200 deg, sweeping 270 deg in the moment's sense (counterclockwise on the sheet = +)
      call sheet%arc(c(1), c(2), r, 200.0_wp, sense * 270.0_wp, stroke=force_colours(m%kind), width=0.45_wp)
      a1 = (200.0_wp + sense * 270.0_wp) * pi / 180.0_wp
      e = [c(1) + r * cos(a1), c(2) - r * sin(a1)]
      tan_dir = sense * [-sin(a1), -cos(a1)]
      call sheet%arrow(e(1) - 2.2_wp * tan_dir(1), e(2) - 2.2_wp * tan_dir(2), e(1), e(2), force_colours(m%kind), &
        0.45_wp, 2.2_wp)
    end associate
  end subroutine put_moment

end module kinetostat_mechanism_view
