!> Geometry of an external spur pair of involute gears with profile shift (the course's gear
!> synthesis, "геометрический расчет эвольвентной зубчатой передачи"): working pressure angle
!> from inv(alpha_w) = inv(alpha) + 2 (x1 + x2) tan(alpha) / (z1 + z2), centre distance,
!> the centre-distance coefficient y and the addendum reduction delta_y = x1 + x2 - y (the
!> standard clearance kept: da = d + 2m(ha* + x - delta_y)), diameters, tooth thicknesses,
!> the transverse contact ratio, the undercut, pointed-tooth and interference conditions, the
!> specific sliding, the choice of the shifts (equal maximum specific sliding inside the
!> blocking contour), the blocking contour's curves, and the points a meshing drawing needs
!> (involute flanks, the line of action). Lengths in mm, angles in rad. Pure; no I/O.
module kinetostat_gear_geometry
  use kinetostat_kinds, only: wp, pi
  use kinetostat_error, only: error_t, fatal_error, exit_geometry, exit_input
  use kinetostat_format, only: short_number
  implicit none
  private
  public :: gear_pair_t, pair_geometry_t, contour_curve_t
  public :: involute, inverse_involute, pair_geometry, shift_sum_for_centre, pair_is_acceptable
  public :: equal_sliding_x2, equal_sliding_split, auto_shift, blocking_contour, contour_names
  public :: involute_flank, line_of_action, eps_alpha_min, contour_lo, contour_hi

  !> The least transverse contact ratio of an automatic choice of the shifts.
  real(wp), parameter :: eps_alpha_min = 1.2_wp
  !> The blocking contour is traced in the square contour_lo <= x1, x2 <= contour_hi.
  real(wp), parameter :: contour_lo = -1.0_wp, contour_hi = 2.0_wp
  !> Grid lines of the contour's square along each axis (marching squares, then bisection on
  !> the cell edges).
  integer, parameter :: contour_grid = 121
  !> Range of the shifts the automatic choice searches, and its grid step.
  real(wp), parameter :: search_lo = -3.0_wp, search_hi = 5.0_wp, search_step = 0.02_wp
  !> The curves of the blocking contour, in output order.
  character(*), parameter :: contour_names(*) = [character(len=13) :: "undercut1", "undercut2", "pointed1", &
    "pointed2", "eps1", "eps1_2", "interference1", "interference2"]
  !> Specific sliding taken as infinite (the active path reaches the other gear's base circle).
  real(wp), parameter :: sliding_huge = 1.0e30_wp

  !> The pair as designed: module, teeth and the basic rack (generating rack).
  type :: gear_pair_t
    !> Module m, mm.
    real(wp) :: m = 1.0_wp
    !> Teeth of gear 1 (the pinion) and gear 2.
    integer :: z1 = 0, z2 = 0
    !> Profile angle of the basic rack alpha, rad.
    real(wp) :: alpha = 20.0_wp * pi / 180.0_wp
    !> Addendum coefficient ha* of the basic rack.
    real(wp) :: ha_star = 1.0_wp
    !> Bottom clearance coefficient c* of the basic rack.
    real(wp) :: c_star = 0.25_wp
    !> The least tooth thickness on the tip circle, in modules.
    real(wp) :: sa_min_star = 0.25_wp
  end type gear_pair_t

  !> The geometry of the pair for shifts x1, x2 (index 1: gear 1, 2: gear 2).
  type :: pair_geometry_t
    !> False when no working pressure angle exists (inv(alpha_w) <= 0: the shifts' sum is
    !> too negative), or a tip circle lies inside its base circle (no involute flank).
    logical :: valid = .false.
    !> Profile shift coefficients x1, x2.
    real(wp) :: x(2) = 0.0_wp
    !> Standard centre distance a = m (z1 + z2)/2, mm.
    real(wp) :: a = 0.0_wp
    !> Working centre distance a_w, mm.
    real(wp) :: a_w = 0.0_wp
    !> Working pressure angle alpha_w, rad.
    real(wp) :: alpha_w = 0.0_wp
    !> Centre distance coefficient y = (a_w - a)/m.
    real(wp) :: y = 0.0_wp
    !> Addendum reduction coefficient delta_y = x1 + x2 - y.
    real(wp) :: delta_y = 0.0_wp
    !> Pitch (reference), base, working pitch, tip and root diameters, mm.
    real(wp) :: d(2) = 0.0_wp, db(2) = 0.0_wp, dw(2) = 0.0_wp, da(2) = 0.0_wp, df(2) = 0.0_wp
    !> Tooth thickness on the pitch circle and on the tip circle, mm.
    real(wp) :: s(2) = 0.0_wp, sa(2) = 0.0_wp
    !> The shift below which the generating rack undercuts the tooth: ha* - (z/2) sin^2(alpha).
    real(wp) :: x_min(2) = 0.0_wp
    !> Transverse contact ratio.
    real(wp) :: eps_alpha = 0.0_wp
    !> x < x_min; sa < sa_min_star*m; the mating tip meshes below this gear's base circle.
    logical :: undercut(2) = .false., pointed(2) = .false., interference(2) = .false.
    !> Radius of curvature of each involute at the tip, sqrt(ra^2 - rb^2) (0 when the tip
    !> circle lies inside the base circle), mm: the tip's distance from N1 (gear 1) or N2.
    real(wp) :: rho_tip(2) = 0.0_wp
    !> Length N1N2 of the line of action between the base circles' tangent points, mm.
    real(wp) :: g = 0.0_wp
    !> Radius of curvature of each gear's involute at its lowest point of contact, mm: the
    !> active path's end near N1 (gear 1) or N2 (gear 2); negative beyond it (interference).
    real(wp) :: rho_low(2) = 0.0_wp
    !> Largest magnitude of the specific sliding of each gear over the active path.
    real(wp) :: sliding(2) = 0.0_wp
    !> Base pitch p_b = pi m cos(alpha), mm.
    real(wp) :: base_pitch = 0.0_wp
  end type pair_geometry_t

  !> One curve of the blocking contour as pieces of polyline in the (x1, x2) plane.
  type :: contour_curve_t
    !> Its name (contour_names).
    character(len=:), allocatable :: name
    !> The points, in order along the curve.
    real(wp), allocatable :: x1(:), x2(:)
    !> First point of each piece (a piece runs to the next one's start; size: pieces).
    integer, allocatable :: piece_start(:)
  end type contour_curve_t

contains

  !> The involute function inv(a) = tan(a) - a.
  elemental real(wp) function involute(a)
    !> Angle, rad, in [0, pi/2).
    real(wp), intent(in) :: a
    involute = tan(a) - a
  end function involute

  !> The angle a in [0, pi/2) with inv(a) = v (v >= 0): Newton's method on tan(a) - a - v,
  !> kept inside a bisection bracket.
  elemental real(wp) function inverse_involute(v) result(a)
    !> Value of the involute function, >= 0.
    real(wp), intent(in) :: v
    real(wp) :: lo, hi, f, step
    integer :: k
    lo = 0.0_wp
    hi = 0.5_wp * pi
    if (.not. v > 0.0_wp) then
      a = 0.0_wp
      return
    end if
    a = min((3.0_wp * v)**(1.0_wp / 3.0_wp), atan(v + 1.0_wp))
    do k = 1, 200
      f = tan(a) - a - v
      if (f > 0.0_wp) then
        hi = a
      else
        lo = a
      end if
      step = f / tan(a)**2
      if (a - step > lo .and. a - step < hi) then
        a = a - step
      else
        step = a - 0.5_wp * (lo + hi)
        a = 0.5_wp * (lo + hi)
      end if
      if (abs(step) <= 4.0_wp * epsilon(1.0_wp) * a .or. hi - lo <= 4.0_wp * epsilon(1.0_wp) * a) exit
    end do
  end function inverse_involute

  !> The geometry of the pair with shifts x1, x2.
  pure function pair_geometry(p, x1, x2) result(g)
    !> The pair.
    type(gear_pair_t), intent(in) :: p
    !> Profile shift coefficients.
    real(wp), intent(in) :: x1, x2
    type(pair_geometry_t) :: g
    real(wp) :: inv_w, r(2), rb(2), ra(2), alpha_a, z(2), lambda(2), low, high
    integer :: i, j
    z = [real(p%z1, wp), real(p%z2, wp)]
    g%x = [x1, x2]
    inv_w = involute(p%alpha) + 2.0_wp * (x1 + x2) * tan(p%alpha) / (z(1) + z(2))
    g%valid = inv_w > 0.0_wp
    if (.not. g%valid) return
    g%alpha_w = inverse_involute(inv_w)
    g%a = 0.5_wp * p%m * (z(1) + z(2))
    g%a_w = g%a * cos(p%alpha) / cos(g%alpha_w)
    g%y = (g%a_w - g%a) / p%m
    g%delta_y = x1 + x2 - g%y
    g%base_pitch = pi * p%m * cos(p%alpha)
    g%g = g%a_w * sin(g%alpha_w)
    do i = 1, 2
      g%d(i) = p%m * z(i)
      g%db(i) = g%d(i) * cos(p%alpha)
      g%dw(i) = g%d(i) * cos(p%alpha) / cos(g%alpha_w)
      g%da(i) = g%d(i) + 2.0_wp * p%m * (p%ha_star + g%x(i) - g%delta_y)
      g%df(i) = g%d(i) - 2.0_wp * p%m * (p%ha_star + p%c_star - g%x(i))
      g%s(i) = p%m * (0.5_wp * pi + 2.0_wp * g%x(i) * tan(p%alpha))
      r(i) = 0.5_wp * g%d(i)
      rb(i) = 0.5_wp * g%db(i)
      ra(i) = 0.5_wp * g%da(i)
      alpha_a = 0.0_wp
      if (ra(i) > rb(i)) alpha_a = acos(rb(i) / ra(i))
      g%sa(i) = g%da(i) * (g%s(i) / g%d(i) + involute(p%alpha) - involute(alpha_a))
      g%x_min(i) = p%ha_star - 0.5_wp * z(i) * sin(p%alpha)**2
      g%rho_tip(i) = sqrt(max(0.0_wp, ra(i)**2 - rb(i)**2))
    end do
    ! a tip circle inside the base circle leaves no involute flank: no gear
    if (any(ra <= rb)) then
      g%valid = .false.
      return
    end if
    g%eps_alpha = (g%rho_tip(1) + g%rho_tip(2) - g%g) / g%base_pitch
    ! the active path: on gear i from its lowest point of contact (the mating tip) to its tip
    do i = 1, 2
      j = 3 - i
      g%rho_low(i) = g%g - g%rho_tip(j)
      low = sliding_at(g%rho_low(i), z(i) / z(j))
      high = sliding_at(g%rho_tip(i), z(i) / z(j))
      lambda(i) = max(abs(low), abs(high))
      g%undercut(i) = g%x(i) < g%x_min(i)
      g%pointed(i) = g%sa(i) < p%sa_min_star * p%m
      g%interference(i) = g%rho_low(i) < 0.0_wp
    end do
    g%sliding = lambda
  contains
    !> Specific sliding of gear i at the point of the line of action at distance rho from its
    !> tangent point: 1 - (g - rho)/rho * z_i/z_j (infinite at and beyond the tangent point).
    pure real(wp) function sliding_at(rho, ratio)
      real(wp), intent(in) :: rho, ratio
      if (rho > 0.0_wp) then
        sliding_at = 1.0_wp - (g%g - rho) / rho * ratio
      else
        sliding_at = -sliding_huge
      end if
    end function sliding_at
  end function pair_geometry

  !> x1 + x2 for a prescribed working centre distance a_w (mm): cos(alpha_w) = a cos(alpha)/a_w,
  !> x1 + x2 = (inv(alpha_w) - inv(alpha)) (z1 + z2) / (2 tan(alpha)).
  pure subroutine shift_sum_for_centre(p, a_w, x_sum, error)
    !> The pair.
    type(gear_pair_t), intent(in) :: p
    !> Working centre distance, mm.
    real(wp), intent(in) :: a_w
    !> The sum of the shifts.
    real(wp), intent(out) :: x_sum
    !> a_w at or below a cos(alpha): no working pressure angle.
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: a, c, alpha_w
    a = 0.5_wp * p%m * real(p%z1 + p%z2, wp)
    c = a * cos(p%alpha) / a_w
    x_sum = 0.0_wp
    if (.not. c < 1.0_wp) then
      call fatal_error(error, exit_input, "must exceed a*cos(alpha) = "//short_number(a * cos(p%alpha))// &
        " mm (the base circles would overlap)")
      return
    end if
    alpha_w = acos(c)
    x_sum = (involute(alpha_w) - involute(p%alpha)) * real(p%z1 + p%z2, wp) / (2.0_wp * tan(p%alpha))
  end subroutine shift_sum_for_centre

  !> Whether the pair with these shifts meets every condition of the blocking contour: no
  !> undercut, no pointed tooth, no interference, eps_alpha >= eps_alpha_min.
  pure logical function pair_is_acceptable(g)
    !> Geometry of the pair.
    type(pair_geometry_t), intent(in) :: g
    pair_is_acceptable = g%valid
    if (.not. g%valid) return
    pair_is_acceptable = .not. (any(g%undercut) .or. any(g%pointed) .or. any(g%interference)) .and. &
      g%eps_alpha >= eps_alpha_min
  end function pair_is_acceptable

  !> Sliding balance lambda1 - lambda2 of the pair (x1, x2): huge and signed towards the gear
  !> whose active path reaches the other's base circle; NaN-free.
  pure real(wp) function sliding_balance(p, x1, x2) result(f)
    type(gear_pair_t), intent(in) :: p
    real(wp), intent(in) :: x1, x2
    type(pair_geometry_t) :: g
    g = pair_geometry(p, x1, x2)
    if (.not. g%valid) then
      f = 0.0_wp
      return
    end if
    f = g%sliding(1) - g%sliding(2)
  end function sliding_balance

  !> For shift x1, the shift x2 that makes the largest specific sliding of both gears equal
  !> (lambda1 - lambda2 grows with x2): the first change of sign from - to + on a grid of x2
  !> over [search_lo, search_hi], then bisection. `found` is false when there is none.
  pure subroutine equal_sliding_x2(p, x1, x2, found)
    !> The pair.
    type(gear_pair_t), intent(in) :: p
    !> Shift of gear 1.
    real(wp), intent(in) :: x1
    !> Shift of gear 2.
    real(wp), intent(out) :: x2
    !> Whether the root exists in the range.
    logical, intent(out) :: found
    call balance_root(p, x1, 0.0_wp, .false., x2, found)
  end subroutine equal_sliding_x2

  !> For a fixed sum x1 + x2 (a prescribed centre distance), the split with equal largest
  !> specific sliding (lambda1 - lambda2 falls as x1 grows along the line).
  pure subroutine equal_sliding_split(p, x_sum, x1, x2, error)
    !> The pair.
    type(gear_pair_t), intent(in) :: p
    !> x1 + x2.
    real(wp), intent(in) :: x_sum
    !> The shifts.
    real(wp), intent(out) :: x1, x2
    !> No split with equal sliding in the searched range.
    type(error_t), allocatable, intent(out) :: error
    logical :: found
    call balance_root(p, 0.0_wp, x_sum, .true., x1, found)
    x2 = x_sum - x1
    if (.not. found) call fatal_error(error, exit_geometry, "no split of x1 + x2 = "//short_number(x_sum)// &
      " gives both gears the same largest specific sliding (x1 from "//short_number(search_lo)//" to "// &
      short_number(search_hi)//")")
  end subroutine equal_sliding_split

  !> The root of the sliding balance along a line of the (x1, x2) plane: x2 for a fixed x1
  !> (`on_sum` false), or x1 with x2 = x_sum - x1 (`on_sum` true). A grid of root_step over
  !> [search_lo, search_hi] for the change of sign (the balance is monotonic along either
  !> line, but infinite where an active path reaches a base circle), bisection, and the
  !> balance at the root must be small (not the edge of an infinite stretch).
  pure subroutine balance_root(p, x1_fixed, x_sum, on_sum, root, found)
    type(gear_pair_t), intent(in) :: p
    real(wp), intent(in) :: x1_fixed, x_sum
    logical, intent(in) :: on_sum
    real(wp), intent(out) :: root
    logical, intent(out) :: found
    !> Grid step of the root's search along the line.
    real(wp), parameter :: root_step = 0.1_wp
    real(wp) :: t0, t1, f0, f1, tm, fm, sense
    type(pair_geometry_t) :: g
    integer :: k, n, it
    ! along x2 the balance rises; along x1 (on a fixed sum) it falls: look for the change
    ! towards the rising sense
    sense = 1.0_wp
    if (on_sum) sense = -1.0_wp
    n = nint((search_hi - search_lo) / root_step)
    found = .false.
    root = 0.0_wp
    t0 = search_lo
    f0 = sense * balance(t0)
    do k = 1, n
      t1 = search_lo + real(k, wp) * root_step
      f1 = sense * balance(t1)
      if (f0 < 0.0_wp .and. f1 >= 0.0_wp) then
        found = .true.
        exit
      end if
      t0 = t1
      f0 = f1
    end do
    if (.not. found) return
    do it = 1, 200
      tm = 0.5_wp * (t0 + t1)
      if (tm <= t0 .or. tm >= t1) exit
      fm = sense * balance(tm)
      if (fm < 0.0_wp) then
        t0 = tm
      else
        t1 = tm
      end if
    end do
    root = 0.5_wp * (t0 + t1)
    if (on_sum) then
      g = pair_geometry(p, root, x_sum - root)
    else
      g = pair_geometry(p, x1_fixed, root)
    end if
    found = g%valid
    if (found) found = abs(g%sliding(1) - g%sliding(2)) <= 1.0e-9_wp * (g%sliding(1) + g%sliding(2))
  contains
    pure real(wp) function balance(t)
      real(wp), intent(in) :: t
      if (on_sum) then
        balance = sliding_balance(p, t, x_sum - t)
      else
        balance = sliding_balance(p, x1_fixed, t)
      end if
    end function balance
  end subroutine balance_root

  !> The course's choice of the shifts inside the blocking contour: on the curve of equal
  !> largest specific sliding (x2 of x1 by equal_sliding_x2), the acceptable point
  !> (pair_is_acceptable) nearest to the unshifted pair (the least x1^2 + x2^2). A grid of
  !> x1, then, around its best point, bisection onto the acceptable range's ends and a
  !> golden-section search inside it; x1 is kept to 1e-6, x2 is its equal-sliding partner.
  pure subroutine auto_shift(p, x1, x2, error)
    !> The pair.
    type(gear_pair_t), intent(in) :: p
    !> The shifts chosen.
    real(wp), intent(out) :: x1, x2
    !> No acceptable point with equal sliding.
    type(error_t), allocatable, intent(out) :: error
    integer :: n, k, best
    real(wp) :: t, lo, hi, a, b, c, d, fc, fd
    real(wp), allocatable :: grid(:), norm(:)
    logical, allocatable :: ok(:)
    real(wp), parameter :: golden = 0.6180339887498948482_wp
    integer :: it

    n = nint((search_hi - search_lo) / search_step)
    allocate (grid(0:n), norm(0:n), ok(0:n))
    do k = 0, n
      grid(k) = search_lo + real(k, wp) * search_step
      call point(grid(k), ok(k), norm(k))
    end do
    x1 = 0.0_wp
    x2 = 0.0_wp
    if (.not. any(ok)) then
      call fatal_error(error, exit_geometry, "no shifts x1, x2 (from "//short_number(search_lo)//" to "//short_number(search_hi)// &
        ") give equal largest specific sliding without undercut, pointed teeth or interference and with "// &
        "eps_alpha >= 1.2: give x1 and x2 (see the blocking contour: kinetostat contour DECK)")
      return
    end if
    best = minloc(norm, mask=ok, dim=1) - 1
    ! the acceptable stretch around the best grid point, its ends found by bisection
    lo = grid(best)
    hi = grid(best)
    if (best > 0) then
      if (ok(best - 1)) then
        lo = grid(best - 1)
      else
        lo = edge(grid(best), grid(best - 1))
      end if
    end if
    if (best < n) then
      if (ok(best + 1)) then
        hi = grid(best + 1)
      else
        hi = edge(grid(best), grid(best + 1))
      end if
    end if
    ! golden section for the least norm on [lo, hi] (acceptable throughout)
    a = lo
    b = hi
    c = b - golden * (b - a)
    d = a + golden * (b - a)
    fc = norm_at(c)
    fd = norm_at(d)
    do it = 1, 200
      if (b - a <= 1.0e-13_wp * max(1.0_wp, abs(a))) exit
      if (fc <= fd) then
        b = d
        d = c
        fd = fc
        c = b - golden * (b - a)
        fc = norm_at(c)
      else
        a = c
        c = d
        fc = fd
        d = a + golden * (b - a)
        fd = norm_at(d)
      end if
    end do
    t = 0.5_wp * (a + b)
    ! the ends themselves may be best (the optimum on a boundary of the contour)
    if (norm_at(lo) <= norm_at(t)) t = lo
    if (norm_at(hi) < norm_at(t)) t = hi
    ! x1 to 1e-6 (a smooth minimum's place is known to about 1e-8 only), on the acceptable
    ! side of a boundary
    x1 = anint(t * 1.0e6_wp) / 1.0e6_wp
    call point(x1, ok(0), c)
    if (.not. ok(0)) then
      x1 = x1 + sign(1.0e-6_wp, t - x1)
      if (x1 == anint(t * 1.0e6_wp) / 1.0e6_wp) x1 = x1 + 1.0e-6_wp
      call point(x1, ok(0), c)
      if (.not. ok(0)) x1 = t
    end if
    call equal_sliding_x2(p, x1, x2, ok(0))
  contains
    !> Whether x1 = t gives an acceptable point on the equal-sliding curve, and its norm.
    pure subroutine point(t, good, size2)
      real(wp), intent(in) :: t
      logical, intent(out) :: good
      real(wp), intent(out) :: size2
      real(wp) :: s2
      logical :: found
      call equal_sliding_x2(p, t, s2, found)
      good = found
      size2 = huge(1.0_wp)
      if (.not. found) return
      good = pair_is_acceptable(pair_geometry(p, t, s2))
      size2 = t**2 + s2**2
    end subroutine point
    !> x1^2 + x2^2 on the equal-sliding curve at x1 = t.
    pure real(wp) function norm_at(t) result(size2)
      real(wp), intent(in) :: t
      logical :: good
      real(wp) :: value
      call point(t, good, value)
      size2 = value
    end function norm_at
    !> The end of the acceptable stretch between an acceptable `inside` and `outside`.
    pure real(wp) function edge(inside, outside)
      real(wp), intent(in) :: inside, outside
      real(wp) :: a_in, a_out, mid, size2
      logical :: good
      integer :: j
      a_in = inside
      a_out = outside
      do j = 1, 200
        mid = 0.5_wp * (a_in + a_out)
        if (mid == a_in .or. mid == a_out) exit
        call point(mid, good, size2)
        if (good) then
          a_in = mid
        else
          a_out = mid
        end if
      end do
      edge = a_in
    end function edge
  end subroutine auto_shift

  !> The blocking contour of the pair (z1, z2) in the square contour_lo <= x1, x2 <=
  !> contour_hi: the undercut lines x_i = x_min_i, and the curves sa_i = sa_min_star*m
  !> (pointed1, pointed2), eps_alpha = 1 and 1.2 (eps1, eps1_2), and rho_low_i = 0
  !> (interference1, interference2), traced by marching squares on a grid with each crossing
  !> of a cell edge found by bisection (so every point lies on its curve to rounding).
  pure subroutine blocking_contour(p, curves)
    !> The pair (its shifts do not matter).
    type(gear_pair_t), intent(in) :: p
    !> One curve per contour_names entry (a curve outside the square has no points).
    type(contour_curve_t), intent(out) :: curves(size(contour_names))
    real(wp) :: xs(contour_grid), x_min
    real(wp), allocatable :: field(:, :, :)
    type(pair_geometry_t) :: g
    integer :: i, j, c
    allocate (field(contour_grid, contour_grid, 6))
    do i = 1, contour_grid
      xs(i) = contour_lo + (contour_hi - contour_lo) * real(i - 1, wp) / real(contour_grid - 1, wp)
    end do
    do j = 1, contour_grid
      do i = 1, contour_grid
        g = pair_geometry(p, xs(i), xs(j))
        do c = 1, 6
          field(i, j, c) = level(g, c)
        end do
      end do
    end do
    do c = 1, size(contour_names)
      curves(c)%name = trim(contour_names(c))
    end do
    ! the undercut lines
    do c = 1, 2
      x_min = p%ha_star - 0.5_wp * real(merge(p%z1, p%z2, c == 1), wp) * sin(p%alpha)**2
      if (x_min >= contour_lo .and. x_min <= contour_hi) then
        if (c == 1) then
          curves(c)%x1 = [x_min, x_min]
          curves(c)%x2 = [contour_lo, contour_hi]
        else
          curves(c)%x1 = [contour_lo, contour_hi]
          curves(c)%x2 = [x_min, x_min]
        end if
        curves(c)%piece_start = [1]
      else
        allocate (curves(c)%x1(0), curves(c)%x2(0), curves(c)%piece_start(0))
      end if
    end do
    do c = 1, 6
      call trace(c, curves(c + 2))
    end do
  contains
    !> The quantity whose zero is curve c (pointed1, pointed2, eps1, eps1_2, interference1,
    !> interference2); huge where the pair has no geometry.
    pure real(wp) function level(gg, cc)
      type(pair_geometry_t), intent(in) :: gg
      integer, intent(in) :: cc
      if (.not. gg%valid) then
        level = huge(1.0_wp)
        return
      end if
      select case (cc)
      case (1, 2)
        level = gg%sa(cc) - p%sa_min_star * p%m
      case (3)
        level = gg%eps_alpha - 1.0_wp
      case (4)
        level = gg%eps_alpha - eps_alpha_min
      case default
        level = gg%rho_low(cc - 4)
      end select
    end function level

    !> The level at (x1, x2).
    pure real(wp) function level_at(x1, x2, cc)
      real(wp), intent(in) :: x1, x2
      integer, intent(in) :: cc
      level_at = level(pair_geometry(p, x1, x2), cc)
    end function level_at

    !> Marching squares for field cc: the crossings on the grid's edges (edge_id), the
    !> segments of each cell between them, chained into polylines (chain_segments).
    pure subroutine trace(cc, curve)
      integer, intent(in) :: cc
      type(contour_curve_t), intent(inout) :: curve
      integer, parameter :: ng = contour_grid
      real(wp), allocatable :: pxy(:, :)
      logical, allocatable :: has(:)
      integer, allocatable :: seg(:, :), order(:)
      integer :: nseg, e(4), m, k, i0, j0
      allocate (pxy(2, 2 * ng * ng), has(2 * ng * ng), seg(2, 2 * ng * ng))
      has = .false.
      pxy = 0.0_wp
      do j0 = 1, ng
        do i0 = 1, ng
          if (i0 < ng) call crossing(cc, i0, j0, i0 + 1, j0, has(edge_id(i0, j0, 1)), pxy(:, edge_id(i0, j0, 1)))
          if (j0 < ng) call crossing(cc, i0, j0, i0, j0 + 1, has(edge_id(i0, j0, 2)), pxy(:, edge_id(i0, j0, 2)))
        end do
      end do
      nseg = 0
      do j0 = 1, ng - 1
        do i0 = 1, ng - 1
          ! the cell's edges: bottom, right, top, left
          e = [edge_id(i0, j0, 1), edge_id(i0 + 1, j0, 2), edge_id(i0, j0 + 1, 1), edge_id(i0, j0, 2)]
          m = count(has(e))
          if (m == 2) then
            nseg = nseg + 1
            seg(:, nseg) = pack(e, has(e))
          else if (m == 4) then
            ! a saddle: pair the edges by the cell centre's sign
            if ((field(i0, j0, cc) > 0.0_wp) .eqv. (centre(cc, i0, j0) > 0.0_wp)) then
              seg(:, nseg + 1) = [e(1), e(2)]
              seg(:, nseg + 2) = [e(3), e(4)]
            else
              seg(:, nseg + 1) = [e(1), e(4)]
              seg(:, nseg + 2) = [e(2), e(3)]
            end if
            nseg = nseg + 2
          end if
        end do
      end do
      call chain_segments(seg(:, 1:nseg), order, curve%piece_start)
      allocate (curve%x1(size(order)), curve%x2(size(order)))
      do k = 1, size(order)
        curve%x1(k) = pxy(1, order(k))
        curve%x2(k) = pxy(2, order(k))
      end do
    end subroutine trace

    !> Id of the edge from grid point (i, j) along x1 (dir 1) or x2 (dir 2).
    pure integer function edge_id(i, j, dir)
      integer, intent(in) :: i, j, dir
      edge_id = 2 * ((j - 1) * contour_grid + i) - 2 + dir
    end function edge_id

    !> Level of the curve at the centre of cell (i, j), for a saddle.
    pure real(wp) function centre(cc, i, j)
      integer, intent(in) :: cc, i, j
      centre = level_at(0.5_wp * (xs(i) + xs(i + 1)), 0.5_wp * (xs(j) + xs(j + 1)), cc)
    end function centre

    !> The crossing of curve c on the edge between grid points (i1,j1) and (i2,j2), if its
    !> level changes sign there (both ends with a geometry), by bisection.
    pure subroutine crossing(cc, i1, j1, i2, j2, found, at)
      integer, intent(in) :: cc, i1, j1, i2, j2
      logical, intent(out) :: found
      real(wp), intent(inout) :: at(2)
      real(wp) :: f1, f2, a1(2), a2(2), mid(2), fm
      integer :: it
      found = .false.
      f1 = field(i1, j1, cc)
      f2 = field(i2, j2, cc)
      if (f1 == huge(1.0_wp) .or. f2 == huge(1.0_wp)) return
      if ((f1 > 0.0_wp) .eqv. (f2 > 0.0_wp)) return
      a1 = [xs(i1), xs(j1)]
      a2 = [xs(i2), xs(j2)]
      do it = 1, 100
        mid = 0.5_wp * (a1 + a2)
        if (all(mid == a1 .or. mid == a2)) exit
        fm = level_at(mid(1), mid(2), cc)
        if ((fm > 0.0_wp) .eqv. (f1 > 0.0_wp)) then
          a1 = mid
        else
          a2 = mid
        end if
      end do
      found = .true.
      at = 0.5_wp * (a1 + a2)
    end subroutine crossing
  end subroutine blocking_contour

  !> Segments (pairs of point ids) chained into polylines: `order` the point ids in order,
  !> `starts` the first index of each polyline. Open polylines start at an end (a point id
  !> that one segment only has), then closed loops.
  pure subroutine chain_segments(seg, order, starts)
    !> The segments.
    integer, intent(in) :: seg(:, :)
    !> Point ids in order along the polylines.
    integer, allocatable, intent(out) :: order(:)
    !> Index in `order` of each polyline's first point.
    integer, allocatable, intent(out) :: starts(:)
    logical :: used(size(seg, 2))
    integer :: n, s, q, cur, at, first
    n = size(seg, 2)
    used = .false.
    allocate (order(0), starts(0))
    do
      ! an unused segment with an end no other unused segment shares, else any unused one
      cur = 0
      first = 0
      search: do s = 1, n
        if (used(s)) cycle search
        if (cur == 0) then
          cur = s
          first = seg(1, s)
        end if
        do q = 1, 2
          if (count(.not. used .and. (seg(1, :) == seg(q, s) .or. seg(2, :) == seg(q, s))) == 1) then
            cur = s
            first = seg(q, s)
            exit search
          end if
        end do
      end do search
      if (cur == 0) exit
      starts = [starts, size(order) + 1]
      at = first
      order = [order, at]
      do
        used(cur) = .true.
        at = merge(seg(2, cur), seg(1, cur), seg(1, cur) == at)
        order = [order, at]
        cur = 0
        do q = 1, n
          if (used(q)) cycle
          if (seg(1, q) == at .or. seg(2, q) == at) then
            cur = q
            exit
          end if
        end do
        if (cur == 0) exit
      end do
    end do
  end subroutine chain_segments

  !> Points of an involute of the base circle of radius rb (mm) from radius r_from to r_to
  !> (both >= rb), n >= 2 points equally spaced in the roll angle, in the frame whose +x axis
  !> passes through the involute's start on the base circle; the involute unwinds towards +y
  !> (counter-clockwise): (rb (cos t + t sin t), rb (sin t - t cos t)), t the roll angle.
  pure function involute_flank(rb, r_from, r_to, n) result(xy)
    !> Base circle radius, mm.
    real(wp), intent(in) :: rb
    !> Radii of the first and the last point, mm (>= rb).
    real(wp), intent(in) :: r_from, r_to
    !> Number of points.
    integer, intent(in) :: n
    real(wp) :: xy(2, n)
    real(wp) :: t0, t1, t
    integer :: k
    t0 = sqrt(max(0.0_wp, (r_from / rb)**2 - 1.0_wp))
    t1 = sqrt(max(0.0_wp, (r_to / rb)**2 - 1.0_wp))
    do k = 1, n
      t = t0 + (t1 - t0) * real(k - 1, wp) / real(max(1, n - 1), wp)
      xy(:, k) = rb * [cos(t) + t * sin(t), sin(t) - t * cos(t)]
    end do
  end function involute_flank

  !> The line of action in the frame with O1 at the origin and O2 on the +x axis, the one of
  !> the two through the pitch point P that touches gear 1's base circle above the centre line
  !> (N1 at the angle alpha_w): N1, N2 (the tangent points on the base circles), P, and the
  !> active path's ends B1 (gear 2's tip circle, near N1) and B2 (gear 1's tip circle, near
  !> N2); columns: N1, N2, P, B1, B2; mm.
  pure function line_of_action(g) result(pts)
    !> Geometry of the pair.
    type(pair_geometry_t), intent(in) :: g
    real(wp) :: pts(2, 5)
    real(wp) :: u(2)
    pts(:, 1) = 0.5_wp * g%db(1) * [cos(g%alpha_w), sin(g%alpha_w)]
    u = [sin(g%alpha_w), -cos(g%alpha_w)]
    pts(:, 2) = pts(:, 1) + g%g * u
    pts(:, 3) = [0.5_wp * g%dw(1), 0.0_wp]
    pts(:, 4) = pts(:, 1) + g%rho_low(1) * u
    pts(:, 5) = pts(:, 1) + g%rho_tip(1) * u
  end function line_of_action

end module kinetostat_gear_geometry
