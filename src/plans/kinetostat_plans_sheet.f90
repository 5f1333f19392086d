!> The plans sheet's geometry: where each drawing goes on the sheet and at which scale, and
!> what a teacher reads off it. One sheet, A2 landscape (594 x 420 mm) in the ГОСТ 2.301
!> frame: the mechanism at a ГОСТ 2.302 scale (mu_l, kinetostat_mechanism_view), the plans of
!> velocities and accelerations at mu_v, mu_a, Zhukovsky's lever (its plan at mu_v of its
!> own, its loads at mu_F) with the table of its loads, the force polygons of the units of the
!> structure (each at its mu_F; an input link's with the link and its forces' arms at a larger
!> scale of its own), the values table, the title block. Everything is drawn in the mechanism
!> drawing's frame (the position frame turned by the sheet's rotation, gravity down the
!> sheet): a vector v of the position frame is drawn as view%direction(v).
!>
!> The scales are the drawing scales a student would take: 1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6 or 8
!> times a power of ten units per mm. With them the sheet compares the balancing effort
!> from the lever with the one from the force polygons the way a teacher checks a student's
!> sheet (compare_efforts).
module kinetostat_plans_sheet
  use kinetostat_kinds, only: wp, pi
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, drawing_force_t, force_pair, point_pivot
  use kinetostat_scales, only: round_scale
  use kinetostat_sheet, only: paper_t, iso_paper, course_paper
  use kinetostat_mechanism_view, only: mechanism_view_t, fit_mechanism_view
  use kinetostat_plans_apart, only: group_apart_drawing, row_pitch
  use kinetostat_plans_base, only: plans_t, lever_load_t, plan_vector_t, plan_equation_t, load_moment, cross, link_index, &
    owner, pivot_of, guide_link, component_normal, component_tangential, component_reaction
  implicit none
  private
  public :: plans_sheet_t, plans_sheet, turn, chain_tips, polygon_tips, panel_inner, lever_arrow, panel_head, &
    group_text, input_link_drawing, fit_kinematic_plans, plan_margin, plan_inner

  !> Room kept around a drawing in its panel for its labels and arrows, mm (a plan of
  !> velocities or accelerations: as much on a large panel, less on a small one: plan_margin).
  real(wp), parameter :: margin = 10.0_wp
  !> A plan's labels' height (class "label"), mm: a plan keeps 1.5 of it around it at the least.
  real(wp), parameter :: label_height = 2.8_wp
  !> A plan's notes at its foot (what is at the pole, what is too short to draw): their
  !> largest and least font sizes (ГОСТ 2.304's smallest), mm, and the pitch of their lines
  !> in font sizes (a line's subscripts and superscripts reach 1.4 of it).
  real(wp), parameter, public :: note_size = 2.6_wp, least_note_size = 1.8_wp, note_pitch = 1.45_wp
  !> The lever's largest load arrow, mm.
  real(wp), parameter :: lever_arrow = 24.0_wp
  !> A panel's heading band at its top and its scale line at its bottom, mm.
  real(wp), parameter :: panel_head = 8.0_wp, panel_foot = 9.0_wp
  !> The smallest box (width, height) a group drawn apart gets, else it is not drawn, mm.
  real(wp), parameter :: min_apart(2) = [36.0_wp, 36.0_wp]
  !> The mechanism's longest force arrow on the course sheet, mm.
  real(wp), parameter :: longest_arrow = 28.0_wp

  !> The sheet's panels (x0, y0, x1, y1; mm) and scales.
  type :: plans_sheet_t
    !> The paper: A2 landscape.
    type(paper_t) :: paper
    !> The panels: the mechanism, the two plans, the lever's drawing and its table of loads,
    !> the force polygons, the values table, the balancing effort's results.
    real(wp) :: mechanism(4) = 0.0_wp, velocity(4) = 0.0_wp, acceleration(4) = 0.0_wp, lever(4) = 0.0_wp, &
      lever_table(4) = 0.0_wp, polygons(4) = 0.0_wp, values(4) = 0.0_wp, results(4) = 0.0_wp
    !> Where the mechanism is drawn (its ГОСТ 2.302 scale; mu_l = view%mu_l()).
    type(mechanism_view_t) :: view
    !> Lengths, m/mm; velocities (the plan and the lever's), (m/s)/mm; accelerations,
    !> (m/s^2)/mm; the lever's loads, N/mm.
    real(wp) :: mu_l = 1.0_wp, mu_v = 1.0_wp, mu_a = 1.0_wp, mu_lever = 1.0_wp, mu_force = 1.0_wp
    !> The course sheet: the mechanism's forces, N/mm (0: the mechanism without its forces).
    real(wp) :: mu_mechanism_force = 0.0_wp
    !> The poles of the plans and of the lever on the sheet, mm.
    real(wp) :: pole_v(2) = 0.0_wp, pole_a(2) = 0.0_wp, pole_lever(2) = 0.0_wp
    !> Every unit's polygon: its cell in the polygons' panel (x0, y0, x1, y1) and its scale,
    !> N/mm; an input link's cell also shows the link with its forces and their arms (the
    !> left part of the cell, `link_boxes`) at a larger scale of its own, mu_link (m/mm; 0:
    !> none).
    real(wp), allocatable :: cells(:, :), mu_f(:), link_boxes(:, :), mu_link(:)
    !> An input link's drawing: its view (a ГОСТ 2.302 scale; the link shifted to its pivot)
    !> and the scale of its forces' arrows, mm per N.
    type(mechanism_view_t), allocatable :: link_views(:)
    real(wp), allocatable :: link_force_scale(:)
    !> The sheet's rotation against the position frame, rad.
    real(wp) :: rotation = 0.0_wp
    !> The course sheet "kinetostatics": the mechanism with its forces, no plans of velocities
    !> and accelerations (the kinematics sheet's), each Assur group drawn apart in the left
    !> part of its polygon's cell (its box in `link_boxes`, its view in `link_views`, mu_link
    !> > 0), the table of its arms at `arms_at` (x, y of the first row) under its polygon.
    logical :: groups_apart = .false.
    real(wp), allocatable :: arms_at(:, :)
    !> The balancing effort as measured on the sheet: from the lever and from the force
    !> polygons (N*m or N), their difference in % of the larger; `compared` false when the
    !> sheet gives no such comparison (the lever not drawn, no input link's polygon).
    logical :: compared = .false.
    real(wp) :: effort_lever = 0.0_wp, effort_polygon = 0.0_wp, difference = 0.0_wp
  end type plans_sheet_t

contains

  !> The geometry of the plans sheet of `plans` (the drawing of the same step gives the
  !> mechanism's size and the sheet's rotation); on A2 landscape, or on `paper_name`
  !> landscape (the course's sheets: A1 by default), its panels grown with the paper.
  pure subroutine plans_sheet(topo, drawing, plans, sheet, paper_name)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    !> "A1" .. "A4" (default "A2").
    character(*), intent(in), optional :: paper_name
    type(plans_t), intent(in) :: plans
    type(plans_sheet_t), intent(out) :: sheet
    real(wp), allocatable :: pts(:, :), tips(:, :)
    real(wp) :: fmax, r, b(4), cell(4), quarter, fx, fy, top, bottom, row, fm, area(4), side, arrow
    type(mechanism_view_t) :: trial
    type(drawing_t) :: link
    integer :: i, e, n, columns, rows, pivot, table_rows
    character(len=16), allocatable :: names(:)
    integer, allocatable :: inner(:)
    r = drawing%view_angle
    quarter = 0.5_wp * pi
    sheet%rotation = r
    ! the panels on A2 landscape, inside the frame (x 20 .. 589, y 5 .. 415): a header band,
    ! the mechanism and the two plans, the lever with its table and the polygons, the values
    ! table left of the title block
    sheet%paper = iso_paper("A2", .true.)
    ! (A4 portrait, ГОСТ 2.301: its title block stands along the short side only)
    if (present(paper_name)) sheet%paper = course_paper(paper_name)
    ! the course sheet (a paper named) draws the groups apart; --format plans does not
    sheet%groups_apart = present(paper_name)
    b = sheet%paper%inside()
    if (sheet%groups_apart .and. .not. sheet%paper%landscape) then
      ! A4 portrait (inside the frame x 20 .. 205, y 5 .. 292): across the top the mechanism
      ! with its forces (three fifths of the width) and, right of it, Zhukovsky's lever over
      ! the balancing effort; under them the polygons with the groups apart in two columns,
      ! the lever's table of loads in the cell after the last polygon (its rows 2.6 mm apart,
      ! closer where they would not fit). The mechanism at the largest ГОСТ 2.302 scale its
      ! points fit at, its forces at the round mu_F whose arrows keep inside its panel at it.
      top = b(2) + 21.0_wp
      bottom = b(4) - 57.0_wp
      row = 92.0_wp
      sheet%mechanism = [b(1) + 2.0_wp, top, b(1) + 2.0_wp + 0.6_wp * (b(3) - b(1) - 4.0_wp), top + row]
      ! (the balancing effort's panel as high as its lines: P_bal and M, the two read off,
      ! the flywheel's and the friction's shares)
      sheet%lever = [sheet%mechanism(3) + 2.0_wp, top, b(3) - 2.0_wp, top + row - 2.0_wp - (panel_head + 5.0_wp + &
        3.2_wp * (merge(2, 0, plans%lever_known) + merge(1, 0, plans%lever_flywheel) + merge(1, 0, plans%lever_friction)))]
      sheet%results = [sheet%lever(1), sheet%lever(4) + 2.0_wp, b(3) - 2.0_wp, top + row]
      sheet%polygons = [b(1) + 2.0_wp, top + row + 2.0_wp, b(3) - 2.0_wp, bottom]
      area = panel_inner(sheet%mechanism) - [0.0_wp, 0.0_wp, 0.0_wp, 4.5_wp]
      side = min(area(3) - area(1), area(4) - area(2))
      call fit_mechanism_view(drawing, area, 0.08_wp * side, sheet%view)
      fm = 0.0_wp
      do i = 1, size(drawing%forces)
        fm = max(fm, norm2(drawing%forces(i)%f))
      end do
      if (fm > 0.0_wp) then
        ! the longest arrow 15 % of the panel's side, shorter until the drawing keeps its scale
        arrow = 0.15_wp * side
        do
          sheet%mu_mechanism_force = round_scale(fm, arrow)
          call fit_mechanism_view(drawing, area, 2.0_wp, trial, force_scale=1.0_wp / sheet%mu_mechanism_force)
          if (trial%drawing_scale%ratio >= sheet%view%drawing_scale%ratio * (1.0_wp - 1.0e-9_wp) .or. arrow < 2.0_wp) exit
          arrow = 0.8_wp * arrow
        end do
        sheet%view = trial
      end if
    else if (sheet%groups_apart) then
      ! the course sheet's panels: across the top the mechanism with its forces, Zhukovsky's
      ! lever and its table of loads; under them the force polygons with the groups apart,
      ! across the sheet down to the title block; the balancing effort left of the title
      ! block. The mechanism at a ГОСТ 2.302 scale with its forces at a round mu_F.
      top = b(2) + 21.0_wp
      bottom = b(4) - 57.0_wp
      ! the top row tall enough for the lever's table (its rows 2.6 mm apart at the least), at
      ! most half the room
      row = 0.38_wp * (bottom - top)
      if (plans%lever_known .and. b(3) - b(1) > 287.0_wp) row = min(max(row, panel_head + 8.0_wp + 2.6_wp * &
        (size(plans%loads) + 1)), &
        0.5_wp * (bottom - top))
      sheet%mechanism = [b(1) + 2.0_wp, top, b(1) + 2.0_wp + 0.55_wp * (b(3) - b(1) - 98.0_wp), top + row]
      sheet%lever = [sheet%mechanism(3) + 2.0_wp, top, b(3) - 94.0_wp, top + row]
      sheet%lever_table = [sheet%lever(3), top, b(3) - 2.0_wp, top + row]
      sheet%polygons = [b(1) + 2.0_wp, top + row + 2.0_wp, b(3) - 2.0_wp, bottom]
      sheet%results = [b(1) + 2.0_wp, bottom + 2.0_wp, b(3) - 187.0_wp, b(4) - 1.0_wp]
      fm = 0.0_wp
      do i = 1, size(drawing%forces)
        fm = max(fm, norm2(drawing%forces(i)%f))
      end do
      if (fm > 0.0_wp) then
        ! the longest arrow and the room around the drawing in proportion on a small sheet
        ! (its foot has the scales and the forces too short to draw, two lines)
        associate (area => panel_inner(sheet%mechanism) - [0.0_wp, 0.0_wp, 0.0_wp, 4.5_wp])
          associate (side => min(area(3) - area(1), area(4) - area(2)))
            sheet%mu_mechanism_force = round_scale(fm, min(longest_arrow, 0.15_wp * side))
            call fit_mechanism_view(drawing, area, min(8.0_wp, 0.08_wp * side), sheet%view, &
              force_scale=1.0_wp / sheet%mu_mechanism_force)
          end associate
        end associate
      else
        call fit_mechanism_view(drawing, panel_inner(sheet%mechanism), 6.0_wp, sheet%view)
      end if
    else
      ! the panels' sizes grow (or shrink) with the paper from A2's (569 x 410 mm inside the
      ! frame); the header band, the title block's 57 mm and the tables' widths stay
      fx = (b(3) - b(1)) / 569.0_wp
      fy = (b(4) - b(2) - 78.0_wp) / 332.0_wp
      sheet%mechanism = [b(1) + 2.0_wp, b(2) + 21.0_wp, b(1) + 2.0_wp + 188.0_wp * fx, b(2) + 21.0_wp + 150.0_wp * fy]
      sheet%velocity = [sheet%mechanism(3) + 2.0_wp, sheet%mechanism(2), sheet%mechanism(3) + 2.0_wp + 188.0_wp * fx, &
        sheet%mechanism(4)]
      sheet%acceleration = [sheet%velocity(3) + 2.0_wp, sheet%mechanism(2), b(3) - 2.0_wp, sheet%mechanism(4)]
      sheet%lever = [b(1) + 2.0_wp, sheet%mechanism(4) + 2.0_wp, b(1) + 2.0_wp + 150.0_wp * fx, b(4) - 57.0_wp]
      sheet%lever_table = [sheet%lever(3), sheet%lever(2), sheet%lever(3) + 92.0_wp, sheet%lever(4)]
      sheet%polygons = [sheet%lever_table(3) + 2.0_wp, sheet%lever(2), b(3) - 2.0_wp, sheet%lever(4)]
      sheet%values = [b(1) + 2.0_wp, sheet%lever(4) + 2.0_wp, b(3) - 300.0_wp, b(4) - 1.0_wp]
      sheet%results = [sheet%values(3) + 2.0_wp, sheet%values(2), b(3) - 187.0_wp, sheet%values(4)]
      ! the mechanism at a ГОСТ 2.302 scale
      call fit_mechanism_view(drawing, panel_inner(sheet%mechanism), 6.0_wp, sheet%view)
      ! the plans: the images and the corners of the equations' chains
      call fit_noted_plan(plans%velocities, plans%velocity_equations, r, plan_inner(sheet%velocity), sheet%mu_v, &
        sheet%pole_v)
      call fit_noted_plan(plans%accelerations, plans%equations, r, plan_inner(sheet%acceleration), sheet%mu_a, &
        sheet%pole_a)
    end if
    sheet%mu_l = sheet%view%mu_l()
    ! the lever: the plan turned by 90 deg more, the images of the loads' points; room for
    ! the load arrows around it
    allocate (pts(2, 0))
    do i = 1, size(plans%velocities)
      pts = add(pts, turn(plans%velocities(i)%v, r + quarter))
    end do
    fmax = 0.0_wp
    if (plans%lever_known) then
      do i = 1, size(plans%loads)
        pts = add(pts, turn(plans%loads(i)%at, r + quarter))
        if (plans%loads(i)%pair) pts = add(pts, turn(plans%loads(i)%at2, r + quarter))
        fmax = max(fmax, norm2(plans%loads(i)%f))
      end do
      fmax = max(fmax, norm2(plans%balancing%f))
    end if
    if (sheet%groups_apart) then
      ! (the course sheet: the lever as large as its panel allows, to be read off - lever_fit)
      call lever_fit(plans, r, sheet%lever, sheet%mu_lever, sheet%pole_lever, sheet%mu_force)
    else
      call fit_plan(pts, panel_inner(sheet%lever) + 0.6_wp * [lever_arrow, lever_arrow, -lever_arrow, -lever_arrow], &
        sheet%mu_lever, sheet%pole_lever)
      sheet%mu_force = round_scale(fmax, lever_arrow)
    end if
    ! the polygons: a grid of cells, each polygon at its own scale; an input link's cell
    ! with the link drawn in its left part
    n = size(plans%group_polygons)
    allocate (sheet%cells(4, n), sheet%mu_f(n), sheet%link_boxes(4, n), sheet%mu_link(n), sheet%link_views(n), &
      sheet%link_force_scale(n), sheet%arms_at(2, n))
    sheet%arms_at = 0.0_wp
    sheet%link_force_scale = 0.0_wp
    sheet%link_boxes = 0.0_wp
    sheet%mu_link = 0.0_wp
    columns = max(1, min(n, 3))
    rows = max(1, (n + columns - 1) / columns)
    ! (A4 portrait: two columns, the lever's table in the cell after the last polygon)
    if (.not. sheet%paper%landscape) then
      columns = 2
      rows = (n + 2) / 2
    end if
    b = panel_inner(sheet%polygons)
    ! (the course sheet's polygons panel has no scale line at its foot: its cells go down)
    if (sheet%groups_apart) b(4) = sheet%polygons(4) - 2.0_wp
    if (.not. sheet%paper%landscape) then
      associate (w => (b(3) - b(1)) / columns, h => (b(4) - b(2)) / rows)
        sheet%lever_table = [b(1) + w * modulo(n, columns) + 1.0_wp, b(2) + h * (n / columns) + 1.0_wp, &
          b(1) + w * (modulo(n, columns) + 1) - 1.0_wp, b(2) + h * (n / columns + 1)]
      end associate
    end if
    do e = 1, n
      associate (w => (b(3) - b(1)) / columns, h => (b(4) - b(2)) / rows)
        sheet%cells(:, e) = [b(1) + w * modulo(e - 1, columns), b(2) + h * ((e - 1) / columns), &
          b(1) + w * (modulo(e - 1, columns) + 1), b(2) + h * ((e - 1) / columns + 1)]
      end associate
      ! the cell: its caption above, its scale below
      cell = sheet%cells(:, e) + [1.0_wp, 5.0_wp, -1.0_wp, -5.0_wp]
      if (plans%group_polygons(e)%input) then
        call input_link_drawing(drawing, plans, e, link, pivot)
        if (pivot > 0) then
          sheet%link_boxes(:, e) = [cell(1), cell(2), cell(1) + 0.55_wp * (cell(3) - cell(1)), cell(4)]
          call fit_link_view(sheet, e, link, sheet%link_boxes(:, e) + [0.0_wp, 4.0_wp, 0.0_wp, 0.0_wp], 3.0_wp)
          cell(1) = sheet%link_boxes(3, e)
        end if
      else if (sheet%groups_apart) then
        ! the group apart: the left part of the cell at its full height; its arms' table under
        ! the polygon (the right part); not when the cell is too small for it
        call group_apart_drawing(drawing, plans, e, link, names, inner)
        ! (A4 portrait: three fifths of the cell, its polygon beside it needs less)
        sheet%link_boxes(:, e) = [cell(1), cell(2) + 4.0_wp, cell(1) + merge(0.5_wp, 0.6_wp, sheet%paper%landscape) * &
          (cell(3) - cell(1)), cell(4)]
        ! (the arms' table's rows: each force and couple, a heading and a result an equation)
        table_rows = size(link%forces) + size(link%moments) + 2 * max(count(inner > 0), 1) + 1
        if (sheet%link_boxes(3, e) - sheet%link_boxes(1, e) < min_apart(1) .or. &
          sheet%link_boxes(4, e) - sheet%link_boxes(2, e) < min_apart(2)) then
          sheet%link_boxes(:, e) = 0.0_wp
        else
          call fit_link_view(sheet, e, link, sheet%link_boxes(:, e), 4.0_wp)
          cell(1) = sheet%link_boxes(3, e) + 1.0_wp
          ! the arms' table when the polygon keeps half the cell's height (A4: the arms are
          ! drawn and named, their table left out)
          if (row_pitch * table_rows <= 0.5_wp * (cell(4) - cell(2))) then
            cell(4) = cell(4) - row_pitch * table_rows
            sheet%arms_at(:, e) = [cell(1), cell(4) + row_pitch]
          end if
        end if
      end if
      call polygon_tips(plans%group_polygons(e)%vectors, tips)
      do i = 1, size(tips, 2)
        tips(:, i) = turn(tips(:, i), r)
      end do
      sheet%mu_f(e) = fit_scale(tips, cell, .false.)
    end do
    call compare_efforts(topo, drawing, plans, sheet)
  end subroutine plans_sheet

  !> The drawing of link (or group) `e` apart with its forces: the force scale that draws
  !> its largest force a quarter of the smaller side of its box link_boxes(:, e), its view
  !> fitted into `frame` with `margin` mm around, and its length scale.
  pure subroutine fit_link_view(sheet, e, link, frame, margin)
    type(plans_sheet_t), intent(inout) :: sheet
    integer, intent(in) :: e
    !> The link's drawing with its forces.
    type(drawing_t), intent(in) :: link
    !> Where its view goes, mm (x1, y1, x2, y2).
    real(wp), intent(in) :: frame(4), margin
    real(wp) :: fmax
    integer :: i
    fmax = 0.0_wp
    do i = 1, size(link%forces)
      fmax = max(fmax, norm2(link%forces(i)%f))
    end do
    associate (box => sheet%link_boxes(:, e))
      sheet%link_force_scale(e) = 0.25_wp * min(box(3) - box(1), box(4) - box(2)) / max(fmax, tiny(1.0_wp))
    end associate
    call fit_mechanism_view(link, frame, margin, sheet%link_views(e), force_scale=sheet%link_force_scale(e))
    sheet%mu_link(e) = sheet%link_views(e)%mu_l()
  end subroutine fit_link_view

  !> Unit t's links as its polygon names them ("2,3").
  pure function group_text(plans, t) result(text)
    type(plans_t), intent(in) :: plans
    integer, intent(in) :: t
    character(len=16) :: text
    integer :: q
    text = ""
    do q = 1, size(plans%groups(t)%names)
      if (q > 1) text = trim(text)//","
      text = trim(text)//trim(plans%groups(t)%names(q))
    end do
  end function group_text

  !> The points with one more.
  pure function add(pts, p) result(more)
    real(wp), intent(in) :: pts(:, :), p(2)
    real(wp), allocatable :: more(:, :)
    allocate (more(2, size(pts, 2) + 1))
    more(:, 1:size(pts, 2)) = pts
    more(:, size(pts, 2) + 1) = p
  end function add

  !> The scale (units per mm, a round scale) at which the points (the origin with them when
  !> `pole`) fit into the box (x0, y0, x1, y1, mm) less its margins.
  pure real(wp) function fit_scale(pts, box, pole, room)
    real(wp), intent(in) :: pts(:, :), box(4)
    logical, intent(in) :: pole
    !> The margins, mm (default: margin).
    real(wp), intent(in), optional :: room
    real(wp) :: lo(2), hi(2), m
    m = margin
    if (present(room)) m = room
    fit_scale = 1.0_wp
    if (size(pts, 2) == 0) return
    lo = minval(pts, 2)
    hi = maxval(pts, 2)
    if (pole) then
      lo = min(lo, 0.0_wp)
      hi = max(hi, 0.0_wp)
    end if
    if (all(hi - lo <= 0.0_wp)) return
    fit_scale = max(round_scale(hi(1) - lo(1), max(box(3) - box(1) - 2.0_wp * m, 1.0_wp)), &
      round_scale(hi(2) - lo(2), max(box(4) - box(2) - 2.0_wp * m, 1.0_wp)))
  end function fit_scale

  !> The points a plan must show, turned by `r` (rad): its images and every corner of its
  !> equations' chains.
  pure function turned_plan_points(images, equations, r) result(all)
    type(plan_vector_t), intent(in) :: images(:)
    type(plan_equation_t), intent(in) :: equations(:)
    real(wp), intent(in) :: r
    real(wp), allocatable :: all(:, :), corners(:, :)
    integer :: q, t
    allocate (all(2, 0))
    do q = 1, size(images)
      all = add(all, turn(images(q)%v, r))
    end do
    do q = 1, size(equations)
      call chain_tips(equations(q), images, corners)
      do t = 1, size(corners, 2)
        all = add(all, turn(corners(:, t), r))
      end do
    end do
  end function turned_plan_points

  !> The geometry of the plans of velocities and accelerations alone, in the panels
  !> `velocity` and `acceleration` (x0, y0, x1, y1, mm) of another sheet (the course's
  !> kinematics sheet) whose mechanism is drawn with `view`: the plans in its frame.
  pure subroutine fit_kinematic_plans(view, plans, velocity, acceleration, geo)
    type(mechanism_view_t), intent(in) :: view
    type(plans_t), intent(in) :: plans
    real(wp), intent(in) :: velocity(4), acceleration(4)
    type(plans_sheet_t), intent(out) :: geo
    geo%view = view
    geo%rotation = view%rotation
    geo%velocity = velocity
    geo%acceleration = acceleration
    call fit_noted_plan(plans%velocities, plans%velocity_equations, geo%rotation, plan_inner(velocity), geo%mu_v, &
      geo%pole_v)
    call fit_noted_plan(plans%accelerations, plans%equations, geo%rotation, plan_inner(acceleration), geo%mu_a, &
      geo%pole_a)
  end subroutine fit_kinematic_plans

  !> A plan of velocities or accelerations in `area` (a panel's drawing area, x0, y0, x1, y1,
  !> mm): its round scale mu and its pole (fit_plan) with plan_margin around it and, at its
  !> foot, the lines of its notes (what lies at the pole, what is too short to draw at mu:
  !> note_lines_needed) in the lower half of the margin, the area raised by what they need
  !> more; refitted at the larger mu they leave until they need no more lines.
  pure subroutine fit_noted_plan(images, equations, r, area, mu, pole)
    type(plan_vector_t), intent(in) :: images(:)
    type(plan_equation_t), intent(in) :: equations(:)
    real(wp), intent(in) :: r, area(4)
    real(wp), intent(out) :: mu, pole(2)
    real(wp), allocatable :: pts(:, :)
    real(wp) :: room(4)
    integer :: lines, more, tries
    allocate (pts(2, 0))
    pts = turned_plan_points(images, equations, r)
    lines = 0
    do tries = 1, 8
      ! (the notes in the lower half of the margin, the area raised by what they need more)
      room = area
      room(4) = area(4) - max(0.0_wp, note_band(lines) - 0.5_wp * plan_margin(area))
      call fit_plan(pts, room, mu, pole, plan_margin(area))
      more = note_lines_needed(images, equations, mu, area(3) - area(1) - 2.0_wp)
      if (more <= lines) exit
      lines = more
    end do
  end subroutine fit_noted_plan

  !> The height of `lines` lines of a plan's notes at their foot, mm (at their largest size).
  pure real(wp) function note_band(lines)
    integer, intent(in) :: lines
    note_band = real(lines, wp) * note_pitch * note_size
  end function note_band

  !> The room a plan keeps around it in its drawing area for its labels, mm: 10 mm on a large
  !> panel, 8 % of the area's smaller side on a smaller one, 1.5 labels' height at the least.
  pure real(wp) function plan_margin(area)
    real(wp), intent(in) :: area(4)
    plan_margin = min(margin, max(1.5_wp * label_height, 0.08_wp * min(area(3) - area(1), area(4) - area(2))))
  end function plan_margin

  !> How many lines of `width` mm a plan's notes need at most at scale mu: "at the pole π: "
  !> and the images within 1 mm of it, "not drawn, shorter than 1 mm: " and the components
  !> shorter (every one, the English words, a character 0.6 of the least note size wide: what
  !> the sheet writes is no longer), each note broken after its commas (kinetostat_plans_draw:
  !> note_lines).
  pure integer function note_lines_needed(images, equations, mu, width) result(lines)
    type(plan_vector_t), intent(in) :: images(:)
    type(plan_equation_t), intent(in) :: equations(:)
    real(wp), intent(in) :: mu, width
    integer, allocatable :: pieces(:)
    integer :: i, e, j
    lines = 0
    allocate (pieces(0))
    do i = 1, size(images)
      if (norm2(images(i)%v) / mu < 1.0_wp) pieces = [pieces, len_trim(images(i)%name) + 3]
    end do
    if (size(pieces) > 0) lines = lines + packed_lines(len("at the pole π: "), pieces)
    deallocate (pieces)
    allocate (pieces(0))
    do e = 1, size(equations)
      do j = 1, size(equations(e)%vectors)
        associate (v => equations(e)%vectors(j)%v)
          if (norm2(v) > 0.0_wp .and. norm2(v) / mu < 1.0_wp) pieces = [pieces, len_trim(equations(e)%vectors(j)%name) + 2]
        end associate
      end do
    end do
    if (size(pieces) > 0) lines = lines + packed_lines(len("not drawn, shorter than 1 mm: "), pieces)
  contains
    !> Lines of a note: its words, then every name (its characters and ", ") on the line
    !> while it fits.
    pure integer function packed_lines(words, names) result(n)
      integer, intent(in) :: words, names(:)
      real(wp) :: used, each
      integer :: k
      each = 0.6_wp * least_note_size
      n = 1
      used = each * real(words, wp)
      do k = 1, size(names)
        if (used + each * real(names(k), wp) > width .and. k > 1) then
          n = n + 1
          used = 0.0_wp
        end if
        used = used + each * real(names(k), wp)
      end do
    end function packed_lines
  end function note_lines_needed

  !> A plan's scale (round) and its pole on the sheet: the points (turned, in the position
  !> frame's units) and the pole fit into `area` (x0, y0, x1, y1, mm) less its margins, centred.
  !> The input link of unit e as a drawing of its own: its points and bars, its forces (all
  !> but the frame's reactions) and moments; `pivot` is its pivot's index (0: none).
  pure subroutine input_link_drawing(drawing, plans, e, link, pivot)
    type(drawing_t), intent(in) :: drawing
    type(plans_t), intent(in) :: plans
    integer, intent(in) :: e
    type(drawing_t), intent(out) :: link
    integer, intent(out) :: pivot
    integer :: j, q
    character(len=16) :: name
    logical :: mine
    allocate (link%points(0), link%bodies(0), link%guides(0), link%forces(0), link%moments(0))
    link%view_angle = drawing%view_angle
    pivot = 0
    name = plans%group_polygons(e)%link
    do j = 1, size(drawing%bodies)
      if (drawing%bodies(j)%name /= name) cycle
      link%bodies = [link%bodies, drawing%bodies(j)]
      do q = 1, size(drawing%bodies(j)%points)
        link%points = [link%points, drawing%points(drawing%bodies(j)%points(q))]
        link%bodies(size(link%bodies))%points(q) = size(link%points)
        if (drawing%points(drawing%bodies(j)%points(q))%kind == point_pivot) pivot = size(link%points)
      end do
    end do
    if (pivot == 0) return
    do j = 1, size(drawing%forces)
      associate (f => drawing%forces(j))
        mine = .false.
        if (f%kind == force_pair) then
          ! F<link><o> as it is, F<o><link> reversed; not the frame's
          if (len_trim(f%name) == 3) then
            if (f%name(2:2) == trim(name) .and. is_moving(f%name(3:3))) then
              link%forces = [link%forces, f]
            else if (f%name(3:3) == trim(name) .and. is_moving(f%name(2:2))) then
              link%forces = [link%forces, drawing_force_t("F"//f%name(3:3)//f%name(2:2), force_pair, f%at, -f%f, "")]
            end if
          end if
        else
          mine = trim(f%on_link) == trim(name) .or. f%name == "G"//trim(name) .or. f%name == "Phi"//trim(name)
          if (mine) link%forces = [link%forces, f]
        end if
      end associate
    end do
    do j = 1, size(drawing%moments)
      associate (m => drawing%moments(j))
        if (trim(m%on_link) == trim(name) .or. m%name == "M"//trim(name) .or. m%name == "MPhi"//trim(name)) then
          link%moments = [link%moments, m]
        end if
      end associate
    end do
    ! shift the link to its pivot (the frame's axes drawn there)
    associate (a => link%points(pivot)%p)
      do j = 1, size(link%forces)
        link%forces(j)%at = link%forces(j)%at - a
      end do
      do j = 1, size(link%moments)
        link%moments(j)%at = link%moments(j)%at - a
      end do
      do j = size(link%points), 1, -1
        link%points(j)%p = link%points(j)%p - a
      end do
    end associate
  contains
    !> Whether a pair force's digit names a moving link of the plans (not the frame).
    pure logical function is_moving(digit)
      character(*), intent(in) :: digit
      integer :: t
      is_moving = .false.
      do t = 1, size(plans%groups)
        if (any(plans%groups(t)%names == digit) .or. any(plans%groups(t)%names == "L"//digit)) is_moving = .true.
      end do
    end function is_moving
  end subroutine input_link_drawing

  !> A plan's scale (round) and its pole on the sheet: the points (turned, in the position
  !> frame's units) and the pole fit into `area` (x0, y0, x1, y1, mm) less its margins, centred.
  pure subroutine fit_plan(pts, area, mu, pole, room)
    real(wp), intent(in) :: pts(:, :), area(4)
    real(wp), intent(out) :: mu, pole(2)
    !> The room kept around the points, mm (default: margin).
    real(wp), intent(in), optional :: room
    real(wp) :: lo(2), hi(2)
    mu = fit_scale(pts, area, .true., room)
    lo = 0.0_wp
    hi = 0.0_wp
    if (size(pts, 2) > 0) then
      lo = min(lo, minval(pts, 2))
      hi = max(hi, maxval(pts, 2))
    end if
    ! the sheet's y runs down: the turned points' y is flipped
    pole(1) = 0.5_wp * (area(1) + area(3)) - 0.5_wp * (lo(1) + hi(1)) / mu
    pole(2) = 0.5_wp * (area(2) + area(4)) + 0.5_wp * (lo(2) + hi(2)) / mu
    pole = anint(pole * 100.0_wp) / 100.0_wp
  end subroutine fit_plan

  !> The course sheet's lever in its panel `box` (x0, y0, x1, y1, mm; its last 7 mm kept for
  !> its note), as large as the panel allows (its arms are what a student measures): the
  !> loads' arrows at the round mu_force that makes the largest at most lever_arrow long and
  !> a quarter of the area's smaller side; the lever at the smallest round mu (the series of
  !> round_scale) at which the pole, the images and every arrow drawn from its image fit
  !> with 3.5 mm around them for the names; centred. `r`: the sheet's rotation, rad.
  pure subroutine lever_fit(plans, r, box, mu, pole, mu_force)
    type(plans_t), intent(in) :: plans
    real(wp), intent(in) :: r, box(4)
    real(wp), intent(out) :: mu, pole(2), mu_force
    real(wp), parameter :: room = 3.5_wp
    real(wp), allocatable :: pts(:, :), tails(:, :), arrows(:, :)
    real(wp) :: area(4), arrow, fmax, lo(2), hi(2), span(2)
    integer :: i, tries
    area = panel_inner(box) - [0.0_wp, 0.0_wp, 0.0_wp, 7.0_wp]
    span = [area(3) - area(1), area(4) - area(2)] - 2.0_wp * room
    arrow = min(lever_arrow, 0.25_wp * min(area(3) - area(1), area(4) - area(2)))
    fmax = norm2(plans%balancing%f)
    do i = 1, size(plans%loads)
      fmax = max(fmax, norm2(plans%loads(i)%f))
    end do
    mu_force = round_scale(fmax, arrow)
    ! the images (turned by 90 deg more than the sheet, y up) and the arrows (mm) at them
    allocate (pts(2, 0), tails(2, 0), arrows(2, 0))
    do i = 1, size(plans%velocities)
      pts = add(pts, turn(plans%velocities(i)%v, r + 0.5_wp * pi))
    end do
    if (plans%lever_known) then
      do i = 1, size(plans%loads)
        call put_load(plans%loads(i), pts, tails, arrows)
      end do
      call put_load(plans%balancing, pts, tails, arrows)
    end if
    pts = add(pts, [0.0_wp, 0.0_wp])
    ! the points alone first, then the next round mu until the arrows fit too
    mu = max(round_scale(maxval(pts(1, :)) - minval(pts(1, :)), max(span(1), 1.0_wp)), &
      round_scale(maxval(pts(2, :)) - minval(pts(2, :)), max(span(2), 1.0_wp)))
    do tries = 1, 60
      call extent(mu, lo, hi)
      if (all(hi - lo <= span)) exit
      mu = round_scale(mu * (1.0_wp + 1.0e-6_wp), 1.0_wp)
    end do
    ! the sheet's y runs down: the turned points' y is flipped
    pole(1) = 0.5_wp * (area(1) + area(3)) - 0.5_wp * (lo(1) + hi(1))
    pole(2) = 0.5_wp * (area(2) + area(4)) + 0.5_wp * (lo(2) + hi(2))
    pole = anint(pole * 100.0_wp) / 100.0_wp
  contains
    !> A load's image(s) and its arrow(s) as drawn (a couple's second force reversed).
    pure subroutine put_load(ld, pts, tails, arrows)
      type(lever_load_t), intent(in) :: ld
      real(wp), allocatable, intent(inout) :: pts(:, :), tails(:, :), arrows(:, :)
      pts = add(pts, turn(ld%at, r + 0.5_wp * pi))
      tails = add(tails, turn(ld%at, r + 0.5_wp * pi))
      arrows = add(arrows, turn(ld%f, r) / mu_force)
      if (.not. ld%pair) return
      pts = add(pts, turn(ld%at2, r + 0.5_wp * pi))
      tails = add(tails, turn(ld%at2, r + 0.5_wp * pi))
      arrows = add(arrows, -turn(ld%f, r) / mu_force)
    end subroutine put_load
    !> The drawing's extent at mu (mm from the pole, y up).
    pure subroutine extent(m, lo, hi)
      real(wp), intent(in) :: m
      real(wp), intent(out) :: lo(2), hi(2)
      integer :: j
      lo = minval(pts, 2) / m
      hi = maxval(pts, 2) / m
      do j = 1, size(tails, 2)
        lo = min(lo, tails(:, j) / m + arrows(:, j))
        hi = max(hi, tails(:, j) / m + arrows(:, j))
      end do
    end subroutine extent
  end subroutine lever_fit

  !> A panel's drawing area: less its heading band and its scale line.
  pure function panel_inner(box) result(area)
    real(wp), intent(in) :: box(4)
    real(wp) :: area(4)
    area = [box(1) + 2.0_wp, box(2) + panel_head, box(3) - 2.0_wp, box(4) - panel_foot]
  end function panel_inner

  !> A plan's drawing area in its panel: less its heading band and the 6.5 mm its scale line
  !> needs at its foot (its notes stand right above that line).
  pure function plan_inner(box) result(area)
    real(wp), intent(in) :: box(4)
    real(wp) :: area(4)
    area = [box(1) + 2.0_wp, box(2) + panel_head, box(3) - 2.0_wp, box(4) - 6.5_wp]
  end function plan_inner

  !> v turned by `angle` rad counterclockwise.
  pure function turn(v, angle) result(w)
    real(wp), intent(in) :: v(2), angle
    real(wp) :: w(2)
    w = [cos(angle) * v(1) - sin(angle) * v(2), sin(angle) * v(1) + cos(angle) * v(2)]
  end function turn

  !> The corners of an equation's chain on the plan: the image it starts from (the pole when
  !> it starts there), then the running sums of its components.
  pure subroutine chain_tips(eq, images, tips)
    type(plan_equation_t), intent(in) :: eq
    type(plan_vector_t), intent(in) :: images(:)
    real(wp), allocatable, intent(out) :: tips(:, :)
    integer :: j
    allocate (tips(2, size(eq%vectors) + 1))
    tips(:, 1) = 0.0_wp
    do j = 1, size(images)
      if (len_trim(eq%from) > 0 .and. images(j)%name == eq%from) tips(:, 1) = images(j)%v
    end do
    do j = 1, size(eq%vectors)
      tips(:, j + 1) = tips(:, j) + eq%vectors(j)%v
    end do
  end subroutine chain_tips

  !> The running sums of the vectors (tips(:, 1) = 0, tips(:, j + 1) = sum of the first j).
  pure subroutine polygon_tips(vectors, tips)
    type(plan_vector_t), intent(in) :: vectors(:)
    real(wp), allocatable, intent(out) :: tips(:, :)
    integer :: j
    allocate (tips(2, size(vectors) + 1))
    tips(:, 1) = 0.0_wp
    do j = 1, size(vectors)
      tips(:, j + 1) = tips(:, j) + vectors(j)%v
    end do
  end subroutine polygon_tips

  !> x rounded to the nearest multiple of `step`.
  pure real(wp) function rounded(x, step)
    real(wp), intent(in) :: x, step
    rounded = step * anint(x / step)
  end function rounded

  !> The balancing effort as a teacher checks a student's sheet: what is read off the
  !> drawing is read at the drawing's precision - every vector taken off a force polygon to
  !> 0.5 mm at its mu_F, every arm to 1 mm at its scale - and what is computed (the loads' values
  !> G = m g, Phi = m a_S, M = J eps, and F = M / l of their couples) is taken as computed:
  !> - from the lever: the moment about the pole of every load (of each force of a couple or
  !>   pair), F times its arm read off the lever at its mu_v; P_bal = -sum / |pb| with |pb| read
  !>   off too, M = P_bal l_AB (a cylinder's force: -sum over the arm between its two lines);
  !> - from the force polygons: a driving moment from the input link's equilibrium about its
  !>   pivot: the reactions of the polygon read off it, the link's loads as computed, each
  !>   with its arm read off the mechanism at mu_l, and the link's moments; a driving force
  !>   between a slider and its guide's link from the slider's forces along the drive (the
  !>   reactions read off their unit's polygon).
  pure subroutine compare_efforts(topo, drawing, plans, sheet)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(plans_t), intent(in) :: plans
    type(plans_sheet_t), intent(inout) :: sheet
    real(wp) :: s, h, f, pbal, a(2), u(2), mu, mu_arm
    integer :: i, d, e, j, l, g, o
    character(len=:), allocatable :: pivot
    sheet%compared = .false.
    if (.not. plans%lever_known) return
    ! the lever
    s = 0.0_wp
    do i = 1, size(plans%loads)
      associate (ld => plans%loads(i))
        s = s + measured_power(ld%f, ld%at)
        if (ld%pair) s = s + measured_power(-ld%f, ld%at2)
      end associate
    end do
    associate (b => plans%balancing)
      if (b%kind == load_moment .or. norm2(b%f) <= 0.0_wp) return
      if (b%pair) then
        ! a drive's force and reaction: the arm between their lines is the sliding speed
        h = rounded(abs(plans%lever_rate) / sheet%mu_lever, 1.0_wp) * sheet%mu_lever
        if (h <= 0.0_wp) return
        sheet%effort_lever = -s / (h * sign(1.0_wp, plans%lever_rate))
      else
        ! P_bal along the pin's velocity: its power P |v_B|
        h = rounded(norm2(b%at) / sheet%mu_lever, 1.0_wp) * sheet%mu_lever
        if (h <= 0.0_wp) return
        pbal = -s / h
        sheet%effort_lever = pbal * plans%balancing_length * sign(1.0_wp, plans%lever_rate)
      end if
    end associate
    ! the force polygons
    d = link_index(topo, owner(plans%driver, ""))
    if (d > 0 .and. .not. plans%balancing%pair) then
      pivot = pivot_of(topo, d)
      if (len(pivot) == 0) return
      a = drawing%at(pivot)
      do e = 1, size(plans%group_polygons)
        if (.not. plans%group_polygons(e)%input) cycle
        if (plans%group_polygons(e)%moment /= plans%driver) cycle
        mu = sheet%mu_f(e)
        mu_arm = sheet%mu_l
        if (sheet%mu_link(e) > 0.0_wp) mu_arm = sheet%mu_link(e)
        s = 0.0_wp
        do j = 1, size(plans%group_polygons(e)%vectors)
          associate (v => plans%group_polygons(e)%vectors(j))
            if (any(v%kind == [component_reaction, component_normal, component_tangential])) cycle
            f = norm2(v%v)
            if (f <= 0.0_wp) cycle
            h = abs(cross(point_of(trim(v%name)) - a, v%v)) / f
            if (is_reaction(trim(v%name))) f = rounded(f / mu, 0.5_wp) * mu
            s = s + sign(1.0_wp, cross(point_of(trim(v%name)) - a, v%v)) * f * rounded(h / mu_arm, 1.0_wp) * mu_arm
          end associate
        end do
        do i = 1, size(plans%loads)
          if (plans%loads(i)%kind == load_moment .and. plans%loads(i)%link == topo%links(d)%name) s = s + &
            plans%loads(i)%value
        end do
        sheet%effort_polygon = -s
        sheet%compared = .true.
      end do
    else if (plans%balancing%pair) then
      ! the slider's forces along the drive
      l = link_index(topo, plans%balancing%link)
      if (l == 0) return
      g = guide_link(topo, l)
      u = plans%balancing%f / norm2(plans%balancing%f) * sign(1.0_wp, plans%effort)
      mu = 0.0_wp
      do e = 1, size(plans%group_polygons)
        if (index(","//trim(plans%group_polygons(e)%link)//",", ","//trim(topo%links(l)%name)//",") > 0) mu = sheet%mu_f(e)
      end do
      if (mu <= 0.0_wp) return
      s = 0.0_wp
      do j = 1, size(drawing%forces)
        associate (fc => drawing%forces(j))
          if (trim(fc%name) == plans%driver) cycle
          if (fc%kind /= force_pair) then
            if (link_index(topo, owner(fc%name, fc%on_link)) == l) s = s + dot_product(fc%f, u)
          else if (len_trim(fc%name) == 3) then
            o = link_index(topo, fc%name(3:3))
            if (link_index(topo, fc%name(2:2)) == l .and. o /= g) s = s + along(fc%f)
            o = link_index(topo, fc%name(2:2))
            if (link_index(topo, fc%name(3:3)) == l .and. o /= g) s = s + along(-fc%f)
          end if
        end associate
      end do
      sheet%effort_polygon = -s
      sheet%compared = .true.
    end if
    ! in % of the larger; an effort that is nought to within 1e-9 of what the loads could give
    ! (their forces times their images' speeds, over the driver's rate) is nought
    s = 0.0_wp
    do i = 1, size(plans%loads)
      s = s + norm2(plans%loads(i)%f) * (norm2(plans%loads(i)%at) + norm2(plans%loads(i)%at2))
    end do
    s = 1.0e-9_wp * s / abs(plans%lever_rate)
    if (sheet%compared) sheet%difference = 100.0_wp * abs(sheet%effort_lever - sheet%effort_polygon) / &
      max(abs(sheet%effort_lever), abs(sheet%effort_polygon), s, tiny(1.0_wp))
  contains
    !> A force f at the velocity image at: its power as the lever gives it, |F| as computed
    !> times its arm read off to 1 mm at the lever's mu_v.
    pure real(wp) function measured_power(f, at)
      real(wp), intent(in) :: f(2), at(2)
      real(wp) :: size_f, arm
      measured_power = 0.0_wp
      size_f = norm2(f)
      if (size_f <= 0.0_wp) return
      arm = abs(dot_product(f, at)) / size_f
      measured_power = sign(1.0_wp, dot_product(f, at)) * size_f * rounded(arm / sheet%mu_lever, 1.0_wp) * sheet%mu_lever
    end function measured_power
    !> The component of f along the drive, |f| read off to 0.5 mm at the polygon's scale mu.
    pure real(wp) function along(f)
      real(wp), intent(in) :: f(2)
      along = 0.0_wp
      if (norm2(f) <= 0.0_wp) return
      along = dot_product(f / norm2(f), u) * rounded(norm2(f) / mu, 0.5_wp) * mu
    end function along
    !> Whether a polygon's vector is a pair's reaction (F<i><j>): read off the polygon.
    pure logical function is_reaction(name)
      character(*), intent(in) :: name
      is_reaction = len(name) == 3 .and. name(1:1) == "F" .and. verify(name(2:3), "0123456789") == 0
    end function is_reaction
    !> Where a force of the input link's polygon acts: the drawing's force of that name, or
    !> of the reversed name (F12: the point of F21).
    pure function point_of(name) result(p)
      character(*), intent(in) :: name
      real(wp) :: p(2)
      integer :: t
      p = 0.0_wp
      do t = 1, size(drawing%forces)
        if (drawing%forces(t)%name == name) p = drawing%forces(t)%at
        if (len(name) == 3 .and. name(1:1) == "F") then
          if (drawing%forces(t)%name == "F"//name(3:3)//name(2:2)) p = drawing%forces(t)%at
        end if
      end do
    end function point_of
  end subroutine compare_efforts

end module kinetostat_plans_sheet
