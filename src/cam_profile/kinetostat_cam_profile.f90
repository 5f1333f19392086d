!> A disc cam for a follower's motion law (the course's cam synthesis, "профилирование
!> кулачка"): the law of motion over segments (dwell, constant velocity, parabolic, harmonic,
!> cycloidal, 3-4-5 polynomial), the size of the cam (the least pitch circle that keeps the
!> pressure angle within its limits for a roller follower, translating or on an arm; the
!> least base circle that keeps the flat face's radius of curvature above rho_min), and per
!> cam angle the pressure angle, the radii of curvature and the pitch and actual profiles.
!>
!> Frames. Fixed frame: the cam's centre O at the origin. A translating follower moves along
!> +y (away from the cam) on the axis x = e (flat face: x = 0); an oscillating one turns about
!> its pivot P, its roller at B = P + arm R(psi0 + s) (O - P)/|O - P| (the rise turns the arm
!> counter-clockwise about P, away from O). The cam turns by the angle phi >= 0 in its own
!> sense (omega > 0 counter-clockwise); the cam frame is the fixed frame at phi = 0, so the
!> profile's 0 deg is the follower at the start of the first segment. The pressure angle is
!> the angle from the follower's direction of motion (+y; the arm's rise direction) to the
!> cam's normal force on it, positive towards +x (along the arm, away from the pivot).
!> Lengths in m, angles in rad (an oscillating follower's s in rad). Pure; no I/O.
module kinetostat_cam_profile
  use kinetostat_kinds, only: wp, pi
  use kinetostat_vec2, only: perp, cross, rotate
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_format, only: short_number
  implicit none
  private
  public :: law_names, law_dwell, law_constant_velocity, law_parabolic, law_harmonic, law_cycloidal, law_poly345
  public :: follower_flat, follower_roller, follower_oscillating, follower_names
  public :: cam_segment_t, cam_design_t, cam_point_t, cam_sizes_t
  public :: segment_motion, motion_at, segment_at, cam_point, size_cam, cam_extremes, segment_limit

  !> Motion laws as written in decks (index = law code).
  character(*), parameter :: law_names(*) = [character(len=17) :: "dwell", "constant_velocity", "parabolic", &
    "harmonic", "cycloidal", "poly345"]
  integer, parameter :: law_dwell = 1, law_constant_velocity = 2, law_parabolic = 3, law_harmonic = 4, &
    law_cycloidal = 5, law_poly345 = 6
  !> Followers as written in decks (index = follower code).
  character(*), parameter :: follower_names(*) = [character(len=11) :: "flat", "roller", "oscillating"]
  integer, parameter :: follower_flat = 1, follower_roller = 2, follower_oscillating = 3
  !> Samples per segment of the dense searches (then a golden-section refinement).
  integer, parameter :: samples = 100
  !> Steps of the scan for an oscillating follower's pitch circle (then bisection).
  integer, parameter :: radius_scan = 100
  !> Golden ratio's conjugate.
  real(wp), parameter :: golden = 0.6180339887498948482_wp
  !> Radius of curvature reported where the pitch curve is straight (its curvature 0), m.
  real(wp), parameter :: straight = 1.0e30_wp

  !> One segment of the law of motion.
  type :: cam_segment_t
    !> Law code (law_dwell ...).
    integer :: law = law_dwell
    !> Cam angle it spans, rad.
    real(wp) :: beta = 0.0_wp
    !> Follower's displacement over it (+ rise, - fall), m (oscillating: rad).
    real(wp) :: lift = 0.0_wp
    !> Cam angle and displacement at its start.
    real(wp) :: phi0 = 0.0_wp, s0 = 0.0_wp
  end type cam_segment_t

  !> The cam as designed: the law, the follower and the limits.
  type :: cam_design_t
    !> follower_flat, follower_roller or follower_oscillating.
    integer :: follower = follower_roller
    !> The law's segments over one turn.
    type(cam_segment_t), allocatable :: seg(:)
    !> Translating roller: offset e of the axis (x = e), m.
    real(wp) :: offset = 0.0_wp
    !> Oscillating: arm length (pivot to roller centre), m, and the pivot (x, y), m.
    real(wp) :: arm = 0.0_wp, pivot(2) = 0.0_wp
    !> Roller radius, m (0: a knife edge).
    real(wp) :: roller_radius = 0.0_wp
    !> Largest pressure angle on the rise (and dwells) and on the return, rad.
    real(wp) :: limit_rise = 0.0_wp, limit_return = 0.0_wp
    !> Flat face: the least radius of curvature of the profile, m.
    real(wp) :: rho_min = 0.0_wp
    !> Cam's angular velocity, rad/s (+ counter-clockwise).
    real(wp) :: omega = 1.0_wp
    !> Size: the pitch (prime) circle's radius (roller) or the base circle's (flat), m.
    real(wp) :: r_prime = 0.0_wp
    !> Base circle radius of the actual profile, m.
    real(wp) :: r_base = 0.0_wp
    !> Oscillating: the arm's angle psi0 at the lowest position, rad.
    real(wp) :: psi0 = 0.0_wp
  end type cam_design_t

  !> Geometry at one cam angle.
  type :: cam_point_t
    !> Pressure angle, rad (flat face: 0).
    real(wp) :: theta = 0.0_wp
    !> Radius of curvature of the actual profile, m (+ convex, - concave).
    real(wp) :: rho = 0.0_wp
    !> Radius of curvature of the pitch curve (roller centre's path on the cam), m.
    real(wp) :: rho_pitch = 0.0_wp
    !> The pitch point (roller centre; flat: the face on the axis) and the contact point on
    !> the actual profile, in the cam frame, m.
    real(wp) :: pitch(2) = 0.0_wp, profile(2) = 0.0_wp
    !> The same pitch radius of curvature by a second formula (self-check), m.
    real(wp) :: rho_check = 0.0_wp
  end type cam_point_t

  !> What the sizing found over the whole turn (dense search, not only the output steps).
  type :: cam_sizes_t
    !> Largest |pressure angle| on the rise (and dwells) and on the return, rad.
    real(wp) :: theta_rise = 0.0_wp, theta_return = 0.0_wp
    !> Smallest radius of curvature of the convex pitch curve (roller), m (huge: none).
    real(wp) :: rho_pitch_min = 0.0_wp
    !> Smallest radius of curvature of the actual profile, m.
    real(wp) :: rho_min = 0.0_wp
    !> Flat face: max s' - min s', m.
    real(wp) :: face_width = 0.0_wp
  end type cam_sizes_t

contains

  !> Displacement, velocity and acceleration analogues of a segment at the fraction xi of it
  !> (0..1): s (from the segment's start), ds = ds/dphi, d2s = d2s/dphi^2 (phi in rad).
  elemental subroutine segment_motion(seg, xi, s, ds, d2s)
    !> The segment.
    type(cam_segment_t), intent(in) :: seg
    !> Fraction of the segment, 0..1.
    real(wp), intent(in) :: xi
    !> Displacement from the segment's start, its first and second derivative in phi.
    real(wp), intent(out) :: s, ds, d2s
    real(wp) :: h, b
    h = seg%lift
    b = seg%beta
    select case (seg%law)
    case (law_constant_velocity)
      s = h * xi
      ds = h / b
      d2s = 0.0_wp
    case (law_parabolic)
      if (xi <= 0.5_wp) then
        s = 2.0_wp * h * xi**2
        ds = 4.0_wp * h * xi / b
        d2s = 4.0_wp * h / b**2
      else
        s = h * (1.0_wp - 2.0_wp * (1.0_wp - xi)**2)
        ds = 4.0_wp * h * (1.0_wp - xi) / b
        d2s = -4.0_wp * h / b**2
      end if
    case (law_harmonic)
      s = 0.5_wp * h * (1.0_wp - cos(pi * xi))
      ds = 0.5_wp * pi * h / b * sin(pi * xi)
      d2s = 0.5_wp * pi**2 * h / b**2 * cos(pi * xi)
    case (law_cycloidal)
      s = h * (xi - sin(2.0_wp * pi * xi) / (2.0_wp * pi))
      ds = h / b * (1.0_wp - cos(2.0_wp * pi * xi))
      d2s = 2.0_wp * pi * h / b**2 * sin(2.0_wp * pi * xi)
    case (law_poly345)
      s = h * xi**3 * (10.0_wp - 15.0_wp * xi + 6.0_wp * xi**2)
      ds = h / b * 30.0_wp * xi**2 * (1.0_wp - xi)**2
      d2s = h / b**2 * 60.0_wp * xi * (1.0_wp - 3.0_wp * xi + 2.0_wp * xi**2)
    case default
      s = 0.0_wp
      ds = 0.0_wp
      d2s = 0.0_wp
    end select
  end subroutine segment_motion

  !> The segment at cam angle phi (rad, 0..2 pi): the one starting at or before phi (the last
  !> one at 2 pi).
  pure integer function segment_at(d, phi) result(i)
    type(cam_design_t), intent(in) :: d
    !> Cam angle, rad.
    real(wp), intent(in) :: phi
    integer :: k
    i = 1
    do k = 2, size(d%seg)
      if (phi >= d%seg(k)%phi0) i = k
    end do
  end function segment_at

  !> The law at cam angle phi (rad): s (from the lowest position), ds/dphi, d2s/dphi^2.
  pure subroutine motion_at(d, phi, s, ds, d2s)
    type(cam_design_t), intent(in) :: d
    real(wp), intent(in) :: phi
    real(wp), intent(out) :: s, ds, d2s
    integer :: i
    real(wp) :: xi
    i = segment_at(d, phi)
    xi = min(1.0_wp, max(0.0_wp, (phi - d%seg(i)%phi0) / d%seg(i)%beta))
    call segment_motion(d%seg(i), xi, s, ds, d2s)
    s = s + d%seg(i)%s0
  end subroutine motion_at

  !> The pressure-angle limit of segment i: the return's on a fall, the rise's otherwise.
  pure real(wp) function segment_limit(d, i)
    type(cam_design_t), intent(in) :: d
    integer, intent(in) :: i
    segment_limit = d%limit_rise
    if (d%seg(i)%lift < 0.0_wp) segment_limit = d%limit_return
  end function segment_limit

  !> Sense of the cam's rotation: +1 counter-clockwise, -1 clockwise.
  pure real(wp) function sense(d)
    type(cam_design_t), intent(in) :: d
    sense = sign(1.0_wp, d%omega)
  end function sense

  !> The pitch point B (fixed frame), its first and second derivative in phi, the follower's
  !> unit direction of motion u, for a pitch circle (roller) of radius r_prime and the
  !> arm's psi0 as in `d`.
  pure subroutine pitch_point(d, s, ds, d2s, b, b1, b2, u)
    type(cam_design_t), intent(in) :: d
    real(wp), intent(in) :: s, ds, d2s
    real(wp), intent(out) :: b(2), b1(2), b2(2), u(2)
    real(wp) :: e_po(2), arm(2)
    select case (d%follower)
    case (follower_oscillating)
      e_po = -d%pivot / norm2(d%pivot)
      arm = d%arm * rotate(e_po, d%psi0 + s)
      b = d%pivot + arm
      b1 = ds * perp(arm)
      b2 = d2s * perp(arm) - ds**2 * arm
      u = perp(arm) / d%arm
    case (follower_flat)
      b = [0.0_wp, d%r_base + s]
      b1 = [0.0_wp, ds]
      b2 = [0.0_wp, d2s]
      u = [0.0_wp, 1.0_wp]
    case default
      b = [d%offset, sqrt(max(0.0_wp, d%r_prime**2 - d%offset**2)) + s]
      b1 = [0.0_wp, ds]
      b2 = [0.0_wp, d2s]
      u = [0.0_wp, 1.0_wp]
    end select
  end subroutine pitch_point

  !> The geometry at cam angle phi (rad) with the law's values s, ds, d2s there (so that a
  !> search may take a segment's one-sided values at its ends).
  pure function cam_point(d, phi, s, ds, d2s) result(p)
    type(cam_design_t), intent(in) :: d
    real(wp), intent(in) :: phi, s, ds, d2s
    type(cam_point_t) :: p
    real(wp) :: b(2), b1(2), b2(2), u(2), w(2), v(2), v1(2), n(2), c(2), sg, vv, y, q
    sg = sense(d)
    call pitch_point(d, s, ds, d2s, b, b1, b2, u)
    if (d%follower == follower_flat) then
      ! the face y = r_base + s touches the cam where its normal velocities agree: x = sg*s'
      c = [sg * ds, d%r_base + s]
      p%theta = 0.0_wp
      p%rho = d%r_base + s + d2s
      p%rho_pitch = p%rho
      ! the contact path's curvature by the general formula (W x W' = 0 for a flat face)
      v = [sg * (d%r_base + s + d2s), 0.0_wp]
      p%rho_check = sign(norm2(v), p%rho)
    else
      ! V = dB/dphi seen from the cam (the relative velocity per |omega|), tangent to the
      ! pitch curve; the outward normal is sg*perp(V)
      v = b1 - sg * perp(b)
      v1 = b2 - sg * perp(b1)
      vv = dot_product(v, v)
      n = sg * perp(v) / sqrt(vv)
      w = -perp(u)
      p%theta = atan2(dot_product(n, w), dot_product(n, u))
      ! a straight stretch (an inflection exactly at this angle) has no finite radius: 1e30
      if (abs(vv - sg * cross(v, v1)) > epsilon(1.0_wp) * vv) then
        p%rho_pitch = vv * sqrt(vv) / (vv - sg * cross(v, v1))
      else
        p%rho_pitch = straight
      end if
      p%rho = p%rho_pitch - d%roller_radius
      c = b - d%roller_radius * n
      if (d%follower == follower_roller) then
        ! the textbook's translating-roller formula (x = e, y = s0 + s)
        y = b(2)
        q = ds - sg * d%offset
        p%rho_check = (y**2 + q**2)**1.5_wp / (y**2 + q**2 - y * d2s + q * ds)
        if (p%rho_pitch == straight) p%rho_check = straight
      else
        ! from the cam-frame derivatives P' = R V, P'' = R (V' - sg perp(V))
        p%rho_check = straight
        if (p%rho_pitch /= straight) p%rho_check = -sg * norm2(rotate(v, -sg * phi))**3 / &
          cross(rotate(v, -sg * phi), rotate(v1 - sg * perp(v), -sg * phi))
      end if
    end if
    p%pitch = rotate(b, -sg * phi)
    p%profile = rotate(c, -sg * phi)
  end function cam_point

  !> Largest value of f over segment i's fraction 0..1: samples, then a golden-section
  !> search between the best sample's neighbours. `which` selects f (see `quantity`).
  pure real(wp) function segment_max(d, i, which) result(best)
    type(cam_design_t), intent(in) :: d
    integer, intent(in) :: i, which
    real(wp) :: f, a, b, c, e, fc, fe, xbest
    integer :: k, it
    best = -huge(1.0_wp)
    xbest = 0.0_wp
    do k = 0, samples
      f = quantity(d, i, real(k, wp) / real(samples, wp), which)
      if (f > best) then
        best = f
        xbest = real(k, wp) / real(samples, wp)
      end if
    end do
    a = max(0.0_wp, xbest - 1.0_wp / real(samples, wp))
    b = min(1.0_wp, xbest + 1.0_wp / real(samples, wp))
    c = b - golden * (b - a)
    e = a + golden * (b - a)
    fc = quantity(d, i, c, which)
    fe = quantity(d, i, e, which)
    do it = 1, 100
      if (b - a <= 1.0e-14_wp) exit
      if (fc >= fe) then
        b = e
        e = c
        fe = fc
        c = b - golden * (b - a)
        fc = quantity(d, i, c, which)
      else
        a = c
        c = e
        fc = fe
        e = a + golden * (b - a)
        fe = quantity(d, i, e, which)
      end if
    end do
    best = max(best, fc, fe)
  end function segment_max

  !> The quantities the searches maximise at the fraction xi of segment i:
  !> 1: the least pitch-circle offset y0 = s0 the pressure angle needs (translating roller),
  !>    |e - sg s'| / tan(limit) - s;
  !> 2: rho_min - (s + s'') (flat face: the base circle it needs);
  !> 3: |theta| - limit (oscillating: the pressure angle's excess);
  !> 4: |theta| on a rise or dwell (else -huge); 5: |theta| on a fall (else -huge);
  !> 6: -rho_pitch where the pitch curve is convex (else -huge); 7: -rho; 8: s'; 9: -s'.
  pure real(wp) function quantity(d, i, xi, which) result(f)
    type(cam_design_t), intent(in) :: d
    integer, intent(in) :: i, which
    real(wp), intent(in) :: xi
    real(wp) :: s, ds, d2s
    type(cam_point_t) :: p
    call segment_motion(d%seg(i), xi, s, ds, d2s)
    s = s + d%seg(i)%s0
    select case (which)
    case (1)
      f = abs(d%offset - sense(d) * ds) / tan(segment_limit(d, i)) - s
    case (2)
      f = d%rho_min - (s + d2s)
    case (8)
      f = ds
    case (9)
      f = -ds
    case default
      p = cam_point(d, d%seg(i)%phi0 + xi * d%seg(i)%beta, s, ds, d2s)
      select case (which)
      case (3)
        f = abs(p%theta) - segment_limit(d, i)
      case (4)
        f = -huge(1.0_wp)
        if (d%seg(i)%lift >= 0.0_wp) f = abs(p%theta)
      case (5)
        f = -huge(1.0_wp)
        if (d%seg(i)%lift < 0.0_wp) f = abs(p%theta)
      case (6)
        f = -huge(1.0_wp)
        if (p%rho_pitch > 0.0_wp) f = -p%rho_pitch
      case default
        f = -p%rho
      end select
    end select
  end function quantity

  !> Largest value of quantity `which` over the whole turn.
  pure real(wp) function turn_max(d, which) result(best)
    type(cam_design_t), intent(in) :: d
    integer, intent(in) :: which
    integer :: i
    best = -huge(1.0_wp)
    do i = 1, size(d%seg)
      best = max(best, segment_max(d, i, which))
    end do
  end function turn_max

  !> The size of the cam: r_prime and r_base (and an oscillating arm's psi0) set in `d`.
  !> Translating roller: the least y0 with |e - sg s'| <= tan(limit) (y0 + s) everywhere,
  !> r_prime = sqrt(y0^2 + e^2). Oscillating: the least r_prime with |theta| <= limit
  !> everywhere, from a scan over the radii the arm reaches, then bisection. Flat face: the
  !> least r_base with r_base + s + s'' >= rho_min everywhere. For a roller r_base =
  !> r_prime - roller_radius, which must be > 0.
  pure subroutine size_cam(d, error)
    type(cam_design_t), intent(inout) :: d
    !> No size meets the limits (geometry error).
    type(error_t), allocatable, intent(out) :: error
    real(wp) :: y0, lo, hi, r, dist, r_min, r_max, s_max, excess, a, b
    logical :: found
    integer :: k, it
    select case (d%follower)
    case (follower_flat)
      d%r_base = turn_max(d, 2)
      d%r_prime = d%r_base
      if (.not. d%r_base > 0.0_wp) then
        call fatal_error(error, exit_geometry, "rho_min is so small that any base circle keeps the profile's "// &
          "radius of curvature above it (r_base + s + s'' >= rho_min needs r_base >= "//short_number(d%r_base)// &
          " m): give the rho_min the cam must keep")
        return
      end if
    case (follower_roller)
      y0 = max(0.0_wp, turn_max(d, 1))
      d%r_prime = sqrt(y0**2 + d%offset**2)
      d%r_base = d%r_prime - d%roller_radius
    case default
      dist = norm2(d%pivot)
      s_max = maxval(d%seg%s0)
      s_max = max(s_max, d%seg(size(d%seg))%s0 + d%seg(size(d%seg))%lift)
      ! psi0 > 0 and psi0 + s_max < pi: the radii the arm's lowest position can reach
      r_min = max(abs(dist - d%arm), d%roller_radius) * (1.0_wp + 1.0e-9_wp)
      r_max = sqrt(dist**2 + d%arm**2 - 2.0_wp * dist * d%arm * cos(pi - s_max)) * (1.0_wp - 1.0e-9_wp)
      found = .false.
      lo = r_min
      hi = r_min
      if (r_max > r_min) then
        do k = 0, radius_scan
          r = r_min + (r_max - r_min) * real(k, wp) / real(radius_scan, wp)
          excess = excess_at(r)
          if (excess <= 0.0_wp) then
            hi = r
            found = .true.
            exit
          end if
          lo = r
        end do
      end if
      if (.not. found) then
        call fatal_error(error, exit_geometry, "no pitch circle the arm reaches keeps the pressure angle within "// &
          "its limits (pivot at "//short_number(dist)//" m from the cam's centre, arm "//short_number(d%arm)// &
          " m): move the pivot, lengthen the arm or allow a larger pressure angle")
        return
      end if
      if (hi > lo) then
        a = lo
        b = hi
        do it = 1, 100
          r = 0.5_wp * (a + b)
          if (r <= a .or. r >= b) exit
          if (excess_at(r) <= 0.0_wp) then
            b = r
          else
            a = r
          end if
        end do
        hi = b
      end if
      d%r_prime = hi
      d%psi0 = arm_angle(d, hi)
      d%r_base = d%r_prime - d%roller_radius
    end select
    if (d%follower /= follower_flat .and. .not. d%r_base > 0.0_wp) then
      call fatal_error(error, exit_geometry, "the pressure angle needs a pitch circle of only r_prime = "// &
        short_number(d%r_prime)//" m, not larger than the roller (roller_radius = "//short_number(d%roller_radius)// &
        " m): no base circle; take a smaller roller")
    end if
  contains
    !> The pressure angle's largest excess over its limit with the pitch circle r, rad.
    pure real(wp) function excess_at(rr)
      real(wp), intent(in) :: rr
      type(cam_design_t) :: trial
      trial = d
      trial%r_prime = rr
      trial%psi0 = arm_angle(d, rr)
      excess_at = turn_max(trial, 3)
    end function excess_at
  end subroutine size_cam

  !> The arm's angle at P between P->O and P->B when B is on the circle of radius r about O.
  pure real(wp) function arm_angle(d, r)
    type(cam_design_t), intent(in) :: d
    real(wp), intent(in) :: r
    real(wp) :: dist
    dist = norm2(d%pivot)
    arm_angle = acos(max(-1.0_wp, min(1.0_wp, (dist**2 + d%arm**2 - r**2) / (2.0_wp * dist * d%arm))))
  end function arm_angle

  !> The sized cam's extremes over the whole turn (dense search): largest |theta| on the rise
  !> and on the return, the least convex pitch radius of curvature, the least profile radius
  !> of curvature, and the flat face's width max s' - min s'.
  pure function cam_extremes(d) result(x)
    type(cam_design_t), intent(in) :: d
    type(cam_sizes_t) :: x
    x%theta_rise = max(0.0_wp, turn_max(d, 4))
    x%theta_return = max(0.0_wp, turn_max(d, 5))
    x%rho_pitch_min = -turn_max(d, 6)
    x%rho_min = -turn_max(d, 7)
    x%face_width = turn_max(d, 8) + turn_max(d, 9)
  end function cam_extremes

end module kinetostat_cam_profile
