!> The velocities and accelerations of the named points of a linkage at every step
!> (--kinematics): vx_<P>, vy_<P> (m/s) of every joint, pivot and centre of mass and ax_<P>,
!> ay_<P> (m/s^2) of every joint and pivot (the centres of mass' accelerations are the
!> mechanism's own columns), in the position frame of the x_<P>, y_<P> columns. Every link's
!> field is v = v0 + omega x r, a = a0 + eps x r - omega^2 r with omega, eps from the table;
!> the translation terms v0, a0 follow in closed form, link by link, from a pivot (at rest)
!> through the revolute joints (one velocity on both links), from two sliders on links
!> already known (each fixes the component across its guide: a 2x2 system; the Coriolis term
!> 2 omega_g x v_rel on a moving guide) and, for the accelerations, from a centre of mass
!> whose acceleration the table gives. The order of that pass is found once per block from
!> the topology; a mechanism where it does not reach every link that has an equation (or a
!> step where a link's two guides are parallel) gets the plans' least-squares solve of every
!> pair equation (kinetostat_plans), so every mechanism with a sketch gains them in one place.
module kinetostat_point_motion
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_step_table, only: step_table_t
  use kinetostat_sketch, only: sketch_t
  use kinetostat_drawing, only: drawing_t, point_pivot, point_com, points_from_sketch
  use kinetostat_plans_base, only: plan_vector_t, slide_t, slides_of
  use kinetostat_plans, only: solve_fields, point_images, field_topology_t, field_topology
  implicit none
  private
  public :: add_point_motion

  !> How a link's translation term follows: from a pivot, a joint with a link already known,
  !> or the table's acceleration of its centre of mass.
  integer, parameter :: from_pivot = 1, from_joint = 2, from_com = 3, from_slides = 4

  !> One step of the closed-form pass: link `link` from point `point` (and link `known`), or
  !> from the sliders `slide(1:2)`.
  type :: pass_step_t
    integer :: link = 0, kind = 0, point = 0, known = 0
    integer :: slide(2) = 0
  end type pass_step_t

contains

  !> Put the velocity and acceleration columns of every named point into each row of the
  !> table's block; nothing when the mechanism has no sketch.
  pure subroutine add_point_motion(topo, table, error)
    !> The mechanism's topology.
    type(sketch_t), intent(in) :: topo
    !> The block's results with their kinematics columns (positions, omega, eps).
    type(step_table_t), intent(inout) :: table
    !> A named point without position columns.
    type(error_t), allocatable, intent(out) :: error
    type(drawing_t) :: drawing
    type(field_topology_t) :: known
    type(pass_step_t), allocatable :: vpass(:), apass(:)
    type(slide_t), allocatable :: slides(:)
    real(wp), allocatable :: omega(:), eps(:), v0(:, :), a0(:, :), p(:, :), u(:, :)
    !> Columns found once for the block: each link's omega and eps, each point's x and y and
    !> its velocity and acceleration columns (0: none), each slider's point and the phi column
    !> of its guide's link (0: the frame).
    integer, allocatable :: c_omega(:), c_eps(:), cx(:), cy(:), host(:), cv(:, :), ca(:, :), s_point(:), s_phi(:)
    !> The points (with a host link) that have velocity columns and those that have
    !> acceleration columns, nv and na of them.
    integer, allocatable :: v_points(:), a_points(:)
    logical, allocatable :: s_used(:)
    logical :: closed, parallel
    integer :: k, i, nl, np, ip, s, j, nv, na
    if (.not. topo%available .or. .not. allocated(topo%links)) return
    if (table%row_count() == 0) return
    nl = size(topo%links)
    allocate (c_omega(nl), c_eps(nl))
    do i = 1, nl
      c_omega(i) = table%column_index("omega"//topo%links(i)%name)
      c_eps(i) = table%column_index("eps"//topo%links(i)%name)
    end do
    ! the points (the same at every row: the topology's) and where their positions are
    call points_from_sketch(topo, table, 1, drawing, error)
    if (allocated(error)) return
    np = size(drawing%points)
    allocate (cx(np), cy(np))
    do ip = 1, np
      cx(ip) = table%column_index("x_"//trim(drawing%points(ip)%name))
      cy(ip) = table%column_index("y_"//trim(drawing%points(ip)%name))
    end do
    known = field_topology(topo, drawing, table)
    call slides_of(topo, drawing, table, 1, slides)
    allocate (s_point(size(slides)), s_phi(size(slides)), s_used(size(slides)), u(2, size(slides)))
    closed = .true.
    do s = 1, size(slides)
      s_point(s) = drawing%point_index(trim(slides(s)%name))
      s_phi(s) = 0
      if (slides(s)%g > 0) s_phi(s) = table%column_index("phi"//topo%links(slides(s)%g)%name)
      if (s_point(s) == 0) closed = .false.
    end do
    if (closed) call closed_pass(known, slides, nl, .false., vpass, closed)
    if (closed) call closed_pass(known, slides, nl, .true., apass, closed)
    if (.not. closed) then
      call by_least_squares(topo, table, drawing, known, c_omega, c_eps, cx, cy, 1, table%row_count())
      return
    end if
    s_used = .false.
    do i = 1, size(vpass)
      if (vpass(i)%kind == from_slides) s_used(vpass(i)%slide) = .true.
    end do
    do i = 1, size(apass)
      if (apass(i)%kind == from_slides) s_used(apass(i)%slide) = .true.
    end do
    ! the link whose field gives each point's image: the first listing it
    allocate (host(np), cv(2, np), ca(2, np), p(2, np), omega(nl), eps(nl), v0(2, nl), a0(2, nl))
    ! (a link the pass does not reach stays at rest; the others are set by every row's pass)
    v0 = 0.0_wp
    a0 = 0.0_wp
    host = 0
    do ip = 1, np
      do i = 1, nl
        if (known%incident(ip, i)) then
          host(ip) = i
          exit
        end if
      end do
    end do
    cv = 0
    ca = 0
    allocate (v_points(np), a_points(np))
    nv = 0
    na = 0
    do k = 1, table%row_count()
      do ip = 1, np
        p(1, ip) = table%rows(cx(ip), k)
        p(2, ip) = table%rows(cy(ip), k)
      end do
      call link_rates(table, k, c_omega, c_eps, omega, eps)
      do s = 1, size(slides)
        if (s_used(s)) u(:, s) = guide_direction(s)
      end do
      parallel = .false.
      call translations(vpass, .false., v0, parallel)
      call translations(apass, .true., a0, parallel)
      if (parallel) then
        ! two guides of a link parallel at this step: the pair equations together
        call by_least_squares(topo, table, drawing, known, c_omega, c_eps, cx, cy, k, k)
        if (k == 1) call find_columns(table, cv, ca, nv, na, v_points, a_points)
        cycle
      end if
      if (k == 1) then
        ! the first row names the columns (as the mechanism's own kinematics columns)
        call first_row(table)
        if (allocated(table%no_room)) return
        call find_columns(table, cv, ca, nv, na, v_points, a_points)
        cycle
      end if
      ! the points with velocity columns, then those with acceleration columns (lists found
      ! with the columns)
      associate (row => table%rows(:, k))
        do j = 1, nv
          ip = v_points(j)
          i = host(ip)
          row(cv(1, ip)) = v0(1, i) - omega(i) * p(2, ip)
          row(cv(2, ip)) = v0(2, i) + omega(i) * p(1, ip)
        end do
        do j = 1, na
          ip = a_points(j)
          i = host(ip)
          row(ca(1, ip)) = a0(1, i) - eps(i) * p(2, ip) - omega(i)**2 * p(1, ip)
          row(ca(2, ip)) = a0(2, i) + eps(i) * p(1, ip) - omega(i)**2 * p(2, ip)
        end do
      end associate
    end do
  contains
    !> Row 1 through the table's named setters (they add the columns).
    pure subroutine first_row(t)
      type(step_table_t), intent(inout) :: t
      character(len=:), allocatable :: name
      integer :: ip, i
      do ip = 1, np
        i = host(ip)
        if (i == 0) cycle
        name = trim(drawing%points(ip)%name)
        if (drawing%points(ip)%kind == point_pivot) then
          call t%put_velocity(1, name, [0.0_wp, 0.0_wp])
          call t%put_acceleration(1, name, [0.0_wp, 0.0_wp])
        else
          call t%put_velocity(1, name, [v0(1, i) - omega(i) * p(2, ip), v0(2, i) + omega(i) * p(1, ip)])
          if (drawing%points(ip)%kind /= point_com) call t%put_acceleration(1, name, &
            [a0(1, i) - eps(i) * p(2, ip) - omega(i)**2 * p(1, ip), a0(2, i) + eps(i) * p(1, ip) - omega(i)**2 * p(2, ip)])
        end if
      end do
    end subroutine first_row
    !> The columns' indices for the rows after the first (a pivot's stay at zero) and the lists
    !> of the points that have them.
    pure subroutine find_columns(t, cv, ca, nv, na, v_points, a_points)
      type(step_table_t), intent(inout) :: t
      integer, intent(inout) :: cv(:, :), ca(:, :)
      !> The points with velocity columns and with acceleration columns, and how many.
      integer, intent(inout) :: nv, na, v_points(:), a_points(:)
      character(len=:), allocatable :: name
      integer :: ip
      call t%finish_columns()
      if (allocated(t%no_room)) return
      do ip = 1, np
        if (host(ip) == 0 .or. drawing%points(ip)%kind == point_pivot) cycle
        name = trim(drawing%points(ip)%name)
        cv(:, ip) = [t%column_index("vx_"//name), t%column_index("vy_"//name)]
        if (drawing%points(ip)%kind /= point_com) ca(:, ip) = [t%column_index("ax_"//name), &
          t%column_index("ay_"//name)]
        if (any(cv(:, ip) == 0)) cv(:, ip) = 0
        if (any(ca(:, ip) == 0)) ca(:, ip) = 0
      end do
      nv = 0
      na = 0
      do ip = 1, np
        if (host(ip) == 0) cycle
        if (cv(1, ip) > 0) then
          nv = nv + 1
          v_points(nv) = ip
        end if
        if (ca(1, ip) > 0) then
          na = na + 1
          a_points(na) = ip
        end if
      end do
    end subroutine find_columns
    !> Unit vector of slider s's guide at row k (as slides_of finds it: a link without a phi
    !> column, a ram, does not turn).
    pure function guide_direction(s) result(d)
      integer, intent(in) :: s
      real(wp) :: d(2), ang
      if (slides(s)%block) then
        ang = slides(s)%angle
        if (s_phi(s) > 0) ang = ang + table%rows(s_phi(s), k)
        ang = ang * deg_to_rad
      else
        ang = slides(s)%angle * deg_to_rad
        if (s_phi(s) > 0) ang = ang + table%rows(s_phi(s), k) * deg_to_rad
      end if
      d = [cos(ang), sin(ang)]
    end function guide_direction
    !> The links' translation terms of this row (velocities or accelerations) by the pass:
    !> each link of the pass from links set before it in the same pass (those the pass does
    !> not reach keep the zero they were given once). (Written component by component into
    !> c, which the caller gives whole: no array temporary, so nothing is allocated per row.)
    pure subroutine translations(pass, accel, c, parallel)
      type(pass_step_t), intent(in) :: pass(:)
      logical, intent(in) :: accel
      real(wp), intent(inout) :: c(:, :)
      !> Set when a link's two guides are parallel at this step.
      logical, intent(inout) :: parallel
      real(wp) :: r(2), det, f(2)
      integer :: st, m, q, j, e
      do st = 1, size(pass)
        m = pass(st)%link
        q = pass(st)%point
        select case (pass(st)%kind)
        case (from_pivot)
          f = -own(m, p(:, q), accel)
        case (from_joint)
          j = pass(st)%known
          f = c(:, j) + own(j, p(:, q), accel) - own(m, p(:, q), accel)
        case (from_com)
          f = [table%rows(known%com_cols(1, q), k), 0.0_wp] - own(m, p(:, q), accel)
          if (known%com_cols(2, q) > 0) f(2) = f(2) + table%rows(known%com_cols(2, q), k)
        case (from_slides)
          ! c x u_e = r_e for the two guides: Cramer's rule
          do e = 1, 2
            r(e) = across(pass(st)%slide(e), m, accel, c)
          end do
          associate (u1 => u(:, pass(st)%slide(1)), u2 => u(:, pass(st)%slide(2)))
            det = u1(1) * u2(2) - u1(2) * u2(1)
            if (abs(det) <= 1.0e-9_wp) then
              parallel = .true.
              return
            end if
            f = [(u1(1) * r(2) - u2(1) * r(1)) / det, (u1(2) * r(2) - u2(2) * r(1)) / det]
          end associate
        case default
          ! (no other kind of step)
          cycle
        end select
        c(1, m) = f(1)
        c(2, m) = f(2)
      end do
    end subroutine translations
    !> The right-hand side r of slider s's equation c_m x u = r for its unknown link m (the
    !> block or the guide's link; the other one known): the block's field minus the guide's
    !> (less the Coriolis acceleration 2 omega_g x v_rel) has no component across the guide.
    pure real(wp) function across(s, m, accel, c)
      integer, intent(in) :: s, m
      logical, intent(in) :: accel
      real(wp), intent(in) :: c(:, :)
      real(wp) :: w(2), cor(2), vrel(2), q(2)
      integer :: b, g
      b = slides(s)%m
      g = slides(s)%g
      q = p(:, s_point(s))
      cor = 0.0_wp
      if (g > 0 .and. accel) then
        vrel = (v0(:, b) + omega(b) * [-q(2), q(1)]) - (v0(:, g) + omega(g) * [-q(2), q(1)])
        cor = 2.0_wp * omega(g) * [-vrel(2), vrel(1)]
      end if
      if (m == b) then
        w = -own(b, q, accel) + cor
        if (g > 0) w = w + c(:, g) + own(g, q, accel)
      else
        w = c(:, b) + own(b, q, accel) - own(g, q, accel) - cor
      end if
      across = w(1) * u(2, s) - w(2) * u(1, s)
    end function across
    !> A link's own part of its field at r (without the translation term).
    pure function own(m, r, accel) result(f)
      integer, intent(in) :: m
      real(wp), intent(in) :: r(2)
      logical, intent(in) :: accel
      real(wp) :: f(2)
      if (accel) then
        f = eps(m) * [-r(2), r(1)] - omega(m)**2 * r
      else
        f = omega(m) * [-r(2), r(1)]
      end if
    end function own
  end subroutine add_point_motion

  !> The order in which the links' translation terms follow in closed form: from the pivots,
  !> breadth first through the joints; then a link two sliders on known links (or the frame)
  !> hold, with non-parallel guides at the first step; then (accelerations) a link whose
  !> centre of mass's acceleration the table gives; each time breadth first again. `closed`
  !> is false when a link that has a pair equation (a pivot, a joint, a centre of mass, a
  !> slider) is not reached: the pair equations are then solved together (least squares). A
  !> link with no equation stays at rest, as there.
  pure subroutine closed_pass(t, slides, nl, accel, pass, closed)
    type(field_topology_t), intent(in) :: t
    type(slide_t), intent(in) :: slides(:)
    integer, intent(in) :: nl
    logical, intent(in) :: accel
    type(pass_step_t), allocatable, intent(out) :: pass(:)
    logical, intent(out) :: closed
    logical :: reached(nl), bound(nl), progress
    integer :: np, i, ip, n, done, s, other, pick(2), found
    np = size(t%pivot)
    allocate (pass(nl))
    n = 0
    reached = .false.
    do i = 1, nl
      do ip = 1, np
        if (t%incident(ip, i) .and. t%pivot(ip)) then
          call add(pass_step_t(i, from_pivot, ip, 0), pass, n, reached)
          exit
        end if
      end do
    end do
    done = 0
    call spread(pass, n, reached, done)
    progress = .true.
    do while (progress .and. n < nl)
      progress = .false.
      do i = 1, nl
        if (reached(i)) cycle
        found = 0
        pick = 0
        do s = 1, size(slides)
          if (slides(s)%m == i) then
            other = slides(s)%g
          else if (slides(s)%g == i) then
            other = slides(s)%m
          else
            cycle
          end if
          if (other > 0) then
            if (.not. reached(other)) cycle
          end if
          if (found == 1) then
            if (abs(slides(pick(1))%u(1) * slides(s)%u(2) - slides(pick(1))%u(2) * slides(s)%u(1)) <= 1.0e-6_wp) cycle
          end if
          found = found + 1
          pick(found) = s
          if (found == 2) exit
        end do
        if (found < 2) cycle
        call add(pass_step_t(i, from_slides, 0, 0, pick), pass, n, reached)
        call spread(pass, n, reached, done)
        progress = .true.
      end do
      if (progress .or. .not. accel) cycle
      do ip = 1, np
        i = t%com_link(ip)
        if (i == 0) cycle
        if (reached(i)) cycle
        call add(pass_step_t(i, from_com, ip, 0), pass, n, reached)
        call spread(pass, n, reached, done)
        progress = .true.
        exit
      end do
    end do
    pass = pass(1:n)
    ! every link with an equation reached?
    bound = .false.
    do ip = 1, np
      do i = 1, nl
        if (.not. t%incident(ip, i)) cycle
        if (t%pivot(ip) .or. count(t%incident(ip, :)) > 1) bound(i) = .true.
      end do
      if (accel .and. t%com_link(ip) > 0) bound(t%com_link(ip)) = .true.
    end do
    do s = 1, size(slides)
      if (slides(s)%m > 0) bound(slides(s)%m) = .true.
      if (slides(s)%g > 0) bound(slides(s)%g) = .true.
    end do
    closed = .not. any(bound .and. .not. reached)
  contains
    pure subroutine add(st, pass, n, reached)
      type(pass_step_t), intent(in) :: st
      type(pass_step_t), intent(inout) :: pass(:)
      integer, intent(inout) :: n
      logical, intent(inout) :: reached(:)
      if (reached(st%link)) return
      n = n + 1
      pass(n) = st
      reached(st%link) = .true.
    end subroutine add
    !> Breadth first from the links reached but not spread yet, through the joints.
    pure subroutine spread(pass, n, reached, done)
      type(pass_step_t), intent(inout) :: pass(:)
      integer, intent(inout) :: n, done
      logical, intent(inout) :: reached(:)
      integer :: j, q, m
      do while (done < n)
        done = done + 1
        j = pass(done)%link
        do q = 1, np
          if (.not. t%incident(q, j)) cycle
          do m = 1, nl
            if (m /= j .and. t%incident(q, m) .and. .not. reached(m)) call add(pass_step_t(m, from_joint, q, j), &
              pass, n, reached)
          end do
        end do
      end do
    end subroutine spread
  end subroutine closed_pass

  !> The links' omega and eps at row k from their columns (0: none, the rate is 0).
  pure subroutine link_rates(table, k, c_omega, c_eps, omega, eps)
    type(step_table_t), intent(in) :: table
    integer, intent(in) :: k, c_omega(:), c_eps(:)
    !> Angular velocities, rad/s, and accelerations, rad/s^2.
    real(wp), intent(out) :: omega(:), eps(:)
    integer :: i
    do i = 1, size(omega)
      omega(i) = 0.0_wp
      if (c_omega(i) > 0) omega(i) = table%rows(c_omega(i), k)
      eps(i) = 0.0_wp
      if (c_eps(i) > 0) eps(i) = table%rows(c_eps(i), k)
    end do
  end subroutine link_rates

  !> The columns of rows first..last by the plans' least-squares solve of every pair equation,
  !> row by row (a mechanism where the closed-form pass does not reach every link).
  pure subroutine by_least_squares(topo, table, drawing, known, c_omega, c_eps, cx, cy, first, last)
    type(sketch_t), intent(in) :: topo
    type(step_table_t), intent(inout) :: table
    type(drawing_t), intent(inout) :: drawing
    type(field_topology_t), intent(in) :: known
    integer, intent(in) :: c_omega(:), c_eps(:), cx(:), cy(:)
    !> The rows to fill.
    integer, intent(in) :: first, last
    type(plan_vector_t), allocatable :: v(:), a(:)
    real(wp), allocatable :: omega(:), eps(:), v0(:, :), a0(:, :), none(:, :)
    real(wp) :: residual
    integer, allocatable :: image(:)
    integer :: k, nl, ip, iv
    nl = size(topo%links)
    allocate (omega(nl), eps(nl), none(2, nl), image(size(drawing%points)))
    none = 0.0_wp
    do k = first, last
      do ip = 1, size(drawing%points)
        drawing%points(ip)%p = [table%rows(cx(ip), k), table%rows(cy(ip), k)]
      end do
      call link_rates(table, k, c_omega, c_eps, omega, eps)
      call solve_fields(topo, drawing, table, k, omega, eps, .false., none, v0, residual, known)
      call solve_fields(topo, drawing, table, k, omega, eps, .true., v0, a0, residual, known)
      call point_images(topo, drawing, omega, eps, v0, .false., v, known)
      call point_images(topo, drawing, omega, eps, a0, .true., a, known)
      if (k == first) then
        do ip = 1, size(drawing%points)
          image(ip) = findloc(v%name, drawing%points(ip)%name, dim=1)
        end do
      end if
      do ip = 1, size(drawing%points)
        associate (pt => drawing%points(ip))
          iv = image(ip)
          if (iv == 0) cycle
          if (pt%kind == point_pivot) then
            call table%put_velocity(k, trim(pt%name), [0.0_wp, 0.0_wp])
            call table%put_acceleration(k, trim(pt%name), [0.0_wp, 0.0_wp])
          else
            call table%put_velocity(k, trim(pt%name), v(iv)%v)
            if (pt%kind /= point_com) call table%put_acceleration(k, trim(pt%name), a(iv)%v)
          end if
        end associate
      end do
    end do
  end subroutine by_least_squares

end module kinetostat_point_motion
