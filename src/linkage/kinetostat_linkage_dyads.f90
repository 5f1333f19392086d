!> The general engine's velocities and accelerations of a linkage whose units are all input
!> units of one link and dyads, straight from the points (as the dyad engine does), without
!> the Jacobian: unit by unit in the structural analysis' order, each link's motion from the
!> links placed before it.
!>
!> An input unit: its link turns (R drive) or slides (P drive) relative to its known link by
!> the drive's rate. A dyad of links 1 and 2: each link's motion is fixed by its outer pair up
!> to one parameter t_j — about the outer turning pair's joint X_j it turns with any rate
!> t_j; along an outer sliding pair it turns with its known link and slides with any rate t_j
!> along the guide u_j. The inner pair's two equations give t_1 and t_2: a turning pair at B,
!> v_1(B) = v_2(B); a sliding pair at the block's point X with the guide's normal n,
!> omega_1 = omega_2 and n . (v_1(X) - v_2(X)) = 0. The accelerations are the same 2 x 2
!> system with the right-hand sides of the velocity terms (the centripetal -omega^2 r, and
!> along a sliding pair Coriolis' 2 omega perp(v_rel)). Each 2 x 2 reports whether its
!> determinant is clear of zero (above small_screen of its rows' scale); where one is not,
!> the caller solves with J (which also decides whether the position is singular).
!>
!> The reactions by the group method in closed form, the last unit first, each with the
!> reactions of the units after it on its links (as the dyad engine solves its dyads): of a
!> dyad, link j's equation that leaves out its outer pair's unknowns — the moments about an
!> outer turning pair's joint, the forces along an outer sliding pair's guide — gives two
!> equations in the inner pair's two unknowns (a force's components; a sliding pair's normal
!> force and couple); each outer pair's unknowns then follow from its link's forces' sum (and a
!> sliding pair's couple from the moments about its block's point). An input unit: its pair's
!> force and the drive's effort from its link's three equations.
module kinetostat_linkage_dyads
  use kinetostat_kinds, only: wp
  use kinetostat_vec2, only: perp, cross
  use kinetostat_linkage_types, only: linkage_t, pair_r, pair_p
  use kinetostat_linkage_closed, only: turned, unit_pairs, dyad_pairs, turn_of
  use kinetostat_linkage_small, only: small_screen
  implicit none
  private
  public :: dyad_plan_t, plan_dyads, dyad_velocities, dyad_accelerations, dyad_reactions

  !> Unit kinds of the plan.
  integer, parameter :: unit_input = 1, unit_dyad = 2

  !> Each unit's links and pairs (every unit an input unit of one link or a dyad).
  type :: dyad_plan_t
    !> The plan applies (every unit an input unit of one link driven at its own pair, or a
    !> dyad of two links and three pairs with one outer pair on each link).
    logical :: ok = .false.
    !> Per unit: unit_input or unit_dyad.
    integer, allocatable :: kind(:)
    !> Per unit: an input unit's link (1) and known link (2); a dyad's links (1, 2).
    integer, allocatable :: link(:, :)
    !> Per unit: an input unit's pair (1) and drive (2); a dyad's outer pairs of its links
    !> (1, 2) and inner pair (3).
    integer, allocatable :: pair(:, :)
    !> Per dyad: the known link of each outer pair (0: the frame).
    integer, allocatable :: known(:, :)
    !> Per dyad: the 2 x 2 system of t_1, t_2 at the last poses (m11, m21, m12, m22) and its
    !> determinant.
    real(wp), allocatable :: m(:, :), det(:)
    !> Per dyad: each link's point X_j (2 x 2), its parameter's direction (vP per t: 2 x 2;
    !> omega per t: 2) and the inner pair's point (turning: the joint; sliding: the block's
    !> point) and the guide's normal (sliding).
    real(wp), allocatable :: px(:, :, :), dv(:, :, :), dw(:, :), pb(:, :), nb(:, :)
    !> Each pair's point on its link a and on its link b at the last poses (a sliding pair:
    !> the block's point for both), m (2 x pairs).
    real(wp), allocatable :: xa(:, :), xb(:, :)
    !> Each pair's links whose points xa and xb are (a sliding pair: the block's link for
    !> both; 0: the frame) and those points relative to their links' reference points at the
    !> reference position (the frame: the points themselves), m (2 x pairs).
    integer, allocatable :: ia(:), ib(:)
    real(wp), allocatable :: da(:, :), db(:, :)
  end type dyad_plan_t

