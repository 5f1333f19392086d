!> The plans sheet's geometry: where each drawing goes on the sheet and at which scale, and
!> what a teacher reads off it. One sheet, A2 landscape (594 x 420 mm) in the ГОСТ 2.301
!> frame: the mechanism at mu_l, the plans of velocities and accelerations at mu_v, mu_a,
!> Zhukovsky's lever (its plan at mu_v of its own, its loads at mu_F), the force polygons of
!> the units of the structure (each at its mu_F), the tables of values and of the lever's
!> loads, the title block. Everything is drawn in the mechanism drawing's frame (the
!> position frame turned by the sheet's rotation, gravity down the sheet).
!>
!> The scales are the drawing scales a student would take: 1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6 or 8
!> times a power of ten units per mm. With them the sheet compares the balancing effort
!> from the lever with the one from the force polygons the way a teacher checks a student's
!> sheet: every vector read off the drawing to 0.5 mm and every arm to 1 mm.
module kinetostat_plans_sheet
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, force_pair
  use kinetostat_plans_base, only: plans_t, plan_vector_t, plan_equation_t, load_moment, cross, perp, link_index, &
    owner, pivot_of, guide_link, component_normal, component_tangential, component_reaction
  implicit none
  private
  public :: plans_sheet_t, plans_sheet, plan_scale, turn, chain_tips, polygon_tips, sheet_size

  !> The sheet: A2 landscape, mm.
  real(wp), parameter :: sheet_size(2) = [594.0_wp, 420.0_wp]
  !> Room kept around a drawing in its panel for its labels and arrows, mm.
  real(wp), parameter :: margin = 10.0_wp
  !> The lever's largest load arrow, mm.
  real(wp), parameter :: lever_arrow = 24.0_wp

  !> The sheet's panels (x, y of the upper left corner, width, height; mm) and scales.
  type :: plans_sheet_t
    real(wp) :: mechanism(4) = [22.0_wp, 30.0_wp, 186.0_wp, 176.0_wp]
    real(wp) :: velocity(4) = [210.0_wp, 30.0_wp, 187.0_wp, 176.0_wp]
    real(wp) :: acceleration(4) = [399.0_wp, 30.0_wp, 188.0_wp, 176.0_wp]
    real(wp) :: lever(4) = [22.0_wp, 208.0_wp, 186.0_wp, 150.0_wp]
    real(wp) :: polygons(4) = [210.0_wp, 208.0_wp, 377.0_wp, 150.0_wp]
    real(wp) :: values(4) = [22.0_wp, 360.0_wp, 186.0_wp, 53.0_wp]
    real(wp) :: lever_table(4) = [210.0_wp, 360.0_wp, 192.0_wp, 53.0_wp]
    !> Lengths, m/mm; velocities (the plan and the lever's), (m/s)/mm; accelerations,
    !> (m/s^2)/mm; the lever's loads, N/mm.
    real(wp) :: mu_l = 1.0_wp, mu_v = 1.0_wp, mu_a = 1.0_wp, mu_lever = 1.0_wp, mu_force = 1.0_wp
    !> Every unit's polygon: its cell in the polygons' panel and its scale, N/mm; an input
    !> link's cell also shows the link with its forces and their arms (the left part of the
    !> cell, `link_boxes`) at a larger scale of its own, mu_link (m/mm; 0: none).
    real(wp), allocatable :: cells(:, :), mu_f(:), link_boxes(:, :), mu_link(:)
    !> The sheet's rotation against the position frame, rad.
    real(wp) :: rotation = 0.0_wp
    !> The balancing effort as measured on the sheet: from the lever and from the force
    !> polygons (N*m or N), their difference in % of the larger; `compared` false when the
    !> sheet gives no such comparison (the lever not drawn, no input link's polygon).
    logical :: compared = .false.
    real(wp) :: effort_lever = 0.0_wp, effort_polygon = 0.0_wp, difference = 0.0_wp
  end type plans_sheet_t

contains

  !> The geometry of the plans sheet of `plans` (the drawing of the same step gives the
  !> mechanism's size and the sheet's rotation).
  pure subroutine plans_sheet(topo, drawing, plans, sheet)
    type(sketch_t), intent(in) :: topo
    type(drawing_t), intent(in) :: drawing
    type(plans_t), intent(in) :: plans
    type(plans_sheet_t), intent(out) :: sheet
    real(wp), allocatable :: pts(:, :), tips(:, :)
    real(wp) :: fmax, r, box(4)
    integer :: i, e, n, columns, rows
    r = drawing%view_angle
    sheet%rotation = r
    ! the mechanism: its points and guides, turned
    allocate (pts(2, 0))
    do i = 1, size(drawing%points)
      pts = add(pts, turn(drawing%points(i)%p, r))
    end do
    if (allocated(drawing%guides)) then
      do i = 1, size(drawing%guides)
        associate (g => drawing%guides(i))
          pts = add(pts, turn(g%p + g%half_length * [cos(g%angle), sin(g%angle)], r))
          pts = add(pts, turn(g%p - g%half_length * [cos(g%angle), sin(g%angle)], r))
        end associate
      end do
    end if
    sheet%mu_l = fit_scale(pts, sheet%mechanism, .false.)
    ! the plans: the images and the corners of the equations' chains
    sheet%mu_v = fit_scale(plan_points(plans%velocities, plans%velocity_equations, r), sheet%velocity, .true.)
    sheet%mu_a = fit_scale(plan_points(plans%accelerations, plans%equations, r), sheet%acceleration, .true.)
    ! the lever: the plan turned by 90 deg more, the images of the loads' points
    deallocate (pts)
    allocate (pts(2, 0))
    do i = 1, size(plans%velocities)
      pts = add(pts, turn(plans%velocities(i)%v, r + 0.5_wp * acos(-1.0_wp)))
    end do
    fmax = 0.0_wp
    if (plans%lever_known) then
      do i = 1, size(plans%loads)
        pts = add(pts, turn(plans%loads(i)%at, r + 0.5_wp * acos(-1.0_wp)))
        if (plans%loads(i)%pair) pts = add(pts, turn(plans%loads(i)%at2, r + 0.5_wp * acos(-1.0_wp)))
        fmax = max(fmax, norm2(plans%loads(i)%f))
      end do
      fmax = max(fmax, norm2(plans%balancing%f))
    end if
    sheet%mu_lever = fit_scale(pts, sheet%lever + [lever_arrow, lever_arrow, -2.0_wp * lever_arrow, -2.0_wp * lever_arrow], &
      .true.)
    sheet%mu_force = 1.0_wp
    if (fmax > 0.0_wp) sheet%mu_force = plan_scale(fmax / lever_arrow)
    ! the polygons: a grid of cells, each polygon at its own scale; an input link's cell
    ! with the link drawn in its left part
    n = size(plans%group_polygons)
    allocate (sheet%cells(4, n), sheet%mu_f(n), sheet%link_boxes(4, n), sheet%mu_link(n))
    sheet%link_boxes = 0.0_wp
    sheet%mu_link = 0.0_wp
    columns = max(1, min(n, 3))
    rows = max(1, (n + columns - 1) / columns)
    do e = 1, n
      sheet%cells(:, e) = [sheet%polygons(1) + 2.0_wp + (sheet%polygons(3) - 4.0_wp) / columns * modulo(e - 1, columns), &
        sheet%polygons(2) + 8.0_wp + (sheet%polygons(4) - 10.0_wp) / rows * ((e - 1) / columns), &
        (sheet%polygons(3) - 4.0_wp) / columns, (sheet%polygons(4) - 10.0_wp) / rows]
      box = sheet%cells(:, e) + [0.0_wp, 4.0_wp, 0.0_wp, -8.0_wp]
      if (plans%group_polygons(e)%input) then
        call link_points(e, pts)
        if (size(pts, 2) >= 2) then
          sheet%link_boxes(:, e) = [box(1), box(2), 0.45_wp * box(3), box(4)]
          sheet%mu_link(e) = fit_scale(pts, sheet%link_boxes(:, e), .false.)
          box = [box(1) + 0.45_wp * box(3), box(2), 0.55_wp * box(3), box(4)]
        end if
      end if
      call polygon_tips(plans%group_polygons(e)%vectors, tips)
      do i = 1, size(tips, 2)
        tips(:, i) = turn(tips(:, i), r)
      end do
      sheet%mu_f(e) = fit_scale(tips, box, .false.)
    end do
    call compare_efforts(topo, drawing, plans, sheet)
  contains
    !> The drawn points of the links of unit e (turned), for its link drawing.
    pure subroutine link_points(e, pts)
      integer, intent(in) :: e
      real(wp), allocatable, intent(out) :: pts(:, :)
      integer :: q, t, l
      character(len=16) :: name
      allocate (pts(2, 0))
      do q = 1, size(drawing%points)
        name = drawing%points(q)%name
        do t = 1, size(plans%groups)
          if (group_text(t) /= plans%group_polygons(e)%link) cycle
          do l = 1, size(plans%groups(t)%links)
            if (any(topo%links(plans%groups(t)%links(l))%points == name) .or. &
              name == "S"//topo%links(plans%groups(t)%links(l))%name) pts = add(pts, turn(drawing%points(q)%p, r))
          end do
        end do
      end do
    end subroutine link_points
    !> Unit t's links as its polygon names them ("2,3").
    pure function group_text(t) result(text)
      integer, intent(in) :: t
      character(len=16) :: text
      integer :: q
      text = ""
      do q = 1, size(plans%groups(t)%names)
        if (q > 1) text = trim(text)//","
        text = trim(text)//trim(plans%groups(t)%names(q))
      end do
    end function group_text
    !> The points a plan must show: its images and every corner of its equations' chains.
    pure function plan_points(images, equations, r) result(all)
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
    end function plan_points
  end subroutine plans_sheet

  !> The points with one more.
  pure function add(pts, p) result(more)
    real(wp), intent(in) :: pts(:, :), p(2)
    real(wp), allocatable :: more(:, :)
    allocate (more(2, size(pts, 2) + 1))
    more(:, 1:size(pts, 2)) = pts
    more(:, size(pts, 2) + 1) = p
  end function add

  !> The scale (units per mm, a drawing scale) at which the points (the origin with them when
  !> `pole`) fit into the panel `box` less its margins.
  pure real(wp) function fit_scale(pts, box, pole)
    real(wp), intent(in) :: pts(:, :), box(4)
    logical, intent(in) :: pole
    real(wp) :: lo(2), hi(2), span
    if (size(pts, 2) == 0) then
      fit_scale = 1.0_wp
      return
    end if
    lo = minval(pts, 2)
    hi = maxval(pts, 2)
    if (pole) then
      lo = min(lo, 0.0_wp)
      hi = max(hi, 0.0_wp)
    end if
    span = max((hi(1) - lo(1)) / max(box(3) - 2.0_wp * margin, 1.0_wp), (hi(2) - lo(2)) / max(box(4) - 2.0_wp * margin - &
      6.0_wp, 1.0_wp))
    fit_scale = 1.0_wp
    if (span > 0.0_wp) fit_scale = plan_scale(span)
  end function fit_scale

  !> A drawing scale (units per mm) at least `span`: the smallest of 1, 1.2, 1.5, 2, 2.5, 3,
  !> 4, 5, 6, 8 times a power of ten (the scales a drawing is made at).
  pure real(wp) function plan_scale(span)
    real(wp), intent(in) :: span
    real(wp), parameter :: steps(*) = [1.0_wp, 1.2_wp, 1.5_wp, 2.0_wp, 2.5_wp, 3.0_wp, 4.0_wp, 5.0_wp, 6.0_wp, &
      8.0_wp, 10.0_wp]
    real(wp) :: decade
    integer :: i
    decade = 10.0_wp**floor(log10(span))
    plan_scale = 10.0_wp * decade
    do i = size(steps), 1, -1
      if (steps(i) * decade >= span * (1.0_wp - 1.0e-12_wp)) plan_scale = steps(i) * decade
    end do
  end function plan_scale

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
    ! in % of the larger; an effort that is nought to within 1e-9 of what the loads give
    ! (their powers over the driver's rate) is nought
    s = 0.0_wp
    do i = 1, size(plans%loads)
      s = s + abs(plans%loads(i)%power)
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
