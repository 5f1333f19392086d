!> Generic mechanism, layer 1: kinematics of the initial link and of the five kinds of
!> class-II Assur groups (dyads) by transfer functions (analogues, d/dphi1 and d2/dphi1^2).
!>
!> Every moving link carries a body frame: origin `o` and angle `th` in the global frame,
!> with their analogues. A point given in link coordinates r is o + R(th) r. The frames of
!> the dyad links are fixed by the kind (outer-inner-outer pairs, links a = first, b = second):
!>
!> | kind | pairs | link a frame                    | link b frame                       |
!> |------|-------|---------------------------------|------------------------------------|
!> | 1    | RRR   | origin A, x-axis A->B           | origin C, x-axis C->B              |
!> | 2    | RRP   | origin A, x-axis A->B           | origin B (pin), x-axis along guide |
!> | 3    | RPR   | origin A, x-axis along the slide| origin C, x-axis along the slide   |
!> | 4    | PRP   | origin B, x-axis along guide 1  | origin B, x-axis along guide 2     |
!> | 5    | RPP   | origin A, x-axis along the slot | origin on the guide, x along guide |
!>
!> A, C: outer pins; B: inner pin; a guide is a line on an earlier link along which the
!> slider's reference point moves (any offset of the slider is part of the line's position).
module kinetostat_assur_kinematics
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use kinetostat_kinds, only: wp, rad_to_deg
  use kinetostat_vec2, only: unit_at, perp, cross, magnitude, fast_magnitude
  use kinetostat_text, only: real_str
  implicit none
  private
  public :: link_state_t, point_state_t, dyad_geometry_t, dyad_pose_t
  public :: point_on, point_motion, crank_state, set_crank_state, frame_state, set_dyad_pose
  public :: kind_rrr, kind_rrp, kind_rpr, kind_prp, kind_rpp, kind_names, kind_has_mode
  public :: pose_ok, pose_no_assembly, pose_dead

  !> Dyad kind codes (outer-inner-outer pairs).
  integer, parameter :: kind_rrr = 1, kind_rrp = 2, kind_rpr = 3, kind_prp = 4, kind_rpp = 5
  !> Names of the kinds, by code.
  character(len=3), parameter :: kind_names(5) = ["RRR", "RRP", "RPR", "PRP", "RPP"]
  !> Whether the kind has two assembly modes (kinds 4 and 5 have one solution).
  logical, parameter :: kind_has_mode(5) = [.true., .true., .true., .false., .false.]
  !> Pose status: assembled.
  integer, parameter :: pose_ok = 0
  !> Pose status: the dyad cannot be assembled at this input (links too short, parallel lines).
  integer, parameter :: pose_no_assembly = 1
  !> Pose status: dead (toggle) position, the transfer functions are undetermined.
  integer, parameter :: pose_dead = 2
  !> Relative tolerance for "just reaches" (a negative discriminant within roundoff is 0).
  real(wp), parameter :: reach_tol = 1.0e-12_wp

  !> State of a link's body frame with its analogues.
  type :: link_state_t
    !> Origin, m.
    real(wp) :: o(2) = 0.0_wp
    !> Angle of the x-axis, rad.
    real(wp) :: th = 0.0_wp
    !> d o / d phi1, m/rad.
    real(wp) :: vo(2) = 0.0_wp
    !> u = d th / d phi1.
    real(wp) :: u = 0.0_wp
    !> d2 o / d phi1^2, m/rad^2.
    real(wp) :: ao(2) = 0.0_wp
    !> eps_q = d2 th / d phi1^2.
    real(wp) :: eq = 0.0_wp
    !> cos(th) and sin(th), kept with th (set_link_frame, crank_state) for point_on.
    real(wp) :: cos_th = 1.0_wp
    !> See cos_th.
    real(wp) :: sin_th = 0.0_wp
  end type link_state_t

  !> A point with its analogues.
  type :: point_state_t
    !> Position, m.
    real(wp) :: p(2) = 0.0_wp
    !> d p / d phi1, m/rad.
    real(wp) :: v(2) = 0.0_wp
    !> d2 p / d phi1^2, m/rad^2.
    real(wp) :: a(2) = 0.0_wp
  end type point_state_t

  !> Geometry of one dyad (lengths in m, angles in rad).
  type :: dyad_geometry_t
    !> Kind code, 1..5.
    integer :: kind = kind_rrr
    !> Assembly mode, +1 or -1 (kinds 1-3).
    integer :: mode = 1
    !> RRR, RRP: length A-B of link a, m.
    real(wp) :: l2 = 0.0_wp
    !> RRR: length C-B of link b, m.
    real(wp) :: l3 = 0.0_wp
    !> RPR: signed distance of pin A from the slide line through C + e*n, m.
    real(wp) :: e = 0.0_wp
    !> RPP: a point of the slot in link b's coordinates, m.
    real(wp) :: slot_at(2) = 0.0_wp
    !> RPP: slot direction relative to link b's x-axis, rad.
    real(wp) :: slot_angle = 0.0_wp
  end type dyad_geometry_t

  !> Result of a dyad's position analysis.
  type :: dyad_pose_t
    !> pose_ok, pose_no_assembly or pose_dead.
    integer :: status = pose_ok
    !> Frames of links a and b.
    type(link_state_t) :: link(2)
    !> Reference points of the pairs: 1 outer of a, 2 inner, 3 outer of b, m.
    real(wp) :: p(2, 3) = 0.0_wp
    !> Unit direction of the sliding line of each prismatic pair (zero for revolute pairs).
    real(wp) :: t(2, 3) = 0.0_wp
    !> Stroke of each prismatic pair: position of its sliding side (link a for pairs 1, 2;
    !> link b for pair 3) along `extend` relative to the other side, m (0 for revolute pairs).
    real(wp) :: stroke(3) = 0.0_wp
    !> d stroke / d phi1, m/rad.
    real(wp) :: stroke_v(3) = 0.0_wp
    !> d2 stroke / d phi1^2, m/rad^2.
    real(wp) :: stroke_a(3) = 0.0_wp
    !> Unit direction in which the sliding side moves when the stroke grows (+-t).
    real(wp) :: extend(2, 3) = 0.0_wp
    !> Why the dyad cannot be assembled, with the numbers (pose_no_assembly only).
    character(len=:), allocatable :: detail
  end type dyad_pose_t

