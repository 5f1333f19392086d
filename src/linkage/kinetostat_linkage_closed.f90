!> The closed forms of the general engine's input units of one link and dyads
!> (kinetostat_linkage places such units with them instead of Newton's method): the
!> intersections of two circles, of a circle and a line, of two lines, and the turn that
!> brings a guide of one link through a point of another. Where there are two positions the
!> one nearest to the pose before (the branch Newton's method from there converges to) is
!> taken.
module kinetostat_linkage_closed
  use kinetostat_kinds, only: wp, pi
  use kinetostat_vec2, only: perp, rotate
  use kinetostat_linkage_types, only: linkage_t, pair_r
  implicit none
  private
  public :: place_units, units_pairs, dyad_arms, point_position, turn_of, turned, position_cs, unit_pairs, dyad_pairs
  public :: circle_circle, circle_line, line_line, turn_through, turn_between, unwrap

  !> Two lines are taken as parallel (no closed form; Newton's method decides) when the sine
  !> of their angle is below this.
  real(wp), parameter :: parallel_sine = 1.0e-9_wp

contains

  !> Each unit of the structural analysis placed in its order for drive values dq by a closed
  !> form (q: in, the poses before, whose branch each unit keeps; out, the new poses). An
  !> input unit: its link's turn from the drive, its joint on the known link. A dyad: by
  !> its kind (place_dyad). placed is false where a unit has none or no position. The
  !> links' turns as cos and sin (cs) come in with q and go out with the new poses: each
  !> turn's cos and sin taken once, where the link is placed.
  pure subroutine place_units(mech, dq, q, placed, cs, arms, pairs_of)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Drive values, rad or m.
    real(wp), intent(in) :: dq(:)
    !> Poses.
    real(wp), intent(inout) :: q(:)
    logical, intent(out) :: placed
    !> cos and sin of each link's turn in q (2 x 0:n, column 0 the frame's: 1 and 0); out,
    !> of the new poses (valid when placed).
    real(wp), intent(inout) :: cs(:, 0:)
    !> The dyads' arms (dyad_arms).
    real(wp), intent(in) :: arms(:, :)
    !> Each unit's pairs as unit_pairs and dyad_pairs find them (units_pairs).
    integer, intent(in) :: pairs_of(:, :)
    integer :: u, nk, d, lk, kn, kp(3), inner, e(2)
    real(wp) :: val, th, x(2), w(2)
    placed = .false.
    do u = 1, size(mech%units)
      kp = pairs_of(1:3, u)
      nk = pairs_of(4, u)
      d = pairs_of(5, u)
      inner = pairs_of(6, u)
      e = pairs_of(7:8, u)
      if (nk > 3) return
      if (mech%units(u)%class == 2 .and. nk == 3) then
        call place_dyad(mech, mech%units(u)%links, inner, e, q, placed, cs, arms(:, u))
        if (.not. placed) return
        cycle
      end if
      if (mech%units(u)%class /= 1 .or. nk /= 1 .or. d == 0) return
      if (mech%drives(d)%pair /= kp(1)) return
      associate (pr => mech%pairs(kp(1)))
        lk = mech%units(u)%links(1)
        kn = pr%a + pr%b - lk
        val = dq(d) - mech%drives(d)%q_ref
        x = position_cs(mech, q, cs, kn, pr%at)
        if (pr%kind == pair_r) then
          th = turn_of(q, kn) + merge(val, -val, lk == pr%a)
        else
          ! the block's point is the guide's moved by the stroke along the guide
          th = turn_of(q, kn)
          w = turned(cs, kn, pr%u) * val
          x = x + merge(-w, w, lk == pr%guide)
        end if
        call put_pose(mech, q, cs, lk, pr%at, x, th)
      end associate
    end do
    placed = .true.
  end subroutine place_units

  !> Unit u's pairs kp(1:nk) (their first rows among its rows, in order; nk = 4: more than
  !> three) and its drive d (the last among its rows; 0: none).
  pure subroutine unit_pairs(mech, u, kp, nk, d)
    type(linkage_t), intent(in) :: mech
    integer, intent(in) :: u
    integer, intent(out) :: kp(3), nk, d
    integer :: i, r, np
    np = size(mech%pairs)
    kp = 0
    nk = 0
    d = 0
    do i = 1, size(mech%units(u)%rows)
      r = mech%units(u)%rows(i)
      if (r > 2 * np) then
        d = r - 2 * np
      else if (mod(r, 2) == 1) then
        if (nk == 3) then
          nk = 4
          return
        end if
        nk = nk + 1
        kp(nk) = (r + 1) / 2
      end if
    end do
  end subroutine unit_pairs

  !> Every unit's pairs for place_units (8 x units): unit_pairs' kp(1:3), nk and d, and a
  !> dyad's (class II, three pairs) inner pair and outer pairs e(1:2) of dyad_pairs (-1 and
  !> 0 for any other unit).
  pure function units_pairs(mech) result(pairs_of)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    integer, allocatable :: pairs_of(:, :)
    integer :: u, kp(3), nk, d, inner, e(2)
    allocate (pairs_of(8, size(mech%units)), source=0)
    do u = 1, size(mech%units)
      call unit_pairs(mech, u, kp, nk, d)
      inner = -1
      e = 0
      if (mech%units(u)%class == 2 .and. nk == 3) call dyad_pairs(mech, mech%units(u)%links, kp, inner, e)
      pairs_of(:, u) = [kp, nk, d, inner, e]
    end do
  end function units_pairs

  !> The dyad of links set(1), set(2), its inner pair and outer pairs e (of set(1), set(2); as
  !> dyad_pairs finds them) placed
  !> in closed form: RRR two circles; RRP a circle and a line (the slider's turn is its
  !> guide's); RPR the common turn that brings the guide through the other link's joint;
  !> PRP two lines (both turns known); RPP the turning link at its joint with the sliding
  !> link's turn, then the sliding link by two lines. placed is false for PPP, for outer
  !> pairs both on one link, and where there is no position.
  !> arms: dyad_arms' column of the dyad; cs: as place_units'.
  pure subroutine place_dyad(mech, set, inner, e, q, placed, cs, arms)
    type(linkage_t), intent(in) :: mech
    integer, intent(in) :: set(2), inner, e(2)
    real(wp), intent(inout) :: q(:)
    logical, intent(out) :: placed
    real(wp), intent(inout) :: cs(:, 0:)
    real(wp), intent(in) :: arms(4)
    integer :: j, kr, kpp, lr, lp
    real(wp) :: a(2), c(2), b(2), x(2), n1(2), n2(2), s1, s2, th, th2
    placed = .false.
    if (inner == 0 .or. any(e == 0)) return
    b = mech%pairs(inner)%at
    associate (p1 => mech%pairs(e(1)), p2 => mech%pairs(e(2)), pin => mech%pairs(inner))
      if (pin%kind == pair_r .and. p1%kind == pair_r .and. p2%kind == pair_r) then
        a = position_cs(mech, q, cs, p1%a + p1%b - set(1), p1%at)
        c = position_cs(mech, q, cs, p2%a + p2%b - set(2), p2%at)
        call circle_circle(a, arms(1), c, arms(2), position_cs(mech, q, cs, set(1), b), x, placed)
        if (.not. placed) return
        call put_pose(mech, q, cs, set(1), b, x, turn_from(x - a, arms(3), q(3 * set(1))))
        call put_pose(mech, q, cs, set(2), b, x, turn_from(x - c, arms(4), q(3 * set(2))))
      else if (pin%kind == pair_r .and. p1%kind /= p2%kind) then
        ! lr: the link of the outer turning pair kr; lp: of the outer sliding pair kpp
        j = merge(1, 2, p1%kind == pair_r)
        lr = set(j)
        lp = set(3 - j)
        kr = e(j)
        kpp = e(3 - j)
        a = position_cs(mech, q, cs, mech%pairs(kr)%a + mech%pairs(kr)%b - lr, mech%pairs(kr)%at)
        call slide_line(kpp, lp, b, th, n1, s1)
        call circle_line(a, arms(j), n1, s1, position_cs(mech, q, cs, lr, b), x, placed)
        if (.not. placed) return
        call put_pose(mech, q, cs, lr, b, x, turn_from(x - a, arms(2 + j), q(3 * lr)))
        call put_pose(mech, q, cs, lp, b, x, th)
      else if (pin%kind == pair_r) then
        call slide_line(e(1), set(1), b, th, n1, s1)
        call slide_line(e(2), set(2), b, th2, n2, s2)
        call line_line(n1, s1, n2, s2, x, placed)
        if (.not. placed) return
        call put_pose(mech, q, cs, set(1), b, x, th)
        call put_pose(mech, q, cs, set(2), b, x, th2)
      else if (p1%kind == pair_r .and. p2%kind == pair_r) then
        ! one turn th for both: (perp(u) turned by th) . (c - a) = -perp(u) . (p1%at - p2%at)
        a = position_cs(mech, q, cs, p1%a + p1%b - set(1), p1%at)
        c = position_cs(mech, q, cs, p2%a + p2%b - set(2), p2%at)
        call turn_through(perp(pin%u), c - a, dot_product(perp(pin%u), p1%at - p2%at), q(3 * set(1)), th, placed)
        if (.not. placed) return
        call put_pose(mech, q, cs, set(1), p1%at, a, th)
        call put_pose(mech, q, cs, set(2), p2%at, c, th)
      else if (p1%kind /= p2%kind) then
        j = merge(1, 2, p1%kind == pair_r)
        lr = set(j)
        lp = set(3 - j)
        kr = e(j)
        kpp = e(3 - j)
        ! the turning link turns with the sliding one, whose turn is its outer guide's
        th = turn_of(q, mech%pairs(kpp)%a + mech%pairs(kpp)%b - lp)
        a = position_cs(mech, q, cs, mech%pairs(kr)%a + mech%pairs(kr)%b - lr, mech%pairs(kr)%at)
        call put_pose(mech, q, cs, lr, mech%pairs(kr)%at, a, th)
        ! the sliding link's point b: on the inner guide through lr's point b, and on the outer
        n1 = perp(turned(cs, lr, pin%u))
        s1 = dot_product(n1, position_cs(mech, q, cs, lr, b))
        call slide_line(kpp, lp, b, th, n2, s2)
        call line_line(n1, s1, n2, s2, x, placed)
        if (.not. placed) return
        call put_pose(mech, q, cs, lp, b, x, th)
      end if
    end associate
  contains
    !> The outer sliding pair k of link lk: lk's turn th (its known link's) and the line
    !> n . x = s its point p lies on.
    pure subroutine slide_line(k, lk, p, th, n, s)
      integer, intent(in) :: k, lk
      real(wp), intent(in) :: p(2)
      real(wp), intent(out) :: th, n(2), s
      associate (pr => mech%pairs(k))
        th = turn_of(q, pr%a + pr%b - lk)
        n = perp(turned(cs, pr%a + pr%b - lk, pr%u))
        s = dot_product(n, position_cs(mech, q, cs, pr%a + pr%b - lk, pr%at) - turned(cs, pr%a + pr%b - lk, pr%at - p))
      end associate
    end subroutine slide_line
  end subroutine place_dyad

  !> The inner pair and the outer pair of each link (e(1) of set(1), e(2) of set(2)) of the
  !> dyad of links set and pairs kp; 0 where there is none (or two outer pairs on one link).
  pure subroutine dyad_pairs(mech, set, kp, inner, e)
    type(linkage_t), intent(in) :: mech
    integer, intent(in) :: set(2), kp(3)
    integer, intent(out) :: inner, e(2)
    integer :: i, j
    inner = 0
    e = 0
    do i = 1, 3
      associate (pr => mech%pairs(kp(i)))
        if (any(set == pr%a) .and. any(set == pr%b)) then
          inner = kp(i)
        else
          j = merge(1, 2, pr%a == set(1) .or. pr%b == set(1))
          if (e(j) /= 0) return
          e(j) = kp(i)
        end if
      end associate
    end do
  end subroutine dyad_pairs

  !> What place_units takes from the geometry alone, per unit (4 x units): of a dyad whose
  !> outer pair on link j (1, 2) turns, the distance of that pair's joint from the inner
  !> joint (row j, m) and that arm's direction at turn 0 (row 2 + j, rad); 0 elsewhere.
  pure function dyad_arms(mech) result(arms)
    type(linkage_t), intent(in) :: mech
    real(wp), allocatable :: arms(:, :)
    integer :: u, nk, d, kp(3), inner, e(2), j
    real(wp) :: v0(2)
    allocate (arms(4, size(mech%units)), source=0.0_wp)
    do u = 1, size(mech%units)
      if (mech%units(u)%class /= 2 .or. size(mech%units(u)%links) /= 2) cycle
      call unit_pairs(mech, u, kp, nk, d)
      if (nk /= 3) cycle
      call dyad_pairs(mech, mech%units(u)%links, kp, inner, e)
      if (inner == 0 .or. any(e == 0)) cycle
      do j = 1, 2
        if (mech%pairs(e(j))%kind /= pair_r) cycle
        v0 = mech%pairs(inner)%at - mech%pairs(e(j))%at
        arms(j, u) = norm2(v0)
        arms(2 + j, u) = atan2(v0(2), v0(1))
      end do
    end do
  end function dyad_arms

  !> Link i's pose with turn th (rad) and its point p (reference position) at x (m); its
  !> turn's cos and sin into cs.
  pure subroutine put_pose(mech, q, cs, i, p, x, th)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(inout) :: q(:)
    real(wp), intent(inout) :: cs(:, 0:)
    integer, intent(in) :: i
    real(wp), intent(in) :: p(2), x(2), th
    q(3 * i) = th
    cs(1, i) = cos(th)
    cs(2, i) = sin(th)
    q(3 * i - 2:3 * i - 1) = x - turned(cs, i, p - mech%links(i)%c)
  end subroutine put_pose

  !> `v` turned by link i's turn (0: the frame) from set_turns (kinetostat_linkage_constraints)
  !> or place_units: rotate(v, turn) bit for bit.
  pure function turned(cs, i, v) result(w)
    !> Turns from set_turns.
    real(wp), intent(in) :: cs(:, 0:)
    !> Link index (0: frame).
    integer, intent(in) :: i
    !> Vector to turn.
    real(wp), intent(in) :: v(2)
    real(wp) :: w(2)
    w = [cs(1, i) * v(1) - cs(2, i) * v(2), cs(2, i) * v(1) + cs(1, i) * v(2)]
  end function turned

  !> point_position with the turns of set_turns.
  pure function position_cs(mech, q, cs, i, p) result(x)
    !> The linkage; link i (0: frame).
    type(linkage_t), intent(in) :: mech
    integer, intent(in) :: i
    !> Poses, their turns (set_turns) and the point at the reference position (m).
    real(wp), intent(in) :: q(:), cs(:, 0:), p(2)
    real(wp) :: x(2)
    x = p
    if (i > 0) x = q(3 * i - 2:3 * i - 1) + turned(cs, i, p - mech%links(i)%c)
  end function position_cs

  !> Position of point `p` (given at the reference position) of link `i` (0: frame) in pose q.
  pure function point_position(mech, q, i, p) result(x)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Poses.
    real(wp), intent(in) :: q(:)
    !> Link index.
    integer, intent(in) :: i
    !> The point at the reference position, m.
    real(wp), intent(in) :: p(2)
    real(wp) :: x(2)
    if (i == 0) then
      x = p
    else
      x = q(3 * i - 2:3 * i - 1) + rotate(p - mech%links(i)%c, q(3 * i))
    end if
  end function point_position

  !> Angle of link i (0: frame) in pose q, rad.
  pure real(wp) function turn_of(q, i)
    real(wp), intent(in) :: q(:)
    integer, intent(in) :: i
    turn_of = 0.0_wp
    if (i > 0) turn_of = q(3 * i)
  end function turn_of

  !> The point x at distance ra from a and rc from c nearest to `near`; ok false when the
  !> circles do not meet (or a = c).
  pure subroutine circle_circle(a, ra, c, rc, near, x, ok)
    !> Centres, m.
    real(wp), intent(in) :: a(2), c(2)
    !> Radii, m.
    real(wp), intent(in) :: ra, rc
    !> The point whose branch is kept, m.
    real(wp), intent(in) :: near(2)
    !> The intersection, m.
    real(wp), intent(out) :: x(2)
    logical, intent(out) :: ok
    real(wp) :: d, e(2), t, h2
    x = a
    d = norm2(c - a)
    ok = d > 0.0_wp
    if (.not. ok) return
    e = (c - a) / d
    t = (d * d + ra * ra - rc * rc) / (2.0_wp * d)
    h2 = ra * ra - t * t
    ok = h2 >= 0.0_wp
    if (.not. ok) return
    x = nearer(a + t * e, sqrt(h2) * perp(e), near)
  end subroutine circle_circle

  !> The point x at distance r from a on the line n . x = s (n a unit vector) nearest to
  !> `near`; ok false when they do not meet.
  pure subroutine circle_line(a, r, n, s, near, x, ok)
    !> Centre (m) and radius (m) of the circle.
    real(wp), intent(in) :: a(2), r
    !> The line's unit normal and its distance from the origin along it, m.
    real(wp), intent(in) :: n(2), s
    !> The point whose branch is kept, m.
    real(wp), intent(in) :: near(2)
    !> The intersection, m.
    real(wp), intent(out) :: x(2)
    logical, intent(out) :: ok
    real(wp) :: dist, h2
    dist = s - dot_product(n, a)
    h2 = r * r - dist * dist
    x = a
    ok = h2 >= 0.0_wp
    if (.not. ok) return
    x = nearer(a + dist * n, sqrt(h2) * perp(n), near)
  end subroutine circle_line

  !> f + h or f - h, whichever is nearer to `near`.
  pure function nearer(f, h, near) result(x)
    real(wp), intent(in) :: f(2), h(2), near(2)
    real(wp) :: x(2)
    if (sum((f + h - near)**2) <= sum((f - h - near)**2)) then
      x = f + h
    else
      x = f - h
    end if
  end function nearer

  !> The point x on the lines n1 . x = s1 and n2 . x = s2 (unit normals); ok false when they
  !> are parallel.
  pure subroutine line_line(n1, s1, n2, s2, x, ok)
    !> Unit normals and distances from the origin along them, m.
    real(wp), intent(in) :: n1(2), s1, n2(2), s2
    !> The intersection, m.
    real(wp), intent(out) :: x(2)
    logical, intent(out) :: ok
    real(wp) :: det
    det = n1(1) * n2(2) - n1(2) * n2(1)
    x = 0.0_wp
    ok = abs(det) > parallel_sine
    if (.not. ok) return
    x = [(s1 * n2(2) - s2 * n1(2)) / det, (n1(1) * s2 - n2(1) * s1) / det]
  end subroutine line_line

  !> The turn theta with (n0 turned by theta) . d = -k nearest to `prev` (rad); ok false when
  !> there is none (|k| > |d|).
  pure subroutine turn_through(n0, d, k, prev, theta, ok)
    !> Unit vector at turn 0; the vector it is dotted with, m; the wanted value's negative, m.
    real(wp), intent(in) :: n0(2), d(2), k
    !> The turn whose branch is kept, rad.
    real(wp), intent(in) :: prev
    !> The turn, rad.
    real(wp), intent(out) :: theta
    logical, intent(out) :: ok
    real(wp) :: len, off, t1, t2
    theta = prev
    len = norm2(d)
    ok = len > 0.0_wp .and. abs(k) <= len
    if (.not. ok) return
    off = acos(-k / len)
    t1 = unwrap(atan2(d(2), d(1)) + off - atan2(n0(2), n0(1)), prev)
    t2 = unwrap(atan2(d(2), d(1)) - off - atan2(n0(2), n0(1)), prev)
    theta = t1
    if (abs(t2 - prev) < abs(t1 - prev)) theta = t2
  end subroutine turn_through

  !> The turn that brings vector v0 (at turn 0) along v, the one nearest to `prev`, rad.
  pure real(wp) function turn_between(v, v0, prev)
    real(wp), intent(in) :: v(2), v0(2), prev
    turn_between = turn_from(v, atan2(v0(2), v0(1)), prev)
  end function turn_between

  !> turn_between with v0's direction (rad) given.
  pure real(wp) function turn_from(v, turn0, prev)
    real(wp), intent(in) :: v(2), turn0, prev
    turn_from = unwrap(atan2(v(2), v(1)) - turn0, prev)
  end function turn_from

  !> The angle theta + 2 pi j nearest to `prev` (theta itself when it is within pi), rad.
  pure real(wp) function unwrap(theta, prev)
    real(wp), intent(in) :: theta, prev
    unwrap = theta
    if (abs(theta - prev) > pi) unwrap = theta - 2.0_wp * pi * anint((theta - prev) / (2.0_wp * pi))
  end function unwrap

end module kinetostat_linkage_closed
