!> The general engine's constraint equations and the points of its links, from the poses
!> alone (no workspace): the rows of the constraints (2 per pair, 1 per drive), phi(q) and
!> the Jacobian J by its rows' links, the velocity-dependent part h of their second
!> derivative, a link point's position, velocity and acceleration, and the links' turns as
!> cos and sin taken once per pose (kinetostat_linkage solves with them).
module kinetostat_linkage_constraints
  use kinetostat_kinds, only: wp
  use kinetostat_vec2, only: rotate, perp
  use kinetostat_linkage_types, only: linkage_t, linkage_pair_t, pair_r, pair_p
  use kinetostat_linkage_closed, only: turn_of, turned, position_cs
  implicit none
  private
  public :: linkage_rows, pair_row, drive_row, linkage_reference_pose, link_point_state, state_at
  public :: set_turns, turned, position_cs, lever_cs, constraints, quadratic_terms

contains

  !> Number of constraint rows (2 per pair, 1 per drive).
  pure integer function linkage_rows(mech)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    linkage_rows = 2 * size(mech%pairs) + size(mech%drives)
  end function linkage_rows

  !> First row of pair `k`.
  pure integer function pair_row(k)
    !> Pair number.
    integer, intent(in) :: k
    pair_row = 2 * k - 1
  end function pair_row

  !> Row of drive `d`.
  pure integer function drive_row(mech, d)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Drive number.
    integer, intent(in) :: d
    drive_row = 2 * size(mech%pairs) + d
  end function drive_row

  !> The poses of the reference position (every link at its reference point, turned by 0).
  pure function linkage_reference_pose(mech) result(q)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    real(wp), allocatable :: q(:)
    integer :: i
    allocate (q(3 * size(mech%links)))
    do i = 1, size(mech%links)
      q(3 * i - 2:3 * i) = [mech%links(i)%c(1), mech%links(i)%c(2), 0.0_wp]
    end do
  end function linkage_reference_pose

  !> Position, velocity and acceleration of point `p` (reference position) of link `i`.
  pure subroutine link_point_state(mech, q, qd, qdd, i, p, x, v, a, cs)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Poses and their derivatives.
    real(wp), intent(in) :: q(:), qd(:), qdd(:)
    !> Link index (0: frame).
    integer, intent(in) :: i
    !> The point at the reference position, m.
    real(wp), intent(in) :: p(2)
    !> Position (m), velocity (m/s), acceleration (m/s^2).
    real(wp), intent(out) :: x(2), v(2), a(2)
    !> The turns of q (set_turns), when the caller has them.
    real(wp), intent(in), optional :: cs(:, 0:)
    if (i == 0) then
      x = p; v = 0.0_wp; a = 0.0_wp
    else if (present(cs)) then
      call state_at(q, qd, qdd, i, turned(cs, i, p - mech%links(i)%c), x, v, a)
    else
      call state_at(q, qd, qdd, i, rotate(p - mech%links(i)%c, q(3 * i)), x, v, a)
    end if
  end subroutine link_point_state

  !> Position, velocity and acceleration of the point of moving link `i` at `r` (m) from its
  !> origin, turned with the link.
  pure subroutine state_at(q, qd, qdd, i, r, x, v, a)
    !> Poses and their derivatives.
    real(wp), intent(in) :: q(:), qd(:), qdd(:)
    !> Link index (> 0).
    integer, intent(in) :: i
    !> The point from the link's origin in the global frame, m.
    real(wp), intent(in) :: r(2)
    !> Position (m), velocity (m/s), acceleration (m/s^2).
    real(wp), intent(out) :: x(2), v(2), a(2)
    x = q(3 * i - 2:3 * i - 1) + r
    v = qd(3 * i - 2:3 * i - 1) + qd(3 * i) * perp(r)
    a = qdd(3 * i - 2:3 * i - 1) + qdd(3 * i) * perp(r) - qd(3 * i)**2 * r
  end subroutine state_at

  !> cos and sin of every link's turn in poses q (column 0: the frame's, of a turn 0): with
  !> `turned`, rotate's arithmetic without a cos and a sin per call.
  pure subroutine set_turns(q, cs)
    !> Poses (3n).
    real(wp), intent(in) :: q(:)
    !> cos and sin of each link's turn (2 x 0:n).
    real(wp), intent(out) :: cs(:, 0:)
    integer :: i
    cs(1, 0) = cos(0.0_wp)
    cs(2, 0) = sin(0.0_wp)
    do i = 1, size(q) / 3
      cs(1, i) = cos(q(3 * i))
      cs(2, i) = sin(q(3 * i))
    end do
  end subroutine set_turns

  !> Lever of point p of link i from its reference point (0 for the frame), m, with the turns
  !> of set_turns.
  pure function lever_cs(mech, cs, i, p) result(r)
    !> The linkage.
    type(linkage_t), intent(in) :: mech
    !> Turns (set_turns).
    real(wp), intent(in) :: cs(:, 0:)
    !> Link index (0: frame).
    integer, intent(in) :: i
    !> The point at the reference position, m.
    real(wp), intent(in) :: p(2)
    real(wp) :: r(2)
    r = 0.0_wp
    if (i > 0) r = turned(cs, i, p - mech%links(i)%c)
  end function lever_cs

  !> Row r of J on the columns of its link in `slot` (work%jl(slot, r)): v.
  pure subroutine put_j(je, r, slot, v)
    real(wp), intent(inout) :: je(:, :, :)
    integer, intent(in) :: r, slot
    real(wp), intent(in) :: v(3)
    je(:, slot, r) = v
  end subroutine put_j

  !> Constraints phi(q) for drive values `dq` and their Jacobian J by its rows' links (je, as
  !> work%je: slot 1 the first link of work%jl, 2 the second).
  pure subroutine constraints(mech, q, dq, phi, je, cs)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: q(:)
    !> Drive values, rad or m.
    real(wp), intent(in) :: dq(:)
    real(wp), intent(out) :: phi(:)
    real(wp), intent(inout) :: je(:, :, :)
    !> The turns of q (set_turns).
    real(wp), intent(in) :: cs(:, 0:)
    real(wp) :: ra(2), rb(2), delta(2), n(2), u(2), xa(2), xb(2)
    integer :: k, r, a, b, blk, gd, d
    phi = 0.0_wp
    do k = 1, size(mech%pairs)
      associate (pr => mech%pairs(k))
        r = pair_row(k)
        if (pr%kind == pair_r) then
          a = pr%a; b = pr%b
          ra = lever_cs(mech, cs, a, pr%at)
          rb = lever_cs(mech, cs, b, pr%at)
          ! (through fixed-size locals: no temporary array from the heap)
          xa = position_cs(mech, q, cs, a, pr%at)
          xb = position_cs(mech, q, cs, b, pr%at)
          phi(r) = xa(1) - xb(1)
          phi(r + 1) = xa(2) - xb(2)
          call put_j(je, r, 1, [1.0_wp, 0.0_wp, -ra(2)])
          call put_j(je, r + 1, 1, [0.0_wp, 1.0_wp, ra(1)])
          call put_j(je, r, 2, [-1.0_wp, 0.0_wp, rb(2)])
          call put_j(je, r + 1, 2, [0.0_wp, -1.0_wp, -rb(1)])
        else
          gd = pr%guide
          blk = pr%a + pr%b - gd
          phi(r) = turn_of(q, blk) - turn_of(q, gd)
          call put_j(je, r, 1, [0.0_wp, 0.0_wp, 1.0_wp])
          call put_j(je, r, 2, [0.0_wp, 0.0_wp, -1.0_wp])
          u = turned(cs, gd, pr%u)
          n = perp(u)
          delta = position_cs(mech, q, cs, blk, pr%at) - position_cs(mech, q, cs, gd, pr%at)
          phi(r + 1) = dot_product(n, delta)
          call slide_row(je, r + 1, n, lever_cs(mech, cs, blk, pr%at), lever_cs(mech, cs, gd, pr%at), delta)
        end if
      end associate
    end do
    do d = 1, size(mech%drives)
      associate (pr => mech%pairs(mech%drives(d)%pair))
        r = drive_row(mech, d)
        if (pr%kind == pair_r) then
          phi(r) = turn_of(q, pr%a) - turn_of(q, pr%b) - (dq(d) - mech%drives(d)%q_ref)
          call put_j(je, r, 1, [0.0_wp, 0.0_wp, 1.0_wp])
          call put_j(je, r, 2, [0.0_wp, 0.0_wp, -1.0_wp])
        else
          gd = pr%guide
          blk = pr%a + pr%b - gd
          u = turned(cs, gd, pr%u)
          delta = position_cs(mech, q, cs, blk, pr%at) - position_cs(mech, q, cs, gd, pr%at)
          phi(r) = dot_product(u, delta) - (dq(d) - mech%drives(d)%q_ref)
          call slide_row(je, r, u, lever_cs(mech, cs, blk, pr%at), lever_cs(mech, cs, gd, pr%at), delta)
        end if
      end associate
    end do
  end subroutine constraints

  !> Row r of J for w . (p_blk - p_gd), w turning with the guide link gd (slot 1 the block's
  !> link, 2 the guide's).
  pure subroutine slide_row(je, r, w, rblk, rgd, delta)
    real(wp), intent(inout) :: je(:, :, :)
    integer, intent(in) :: r
    real(wp), intent(in) :: w(2), rblk(2), rgd(2), delta(2)
    call put_j(je, r, 1, [w(1), w(2), dot_product(w, perp(rblk))])
    call put_j(je, r, 2, [-w(1), -w(2), dot_product(perp(w), delta) - dot_product(w, perp(rgd))])
  end subroutine slide_row

  !> The velocity-dependent part h of the constraints' second derivative (J qdd + h = drive
  !> accelerations).
  pure subroutine quadratic_terms(mech, q, qd, zero, h, cs)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: q(:), qd(:)
    !> Zeros (3n).
    real(wp), intent(in) :: zero(:)
    !> h (rows).
    real(wp), intent(out) :: h(:)
    !> The turns of q (set_turns).
    real(wp), intent(in) :: cs(:, 0:)
    real(wp) :: ra(2), rb(2), u(2)
    integer :: k, r, d
    h = 0.0_wp
    do k = 1, size(mech%pairs)
      associate (pr => mech%pairs(k))
        r = pair_row(k)
        if (pr%kind == pair_r) then
          ra = lever_cs(mech, cs, pr%a, pr%at)
          rb = lever_cs(mech, cs, pr%b, pr%at)
          h(r:r + 1) = -turn_of(qd, pr%a)**2 * ra + turn_of(qd, pr%b)**2 * rb
        else
          u = turned(cs, pr%guide, pr%u)
          h(r + 1) = slide_h(mech, q, qd, zero, cs, pr, perp(u))
        end if
      end associate
    end do
    do d = 1, size(mech%drives)
      associate (pr => mech%pairs(mech%drives(d)%pair))
        if (pr%kind == pair_p) then
          u = turned(cs, pr%guide, pr%u)
          h(drive_row(mech, d)) = slide_h(mech, q, qd, zero, cs, pr, u)
        end if
      end associate
    end do
  end subroutine quadratic_terms

  !> h of a sliding row w . delta (delta: the block's point minus the guide's, w turning with
  !> the guide link g): -wg^2 w.delta + 2 wg perp(w).d(delta)/dt + w.(centripetal
  !> accelerations of the block's point minus the guide's).
  pure real(wp) function slide_h(mech, q, qd, zero, cs, pr, w)
    type(linkage_t), intent(in) :: mech
    real(wp), intent(in) :: q(:), qd(:), zero(:), cs(:, 0:)
    type(linkage_pair_t), intent(in) :: pr
    real(wp), intent(in) :: w(2)
    real(wp) :: x1(2), v1(2), a1(2), x2(2), v2(2), a2(2), wg
    integer :: blk
    blk = pr%a + pr%b - pr%guide
    call link_point_state(mech, q, qd, zero, blk, pr%at, x1, v1, a1, cs)
    call link_point_state(mech, q, qd, zero, pr%guide, pr%at, x2, v2, a2, cs)
    wg = turn_of(qd, pr%guide)
    slide_h = -wg**2 * dot_product(w, x1 - x2) + 2.0_wp * wg * dot_product(perp(w), v1 - v2) + &
              dot_product(w, a1 - a2)
  end function slide_h

end module kinetostat_linkage_constraints
