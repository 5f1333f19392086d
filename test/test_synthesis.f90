!> Design kinds: the gear pair's geometry against a second computation (the inverse involute
!> by bisection, eps_alpha from the path of contact's ends, a published example), the undercut flag
!> of z = 12 without shift, the meshing drawing's points on involutes and tip circles, the
!> automatic shifts' conditions, the planetary train against brute force, and the cam: the
!> pressure angle never above its limit and the flat face's radius of curvature never below
!> rho_min on a dense grid, the size minimal (a smaller cam breaks the limit).
module test_synthesis
  use kinetostat_kinds, only: wp, pi, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t
  use kinetostat_gear_geometry, only: gear_pair_t, pair_geometry_t, pair_geometry, involute, inverse_involute, &
    auto_shift, equal_sliding_split, shift_sum_for_centre, pair_is_acceptable, involute_flank, line_of_action, &
    blocking_contour, contour_curve_t, contour_names
  use kinetostat_planetary_synthesis, only: planetary_spec_t, planetary_train_t, planetary_search, train_conditions
  use kinetostat_cam_profile, only: cam_design_t, cam_segment_t, cam_point_t, cam_point, motion_at, size_cam, &
    segment_limit, segment_motion, follower_flat, follower_roller, follower_oscillating, &
    law_dwell, law_cycloidal, law_harmonic, law_poly345, law_parabolic
  use kinetostat_gear_teeth, only: tooth_outline_t, tooth_outline, rack_tip_radius
  use test_harness, only: test_counts_t, check_close, check_true
  implicit none
  private
  public :: run_synthesis_tests