contains

  !> The plan of `mech`'s units (plan%ok false when a unit is neither kind).
  pure subroutine plan_dyads(mech, plan)
    type(linkage_t), intent(in) :: mech
    type(dyad_plan_t), intent(out) :: plan
    integer :: u, nu, np, nk, d, kp(3), j, inner, e(2), k
    plan%ok = .false.
    if (.not. allocated(mech%units)) return
    nu = size(mech%units)
    np = size(mech%pairs)
    allocate (plan%kind(nu), plan%link(2, nu), plan%pair(3, nu), plan%known(2, nu), source=0)
    allocate (plan%m(4, nu), plan%det(nu), plan%dw(2, nu), plan%pb(2, nu), plan%nb(2, nu), source=0.0_wp)
    allocate (plan%px(2, 2, nu), plan%dv(2, 2, nu), plan%xa(2, np), plan%xb(2, np), source=0.0_wp)
    allocate (plan%ia(np), plan%ib(np), source=0)
    allocate (plan%da(2, np), plan%db(2, np), source=0.0_wp)
    do k = 1, np
      associate (pr => mech%pairs(k))
        if (pr%kind == pair_r) then
          plan%ia(k) = pr%a
          plan%ib(k) = pr%b
        else
          plan%ia(k) = pr%a + pr%b - pr%guide
          plan%ib(k) = plan%ia(k)
        end if
        plan%da(:, k) = local_point(plan%ia(k), pr%at)
        plan%db(:, k) = local_point(plan%ib(k), pr%at)
      end associate
    end do
    do u = 1, nu
      call unit_pairs(mech, u, kp, nk, d)
      if (nk > 3) return
      if (mech%units(u)%class == 1) then
        if (size(mech%units(u)%links) /= 1 .or. nk /= 1 .or. d == 0) return
        if (mech%drives(d)%pair /= kp(1)) return
        plan%kind(u) = unit_input
        plan%link(1, u) = mech%units(u)%links(1)
        plan%link(2, u) = mech%pairs(kp(1))%a + mech%pairs(kp(1))%b - plan%link(1, u)
        plan%pair(1:2, u) = [kp(1), d]
      else if (mech%units(u)%class == 2) then
        if (size(mech%units(u)%links) /= 2 .or. nk /= 3 .or. d /= 0) return
        associate (set => mech%units(u)%links)
          call dyad_pairs(mech, set, kp, inner, e)
          if (inner == 0 .or. any(e == 0)) return
          plan%kind(u) = unit_dyad
          plan%link(:, u) = set
          plan%pair(:, u) = [e(1), e(2), inner]
          do j = 1, 2
            plan%known(j, u) = mech%pairs(e(j))%a + mech%pairs(e(j))%b - set(j)
          end do
        end associate
      else
        return
      end if
    end do
    plan%ok = .true.
  contains
    !> Point p (m) from link i's reference point at the reference position, as position_cs
    !> takes it (the frame: p).
    pure function local_point(i, p) result(x)
      integer, intent(in) :: i
      real(wp), intent(in) :: p(2)
      real(wp) :: x(2)
      x = p
      if (i > 0) x = p - mech%links(i)%c
    end function local_point
  end subroutine plan_dyads

  !> Pair k's point on link lk (one of its links; a sliding pair: the block's point) at the
  !> poses of the last dyad_velocities.
  pure function joint_of(mech, plan, k, lk) result(x)
    type(linkage_t), intent(in) :: mech
    type(dyad_plan_t), intent(in) :: plan
    integer, intent(in) :: k, lk
    real(wp) :: x(2)
    if (lk == mech%pairs(k)%a) then
      x = plan%xa(:, k)
    else
      x = plan%xb(:, k)
    end if
  end function joint_of

  !> Input unit un: its link lk, known link kn, the drive's pair's point x (a turning pair's
  !> joint on lk; a sliding pair's block point), the guide u (sliding), and the sign sgn of
  !> the drive's rate in lk's motion relative to kn (turning: +1 where lk is the pair's link a;
  !> sliding: +1 where lk is the block).
  pure subroutine input_unit(mech, plan, cs, un, lk, kn, x, u, sgn)
    type(linkage_t), intent(in) :: mech
    type(dyad_plan_t), intent(in) :: plan
    real(wp), intent(in) :: cs(:, 0:)
    integer, intent(in) :: un
    integer, intent(out) :: lk, kn
    real(wp), intent(out) :: x(2), u(2), sgn
    lk = plan%link(1, un)
    kn = plan%link(2, un)
    associate (pr => mech%pairs(plan%pair(1, un)))
      u = 0.0_wp
      if (pr%kind == pair_r) then
        x = joint_of(mech, plan, plan%pair(1, un), lk)
        sgn = merge(1.0_wp, -1.0_wp, lk == pr%a)
      else
        x = joint_of(mech, plan, plan%pair(1, un), pr%a + pr%b - pr%guide)
        u = turned(cs, pr%guide, pr%u)
        sgn = merge(-1.0_wp, 1.0_wp, lk == pr%guide)
      end if
    end associate
  end subroutine input_unit

  !> Velocity of link i's point x (0: the frame) from the velocities qd.
  pure function point_velocity(q, qd, i, x) result(v)
    real(wp), intent(in) :: q(:), qd(:), x(2)
    integer, intent(in) :: i
    real(wp) :: v(2)
    v = 0.0_wp
    if (i > 0) v = qd(3 * i - 2:3 * i - 1) + qd(3 * i) * perp(x - q(3 * i - 2:3 * i - 1))
  end function point_velocity

  !> Acceleration of link i's point x (0: the frame) from the velocities qd and accelerations
  !> qdd.
  pure function point_acceleration(q, qd, qdd, i, x) result(a)
    real(wp), intent(in) :: q(:), qd(:), qdd(:), x(2)
    integer, intent(in) :: i
    real(wp) :: a(2), r(2)
    a = 0.0_wp
    if (i == 0) return
    r = x - q(3 * i - 2:3 * i - 1)
    a = qdd(3 * i - 2:3 * i - 1) + qdd(3 * i) * perp(r) - qd(3 * i)**2 * r
  end function point_acceleration

  !> The velocities qd of poses q (turns cs) for the drives' rates `rate`, unit by unit; the
  !> dyads' 2 x 2 systems into the plan (for dyad_accelerations). ok false where a dyad's
  !> determinant is not clear of zero.
  pure subroutine dyad_velocities(mech, plan, q, cs, rate, qd, ok)
    type(linkage_t), intent(in) :: mech
    type(dyad_plan_t), intent(inout) :: plan
    real(wp), intent(in) :: q(:), cs(:, 0:), rate(:)
    real(wp), intent(out) :: qd(:)
    logical, intent(out) :: ok
    real(wp) :: x(2), u(2), w, vp(2), b(2, 2), beta(2), rhs(2), t(2), c1(2), c2(2), scale, sgn
    integer :: un, j, lk, kn, k
    qd = 0.0_wp
    ok = .false.
    ! each pair's points, once for the poses (dyad_accelerations and dyad_reactions take them)
    ! (position_cs's arithmetic with the plan's local points; element by element, which
    ! takes no memcpy for two numbers)
    do k = 1, size(plan%ia)
      call place_point(plan%ia(k), plan%da(1, k), plan%da(2, k), plan%xa(1, k), plan%xa(2, k))
      call place_point(plan%ib(k), plan%db(1, k), plan%db(2, k), plan%xb(1, k), plan%xb(2, k))
    end do
    do un = 1, size(plan%kind)
      if (plan%kind(un) == unit_input) then
        call input_unit(mech, plan, cs, un, lk, kn, x, u, sgn)
        if (mech%pairs(plan%pair(1, un))%kind == pair_r) then
          w = turn_of(qd, kn) + sgn * rate(plan%pair(2, un))
          vp = point_velocity(q, qd, kn, x)
        else
          w = turn_of(qd, kn)
          vp = point_velocity(q, qd, kn, x) + (sgn * rate(plan%pair(2, un))) * u
        end if
        call put_velocity(qd, lk, x, vp, w)
        cycle
      end if
      ! a dyad: each link's point X_j, its known motion (b, beta) and its parameter's (dv, dw)
      do j = 1, 2
        lk = plan%link(j, un)
        kn = plan%known(j, un)
        associate (pr => mech%pairs(plan%pair(j, un)))
          if (pr%kind == pair_r) then
            x = joint_of(mech, plan, plan%pair(j, un), lk)
            b(:, j) = point_velocity(q, qd, kn, x)
            beta(j) = 0.0_wp
            plan%dv(:, j, un) = 0.0_wp
            plan%dw(j, un) = 1.0_wp
          else
            x = joint_of(mech, plan, plan%pair(j, un), pr%a + pr%b - pr%guide)
            b(:, j) = point_velocity(q, qd, kn, x)
            beta(j) = turn_of(qd, kn)
            plan%dv(:, j, un) = turned(cs, pr%guide, pr%u)
            plan%dw(j, un) = 0.0_wp
          end if
          plan%px(:, j, un) = x
        end associate
      end do
      associate (pin => mech%pairs(plan%pair(3, un)), px => plan%px(:, :, un), dvj => plan%dv(:, :, un), &
                 dwj => plan%dw(:, un), m => plan%m(:, un))
        if (pin%kind == pair_r) then
          x = joint_of(mech, plan, plan%pair(3, un), plan%link(1, un))
          plan%pb(:, un) = x
          c1 = dvj(:, 1) + dwj(1) * perp(x - px(:, 1))
          c2 = dvj(:, 2) + dwj(2) * perp(x - px(:, 2))
          m = [c1(1), c1(2), -c2(1), -c2(2)]
          rhs = b(:, 2) + beta(2) * perp(x - px(:, 2)) - b(:, 1) - beta(1) * perp(x - px(:, 1))
        else
          x = joint_of(mech, plan, plan%pair(3, un), pin%a + pin%b - pin%guide)
          plan%pb(:, un) = x
          plan%nb(:, un) = perp(turned(cs, pin%guide, pin%u))
          c1 = dvj(:, 1) + dwj(1) * perp(x - px(:, 1))
          c2 = dvj(:, 2) + dwj(2) * perp(x - px(:, 2))
          m = [dwj(1), dot_product(plan%nb(:, un), c1), -dwj(2), -dot_product(plan%nb(:, un), c2)]
          rhs(1) = beta(2) - beta(1)
          rhs(2) = dot_product(plan%nb(:, un), b(:, 2) + beta(2) * perp(x - px(:, 2)) - b(:, 1) - &
                               beta(1) * perp(x - px(:, 1)))
        end if
        plan%det(un) = m(1) * m(4) - m(3) * m(2)
        scale = (abs(m(1)) + abs(m(3))) * (abs(m(2)) + abs(m(4)))
        if (.not. abs(plan%det(un)) > small_screen * scale) return
        t = solve2(m, plan%det(un), rhs)
        do j = 1, 2
          k = plan%link(j, un)
          call put_velocity(qd, k, px(:, j), b(:, j) + t(j) * dvj(:, j), beta(j) + t(j) * dwj(j))
        end do
      end associate
    end do
    ok = .true.
  contains
    !> The point (x1, x2) of link i at (d1, d2) from its reference point at the reference
    !> position (the frame: at (d1, d2)), in the poses q.
    pure subroutine place_point(i, d1, d2, x1, x2)
      integer, intent(in) :: i
      real(wp), intent(in) :: d1, d2
      real(wp), intent(out) :: x1, x2
      if (i > 0) then
        x1 = q(3 * i - 2) + (cs(1, i) * d1 - cs(2, i) * d2)
        x2 = q(3 * i - 1) + (cs(2, i) * d1 + cs(1, i) * d2)
      else
        x1 = d1
        x2 = d2
      end if
    end subroutine place_point
    !> Link i's velocities from its point x's velocity vx and its rate w.
    pure subroutine put_velocity(qd, i, x, vx, w)
      real(wp), intent(inout) :: qd(:)
      integer, intent(in) :: i
      real(wp), intent(in) :: x(2), vx(2), w
      qd(3 * i) = w
      qd(3 * i - 2:3 * i - 1) = vx + w * perp(q(3 * i - 2:3 * i - 1) - x)
    end subroutine put_velocity
  end subroutine dyad_velocities

  !> The accelerations qdd of poses q with velocities qd (of dyad_velocities, whose 2 x 2
  !> systems the plan holds) for the drives' accelerations `acc`.
  pure subroutine dyad_accelerations(mech, plan, q, cs, qd, acc, qdd)
    type(linkage_t), intent(in) :: mech
    type(dyad_plan_t), intent(in) :: plan
    real(wp), intent(in) :: q(:), cs(:, 0:), qd(:), acc(:)
    real(wp), intent(out) :: qdd(:)
    real(wp) :: x(2), u(2), al, ap(2), b(2, 2), beta(2), rhs(2), t(2), r1(2), r2(2), w1, w2, wg, sgn
    integer :: un, j, lk, kn
    qdd = 0.0_wp
    do un = 1, size(plan%kind)
      if (plan%kind(un) == unit_input) then
        call input_unit(mech, plan, cs, un, lk, kn, x, u, sgn)
        if (mech%pairs(plan%pair(1, un))%kind == pair_r) then
          al = turn_of(qdd, kn) + sgn * acc(plan%pair(2, un))
          ap = point_acceleration(q, qd, qdd, kn, x)
        else
          al = turn_of(qdd, kn)
          ap = point_acceleration(q, qd, qdd, kn, x) + 2.0_wp * turn_of(qd, kn) * &
               perp(point_velocity(q, qd, lk, x) - point_velocity(q, qd, kn, x)) + (sgn * acc(plan%pair(2, un))) * u
        end if
        call put_acceleration(qdd, lk, x, ap, al)
        cycle
      end if
      associate (px => plan%px(:, :, un), dvj => plan%dv(:, :, un), dwj => plan%dw(:, un), m => plan%m(:, un))
        do j = 1, 2
          lk = plan%link(j, un)
          kn = plan%known(j, un)
          b(:, j) = point_acceleration(q, qd, qdd, kn, px(:, j))
          if (dwj(j) /= 0.0_wp) then
            beta(j) = 0.0_wp
          else
            ! along the outer guide: Coriolis' term of the sliding
            beta(j) = turn_of(qdd, kn)
            b(:, j) = b(:, j) + 2.0_wp * turn_of(qd, kn) * &
                      perp(point_velocity(q, qd, lk, px(:, j)) - point_velocity(q, qd, kn, px(:, j)))
          end if
        end do
        w1 = turn_of(qd, plan%link(1, un))
        w2 = turn_of(qd, plan%link(2, un))
        x = plan%pb(:, un)
        r1 = x - px(:, 1)
        r2 = x - px(:, 2)
        associate (pin => mech%pairs(plan%pair(3, un)))
          if (pin%kind == pair_r) then
            rhs = b(:, 2) + beta(2) * perp(r2) - w2**2 * r2 - b(:, 1) - beta(1) * perp(r1) + w1**2 * r1
          else
            wg = turn_of(qd, pin%guide)
            rhs(1) = beta(2) - beta(1)
            rhs(2) = dot_product(plan%nb(:, un), b(:, 2) + beta(2) * perp(r2) - w2**2 * r2 - b(:, 1) - &
                                 beta(1) * perp(r1) + w1**2 * r1 + 2.0_wp * wg * &
                                 perp(point_velocity(q, qd, plan%link(1, un), x) - &
                                      point_velocity(q, qd, plan%link(2, un), x)))
          end if
        end associate
        t = solve2(m, plan%det(un), rhs)
        do j = 1, 2
          call put_acceleration(qdd, plan%link(j, un), px(:, j), b(:, j) + t(j) * dvj(:, j), beta(j) + t(j) * dwj(j))
        end do
      end associate
    end do
  contains
    !> Link i's accelerations from its point x's acceleration ax and its angular
    !> acceleration al (its rate from qd).
    pure subroutine put_acceleration(qdd, i, x, ax, al)
      real(wp), intent(inout) :: qdd(:)
      integer, intent(in) :: i
      real(wp), intent(in) :: x(2), ax(2), al
      real(wp) :: r(2)
      r = q(3 * i - 2:3 * i - 1) - x
      qdd(3 * i) = al
      qdd(3 * i - 2:3 * i - 1) = ax + al * perp(r) - qd(3 * i)**2 * r
    end subroutine put_acceleration
  end subroutine dyad_accelerations

  !> The reactions of poses q (turns cs) by the group method in closed form (the module's
  !> header), with the plan's points of dyad_velocities at q. load: each link's own loads
  !> (force, N, and moment about its reference point, N*m: 3 x n; the reactions of the
  !> units solved are added to the links before them). Results as linkage_step_t's f, normal,
  !> couple, effort. ok false where a dyad's 2 x 2 is near a zero determinant.
  pure subroutine dyad_reactions(mech, plan, q, cs, load, f, normal, couple, effort, ok)
    type(linkage_t), intent(in) :: mech
    type(dyad_plan_t), intent(in) :: plan
    real(wp), intent(in) :: q(:), cs(:, 0:)
    real(wp), intent(inout) :: load(:, :)
    real(wp), intent(out) :: f(:, :), normal(:), couple(:), effort(:)
    logical, intent(out) :: ok
    real(wp) :: m(4), rhs(2), x(2), sig(2), fin(2), cin, xo(2), n(2), u(2), fo(2), co, det, mx
    integer :: un, j, lk, kn, k, d
    ok = .false.
    do un = size(plan%kind), 1, -1
      if (plan%kind(un) == unit_input) then
        lk = plan%link(1, un)
        kn = plan%link(2, un)
        k = plan%pair(1, un)
        d = plan%pair(2, un)
        associate (pr => mech%pairs(k))
          if (pr%kind == pair_r) then
            xo = joint_of(mech, plan, k, lk)
            fo = -load(1:2, lk)
            co = -moment_about(q, load, lk, xo)
            ! on a: the force and the drive's moment
            f(:, k) = merge(fo, -fo, lk == pr%a)
            normal(k) = 0.0_wp
            couple(k) = 0.0_wp
            effort(d) = merge(co, -co, lk == pr%a)
            ! (each link's own coordinates of the joint, as the self-check takes them)
            call add_load(q, load, kn, joint_of(mech, plan, k, kn), -fo, -co)
          else
            xo = joint_of(mech, plan, k, pr%a + pr%b - pr%guide)
            u = turned(cs, pr%guide, pr%u)
            n = perp(u)
            ! on lk: normal force along n, effort along u, couple
            normal(k) = -dot_product(n, load(1:2, lk))
            effort(d) = -dot_product(u, load(1:2, lk))
            couple(k) = -moment_about(q, load, lk, xo)
            fo = normal(k) * n + effort(d) * u
            co = couple(k)
            if (lk /= pr%a) then
              normal(k) = -normal(k)
              effort(d) = -effort(d)
              couple(k) = -couple(k)
            end if
            f(:, k) = normal(k) * n
            call add_load(q, load, kn, xo, -fo, -co)
          end if
        end associate
        cycle
      end if
      ! a dyad: the inner pair's unknowns x (on link 1: sig(1) = +-1 as link 1 is its a or b;
      ! on link 2 the opposite)
      associate (pin => mech%pairs(plan%pair(3, un)), px => plan%px(:, :, un))
        sig(1) = merge(1.0_wp, -1.0_wp, plan%link(1, un) == pin%a)
        sig(2) = -sig(1)
        do j = 1, 2
          lk = plan%link(j, un)
          associate (po => mech%pairs(plan%pair(j, un)))
            if (po%kind == pair_r) then
              ! the moments about the outer joint
              mx = moment_about(q, load, lk, px(:, j))
              if (pin%kind == pair_r) then
                m(j) = -sig(j) * (plan%pb(2, un) - px(2, j))
                m(2 + j) = sig(j) * (plan%pb(1, un) - px(1, j))
              else
                m(j) = sig(j) * cross(plan%pb(:, un) - px(:, j), plan%nb(:, un))
                m(2 + j) = sig(j)
              end if
              rhs(j) = -mx
            else
              ! the forces along the outer guide
              u = plan%dv(:, j, un)
              if (pin%kind == pair_r) then
                m(j) = sig(j) * u(1)
                m(2 + j) = sig(j) * u(2)
              else
                m(j) = sig(j) * dot_product(u, plan%nb(:, un))
                m(2 + j) = 0.0_wp
              end if
              rhs(j) = -dot_product(u, load(1:2, lk))
            end if
          end associate
        end do
        det = m(1) * m(4) - m(3) * m(2)
        if (.not. abs(det) > small_screen * (abs(m(1)) + abs(m(3))) * (abs(m(2)) + abs(m(4)))) return
        x = solve2(m, det, rhs)
        k = plan%pair(3, un)
        ! (the force on link j is sig(j) times the unknowns': on the pair's link a, x itself)
        if (pin%kind == pair_r) then
          f(:, k) = x
          normal(k) = 0.0_wp
          couple(k) = 0.0_wp
          fin = x
          cin = 0.0_wp
        else
          normal(k) = x(1)
          couple(k) = x(2)
          f(:, k) = normal(k) * plan%nb(:, un)
          fin = x(1) * plan%nb(:, un)
          cin = x(2)
        end if
        ! the inner pair's reaction on each link (sig(j) times fin, cin at pb), then each
        ! outer pair's unknowns from that link's equations
        do j = 1, 2
          lk = plan%link(j, un)
          if (j == 2 .and. pin%kind == pair_r) then
            ! (each link's own coordinates of the joint, as the self-check takes them)
            call add_load(q, load, lk, joint_of(mech, plan, plan%pair(3, un), lk), sig(j) * fin, sig(j) * cin)
          else
            call add_load(q, load, lk, plan%pb(:, un), sig(j) * fin, sig(j) * cin)
          end if
          kn = plan%known(j, un)
          k = plan%pair(j, un)
          associate (po => mech%pairs(k))
            xo = px(:, j)
            if (po%kind == pair_r) then
              fo = -load(1:2, lk)
              co = 0.0_wp
              f(:, k) = merge(fo, -fo, lk == po%a)
              normal(k) = 0.0_wp
              couple(k) = 0.0_wp
              xo = joint_of(mech, plan, k, kn)
            else
              n = perp(plan%dv(:, j, un))
              normal(k) = -dot_product(n, load(1:2, lk))
              co = -moment_about(q, load, lk, xo)
              fo = normal(k) * n
              couple(k) = co
              if (lk /= po%a) then
                normal(k) = -normal(k)
                couple(k) = -couple(k)
              end if
              f(:, k) = normal(k) * n
            end if
            call add_load(q, load, kn, xo, -fo, -co)
          end associate
        end do
      end associate
    end do
    ok = .true.
  end subroutine dyad_reactions

  !> The moment of link i's loads (load: force, moment about its reference point) about x.
  pure real(wp) function moment_about(q, load, i, x)
    real(wp), intent(in) :: q(:), load(:, :), x(2)
    integer, intent(in) :: i
    moment_about = load(3, i) + cross(q(3 * i - 2:3 * i - 1) - x, load(1:2, i))
  end function moment_about

  !> Force fo at point x and couple co added to link i's loads (nothing for the frame).
  pure subroutine add_load(q, load, i, x, fo, co)
    real(wp), intent(in) :: q(:), x(2), fo(2), co
    real(wp), intent(inout) :: load(:, :)
    integer, intent(in) :: i
    if (i == 0) return
    load(1:2, i) = load(1:2, i) + fo
    load(3, i) = load(3, i) + cross(x - q(3 * i - 2:3 * i - 1), fo) + co
  end subroutine add_load

  !> [m(1) m(3); m(2) m(4)] t = rhs by Cramer's rule with the determinant det.
  pure function solve2(m, det, rhs) result(t)
    real(wp), intent(in) :: m(4), det, rhs(2)
    real(wp) :: t(2)
    t(1) = (rhs(1) * m(4) - m(3) * rhs(2)) / det
    t(2) = (m(1) * rhs(2) - rhs(1) * m(2)) / det
  end function solve2

end module kinetostat_linkage_dyads
