!> Friction in the pairs of an `&linkage` deck (docs/friction.md, the `&assur` model): journal
!> friction in the turning pairs, sliding friction in the sliding pairs, put back into the
!> force analysis as further loads and solved with the reactions by a fixed-point iteration
!> from the frictionless solution; the power lost in every pair.
!>
!> Per pair k between links a and b (F<a><b> acts on a):
!> - turning pair, coefficient f, journal radius r: a couple Q = f*r*|F| on each link, on a
!>   -Q*sense, on b +Q*sense, sense the sign of the relative analogue u_a - u_b;
!> - sliding pair, coefficient f: a force Q = f*|N| (two-contact model with span c > 0:
!>   Q = f*max(|N|, 2|M|/c)) along the guide through the block's point, on a -Q*sense*t,
!>   on b +Q*sense*t, sense the sign of t.(v_a - v_b) at that point (t the guide's direction);
!> - the analogues are those of the drives' motion per unit of the reference rate (the
!>   largest |rate| of the drives; one drive: its analogue times the motion sign s, the sign
!>   of its rate); with every drive at rest, the motion in which every drive increases
!>   (impending motion). A relative analogue within 1e-10 of its scale: no friction there;
!> - loss per unit of the reference rate R = Q*|relative analogue| and power loss
!>   P = R*(reference rate), W.
!> The friction loads are the linkage's own loads: the kernel (linkage_statics) solves the
!> linkage with them as further forces (on a link's point of the guide line, turning with it)
!> and moments; only this module knows they are friction.
module kinetostat_linkage_friction
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str
  use kinetostat_pair_friction, only: friction_max_iterations, friction_zero_rel, roundoff_rel, sign_floor_rel, &
    friction_load, relative, note_pair_changes, reverses_at_rest, self_locking_error, friction_iteration_t
  use kinetostat_vec2, only: perp, rotate, magnitude, largest_magnitude
  use kinetostat_linkage, only: linkage_t, linkage_step_t, linkage_work_t, linkage_force_t, pair_r, pair_p, &
    linkage_statics, linkage_velocity_analogues, point_position
  implicit none
  private
  public :: linkage_friction_t, linkage_friction_solve

  !> Friction results of one step.
  type :: linkage_friction_t
    !> The drives' efforts of the same step without friction (N*m or N).
    real(wp), allocatable :: effort0(:)
    !> Size of each pair's friction couple (N*m) or force (N).
    real(wp), allocatable :: q(:)
    !> Loss of each pair per unit of the reference rate (N*m/rad or N), and its power, W.
    real(wp), allocatable :: rate(:), loss(:)
    !> Total loss per unit of the reference rate, and the total power loss P_loss, W.
    real(wp) :: rate_total = 0.0_wp, p_loss = 0.0_wp
    !> Virtual power of the drives per unit of the reference rate (one drive: its effort times
    !> its motion sign).
    real(wp) :: driver_rate = 0.0_wp
    !> Iterations of the coupled solve.
    integer :: iterations = 0
  end type linkage_friction_t

contains

  !> The step with friction: `step` holds the frictionless solution of poses q, qd, qdd for
  !> the loads fval, mval and the drives' rates dv; on return the reactions, efforts and
  !> self-check with the friction loads, a sliding pair's force the whole reaction (normal
  !> plus friction). f, r, span per pair (coefficient, journal radius m, contact span m).
  !> Exit 3 naming the pair when the iteration does not converge (jamming) or, with every
  !> drive at rest, friction reverses the first drive's effort (self-locking).
  pure subroutine linkage_friction_solve(mech, f, r, span, fval, mval, dv, step, work, fr, error)
    type(linkage_t), intent(in) :: mech
    !> Friction coefficient, journal radius (m) and contact span (m) of every pair.
    real(wp), intent(in) :: f(:), r(:), span(:)
    !> The step's force magnitudes (N) and moments (N*m), as for linkage_statics.
    real(wp), intent(in) :: fval(:), mval(:)
    !> The drives' rates (rad/s or m/s).
    real(wp), intent(in) :: dv(:)
    type(linkage_step_t), intent(inout) :: step
    type(linkage_work_t), intent(inout) :: work
    type(linkage_friction_t), intent(out) :: fr
    type(error_t), allocatable, intent(out) :: error
    type(linkage_t) :: loaded
    type(linkage_step_t) :: old
    real(wp), allocatable :: v(:, :), an(:), rel(:), sense(:), t(:, :), p(:, :), fx(:), mx(:), weight(:)
    type(friction_iteration_t) :: iteration
    real(wp) :: ref_rate, change, fmax, roundoff_driver
    integer :: np, nd, k, it, where, nf0, nm0, i, j
    logical :: done

    np = size(mech%pairs)
    nd = size(mech%drives)
    allocate (v(size(step%q), nd), rel(np), sense(np), t(2, np), p(2, np), weight(nd))
    call linkage_velocity_analogues(mech, step%q, v, error)
    if (allocated(error)) return
    ref_rate = maxval(abs(dv))
    if (ref_rate > 0.0_wp) then
      weight = dv / ref_rate
    else
      weight = 1.0_wp
    end if
    an = matmul(v, weight)
    ! each pair's relative analogue and sense; a sliding pair's point and direction
    do k = 1, np
      associate (pr => mech%pairs(k))
        p(:, k) = 0.0_wp
        t(:, k) = 0.0_wp
        if (pr%kind == pair_p) then
          p(:, k) = point_position(mech, step%q, pr%a + pr%b - pr%guide, pr%at)
          t(:, k) = pr%u
          if (pr%guide > 0) t(:, k) = rotate(pr%u, step%q(3 * pr%guide))
          rel(k) = dot_product(t(:, k), point_rate(pr%a, p(:, k)) - point_rate(pr%b, p(:, k)))
          sense(k) = sense_of(rel(k), friction_zero_rel * mech%size)
        else
          rel(k) = link_rate(pr%a) - link_rate(pr%b)
          sense(k) = sense_of(rel(k), friction_zero_rel * max(1.0_wp, abs(link_rate(pr%a)), abs(link_rate(pr%b))))
        end if
      end associate
    end do

    ! the linkage with the friction loads as further forces (sliding pairs) and moments
    ! (turning pairs), two per pair (on a and on b; none on the frame)
    loaded = mech
    nf0 = size(mech%forces)
    nm0 = size(mech%moment_link)
    do k = 1, np
      if (.not. f(k) > 0.0_wp) cycle
      associate (pr => mech%pairs(k))
        do j = 1, 2
          i = merge(pr%a, pr%b, j == 1)
          if (i == 0) cycle
          if (pr%kind == pair_p) then
            loaded%forces = [loaded%forces, linkage_force_t(link=i, at=pr%at, dir=pr%u, follow=.true.)]
          else
            loaded%moment_link = [loaded%moment_link, i]
          end if
        end do
      end associate
    end do
    allocate (fx(size(loaded%forces)), mx(size(loaded%moment_link)))
    fx(1:nf0) = fval
    mx(1:nm0) = mval

    fr%effort0 = step%effort
    allocate (fr%q(np), fr%rate(np), fr%loss(np))
    fmax = largest_magnitude(step%f)
    roundoff_driver = sign_floor_rel * fmax * mech%size
    where = 0
    do it = 1, friction_max_iterations
      call friction_loads(step, fr%q, fr%rate, fx, mx)
      old = step
      step = linkage_step_t(q=old%q, qd=old%qd, qdd=old%qdd)
      call linkage_statics(loaded, fx, mx, step, work, error)
      if (allocated(error)) return
      call largest_change(old, step, change, where)
      call iteration%next(it, change, done)
      if (done) exit
    end do
    fr%iterations = iteration%iterations
    if (.not. iteration%converged) then
      call iteration%failure(where_text(where), error)
      return
    end if
    ! the losses by the final reactions
    call friction_loads(step, fr%q, fr%rate, fx, mx)
    fr%rate_total = sum(fr%rate)
    fr%loss = fr%rate * ref_rate
    fr%p_loss = fr%rate_total * ref_rate
    fr%driver_rate = dot_product(step%effort, weight)
    if (ref_rate == 0.0_wp) then
      if (reverses_at_rest(fr%effort0(1), step%effort(1), roundoff_driver)) then
        call self_locking_error(real_str(fr%effort0(1)), real_str(step%effort(1)), where_text(maxloc(fr%rate, 1)), error)
        return
      end if
    end if
    ! a sliding pair's reported reaction is the whole reaction: normal plus friction
    do k = 1, np
      if (mech%pairs(k)%kind == pair_p .and. f(k) > 0.0_wp) step%f(:, k) = step%f(:, k) - fr%q(k) * sense(k) * t(:, k)
    end do

  contains

    !> The friction loads of the reactions of `st` into fx, mx (after the deck's loads), and
    !> each pair's Q and loss per unit of the reference rate.
    pure subroutine friction_loads(st, qv, ratev, fxv, mxv)
      type(linkage_step_t), intent(in) :: st
      !> Each pair's Q and loss per unit of the reference rate.
      real(wp), intent(out) :: qv(:), ratev(:)
      !> The loads: the deck's, then the friction loads.
      real(wp), intent(inout) :: fxv(:), mxv(:)
      integer :: kk, jf, jm
      jf = nf0
      jm = nm0
      qv = 0.0_wp
      ratev = 0.0_wp
      do kk = 1, np
        if (.not. f(kk) > 0.0_wp) cycle
        associate (pr => mech%pairs(kk))
          qv(kk) = friction_load(f(kk), r(kk), span(kk), pr%kind == pair_p, st%f(:, kk), st%normal(kk), st%couple(kk))
          ratev(kk) = qv(kk) * abs(rel(kk)) * abs(sense(kk))
          if (pr%kind == pair_p) then
            if (pr%a > 0) call put(fxv, jf, -qv(kk) * sense(kk))
            if (pr%b > 0) call put(fxv, jf, qv(kk) * sense(kk))
          else
            if (pr%a > 0) call put(mxv, jm, -qv(kk) * sense(kk))
            if (pr%b > 0) call put(mxv, jm, qv(kk) * sense(kk))
          end if
        end associate
      end do
    end subroutine friction_loads

    !> The next load value.
    pure subroutine put(x, jj, value)
      real(wp), intent(inout) :: x(:)
      integer, intent(inout) :: jj
      real(wp), intent(in) :: value
      jj = jj + 1
      x(jj) = value
    end subroutine put

    !> Angular analogue of link i (0: the frame).
    pure real(wp) function link_rate(i)
      integer, intent(in) :: i
      link_rate = 0.0_wp
      if (i > 0) link_rate = an(3 * i)
    end function link_rate

    !> Velocity analogue of the point of link i (0: the frame) now at x.
    pure function point_rate(i, x) result(w)
      integer, intent(in) :: i
      real(wp), intent(in) :: x(2)
      real(wp) :: w(2)
      w = 0.0_wp
      if (i > 0) w = an(3 * i - 2:3 * i - 1) + an(3 * i) * perp(x - step%q(3 * i - 2:3 * i - 1))
    end function point_rate

    !> Largest relative change between two solutions (pair forces, sliding pairs' couples, the
    !> drives' efforts), and where: the pair, or 0 for an effort.
    pure subroutine largest_change(a, b, ch, at)
      type(linkage_step_t), intent(in) :: a, b
      real(wp), intent(out) :: ch
      integer, intent(out) :: at
      real(wp) :: floor
      integer :: kk
      floor = roundoff_rel * largest_magnitude(b%f)
      ch = 0.0_wp
      at = 0
      do kk = 1, size(b%effort)
        ch = max(ch, relative(abs(b%effort(kk) - a%effort(kk)), max(abs(b%effort(kk)), floor * mech%size)))
      end do
      call note_pair_changes(a%f, b%f, a%couple, b%couple, floor, mech%size, ch, at)
    end subroutine largest_change

    !> "pair J21" or "the drives' efforts" for messages.
    pure function where_text(kk) result(text)
      integer, intent(in) :: kk
      character(len=:), allocatable :: text
      if (kk < 1 .or. kk > np) then
        text = "the drives' efforts"
      else
        text = "pair "//trim(mech%pairs(kk)%name)
      end if
    end function where_text
  end subroutine linkage_friction_solve

  !> +1 or -1 as x, 0 within tol of 0.
  elemental real(wp) function sense_of(x, tol)
    real(wp), intent(in) :: x, tol
    sense_of = 0.0_wp
    if (abs(x) > tol) sense_of = sign(1.0_wp, x)
  end function sense_of


end module kinetostat_linkage_friction