contains

  subroutine run_synthesis_tests(t)
    type(test_counts_t), intent(inout) :: t
    call test_inverse_involute(t)
    call test_published_example(t)
    call test_undercut_z12(t)
    call test_path_of_contact(t)
    call test_drawing_points(t)
    call test_tooth_outline(t)
    call test_auto_shift(t)
    call test_centre_distance(t)
    call test_contour_points(t)
    call test_planetary_brute_force(t)
    call test_cam_laws(t)
    call test_cam_roller_limits(t)
    call test_cam_flat_rho(t)
    call test_cam_oscillating_limits(t)
  end subroutine run_synthesis_tests

  !> inv^-1 (Newton in a bracket) against bisection on tan(a) - a, relative 1e-13.
  subroutine test_inverse_involute(t)
    type(test_counts_t), intent(inout) :: t
    real(wp) :: v, lo, hi, mid
    integer :: k, it
    do k = 1, 12
      v = 10.0_wp**(-7 + k * 0.6_wp)
      lo = 0.0_wp
      hi = 0.5_wp * pi - 1.0e-12_wp
      do it = 1, 200
        mid = 0.5_wp * (lo + hi)
        if (tan(mid) - mid < v) then
          lo = mid
        else
          hi = mid
        end if
      end do
      call check_close(t, "inverse involute vs bisection", 0.5_wp * (lo + hi), inverse_involute(v), 1.0e-13_wp, 0.0_wp)
    end do
    call check_close(t, "inverse involute of inv(20 deg)", 20.0_wp * deg_to_rad, &
      inverse_involute(involute(20.0_wp * deg_to_rad)), 1.0e-14_wp, 0.0_wp)
  end subroutine test_inverse_involute

  !> The published worked example (bolsover.com, "Profile Shifted External Spur Gears":
  !> m 3, z 12/24, x 0.6/0.36; its figures printed to 3-5 digits, its centre distance rounded
  !> to 56.500 mm): alpha_w 26.0888 deg, y 0.83333, dw 37.667/75.333, da 44.840/79.400,
  !> df 32.100/66.660, contact ratio 1.202; within the printed digits and that rounding.
  subroutine test_published_example(t)
    type(test_counts_t), intent(inout) :: t
    type(pair_geometry_t) :: g
    g = pair_geometry(gear_pair_t(m=3.0_wp, z1=12, z2=24), 0.6_wp, 0.36_wp)
    call check_close(t, "example alpha_w", 26.0888_wp, g%alpha_w * rad_to_deg, 0.0_wp, 5.0e-4_wp)
    call check_close(t, "example a_w", 56.500_wp, g%a_w, 0.0_wp, 5.0e-4_wp)
    call check_close(t, "example y", 0.83333_wp, g%y, 0.0_wp, 1.0e-4_wp)
    call check_close(t, "example da1", 44.840_wp, g%da(1), 0.0_wp, 5.0e-4_wp)
    call check_close(t, "example da2", 79.400_wp, g%da(2), 0.0_wp, 5.0e-4_wp)
    call check_close(t, "example df1", 32.100_wp, g%df(1), 0.0_wp, 5.0e-4_wp)
    call check_close(t, "example df2", 66.660_wp, g%df(2), 0.0_wp, 5.0e-4_wp)
    call check_close(t, "example dw1", 37.667_wp, g%dw(1), 0.0_wp, 5.0e-4_wp)
    call check_close(t, "example dw2", 75.333_wp, g%dw(2), 0.0_wp, 5.0e-4_wp)
    call check_close(t, "example eps_alpha", 1.202_wp, g%eps_alpha, 0.0_wp, 5.0e-4_wp)
    call check_true(t, "example pair within the blocking contour", .not. (any(g%undercut) .or. any(g%pointed) .or. &
      any(g%interference)), "a flag is set")
  end subroutine test_published_example

  !> z = 12 without shift is undercut (x_min = 1 - 6 sin^2 20 deg = 0.298), z = 18 is not.
  subroutine test_undercut_z12(t)
    type(test_counts_t), intent(inout) :: t
    type(pair_geometry_t) :: g
    g = pair_geometry(gear_pair_t(m=2.0_wp, z1=12, z2=40), 0.0_wp, 0.0_wp)
    call check_true(t, "z = 12 without shift: undercut1", g%undercut(1), "not flagged")
    call check_true(t, "z = 40 without shift: no undercut2", .not. g%undercut(2), "flagged")
    call check_close(t, "x_min of z = 12", 1.0_wp - 6.0_wp * sin(20.0_wp * deg_to_rad)**2, g%x_min(1), 1.0e-14_wp, 0.0_wp)
    g = pair_geometry(gear_pair_t(m=2.0_wp, z1=12, z2=40), 0.3_wp, 0.0_wp)
    call check_true(t, "z = 12 with x = 0.3: no undercut", .not. g%undercut(1), "flagged")
    ! z_min = 2/sin^2(20 deg) = 17.1: z = 17 is undercut by x_min = 0.0057, z = 18 is not
    g = pair_geometry(gear_pair_t(m=2.0_wp, z1=17, z2=40), 0.0_wp, 0.0_wp)
    call check_true(t, "z = 17 without shift: x_min = 0.0057, undercut", g%undercut(1), "not flagged")
    g = pair_geometry(gear_pair_t(m=2.0_wp, z1=18, z2=40), 0.0_wp, 0.0_wp)
    call check_true(t, "z = 18 without shift: no undercut", .not. g%undercut(1), "flagged")
  end subroutine test_undercut_z12

  !> eps_alpha of the formula against the path of contact measured on the line of action's
  !> points (B1B2 / p_b), and B1, B2 on the tip circles; relative 1e-12.
  subroutine test_path_of_contact(t)
    type(test_counts_t), intent(inout) :: t
    type(pair_geometry_t) :: g
    real(wp) :: pts(2, 5), x(4)
    integer :: k
    x = [0.0_wp, 0.3_wp, 0.6_wp, -0.2_wp]
    do k = 1, 4
      g = pair_geometry(gear_pair_t(m=2.5_wp, z1=18, z2=45), x(k), x(5 - k))
      pts = line_of_action(g)
      call check_close(t, "eps_alpha = B1B2 / p_b", g%eps_alpha, norm2(pts(:, 5) - pts(:, 4)) / g%base_pitch, &
        1.0e-12_wp, 0.0_wp)
      call check_close(t, "B2 on the tip circle of gear 1", 0.5_wp * g%da(1), norm2(pts(:, 5)), 1.0e-12_wp, 0.0_wp)
      call check_close(t, "B1 on the tip circle of gear 2", 0.5_wp * g%da(2), norm2(pts(:, 4) - [g%a_w, 0.0_wp]), &
        1.0e-12_wp, 0.0_wp)
      call check_close(t, "N1 on the base circle of gear 1", 0.5_wp * g%db(1), norm2(pts(:, 1)), 1.0e-12_wp, 0.0_wp)
      call check_close(t, "N2 on the base circle of gear 2", 0.5_wp * g%db(2), norm2(pts(:, 2) - [g%a_w, 0.0_wp]), &
        1.0e-12_wp, 0.0_wp)
      call check_close(t, "the line of action through P", 0.0_wp, &
        (pts(1, 3) - pts(1, 1)) * (pts(2, 2) - pts(2, 1)) - (pts(2, 3) - pts(2, 1)) * (pts(1, 2) - pts(1, 1)), &
        0.0_wp, 1.0e-11_wp)
    end do
  end subroutine test_path_of_contact

  !> The meshing drawing's flank points lie on the involute of the base circle: at radius r
  !> the polar angle from the involute's start is inv(acos(rb/r)) (counter-clockwise).
  subroutine test_drawing_points(t)
    type(test_counts_t), intent(inout) :: t
    real(wp) :: xy(2, 40), rb, r, polar
    integer :: k
    rb = 33.8289343_wp / 2.0_wp
    xy = involute_flank(rb, rb, 22.42_wp, 40)
    do k = 1, 40
      r = norm2(xy(:, k))
      polar = atan2(xy(2, k), xy(1, k))
      call check_close(t, "flank point on the involute", involute(acos(min(1.0_wp, rb / r))), polar, 0.0_wp, 1.0e-13_wp)
    end do
    call check_close(t, "flank ends on the tip circle", 22.42_wp, norm2(xy(:, 40)), 1.0e-13_wp, 0.0_wp)
  end subroutine test_drawing_points

  !> The tooth drawn (kinetostat_gear_teeth) against the tooth the rack cuts, computed a second
  !> way: the rack's outline (straight flank, tip rounding, tip line) moved through 6001
  !> positions of its rolling on the pitch circle, the material it leaves at each of 24 radii
  !> from the root to the tip (the least half angle over all positions), against the outline's
  !> half angle at that radius (its polyline's crossing), within 1e-3 m along the arc (the
  !> drawing's chords between its points are ~5e-4 m off the curve):
  !> ordinary teeth, a pointed one, an undercut one (z = 8 without shift), a negative shift.
  !> And the flank on the involute, the fillet meeting it, the flank through P in the mesh.
  subroutine test_tooth_outline(t)
    type(test_counts_t), intent(inout) :: t
    call case(gear_pair_t(m=4.0_wp, z1=13, z2=27), 0.395615_wp, -0.0902505_wp, 1)
    call case(gear_pair_t(m=4.0_wp, z1=13, z2=27), 0.395615_wp, -0.0902505_wp, 2)
    call case(gear_pair_t(m=3.0_wp, z1=12, z2=24), 0.6_wp, 0.36_wp, 1)
    call case(gear_pair_t(m=5.0_wp, z1=8, z2=20), 0.0_wp, 0.0_wp, 1)
    call case(gear_pair_t(m=2.0_wp, z1=10, z2=30), 1.1_wp, -0.5_wp, 1)
    call case(gear_pair_t(m=2.0_wp, z1=10, z2=30), 1.1_wp, -0.5_wp, 2)
  contains
    subroutine case(p, x1, x2, i)
      type(gear_pair_t), intent(in) :: p
      real(wp), intent(in) :: x1, x2
      integer, intent(in) :: i
      type(pair_geometry_t) :: g
      type(tooth_outline_t) :: tooth
      real(wp), allocatable :: path(:, :)
      real(wp) :: r(24), cut(24), worst, drawn, rr, worst_flank
      integer :: k
      character(len=40) :: name
      g = pair_geometry(p, x1, x2)
      tooth = tooth_outline(p, g, i)
      write (name, '("z = ", i0, ", x = ", f0.3)') merge(p%z1, p%z2, i == 1), g%x(i)
      path = reshape([tooth%fillet, tooth%flank], [2, size(tooth%fillet, 2) + size(tooth%flank, 2)])
      worst = 0.0_wp
      do k = 1, 24
        r(k) = tooth%rf + (tooth%r_end - tooth%rf) * (real(k, wp) - 0.5_wp) / 24.0_wp
      end do
      cut = rack_cut(p, g, i, r)
      do k = 1, 24
        drawn = half_angle(path, r(k))
        worst = max(worst, abs(drawn - cut(k)) * r(k))
      end do
      call check_close(t, "tooth drawn as the rack cuts it, "//trim(name)//" (mm along the arc)", 0.0_wp, worst, &
        0.0_wp, 1.0e-3_wp * p%m)
      ! every flank point on the involute: half angle base_half - inv(acos(rb/r))
      worst_flank = 0.0_wp
      do k = 1, size(tooth%flank, 2)
        rr = norm2(tooth%flank(:, k))
        worst_flank = max(worst_flank, abs(atan2(tooth%flank(2, k), tooth%flank(1, k)) - (tooth%base_half - &
          involute(acos(min(1.0_wp, tooth%rb / rr))))))
      end do
      call check_close(t, "flank on the involute, "//trim(name)//" (rad)", 0.0_wp, worst_flank, 0.0_wp, 1.0e-13_wp)
      call check_close(t, "fillet meets the flank, "//trim(name), 0.0_wp, norm2(tooth%fillet(:, size(tooth%fillet, 2)) &
        - tooth%flank(:, 1)), 0.0_wp, 1.0e-4_wp * p%m)
    end subroutine case
    !> The half angle of the outline `path` at radius r: the least over its crossings.
    pure real(wp) function half_angle(path, r) result(psi)
      real(wp), intent(in) :: path(:, :), r
      real(wp) :: r1, r2, s, q(2)
      integer :: k
      psi = huge(1.0_wp)
      do k = 1, size(path, 2) - 1
        r1 = norm2(path(:, k))
        r2 = norm2(path(:, k + 1))
        if ((r1 - r) * (r2 - r) > 0.0_wp .or. r1 == r2) cycle
        s = (r - r1) / (r2 - r1)
        q = path(:, k) + s * (path(:, k + 1) - path(:, k))
        psi = min(psi, atan2(q(2), q(1)))
      end do
    end function half_angle
    !> The half angle of the tooth the rack leaves at each radius r(m): the rack's right side
    !> (its straight flank down to the rounding, the rounding, the tip line's half) as a
    !> polyline of 161 points, moved by u in 6001 steps, each position turned into the gear's
    !> frame (once for all the radii); the largest angle it reaches right of the space's axis
    !> at radius r(m) is the space's half, pi/z less it the tooth's.
    pure function rack_cut(p, g, i, r) result(psi)
      type(gear_pair_t), intent(in) :: p
      type(pair_geometry_t), intent(in) :: g
      integer, intent(in) :: i
      real(wp), intent(in) :: r(:)
      real(wp) :: psi(size(r))
      real(wp) :: rp, rho, y_ref, y_tip, yc, xc, y_tan, top, side(2, 161), q(2, 161), u, span, best(size(r)), a, z
      real(wp) :: r1, r2, s, e(2), delta, radius(161)
      integer :: k, j, m
      z = real(merge(p%z1, p%z2, i == 1), wp)
      rp = 0.5_wp * g%d(i)
      rho = rack_tip_radius(p)
      y_ref = rp + g%x(i) * p%m
      y_tip = y_ref - (p%ha_star + p%c_star) * p%m
      yc = y_tip + rho
      xc = 0.25_wp * pi * p%m - (y_ref - yc) * tan(p%alpha) - rho / cos(p%alpha)
      y_tan = yc - rho * sin(p%alpha)
      top = y_ref + 1.5_wp * p%m
      do k = 1, 80
        a = top + (y_tan - top) * real(k - 1, wp) / 79.0_wp
        side(:, k) = [0.25_wp * pi * p%m - (y_ref - a) * tan(p%alpha), a]
      end do
      do k = 1, 80
        a = -p%alpha + (p%alpha - 0.5_wp * pi) * real(k, wp) / 80.0_wp
        side(:, 80 + k) = [xc + rho * cos(a), yc + rho * sin(a)]
      end do
      side(:, 161) = [0.0_wp, y_tip]
      span = 2.5_wp * p%m + 0.6_wp * rp
      best = -huge(1.0_wp)
      do j = 0, 6000
        u = -span + 2.0_wp * span * real(j, wp) / 6000.0_wp
        do k = 1, 161
          e = side(:, k) + [u, 0.0_wp]
          q(:, k) = [cos(u / rp) * e(1) - sin(u / rp) * e(2), sin(u / rp) * e(1) + cos(u / rp) * e(2)]
          radius(k) = norm2(q(:, k))
        end do
        do m = 1, size(r)
          do k = 1, 160
            r1 = radius(k)
            r2 = radius(k + 1)
            if ((r1 - r(m)) * (r2 - r(m)) > 0.0_wp .or. r1 == r2) cycle
            s = (r(m) - r1) / (r2 - r1)
            e = q(:, k) + s * (q(:, k + 1) - q(:, k))
            delta = 0.5_wp * pi - atan2(e(2), e(1))
            if (abs(delta) < 1.5_wp * pi / z) best(m) = max(best(m), delta)
          end do
        end do
      end do
      psi = pi / z - best
    end function rack_cut
  end subroutine test_tooth_outline

  !> shift = 'auto': the point is acceptable, the sliding is equal, and a slightly nearer
  !> point of the equal-sliding curve is not acceptable or not nearer.
  subroutine test_auto_shift(t)
    type(test_counts_t), intent(inout) :: t
    type(gear_pair_t) :: p
    type(pair_geometry_t) :: g
    type(error_t), allocatable :: error
    real(wp) :: x1, x2
    integer :: k, z1(3), z2(3)
    z1 = [13, 20, 25]
    z2 = [27, 40, 60]
    do k = 1, 3
      p = gear_pair_t(m=4.0_wp, z1=z1(k), z2=z2(k))
      call auto_shift(p, x1, x2, error)
      call check_true(t, "auto shift found", .not. allocated(error), "no shift")
      if (allocated(error)) cycle
      g = pair_geometry(p, x1, x2)
      call check_true(t, "auto shift acceptable", pair_is_acceptable(g), "a condition is broken")
      call check_close(t, "auto shift: equal sliding", g%sliding(1), g%sliding(2), 1.0e-9_wp, 0.0_wp)
    end do
    ! z1 = 5 cannot be made acceptable with equal sliding
    call auto_shift(gear_pair_t(m=4.0_wp, z1=5, z2=60), x1, x2, error)
    call check_true(t, "auto shift of z1 = 5 fails", allocated(error), "a shift was found")
  end subroutine test_auto_shift

  !> A prescribed centre distance: x1 + x2 from inv(alpha_w), the pair's a_w back, the split
  !> with equal sliding.
  subroutine test_centre_distance(t)
    type(test_counts_t), intent(inout) :: t
    type(gear_pair_t) :: p
    type(pair_geometry_t) :: g
    type(error_t), allocatable :: error
    real(wp) :: x_sum, x1, x2
    p = gear_pair_t(m=3.0_wp, z1=14, z2=35)
    call shift_sum_for_centre(p, 75.0_wp, x_sum, error)
    call check_true(t, "a_w = 75 accepted", .not. allocated(error), "refused")
    call equal_sliding_split(p, x_sum, x1, x2, error)
    call check_true(t, "a_w = 75 split", .not. allocated(error), "no split")
    g = pair_geometry(p, x1, x2)
    call check_close(t, "a_w of the split", 75.0_wp, g%a_w, 1.0e-12_wp, 0.0_wp)
    call check_close(t, "split: equal sliding", g%sliding(1), g%sliding(2), 1.0e-9_wp, 0.0_wp)
    call shift_sum_for_centre(p, 60.0_wp, x_sum, error)
    call check_true(t, "a_w below a cos(alpha) refused", allocated(error), "accepted")
  end subroutine test_centre_distance

  !> Each contour point lies on its curve (its level 0 to 1e-9).
  subroutine test_contour_points(t)
    type(test_counts_t), intent(inout) :: t
    type(gear_pair_t) :: p
    type(contour_curve_t) :: curves(size(contour_names))
    type(pair_geometry_t) :: g
    real(wp) :: worst(6), level
    integer :: c, k, gear
    p = gear_pair_t(m=1.0_wp, z1=12, z2=24)
    call blocking_contour(p, curves)
    worst = 0.0_wp
    do c = 3, 8
      call check_true(t, "contour curve "//curves(c)%name//" has points", size(curves(c)%x1) > 10, "empty")
      do k = 1, size(curves(c)%x1)
        g = pair_geometry(p, curves(c)%x1(k), curves(c)%x2(k))
        ! gear 1 or 2 of the pointed and interference curves
        gear = 2 - mod(c, 2)
        select case (c)
        case (3, 4)
          level = g%sa(gear) - 0.25_wp
        case (5)
          level = g%eps_alpha - 1.0_wp
        case (6)
          level = g%eps_alpha - 1.2_wp
        case default
          level = g%rho_low(gear)
        end select
        worst(c - 2) = max(worst(c - 2), abs(level))
      end do
      call check_close(t, "contour points on "//curves(c)%name, 0.0_wp, worst(c - 2), 0.0_wp, 1.0e-9_wp)
    end do
    call check_close(t, "undercut1 line at x1_min", 1.0_wp - 6.0_wp * sin(20.0_wp * deg_to_rad)**2, curves(1)%x1(1), &
      1.0e-14_wp, 0.0_wp)
  end subroutine test_contour_points

  !> The planetary answer meets every condition and no smaller ring does (brute force over
  !> every z1 of every ring below it); of its ring, no other train is nearer u.
  subroutine test_planetary_brute_force(t)
    type(test_counts_t), intent(inout) :: t
    type(planetary_spec_t) :: spec
    type(planetary_train_t) :: best, other
    type(error_t), allocatable :: error
    real(wp) :: u(5), tol(5)
    integer :: k(5), c, z1, z3, found
    u = [5.0_wp, 3.2_wp, 7.1_wp, 4.0_wp, 6.3_wp]
    k = [3, 3, 3, 5, 2]
    tol = [0.04_wp, 0.04_wp, 0.02_wp, 0.01_wp, 0.0_wp]
    do c = 1, 5
      spec = planetary_spec_t(u=u(c), k=k(c), u_tolerance=tol(c))
      call planetary_search(spec, best, error)
      call check_true(t, "planetary answer found", .not. allocated(error), "none")
      if (allocated(error)) cycle
      call check_true(t, "planetary answer meets every condition", all(best%met), "a condition is broken")
      found = 0
      do z3 = 1, best%z3
        do z1 = 1, z3 - 1
          if (modulo(z3 - z1, 2) /= 0) cycle
          other = train_conditions(spec, z1, (z3 - z1) / 2, z3)
          if (.not. all(other%met)) cycle
          if (z3 < best%z3) found = found + 1
          if (z3 == best%z3 .and. abs(other%u_deviation) < abs(best%u_deviation)) found = found + 1
        end do
      end do
      call check_true(t, "planetary: no smaller ring, no nearer ratio", found == 0, "brute force found better")
    end do
  end subroutine test_planetary_brute_force

  !> Each law's s' and s'' against central differences of its s (h = 1e-5 of the segment).
  subroutine test_cam_laws(t)
    type(test_counts_t), intent(inout) :: t
    type(cam_segment_t) :: seg
    integer :: law, k
    real(wp) :: xi, s, ds, d2s, sp, sm, dummy1, dummy2, h
    h = 1.0e-5_wp
    do law = 2, 6
      seg = cam_segment_t(law=law, beta=1.3_wp, lift=0.02_wp)
      do k = 1, 9
        xi = real(k, wp) / 10.0_wp + 0.013_wp
        call segment_motion(seg, xi, s, ds, d2s)
        call segment_motion(seg, xi + h, sp, dummy1, dummy2)
        call segment_motion(seg, xi - h, sm, dummy1, dummy2)
        call check_close(t, "cam law s' by differences", (sp - sm) / (2.0_wp * h * seg%beta), ds, 1.0e-7_wp, 1.0e-11_wp)
        call check_close(t, "cam law s'' by differences", (sp - 2.0_wp * s + sm) / (h * seg%beta)**2, d2s, 1.0e-4_wp, &
          1.0e-7_wp)
      end do
      call segment_motion(seg, 1.0_wp, s, ds, d2s)
      call check_close(t, "cam law ends at its lift", 0.02_wp, s, 1.0e-14_wp, 0.0_wp)
    end do
  end subroutine test_cam_laws

  !> A translating roller (both senses, an offset): |theta| <= its limit on a dense grid of
  !> cam angles, and 0.1 % smaller a pitch circle breaks the limit somewhere.
  subroutine test_cam_roller_limits(t)
    type(test_counts_t), intent(inout) :: t
    type(cam_design_t) :: d, smaller
    type(error_t), allocatable :: error
    real(wp) :: omega(2), offset(2)
    integer :: c
    omega = [10.0_wp, -10.0_wp]
    offset = [0.005_wp, 0.004_wp]
    do c = 1, 2
      d = cam_design_t(follower=follower_roller, seg=four_segments(law_cycloidal, law_harmonic, 0.02_wp), &
        offset=offset(c), roller_radius=0.008_wp, limit_rise=30.0_wp * deg_to_rad, limit_return=45.0_wp * deg_to_rad, &
        omega=omega(c))
      call size_cam(d, error)
      call check_true(t, "roller cam sized", .not. allocated(error), "no size")
      call check_close(t, "roller: largest excess of theta over its limit", 0.0_wp, max(0.0_wp, largest_excess(d)), &
        0.0_wp, 1.0e-12_wp)
      smaller = d
      smaller%r_prime = 0.999_wp * d%r_prime
      call check_true(t, "roller: a smaller pitch circle breaks the limit", largest_excess(smaller) > 0.0_wp, &
        "it does not")
    end do
  end subroutine test_cam_roller_limits

  !> The flat face: rho >= rho_min on a dense grid, 0.1 mm less base circle breaks it, and
  !> rho = r_base + s + s'' against the curvature of the contact points (differences).
  subroutine test_cam_flat_rho(t)
    type(test_counts_t), intent(inout) :: t
    type(cam_design_t) :: d
    type(error_t), allocatable :: error
    type(cam_point_t) :: p
    real(wp) :: phi, s, ds, d2s, least
    integer :: k
    d = cam_design_t(follower=follower_flat, seg=four_segments(law_poly345, law_cycloidal, 0.02_wp), &
      rho_min=0.005_wp, omega=-3.0_wp)
    call size_cam(d, error)
    call check_true(t, "flat cam sized", .not. allocated(error), "no size")
    least = huge(1.0_wp)
    do k = 0, 7200
      phi = 2.0_wp * pi * real(k, wp) / 7200.0_wp
      call motion_at(d, phi, s, ds, d2s)
      p = cam_point(d, phi, s, ds, d2s)
      least = min(least, p%rho)
    end do
    call check_true(t, "flat: rho never below rho_min", least >= 0.005_wp * (1.0_wp - 1.0e-12_wp), "below")
    call check_close(t, "flat: rho reaches rho_min", 0.005_wp, least, 1.0e-6_wp, 0.0_wp)
    d%r_base = d%r_base - 1.0e-4_wp
    least = huge(1.0_wp)
    do k = 0, 3600
      phi = 2.0_wp * pi * real(k, wp) / 3600.0_wp
      call motion_at(d, phi, s, ds, d2s)
      least = min(least, d%r_base + s + d2s)
    end do
    call check_true(t, "flat: a smaller base circle breaks rho_min", least < 0.005_wp, "it does not")
  end subroutine test_cam_flat_rho

  !> The oscillating roller: |theta| <= its limits on a dense grid, and 0.2 % smaller a pitch
  !> circle breaks them.
  subroutine test_cam_oscillating_limits(t)
    type(test_counts_t), intent(inout) :: t
    type(cam_design_t) :: d, smaller
    type(error_t), allocatable :: error
    real(wp) :: dist, arm
    d = cam_design_t(follower=follower_oscillating, seg=four_segments(law_poly345, law_parabolic, 20.0_wp * deg_to_rad), &
      arm=0.08_wp, pivot=[0.09_wp, 0.06_wp], roller_radius=0.01_wp, limit_rise=40.0_wp * deg_to_rad, &
      limit_return=50.0_wp * deg_to_rad, omega=5.0_wp)
    call size_cam(d, error)
    call check_true(t, "oscillating cam sized", .not. allocated(error), "no size")
    call check_close(t, "oscillating: largest excess of theta", 0.0_wp, max(0.0_wp, largest_excess(d)), 0.0_wp, 1.0e-9_wp)
    smaller = d
    smaller%r_prime = 0.998_wp * d%r_prime
    dist = norm2(d%pivot)
    arm = d%arm
    smaller%psi0 = acos((dist**2 + arm**2 - smaller%r_prime**2) / (2.0_wp * dist * arm))
    call check_true(t, "oscillating: a smaller pitch circle breaks the limit", largest_excess(smaller) > 0.0_wp, &
      "it does not")
  end subroutine test_cam_oscillating_limits

  !> Largest |theta| - limit over 8000 cam angles (each segment's own values at its ends).
  real(wp) function largest_excess(d) result(worst)
    type(cam_design_t), intent(in) :: d
    type(cam_point_t) :: p
    real(wp) :: phi, s, ds, d2s, xi
    integer :: i, k
    worst = -huge(1.0_wp)
    do i = 1, size(d%seg)
      do k = 0, 2000
        xi = real(k, wp) / 2000.0_wp
        call segment_motion(d%seg(i), xi, s, ds, d2s)
        phi = d%seg(i)%phi0 + xi * d%seg(i)%beta
        p = cam_point(d, phi, s + d%seg(i)%s0, ds, d2s)
        worst = max(worst, abs(p%theta) - segment_limit(d, i))
      end do
    end do
  end function largest_excess

  !> Rise (law_up) over 120 deg, dwell 60, return (law_down) over 120, dwell 60; lift h.
  function four_segments(law_up, law_down, h) result(seg)
    integer, intent(in) :: law_up, law_down
    real(wp), intent(in) :: h
    type(cam_segment_t) :: seg(4)
    real(wp) :: b(4)
    b = [120.0_wp, 60.0_wp, 120.0_wp, 60.0_wp] * deg_to_rad
    seg(1) = cam_segment_t(law=law_up, beta=b(1), lift=h, phi0=0.0_wp, s0=0.0_wp)
    seg(2) = cam_segment_t(law=law_dwell, beta=b(2), lift=0.0_wp, phi0=b(1), s0=h)
    seg(3) = cam_segment_t(law=law_down, beta=b(3), lift=-h, phi0=b(1) + b(2), s0=h)
    seg(4) = cam_segment_t(law=law_dwell, beta=b(4), lift=0.0_wp, phi0=b(1) + b(2) + b(3), s0=0.0_wp)
  end function four_segments

end module test_synthesis