contains

  !> The frame (fixed link): origin 0, angle 0, no motion.
  pure function frame_state() result(ls)
    type(link_state_t) :: ls
    ls = link_state_t()
  end function frame_state

  !> Crank pivoted at `pivot` (m, global), its x-axis at angle phi1 (rad): u = 1, eps_q = 0.
  pure function crank_state(pivot, phi1) result(ls)
    !> Pivot A, m.
    real(wp), intent(in) :: pivot(2)
    !> Crank angle, rad.
    real(wp), intent(in) :: phi1
    type(link_state_t) :: ls
    call set_crank_state(pivot, phi1, ls)
  end function crank_state

  !> crank_state(pivot, phi1) into `ls` (a step's hot path: set in place, not returned
  !> through memory).
  pure subroutine set_crank_state(pivot, phi1, ls)
    !> Pivot A, m.
    real(wp), intent(in) :: pivot(2)
    !> Crank angle, rad.
    real(wp), intent(in) :: phi1
    !> The crank's frame.
    type(link_state_t), intent(inout) :: ls
    ls%o = pivot
    ls%th = phi1
    ls%vo = 0.0_wp
    ls%u = 1.0_wp
    ls%ao = 0.0_wp
    ls%eq = 0.0_wp
    ls%cos_th = cos(phi1)
    ls%sin_th = sin(phi1)
  end subroutine set_crank_state

  !> A link's frame into `ls`: origin `o` (m), angle `th` (rad) with its cosine and sine
  !> `e` = [cos(th), sin(th)] (as unit_at(th) gives them, or the direction whose angle th
  !> is), and their analogues (set in place: a frame returned by a function comes back
  !> through memory).
  pure subroutine set_link_frame(ls, o, th, vo, u, ao, eq, e)
    !> The frame.
    type(link_state_t), intent(inout) :: ls
    !> Origin, m.
    real(wp), intent(in) :: o(2)
    !> Angle of the x-axis, rad.
    real(wp), intent(in) :: th
    !> d o / d phi1, m/rad.
    real(wp), intent(in) :: vo(2)
    !> d th / d phi1.
    real(wp), intent(in) :: u
    !> d2 o / d phi1^2, m/rad^2.
    real(wp), intent(in) :: ao(2)
    !> d2 th / d phi1^2.
    real(wp), intent(in) :: eq
    !> [cos(th), sin(th)].
    real(wp), intent(in) :: e(2)
    ls = link_state_t(o=o, th=th, vo=vo, u=u, ao=ao, eq=eq, cos_th=e(1), sin_th=e(2))
  end subroutine set_link_frame

  !> A point given in a link's coordinates `r` (m), with its analogues.
  pure function point_on(ls, r) result(ps)
    !> Link frame.
    type(link_state_t), intent(in) :: ls
    !> Local coordinates, m.
    real(wp), intent(in) :: r(2)
    type(point_state_t) :: ps
    call point_motion(ls, r, ps)
  end function point_on

  !> point_on(ls, r) into ps (a step's hot path: a function's result of this size comes back
  !> through memory, which costs a small mechanism's step more than the arithmetic).
  pure subroutine point_motion(ls, r, ps)
    !> Link frame.
    type(link_state_t), intent(in) :: ls
    !> Local coordinates, m.
    real(wp), intent(in) :: r(2)
    !> The point's position, m, and its velocity and acceleration analogues (every
    !> component set; inout only to spare a call the defaults' initialisation).
    type(point_state_t), intent(inout) :: ps
    real(wp) :: w1, w2, u2
    ! rotate(r, ls%th) with the frame's own cosine and sine, w = [w1, w2], perp(w) = [-w2, w1]
    ! (in scalars: the array expressions cost a small mechanism's step more than the arithmetic)
    w1 = ls%cos_th * r(1) - ls%sin_th * r(2)
    w2 = ls%sin_th * r(1) + ls%cos_th * r(2)
    u2 = ls%u**2
    ps%p(1) = ls%o(1) + w1
    ps%p(2) = ls%o(2) + w2
    ps%v(1) = ls%vo(1) + ls%u * (-w2)
    ps%v(2) = ls%vo(2) + ls%u * w1
    ps%a(1) = ls%ao(1) + ls%eq * (-w2) - u2 * w1
    ps%a(2) = ls%ao(2) + ls%eq * w1 - u2 * w2
  end subroutine point_motion

  !> Solve [c1 c2] x = rhs (2x2); `ok` false when the columns are (nearly) parallel:
  !> |det| <= reach_tol |c1| |c2| (the lengths by hypot). The test is settled first from the
  !> squared lengths when that is possible with a margin of 2 (far beyond their roundoff), so
  !> the two hypot calls are made only near the threshold or at extreme magnitudes.
  pure subroutine solve2(c1, c2, rhs, x, ok)
    real(wp), intent(in) :: c1(2), c2(2), rhs(2)
    real(wp), intent(out) :: x(2)
    logical, intent(out) :: ok
    real(wp), parameter :: sq_low = 1.0e-100_wp, sq_high = 1.0e100_wp
    real(wp) :: det, scale, sq1, sq2
    det = cross(c1, c2)
    sq1 = c1(1)**2 + c1(2)**2
    sq2 = c2(1)**2 + c2(2)**2
    if (sq1 >= sq_low .and. sq1 <= sq_high .and. sq2 >= sq_low .and. sq2 <= sq_high .and. &
        det**2 > 4.0_wp * reach_tol**2 * (sq1 * sq2)) then
      ok = .true.
    else
      scale = magnitude(c1) * magnitude(c2)
      ok = abs(det) > reach_tol * scale .and. scale > 0.0_wp
    end if
    if (.not. ok) then
      x = 0.0_wp
      return
    end if
    x(1) = cross(rhs, c2) / det
    x(2) = cross(c1, rhs) / det
  end subroutine solve2

  !> solve2 again with the same columns `c1`, `c2` for another right-hand side `rhs` (the
  !> columns found solvable by solve2 before: no test), the same arithmetic.
  pure subroutine solve2_again(c1, c2, rhs, x)
    real(wp), intent(in) :: c1(2), c2(2), rhs(2)
    real(wp), intent(out) :: x(2)
    real(wp) :: det
    det = cross(c1, c2)
    x(1) = cross(rhs, c2) / det
    x(2) = cross(c1, rhs) / det
  end subroutine solve2_again

  !> Position analysis of a dyad: `q1` and `q3` are the frames of the links its outer pairs
  !> attach to, `at1`/`at3` the attachment points in those links' coordinates (m) and
  !> `ang1`/`ang3` the guide directions relative to those links (rad, prismatic outer pairs).
  pure subroutine set_dyad_pose(g, q1, at1, ang1, q3, at3, ang3, pose, angles)
    !> Dyad geometry.
    type(dyad_geometry_t), intent(in) :: g
    !> Frame of the link pair 1 attaches to.
    type(link_state_t), intent(in) :: q1
    !> Attachment point on it (pin, or a point of the guide line), m.
    real(wp), intent(in) :: at1(2)
    !> Guide direction on it (prismatic pair 1 only), rad.
    real(wp), intent(in) :: ang1
    !> Frame of the link pair 3 attaches to.
    type(link_state_t), intent(in) :: q3
    !> Attachment point on it, m.
    real(wp), intent(in) :: at3(2)
    !> Guide direction on it (prismatic pair 3 only), rad.
    real(wp), intent(in) :: ang3
    !> The pose (inout: a pose of the same dyad reused from step to step is not set to its
    !> defaults whole; the parts a kind leaves are, and every kind sets the rest).
    type(dyad_pose_t), intent(inout) :: pose
    !> Whether the links' angles `th` are wanted (default true). Without them an RRR dyad's
    !> two and an RRP dyad's link a take no atan2 and their `th` is NaN (their directions,
    !> cos_th and sin_th, are set): for a step whose results show no link angle and whose
    !> later dyads turn no guide with these links.
    logical, intent(in), optional :: angles
    type(point_state_t) :: a, c
    logical :: with_angles
    with_angles = .true.
    if (present(angles)) with_angles = angles
    pose%status = pose_ok
    if (allocated(pose%detail)) deallocate (pose%detail)
    pose%t = 0.0_wp
    pose%stroke = 0.0_wp
    pose%stroke_v = 0.0_wp
    pose%stroke_a = 0.0_wp
    pose%extend = 0.0_wp
    call point_motion(q1, at1, a)
    call point_motion(q3, at3, c)
    select case (g%kind)
    case (kind_rrr)
      call pose_rrr(g, a, c, pose, with_angles)
    case (kind_rrp)
      call pose_rrp(g, a, c, q3%th + ang3, q3%u, q3%eq, pose, with_angles)
    case (kind_rpr)
      call pose_rpr(g, a, c, pose)
    case (kind_prp)
      call pose_prp(a, q1%th + ang1, q1%u, q1%eq, c, q3%th + ang3, q3%u, q3%eq, pose)
    case (kind_rpp)
      call pose_rpp(g, a, c, q3%th + ang3, q3%u, q3%eq, pose)
    case default
      pose%status = pose_no_assembly
    end select
  end subroutine set_dyad_pose

  !> RRR: B = A + l2 e(th_a) = C + l3 e(th_b); mode +1 puts B left of A->C. The directions
  !> come from the triangle ABC by algebra: e_a is A->C's unit vector turned by the angle at
  !> A (its cosine by the law of cosines, its sine from that cosine), e_b is C->B's unit
  !> vector; each link's angle is the atan2 of its direction, th_a on the branch
  !> atan2(A->C) + mode * angle at A (in (-2 pi, 2 pi]: the same angle as before, not
  !> reduced into (-pi, pi]).
  pure subroutine pose_rrr(g, a, c, pose, angles)
    type(dyad_geometry_t), intent(in) :: g
    type(point_state_t), intent(in) :: a, c
    type(dyad_pose_t), intent(inout) :: pose
    !> Whether th_a and th_b are computed (else NaN).
    logical, intent(in) :: angles
    real(wp), parameter :: two_pi = 2.0_wp * acos(-1.0_wp)
    real(wp) :: d(2), l, cos_al, sin_al, tha, thb, b(2), ea(2), eb(2), x(2), rhs(2), ua, ub, dh(2), cb(2)
    !> The velocity and acceleration equations' columns (the same matrix for both).
    real(wp) :: col1(2), col2(2)
    logical :: ok, d_up, d_down
    d = c%p - a%p
    l = magnitude(d)
    if (.not. l > 0.0_wp) then
      pose%status = pose_no_assembly
      pose%detail = "its outer joints coincide (distance 0 m)"
      return
    end if
    cos_al = (g%l2**2 + l**2 - g%l3**2) / (2.0_wp * g%l2 * l)
    if (abs(cos_al) > 1.0_wp + reach_tol) then
      pose%status = pose_no_assembly
      pose%detail = "distance between its outer joints "//real_str(l)//" m is outside [|l2 - l3|, l2 + l3] = ["// &
        real_str(abs(g%l2 - g%l3))//", "//real_str(g%l2 + g%l3)//"] m"
      return
    end if
    cos_al = max(-1.0_wp, min(1.0_wp, cos_al))
    ! sin of the angle at A (in [0, pi]), signed by the mode: (1 - c)(1 + c) keeps its digits
    ! where c is near +-1
    sin_al = real(g%mode, wp) * sqrt((1.0_wp - cos_al) * (1.0_wp + cos_al))
    dh = d / l
    ea = [dh(1) * cos_al - dh(2) * sin_al, dh(2) * cos_al + dh(1) * sin_al]
    b = a%p + g%l2 * ea
    cb = b - c%p
    eb = cb / fast_magnitude(cb)
    if (angles) then
      thb = atan2(cb(2), cb(1))
      ! th_a on the branch of atan2(d) + mode * alpha: atan2(d) lies in (0, pi] (d_up) or in
      ! [-pi, 0) (d_down, -pi for d(2) = -0); adding alpha in [0, pi] turns past pi only from
      ! above the x-axis, subtracting it past -pi only from below
      tha = atan2(ea(2), ea(1))
      d_up = d(2) > 0.0_wp .or. (d(2) == 0.0_wp .and. d(1) < 0.0_wp .and. sign(1.0_wp, d(2)) > 0.0_wp)
      d_down = d(2) < 0.0_wp .or. (d(2) == 0.0_wp .and. d(1) < 0.0_wp .and. sign(1.0_wp, d(2)) < 0.0_wp)
      if (g%mode > 0) then
        if (d_up .and. tha <= 0.0_wp) tha = tha + two_pi
      else
        if (d_down .and. tha > 0.0_wp) tha = tha - two_pi
      end if
    else
      tha = ieee_value(tha, ieee_quiet_nan)
      thb = tha
    end if
    col1 = g%l2 * perp(ea)
    col2 = -g%l3 * perp(eb)
    call solve2(col1, col2, c%v - a%v, x, ok)
    if (.not. ok) then
      pose%status = pose_dead
      return
    end if
    ua = x(1)
    ub = x(2)
    rhs = c%a - a%a + g%l2 * ua**2 * ea - g%l3 * ub**2 * eb
    call solve2_again(col1, col2, rhs, x)
    call set_link_frame(pose%link(1), o=a%p, th=tha, vo=a%v, u=ua, ao=a%a, eq=x(1), e=ea)
    call set_link_frame(pose%link(2), o=c%p, th=thb, vo=c%v, u=ub, ao=c%a, eq=x(2), e=eb)
    pose%p(:, 1) = a%p
    pose%p(:, 2) = b
    pose%p(:, 3) = c%p
  end subroutine pose_rrr

  !> RRP: B = A + l2 e(th_a) = G + s t (guide through G at angle gam); mode +1 takes the
  !> larger s (B further along +t).
  pure subroutine pose_rrp(g, a, gp, gam, gam_u, gam_eq, pose, angles)
    type(dyad_geometry_t), intent(in) :: g
    type(point_state_t), intent(in) :: a, gp
    real(wp), intent(in) :: gam, gam_u, gam_eq
    type(dyad_pose_t), intent(inout) :: pose
    !> Whether th_a is computed (else NaN).
    logical, intent(in) :: angles
    real(wp) :: t(2), n(2), d(2), dt, disc, s, b(2), tha, ea(2), x(2), rhs(2), ua, ds
    real(wp) :: vb(2), ab(2), col1(2)
    logical :: ok
    t = unit_at(gam)
    n = perp(t)
    d = gp%p - a%p
    dt = dot_product(d, t)
    disc = dt**2 - dot_product(d, d) + g%l2**2
    if (disc < -reach_tol * g%l2**2) then
      pose%status = pose_no_assembly
      pose%detail = "distance from its joint to the guide "//real_str(sqrt(max(dot_product(d, d) - dt**2, 0.0_wp)))// &
        " m exceeds l2 = "//real_str(g%l2)//" m"
      return
    end if
    s = -dt + real(g%mode, wp) * sqrt(max(disc, 0.0_wp))
    b = gp%p + s * t
    if (angles) then
      tha = atan2(b(2) - a%p(2), b(1) - a%p(1))
    else
      tha = ieee_value(tha, ieee_quiet_nan)
    end if
    ea = (b - a%p) / fast_magnitude(b - a%p)
    col1 = g%l2 * perp(ea)
    call solve2(col1, -t, gp%v + s * gam_u * n - a%v, x, ok)
    if (.not. ok) then
      pose%status = pose_dead
      return
    end if
    ua = x(1)
    ds = x(2)
    rhs = gp%a + (2.0_wp * ds * gam_u + s * gam_eq) * n - s * gam_u**2 * t - a%a + g%l2 * ua**2 * ea
    call solve2_again(col1, -t, rhs, x)
    vb = a%v + g%l2 * ua * perp(ea)
    ab = a%a + g%l2 * x(1) * perp(ea) - g%l2 * ua**2 * ea
    call set_link_frame(pose%link(1), o=a%p, th=tha, vo=a%v, u=ua, ao=a%a, eq=x(1), e=ea)
    call set_link_frame(pose%link(2), o=b, th=gam, vo=vb, u=gam_u, ao=ab, eq=gam_eq, e=t)
    pose%p(:, 1) = a%p
    pose%p(:, 2) = b
    pose%p(:, 3) = b
    pose%t(:, 3) = t
    call set_stroke(pose, 3, s, ds, x(2), t)
  end subroutine pose_rrp

  !> RPR: A - C = s t + e n with t = e(th) the common slide direction; mode +1 takes s > 0.
  pure subroutine pose_rpr(g, a, c, pose)
    type(dyad_geometry_t), intent(in) :: g
    type(point_state_t), intent(in) :: a, c
    type(dyad_pose_t), intent(inout) :: pose
    real(wp) :: d(2), l2sq, disc, s, th, t(2), n(2), x(2), rhs(2), u, ds, col1(2)
    logical :: ok
    d = a%p - c%p
    l2sq = dot_product(d, d)
    disc = l2sq - g%e**2
    if (disc < -reach_tol * max(l2sq, g%e**2) .or. .not. l2sq > 0.0_wp) then
      pose%status = pose_no_assembly
      pose%detail = "distance between its outer joints "//real_str(sqrt(l2sq))//" m is less than the slider's offset |e| = "// &
        real_str(abs(g%e))//" m"
      return
    end if
    s = real(g%mode, wp) * sqrt(max(disc, 0.0_wp))
    th = atan2(d(2), d(1)) - atan2(g%e, s)
    t = unit_at(th)
    n = perp(t)
    col1 = s * n - g%e * t
    call solve2(col1, t, a%v - c%v, x, ok)
    if (.not. ok) then
      pose%status = pose_dead
      return
    end if
    u = x(1)
    ds = x(2)
    rhs = a%a - c%a - 2.0_wp * ds * u * n + u**2 * (s * t + g%e * n)
    call solve2_again(col1, t, rhs, x)
    call set_link_frame(pose%link(1), o=a%p, th=th, vo=a%v, u=u, ao=a%a, eq=x(1), e=t)
    call set_link_frame(pose%link(2), o=c%p, th=th, vo=c%v, u=u, ao=c%a, eq=x(1), e=t)
    pose%p(:, 1) = a%p
    pose%p(:, 2) = a%p
    pose%p(:, 3) = c%p
    pose%t(:, 2) = t
    ! pin A (link a) moves away from C (link b) as |s| grows: the actuator's length
    call set_stroke(pose, 2, real(g%mode, wp) * s, real(g%mode, wp) * ds, real(g%mode, wp) * x(2), &
                    real(g%mode, wp) * t)
  end subroutine pose_rpr

  !> PRP: B = G1 + s1 t1 = G2 + s2 t2 (intersection of the two guides).
  pure subroutine pose_prp(g1, gam1, u1, eq1, g2, gam2, u2, eq2, pose)
    type(point_state_t), intent(in) :: g1, g2
    real(wp), intent(in) :: gam1, u1, eq1, gam2, u2, eq2
    type(dyad_pose_t), intent(inout) :: pose
    real(wp) :: t1(2), t2(2), n1(2), n2(2), x(2), s1, s2, ds1, ds2, rhs(2), b(2), vb(2), ab(2)
    logical :: ok
    t1 = unit_at(gam1)
    t2 = unit_at(gam2)
    n1 = perp(t1)
    n2 = perp(t2)
    call solve2(t1, -t2, g2%p - g1%p, x, ok)
    if (.not. ok) then
      pose%status = pose_no_assembly
      pose%detail = "its two guides are parallel (directions "//real_str(modulo(gam1 * rad_to_deg, 360.0_wp))//" and "// &
        real_str(modulo(gam2 * rad_to_deg, 360.0_wp))//" deg)"
      return
    end if
    s1 = x(1)
    s2 = x(2)
    b = g1%p + s1 * t1
    call solve2_again(t1, -t2, g2%v - g1%v + s2 * u2 * n2 - s1 * u1 * n1, x)
    ds1 = x(1)
    ds2 = x(2)
    rhs = g2%a - g1%a + (2.0_wp * ds2 * u2 + s2 * eq2) * n2 - s2 * u2**2 * t2 &
          - (2.0_wp * ds1 * u1 + s1 * eq1) * n1 + s1 * u1**2 * t1
    call solve2_again(t1, -t2, rhs, x)
    vb = g1%v + ds1 * t1 + s1 * u1 * n1
    ab = g1%a + x(1) * t1 + (2.0_wp * ds1 * u1 + s1 * eq1) * n1 - s1 * u1**2 * t1
    call set_link_frame(pose%link(1), o=b, th=gam1, vo=vb, u=u1, ao=ab, eq=eq1, e=t1)
    call set_link_frame(pose%link(2), o=b, th=gam2, vo=vb, u=u2, ao=ab, eq=eq2, e=t2)
    pose%p(:, 1) = b
    pose%p(:, 2) = b
    pose%p(:, 3) = b
    pose%t(:, 1) = t1
    pose%t(:, 3) = t2
    call set_stroke(pose, 1, s1, ds1, x(1), t1)
    call set_stroke(pose, 3, s2, ds2, x(2), t2)
  end subroutine pose_prp

  !> RPP: link b slides along the guide (G, t), its origin O_b = G + s_b t; the slot of b
  !> (through O_b + R(gam) slot_at, direction gam + slot_angle) carries pin A at s_a.
  pure subroutine pose_rpp(g, a, gp, gam, gam_u, gam_eq, pose)
    type(dyad_geometry_t), intent(in) :: g
    type(point_state_t), intent(in) :: a, gp
    real(wp), intent(in) :: gam, gam_u, gam_eq
    type(dyad_pose_t), intent(inout) :: pose
    real(wp) :: t(2), n(2), ts(2), ns(2), w(2), x(2), sb, sa, dsb, dsa, rhs(2), ob(2), vb(2), ab(2)
    logical :: ok
    t = unit_at(gam)
    n = perp(t)
    ts = unit_at(gam + g%slot_angle)
    ns = perp(ts)
    w = a%p - gp%p
    ! rotate(g%slot_at, gam) with t = [cos(gam), sin(gam)]
    call solve2(t, ts, w - [t(1) * g%slot_at(1) - t(2) * g%slot_at(2), t(2) * g%slot_at(1) + t(1) * g%slot_at(2)], &
                x, ok)
    if (.not. ok) then
      pose%status = pose_no_assembly
      pose%detail = "its slot is parallel to its guide (slot_angle = "//real_str(g%slot_angle * rad_to_deg)//" deg)"
      return
    end if
    sb = x(1)
    sa = x(2)
    call solve2_again(t, ts, a%v - gp%v - gam_u * perp(w), x)
    dsb = x(1)
    dsa = x(2)
    rhs = a%a - gp%a - 2.0_wp * gam_u * (dsb * n + dsa * ns) - gam_eq * perp(w) + gam_u**2 * w
    call solve2_again(t, ts, rhs, x)
    ob = gp%p + sb * t
    vb = gp%v + dsb * t + sb * gam_u * n
    ab = gp%a + x(1) * t + (2.0_wp * dsb * gam_u + sb * gam_eq) * n - sb * gam_u**2 * t
    call set_link_frame(pose%link(1), o=a%p, th=gam + g%slot_angle, vo=a%v, u=gam_u, ao=a%a, eq=gam_eq, e=ts)
    call set_link_frame(pose%link(2), o=ob, th=gam, vo=vb, u=gam_u, ao=ab, eq=gam_eq, e=t)
    pose%p(:, 1) = a%p
    pose%p(:, 2) = a%p
    pose%p(:, 3) = ob
    pose%t(:, 2) = ts
    pose%t(:, 3) = t
    call set_stroke(pose, 2, sa, dsa, x(2), ts)
    call set_stroke(pose, 3, sb, dsb, x(1), t)
  end subroutine pose_rpp

  !> Record the stroke of prismatic pair `j` with its analogues and extension direction.
  pure subroutine set_stroke(pose, j, s, ds, dds, extend)
    !> Pose being filled.
    type(dyad_pose_t), intent(inout) :: pose
    !> Pair index 1..3.
    integer, intent(in) :: j
    !> Stroke, m; d/dphi1, m/rad; d2/dphi1^2, m/rad^2.
    real(wp), intent(in) :: s, ds, dds
    !> Unit direction of extension.
    real(wp), intent(in) :: extend(2)
    pose%stroke(j) = s
    pose%stroke_v(j) = ds
    pose%stroke_a(j) = dds
    pose%extend(:, j) = extend
  end subroutine set_stroke

end module kinetostat_assur_kinematics
