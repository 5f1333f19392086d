!> Generic mechanism, friction in the kinematic pairs (manual section 1): journal friction
!> in the turning pairs, sliding friction in the prismatic pairs, put back into the
!> kinetostatic analysis as further loads and solved together with the reactions by a
!> fixed-point iteration from the frictionless solution; the power lost in every pair.
!>
!> Model (per result pair: dyad pairs 3(d-1)+j, then the crank pin; "this" link is the one
!> the reported reaction F acts on, "other" the link it comes from):
!> - turning pair, coefficient f, journal radius r: a couple of size Q = f*r*|F| on each
!>   link, opposing their relative rotation (u_this - u_other, u = d theta / d phi1);
!> - sliding pair, coefficient f: a force of size Q = f*|N| along the sliding line at the
!>   pair's reference point, opposing the relative sliding t.(v_this - v_other); with a
!>   contact span c > 0 (the shorter of the guide and the block, centred on the reference
!>   point) the two-contact model Q = f*(|N1| + |N2|), N1 + N2 = N, (N2 - N1)*c/2 = M, i.e.
!>   Q = f*max(|N|, 2|M|/c);
!> - senses from the velocity analogues times the motion sign s of the input (the sign of
!>   omega1; at rest, the direction the run moves the input: impending motion). A relative
!>   analogue within roundoff of zero (1e-10 of its scale) gives no friction at that step;
!> - loss per radian of the input R = Q*|relative analogue| (N*m/rad) and power loss
!>   P = R*|omega1| (W); the friction loads' virtual power per unit crank speed is -s*sum R.
!> The driver is the crank's balancing moment M1, or a linear actuator's force F_drive (the
!> input link's motion prescribed): friction in the actuator's own pair is a pair like any other.
module kinetostat_assur_friction
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t
  use kinetostat_text, only: real_str
  use kinetostat_pair_friction, only: friction_tolerance, friction_max_iterations, friction_zero_rel, roundoff_rel, &
    sign_floor_rel, friction_load, relative, note_pair_changes, reverses_at_rest, self_locking_error, &
    friction_iteration_t
  use kinetostat_vec2, only: perp, magnitude, largest_magnitude
  use kinetostat_selfcheck, only: link_balance_t, balance_add_force, balance_add_couple, equilibrium_residual, &
    power_mismatch
  use kinetostat_assur_kinematics, only: link_state_t, dyad_pose_t
  use kinetostat_assur_statics, only: pair_is_prismatic
  use kinetostat_assur, only: assur_mech_t, assur_step_t, assur_step, assur_kinematics, link_a, link_b, &
    pair_index, crank_pin_index
  implicit none
  private
  public :: pair_friction_t, friction_step_t, assur_friction_step, friction_active
  public :: friction_tolerance, friction_max_iterations, friction_zero_rel

  !> Friction data of one pair.
  type :: pair_friction_t
    !> Friction coefficient, >= 0.
    real(wp) :: f = 0.0_wp
    !> Journal radius (turning pair), m.
    real(wp) :: r = 0.0_wp
    !> Contact span of the two-contact model (sliding pair), m; 0: resultant-normal model.
    real(wp) :: span = 0.0_wp
    !> Name of the pair's reaction ("F21") for messages.
    character(len=16) :: name = ""
  end type pair_friction_t

  !> Friction results of one step.
  type :: friction_step_t
    !> Size of the friction couple (turning, N*m) or force (sliding, N) of each pair.
    real(wp), allocatable :: effort(:)
    !> Loss per radian of the input of each pair, Q*|relative analogue|, N*m/rad.
    real(wp), allocatable :: rate(:)
    !> Power loss of each pair, W.
    real(wp), allocatable :: loss(:)
    !> Total power loss P_loss, W.
    real(wp) :: p_loss = 0.0_wp
    !> Total loss per radian of the input, N*m/rad.
    real(wp) :: rate_total = 0.0_wp
    !> The driving effort of the same step without friction: M1 (N*m), or F_drive (N) when a
    !> linear actuator drives.
    real(wp) :: driver_frictionless = 0.0_wp
    !> Virtual power of the driver per unit crank rate, N*m/rad: M1, or F_drive*stroke'.
    real(wp) :: driver_rate = 0.0_wp
    !> Motion sign of the input used for the friction senses (+1 or -1).
    real(wp) :: motion_sign = 1.0_wp
    !> Iterations of the coupled solve.
    integer :: iterations = 0
  end type friction_step_t

  !> Geometry of one pair at one step.
  type :: pair_geometry_t
    !> Internal index of the link the reaction acts on, and of the link it comes from.
    integer :: this = 1, other = 0
    !> Reference point, m.
    real(wp) :: p(2) = 0.0_wp
    !> Sliding direction (prismatic pairs).
    real(wp) :: t(2) = 0.0_wp
    !> Whether the pair is prismatic.
    logical :: prismatic = .false.
    !> Relative analogue: turning u_this - u_other; sliding t.(v_this - v_other), m/rad.
    real(wp) :: rel = 0.0_wp
    !> Sense of the relative motion (+1, -1, or 0 when the relative analogue is zero).
    real(wp) :: sense = 0.0_wp
    !> Sum of the magnitudes of the two links' rates at the pair (power-balance scale).
    real(wp) :: rate_scale = 0.0_wp
  end type pair_geometry_t

contains

  !> Whether any pair has friction.
  pure logical function friction_active(friction)
    !> Friction data per pair.
    type(pair_friction_t), intent(in) :: friction(:)
    friction_active = any(friction%f > 0.0_wp)
  end function friction_active

  !> Velocity analogue of the point `p` (m) carried by a link, m/rad.
  pure function point_rate(st, p) result(v)
    type(link_state_t), intent(in) :: st
    real(wp), intent(in) :: p(2)
    real(wp) :: v(2)
    v = st%vo + st%u * perp(p - st%o)
  end function point_rate

  !> The pairs' links, points and relative analogues at one position; `s` is the motion sign.
  pure function pair_geometry(mech, states, poses, s) result(pg)
    type(assur_mech_t), intent(in) :: mech
    type(link_state_t), intent(in) :: states(0:)
    type(dyad_pose_t), intent(in) :: poses(:)
    real(wp), intent(in) :: s
    type(pair_geometry_t), allocatable :: pg(:)
    integer :: d, j, ip, nd
    real(wp) :: scale, vt(2), tol
    integer, parameter :: this_link(3) = [0, 0, 1], other_side(3) = [1, 0, 2]
    nd = size(mech%dyads)
    allocate (pg(3 * nd + 1))
    scale = 0.0_wp
    do d = 1, nd
      do j = 1, 3
        scale = max(scale, magnitude(poses(d)%p(:, j) - mech%pivot))
      end do
    end do
    if (.not. scale > 0.0_wp) scale = 1.0_wp
    do d = 1, nd
      do j = 1, 3
        ip = pair_index(d, j)
        pg(ip)%this = link_a(d) + this_link(j)
        if (other_side(j) == 0) then
          pg(ip)%other = link_b(d)
        else
          pg(ip)%other = mech%dyads(d)%on(other_side(j))
        end if
        pg(ip)%p = poses(d)%p(:, j)
        pg(ip)%t = poses(d)%t(:, j)
        pg(ip)%prismatic = pair_is_prismatic(mech%dyads(d)%geom%kind, j)
      end do
    end do
    ip = crank_pin_index(nd)
    pg(ip)%this = 1
    pg(ip)%other = 0
    pg(ip)%p = mech%pivot
    do ip = 1, size(pg)
      associate (a => states(pg(ip)%this), b => states(pg(ip)%other))
        if (pg(ip)%prismatic) then
          vt = [dot_product(pg(ip)%t, point_rate(a, pg(ip)%p)), dot_product(pg(ip)%t, point_rate(b, pg(ip)%p))]
          pg(ip)%rel = vt(1) - vt(2)
          pg(ip)%rate_scale = abs(vt(1)) + abs(vt(2))
          tol = friction_zero_rel * scale
        else
          pg(ip)%rel = a%u - b%u
          pg(ip)%rate_scale = abs(a%u) + abs(b%u)
          tol = friction_zero_rel * max(1.0_wp, abs(a%u), abs(b%u))
        end if
        if (abs(pg(ip)%rel) > tol) pg(ip)%sense = sign(1.0_wp, pg(ip)%rel) * s
      end associate
    end do
  end function pair_geometry

  !> Friction loads from the reactions of `step`: `extra` on every link (moments about the
  !> link's origin), their virtual power per unit crank speed and its scale, and per pair the
  !> friction effort Q and the loss per radian R.
  pure subroutine friction_loads(friction, pg, states, step, s, extra, power, scale, effort, rate)
    type(pair_friction_t), intent(in) :: friction(:)
    type(pair_geometry_t), intent(in) :: pg(:)
    type(link_state_t), intent(in) :: states(0:)
    type(assur_step_t), intent(in) :: step
    !> Motion sign of the input.
    real(wp), intent(in) :: s
    type(link_balance_t), intent(out) :: extra(0:)
    real(wp), intent(out) :: power, scale
    real(wp), intent(out) :: effort(:), rate(:)
    real(wp) :: q
    integer :: ip
    power = 0.0_wp
    scale = 0.0_wp
    effort = 0.0_wp
    rate = 0.0_wp
    do ip = 1, size(pg)
      if (.not. friction(ip)%f > 0.0_wp) cycle
      associate (g => pg(ip))
        q = friction_load(friction(ip)%f, friction(ip)%r, friction(ip)%span, g%prismatic, step%f(:, ip), &
          step%n(ip), step%m(ip))
        effort(ip) = q
        if (g%sense == 0.0_wp) cycle
        rate(ip) = q * abs(g%rel)
        if (g%prismatic) then
          call balance_add_force(extra(g%this), states(g%this)%o, g%p, -q * g%sense * g%t)
          call balance_add_force(extra(g%other), states(g%other)%o, g%p, q * g%sense * g%t)
        else
          call balance_add_couple(extra(g%this), -q * g%sense)
          call balance_add_couple(extra(g%other), q * g%sense)
        end if
        power = power - s * rate(ip)
        scale = scale + q * g%rate_scale
      end associate
    end do
  end subroutine friction_loads

  !> Largest relative change between two solutions of a step (pair forces, prismatic pair
  !> moments, M1), and the pair where it occurs (0: M1). A change counts relative to the
  !> reaction itself, with a roundoff floor of roundoff_rel times the step's largest.
  pure subroutine largest_change(old, new, length, change, where)
    type(assur_step_t), intent(in) :: old, new
    !> Length scale for moments, m.
    real(wp), intent(in) :: length
    real(wp), intent(out) :: change
    integer, intent(out) :: where
    real(wp) :: floor
    floor = roundoff_rel * largest_magnitude(new%f)
    change = max(relative(abs(new%m1 - old%m1), max(abs(new%m1), floor * length)), &
                 relative(abs(new%f_drive - old%f_drive), max(abs(new%f_drive), floor)))
    where = 0
    call note_pair_changes(old%f, new%f, old%m, new%m, floor, length, change, where)
  end subroutine largest_change

  !> Kinetostatics with friction at one input position: the step of kinetostat_assur with
  !> the friction loads of every pair, iterated from the frictionless solution until every
  !> reaction is converged to friction_tolerance (at most friction_max_iterations). `s` is
  !> the motion sign of the input (+1 CCW, -1 CW). The self-check figures of `step` are those
  !> of the final reactions with the friction loads they imply. Exit 3 (naming the pair) when
  !> the iteration does not converge, or when the input is at rest and friction reverses the
  !> sign of M1 (self-locking).
  pure subroutine assur_friction_step(mech, friction, phi1, omega1, eps1, s, f_mag, m_mag, step, fs, error)
    !> Mechanism.
    type(assur_mech_t), intent(in) :: mech
    !> Friction data per pair (dyad pairs, then the crank pin).
    type(pair_friction_t), intent(in) :: friction(:)
    !> Crank angle, rad.
    real(wp), intent(in) :: phi1
    !> Crank speed, rad/s.
    real(wp), intent(in) :: omega1
    !> Crank angular acceleration, rad/s^2.
    real(wp), intent(in) :: eps1
    !> Motion sign of the input, +1 or -1.
    real(wp), intent(in) :: s
    !> Magnitudes of the external forces at this step, N.
    real(wp), intent(in) :: f_mag(:)
    !> External moments at this step, N*m.
    real(wp), intent(in) :: m_mag(:)
    !> Results with friction.
    type(assur_step_t), intent(out) :: step
    !> Friction results.
    type(friction_step_t), intent(out) :: fs
    !> Geometry error, no convergence or self-locking.
    type(error_t), allocatable, intent(out) :: error
    type(link_state_t) :: states(0:2 * size(mech%dyads) + 1)
    type(dyad_pose_t) :: poses(size(mech%dyads))
    type(link_balance_t) :: used(0:2 * size(mech%dyads) + 1), final(0:2 * size(mech%dyads) + 1)
    type(link_balance_t) :: balances(0:2 * size(mech%dyads) + 1)
    type(pair_geometry_t), allocatable :: pg(:)
    type(assur_step_t) :: old
    type(friction_iteration_t) :: iteration
    real(wp) :: power_used, scale_used, power_final, scale_final, change, length, roundoff_driver, ds
    real(wp), allocatable :: effort(:), rate(:)
    integer :: it, where, np, i
    logical :: done, actuator

    call assur_step(mech, phi1, omega1, eps1, f_mag, m_mag, step, error)
    if (allocated(error)) return
    call assur_kinematics(mech, phi1, states, poses, error)
    if (allocated(error)) return
    np = size(step%f, 2)
    allocate (effort(np), rate(np))
    pg = pair_geometry(mech, states, poses, s)
    length = 0.0_wp
    do i = 1, np
      length = max(length, magnitude(pg(i)%p - mech%pivot))
    end do
    if (.not. length > 0.0_wp) length = 1.0_wp
    ! the driver: the crank's balancing moment, or a linear actuator's force (stroke' = ds)
    actuator = mech%drive_dyad > 0
    ds = 1.0_wp
    if (actuator) ds = poses(mech%drive_dyad)%stroke_v(mech%drive_pair)
    fs%driver_frictionless = driver_of(step)
    ! a frictionless driving effort at roundoff level has no sign (self-locking test below)
    roundoff_driver = max(roundoff_rel * step%power_scale / abs(ds), sign_floor_rel * step%load_scale)
    fs%motion_sign = s
    where = 0
    do it = 1, friction_max_iterations
      call friction_loads(friction, pg, states, step, s, used, power_used, scale_used, effort, rate)
      old = step
      call assur_step(mech, phi1, omega1, eps1, f_mag, m_mag, step, error, used, power_used, scale_used, balances)
      if (allocated(error)) return
      call largest_change(old, step, length, change, where)
      call iteration%next(it, change, done)
      if (done) exit
    end do
    fs%iterations = iteration%iterations
    if (.not. iteration%converged) then
      call iteration%failure(pair_text(friction, where), error)
      return
    end if

    ! self-check with the friction loads of the final reactions
    call friction_loads(friction, pg, states, step, s, final, power_final, scale_final, effort, rate)
    do i = 1, ubound(balances, 1)
      balances(i)%sum_f = balances(i)%sum_f + final(i)%sum_f - used(i)%sum_f
      balances(i)%sum_m = balances(i)%sum_m + final(i)%sum_m - used(i)%sum_m
    end do
    step%residual = equilibrium_residual(balances(1:))
    step%power_scale = step%power_scale - scale_used + scale_final
    if (actuator) then
      step%f_drive_power = step%f_drive_power + (power_used - power_final) / ds
      step%mismatch = power_mismatch(step%f_drive, step%f_drive_power, step%power_scale / abs(ds), step%load_scale)
    else
      step%m1_power = step%m1_power + power_used - power_final
      step%mismatch = power_mismatch(step%m1, step%m1_power, step%power_scale, step%load_scale)
    end if
    fs%driver_rate = driver_of(step) * ds
    fs%effort = effort
    fs%rate = rate
    fs%loss = rate * abs(omega1)
    fs%rate_total = sum(rate)
    fs%p_loss = fs%rate_total * abs(omega1)

    ! self-locking: the input at rest and friction reverses the driving effort
    if (omega1 == 0.0_wp) then
      if (reverses_at_rest(fs%driver_frictionless, driver_of(step), roundoff_driver)) then
        call self_locking_error(driver_text(actuator, fs%driver_frictionless), driver_text(actuator, driver_of(step)), &
          pair_text(friction, maxloc(rate, 1)), error)
        return
      end if
    end if

    ! a sliding pair's reported reaction is the whole reaction: its normal force (kept in
    ! step%n, the <F>N column) plus the friction force along the sliding line, which the
    ! solve carried as a load of its own (the load on "this" link: -Q * sense * t)
    do i = 1, np
      if (.not. pg(i)%prismatic .or. .not. friction(i)%f > 0.0_wp) cycle
      step%f(:, i) = step%f(:, i) - effort(i) * pg(i)%sense * pg(i)%t
    end do

  contains

    !> The driving effort of a step: M1, or F_drive with an actuator.
    pure real(wp) function driver_of(st)
      type(assur_step_t), intent(in) :: st
      driver_of = st%m1
      if (actuator) driver_of = st%f_drive
    end function driver_of

  end subroutine assur_friction_step

  !> "M1 = x N*m" or "F_drive = x N" for messages.
  pure function driver_text(actuator, x) result(text)
    logical, intent(in) :: actuator
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    if (actuator) then
      text = "F_drive = "//real_str(x)//" N"
    else
      text = "M1 = "//real_str(x)//" N*m"
    end if
  end function driver_text

  !> "pair F21" (or "M1" for index 0) for messages.
  pure function pair_text(friction, ip) result(text)
    type(pair_friction_t), intent(in) :: friction(:)
    integer, intent(in) :: ip
    character(len=:), allocatable :: text
    if (ip < 1 .or. ip > size(friction)) then
      text = "M1"
    else
      text = "pair "//trim(friction(ip)%name)
    end if
  end function pair_text

end module kinetostat_assur_friction
