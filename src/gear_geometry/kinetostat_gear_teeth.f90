!> The outline of one tooth of a spur gear cut by the generating rack, for the meshing drawing:
!> the involute flanks (kinetostat_gear_geometry's involute_flank, so every flank point lies on
!> an involute of the base circle), the root fillet the rack's rounded tip cuts (its envelope
!> in the rolling of the rack's line x*m off its reference line on the pitch circle), the root
!> arc and the tip arc. An undercut tooth (x < x_min) is cut as the rack cuts it: the fillet's
!> trace crosses the involute, and the flank begins at the crossing; a pointed tooth ends where
!> its two flanks meet, below the tip circle.
!>
!> The rack (ГОСТ 13755's form): profile angle alpha, addendum ha*·m, clearance c*·m, its tip
!> rounded by rho_f = c*·m/(1 - sin alpha), the largest radius that keeps the straight flank
!> down to the depth ha*·m (0.38·m for the standard rack; less when the rack's tooth is too
!> narrow for it). Lengths in mm, angles in rad. Pure; no I/O.
module kinetostat_gear_teeth
  use kinetostat_kinds, only: wp, pi
  use kinetostat_vec2, only: rotate
  use kinetostat_gear_geometry, only: gear_pair_t, pair_geometry_t, involute, inverse_involute, involute_flank
  implicit none
  private
  public :: tooth_outline_t, tooth_outline, rack_tip_radius

  !> Points of the fillet's trace, of the involute and of the undercut search.
  integer, parameter :: fillet_points = 48, flank_points = 28, search_points = 160

  !> One tooth in its own frame: the gear's centre at the origin, the tooth's axis along +x.
  !> The side given is the one at positive angles (counter-clockwise from the axis); the other
  !> side is its mirror image in the x axis.
  type :: tooth_outline_t
    !> The angular pitch 2 pi/z, rad; half of it is where the spaces' middles are.
    real(wp) :: pitch_angle = 0.0_wp
    !> Root, base, tip radius, mm.
    real(wp) :: rf = 0.0_wp, rb = 0.0_wp, ra = 0.0_wp
    !> The root arc of the side: from the space's middle (angle pitch_angle/2) to where the
    !> fillet starts (angle root_end), on the root circle.
    real(wp) :: root_end = 0.0_wp
    !> The fillet from the root circle up to where the flank begins, mm (2, n).
    real(wp), allocatable :: fillet(:, :)
    !> The involute flank from the fillet's end up to the tip (or the point), mm (2, n).
    real(wp), allocatable :: flank(:, :)
    !> Radius where the flank begins (the limit point, or the undercut's crossing), mm.
    real(wp) :: r_join = 0.0_wp
    !> Radius where the flank ends: the tip circle, or the point of a pointed tooth, mm.
    real(wp) :: r_end = 0.0_wp
    !> Half the tip land's angle (0 for a pointed tooth), rad.
    real(wp) :: tip_half = 0.0_wp
    !> The involute's angle at the base circle, rad: a flank point at radius r has the polar
    !> angle base_half - inv(acos(rb/r)).
    real(wp) :: base_half = 0.0_wp
  end type tooth_outline_t

contains

  !> The radius of the generating rack's tip rounding, mm: c*·m/(1 - sin alpha), smaller when
  !> the rack's tooth has not the room for it (its tip land would be negative), 0 at least.
  pure real(wp) function rack_tip_radius(p)
    !> The pair (its basic rack).
    type(gear_pair_t), intent(in) :: p
    real(wp) :: room
    rack_tip_radius = p%c_star * p%m / (1.0_wp - sin(p%alpha))
    ! the half tip land with that radius: pi m/4 - (ha* + c*) m tan(a) + rho tan(a) - rho/cos(a)
    room = 0.25_wp * pi * p%m - (p%ha_star + p%c_star) * p%m * tan(p%alpha)
    if (room + rack_tip_radius * (tan(p%alpha) - 1.0_wp / cos(p%alpha)) < 0.0_wp) then
      rack_tip_radius = max(0.0_wp, room / (1.0_wp / cos(p%alpha) - tan(p%alpha)))
    end if
  end function rack_tip_radius

  !> The outline of a tooth of gear `i` (1 or 2) of the pair with geometry `g`.
  pure function tooth_outline(p, g, i) result(t)
    !> The pair.
    type(gear_pair_t), intent(in) :: p
    !> Its geometry (shifts, diameters, thicknesses).
    type(pair_geometry_t), intent(in) :: g
    !> Which gear.
    integer, intent(in) :: i
    type(tooth_outline_t) :: t
    real(wp) :: z, r, rho, y_ref, y_tip, yc, xc, u_a, u_b, u, t_end, t_n, turn, pxy(2), e(2), d(2)
    real(wp) :: trace(2, 2 * fillet_points), inv_curve(2, search_points), cross_at(2), alpha_p, r_point
    integer :: k, n_trace, hit
    logical :: undercut

    z = real(merge(p%z1, p%z2, i == 1), wp)
    r = 0.5_wp * g%d(i)
    t%pitch_angle = 2.0_wp * pi / z
    t%rf = 0.5_wp * g%df(i)
    t%rb = 0.5_wp * g%db(i)
    t%ra = 0.5_wp * g%da(i)
    t%base_half = g%s(i) / g%d(i) + involute(p%alpha)
    ! the point of a pointed tooth: the flank's angle falls to 0
    alpha_p = inverse_involute(t%base_half)
    r_point = t%rb / cos(alpha_p)

    ! the rack in the fixed frame: the gear's centre at the origin, the space cut at +y, the
    ! rolling line y = r touching the pitch circle at I = (0, r); the rack's reference line at
    ! y = r + x m, its tip line at y = rf; the rounding's centre (xc, yc) of the tooth's right
    ! side (x > 0); the rack moved by u turns the gear by -u/r.
    rho = rack_tip_radius(p)
    y_ref = r + g%x(i) * p%m
    y_tip = y_ref - (p%ha_star + p%c_star) * p%m
    yc = y_tip + rho
    xc = max(0.0_wp, 0.25_wp * pi * p%m - (y_ref - yc) * tan(p%alpha) - rho / cos(p%alpha))
    ! the rounding cuts from its lowest point (the tip line's end, u_a) to its tangent point
    ! with the straight flank (u_b), where its normal through I leans by alpha
    u_a = -xc
    u_b = -xc + (r - yc) / tan(p%alpha)
    n_trace = 0
    do k = 1, fillet_points
      u = u_a + (u_b - u_a) * real(k - 1, wp) / real(fillet_points - 1, wp)
      d = [xc + u, yc - r]
      if (d(2) > 0.0_wp) d = -d
      if (norm2(d) > 0.0_wp) then
        d = d / norm2(d)
      else
        d = [cos(p%alpha), -sin(p%alpha)]
      end if
      e = [xc + u, yc] + rho * d
      n_trace = n_trace + 1
      trace(:, n_trace) = to_tooth(e, u)
    end do
    ! the straight flank below the pitch point: its contact runs along the rack's line of
    ! action from I (distance 0) to the tangent point (t_end); past N (t_n = r sin alpha) it
    ! cuts into the involute: an undercut, whose trace follows the fillet's
    t_end = (r - (yc - rho * sin(p%alpha))) / sin(p%alpha)
    t_n = r * sin(p%alpha)
    undercut = t_end > t_n
    if (undercut) then
      do k = 1, fillet_points
        turn = t_end + (t_n - t_end) * real(k, wp) / real(fillet_points, wp)
        e = [turn * cos(p%alpha), r - turn * sin(p%alpha)]
        u = e(1) - (0.25_wp * pi * p%m - (y_ref - e(2)) * tan(p%alpha))
        n_trace = n_trace + 1
        trace(:, n_trace) = to_tooth(e, u)
      end do
    end if

    ! where the root arc ends: the fillet's first point
    t%root_end = atan2(trace(2, 1), trace(1, 1))
    t%r_end = min(t%ra, r_point)
    hit = 0
    if (undercut) then
      ! the flank begins where the trace crosses the involute (first crossing along the
      ! trace from the root, away from the cusp on the base circle)
      do k = 1, search_points
        inv_curve(:, k) = flank_point(t%rb + (t%r_end - t%rb) * (real(k - 1, wp) / real(search_points - 1, wp))**2)
      end do
      call first_crossing(trace(:, 1:n_trace), inv_curve, hit, cross_at)
    end if
    if (hit > 0) then
      t%fillet = reshape([trace(:, 1:hit), cross_at], [2, hit + 1])
      t%r_join = norm2(cross_at)
    else if (undercut) then
      ! no crossing found: the trace up to the cusp, the flank from the base circle
      t%fillet = trace(:, 1:n_trace)
      t%r_join = t%rb
    else
      t%fillet = trace(:, 1:fillet_points)
      t%r_join = norm2(trace(:, fillet_points))
    end if
    t%r_join = max(t%rb, min(t%r_join, t%r_end))
    allocate (t%flank(2, flank_points))
    t%flank = involute_flank(t%rb, t%r_join, t%r_end, flank_points)
    do k = 1, flank_points
      pxy = t%flank(:, k)
      t%flank(:, k) = rotate([pxy(1), -pxy(2)], t%base_half)
    end do
    t%tip_half = 0.0_wp
    if (t%ra < r_point) t%tip_half = t%base_half - involute(acos(min(1.0_wp, t%rb / t%ra)))
  contains
    !> A point of the rack (fixed frame, rack moved by uu) in the frame of the tooth right of
    !> the space (its axis at pi/2 - pi/z): turned with the gear, then by -(pi/2 - pi/z).
    pure function to_tooth(q, uu) result(v)
      real(wp), intent(in) :: q(2), uu
      real(wp) :: v(2)
      v = rotate(q, uu / r - (0.5_wp * pi - 0.5_wp * t%pitch_angle))
    end function to_tooth
    !> The flank's point at radius rr (counter-clockwise side).
    pure function flank_point(rr) result(v)
      real(wp), intent(in) :: rr
      real(wp) :: v(2), a
      a = t%base_half - involute(acos(min(1.0_wp, t%rb / rr)))
      v = rr * [cos(a), sin(a)]
    end function flank_point
  end function tooth_outline

  !> The first segment of polyline `a` (from its start) that crosses polyline `b`, and where;
  !> the segments at the two polylines' common end (the cusp on the base circle) are not
  !> counted. hit = 0 when none: else the index in `a` of the crossing segment's first point.
  pure subroutine first_crossing(a, b, hit, at)
    real(wp), intent(in) :: a(:, :), b(:, :)
    integer, intent(out) :: hit
    real(wp), intent(out) :: at(2)
    integer :: i, j
    real(wp) :: d1(2), d2(2), w(2), den, s, q
    hit = 0
    at = 0.0_wp
    do i = 1, size(a, 2) - 2
      d1 = a(:, i + 1) - a(:, i)
      do j = 2, size(b, 2) - 1
        d2 = b(:, j + 1) - b(:, j)
        den = d1(1) * d2(2) - d1(2) * d2(1)
        if (den == 0.0_wp) cycle
        w = b(:, j) - a(:, i)
        s = (w(1) * d2(2) - w(2) * d2(1)) / den
        q = (w(1) * d1(2) - w(2) * d1(1)) / den
        if (s >= 0.0_wp .and. s <= 1.0_wp .and. q >= 0.0_wp .and. q <= 1.0_wp) then
          hit = i
          at = a(:, i) + s * d1
          return
        end if
      end do
    end do
  end subroutine first_crossing

end module kinetostat_gear_teeth
