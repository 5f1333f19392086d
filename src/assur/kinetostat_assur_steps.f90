!> `&assur` decks: the values of a validated deck at a step: the crank's angle, speed and
!> acceleration, the loads' values (windows, columns, tables over a link's position,
!> technological resistances).
module kinetostat_assur_steps
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t
  use kinetostat_vec2, only: magnitude
  use kinetostat_assur_kinematics, only: link_state_t, point_state_t, point_on, dyad_pose_t
  use kinetostat_assur, only: assur_kinematics, link_position
  use kinetostat_assur_deck_types, only: load_window, load_column, load_table, crank_index, resist_none, &
    resist_moment, resist_zero_rel, load_schedule_t, assur_deck_t
  use kinetostat_load_table, only: table_interpolate, table_cyclic
  implicit none
  private
  public :: assur_window, assur_phi1_deg, assur_omega1_steps, assur_omega1, assur_eps1, assur_motion_sign, &
    assur_load_value, assur_load_steps, table_value, table_angle, &
    table_position


contains


  !> Windowed value at crank angle `phi_deg`: `value` for phi_on <= phi <= phi_off
  !> (absolute degrees, 1e-9 deg tolerance), `idle` elsewhere.
  elemental function assur_window(phi_deg, phi_on, phi_off, value, idle) result(v)
    !> Crank angle, deg.
    real(wp), intent(in) :: phi_deg
    !> Window, deg.
    real(wp), intent(in) :: phi_on, phi_off
    !> Values inside and outside.
    real(wp), intent(in) :: value, idle
    real(wp) :: v
    real(wp), parameter :: angle_tol = 1.0e-9_wp
    if (phi_deg >= phi_on - angle_tol .and. phi_deg <= phi_off + angle_tol) then
      v = value
    else
      v = idle
    end if
  end function assur_window

  !> Crank angle of step k, deg: the list's k-th angle, or phi_start + (k - 1)*dphi.
  pure real(wp) function assur_phi1_deg(deck, k) result(phi)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> Step number, 1..n.
    integer, intent(in) :: k
    if (allocated(deck%phi_list)) then
      phi = deck%phi_list(k)
    else
      phi = deck%phi_start + real(k - 1, wp) * deck%dphi
    end if
  end function assur_phi1_deg

  !> Crank speed of steps k1..k2, rad/s: prescribed per step, or the constant omega1; for
  !> an angle list at constant |omega1| its sign is that of the move that brought the crank
  !> to the step's angle, + from a smaller angle, - from a larger one (a turning point keeps
  !> the sign it was reached with); the steps before the first move (and their repeats)
  !> take the first move's sign; without any move omega1 is kept as given. A rocking list
  !> thus equals its monotonic runs, each turning point ending a run. (Computed for a span
  !> of steps: the sign carries from step to step; the search back for the move before k1
  !> ends at that move.)
  pure function assur_omega1_steps(deck, k1, k2) result(w)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> First and last step, 1 <= k1, k2 <= n.
    integer, intent(in) :: k1, k2
    !> Speed of steps k1..k2, rad/s.
    real(wp) :: w(max(0, k2 - k1 + 1))
    !> Direction of the last move at or before the step (+1, -1; 0: none at all).
    real(wp) :: dir
    !> Step number.
    integer :: k
    if (deck%prescribed) then
      w = deck%omega1_values(k1:k2)
      return
    end if
    w = deck%omega1_const
    if (.not. allocated(deck%phi_list) .or. k2 < k1) return
    associate (phi => deck%phi_list)
      dir = deck%first_move
      do k = k1, 2, -1
        if (phi(k) /= phi(k - 1)) then
          dir = sign(1.0_wp, phi(k) - phi(k - 1))
          exit
        end if
      end do
      do k = k1, k2
        if (k > k1) then
          if (phi(k) /= phi(k - 1)) dir = sign(1.0_wp, phi(k) - phi(k - 1))
        end if
        if (dir /= 0.0_wp) w(k - k1 + 1) = dir * abs(deck%omega1_const)
      end do
    end associate
  end function assur_omega1_steps

  !> Crank speed of step k, rad/s (see assur_omega1_steps).
  pure real(wp) function assur_omega1(deck, k) result(omega1)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> Step number, 1..n.
    integer, intent(in) :: k
    !> The one-element span k..k, rad/s.
    real(wp) :: w(1)
    w = assur_omega1_steps(deck, k, k)
    omega1 = w(1)
  end function assur_omega1

  !> Crank acceleration of step k, rad/s^2: prescribed per step, else 0.
  pure real(wp) function assur_eps1(deck, k) result(eps1)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> Step number, 1..n.
    integer, intent(in) :: k
    eps1 = 0.0_wp
    if (deck%prescribed) eps1 = deck%eps1_values(k)
  end function assur_eps1

  !> Motion sign of the input at a step of crank speed omega1 (rad/s): -1 when omega1 < 0,
  !> else +1 (phi1 increasing, also with the input at rest).
  elemental real(wp) function assur_motion_sign(omega1) result(motion)
    !> Crank speed of the step, rad/s.
    real(wp), intent(in) :: omega1
    motion = merge(-1.0_wp, 1.0_wp, omega1 < 0.0_wp)
  end function assur_motion_sign

  !> Value of a load at step k, N or N*m (its schedule: constant, window, step_values
  !> column, or table over a link's position; a table's step whose position fails gives 0,
  !> the step itself reports the failure).
  pure real(wp) function assur_load_value(deck, load, k) result(value)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> The load's schedule (deck%force_load(i) or deck%moment_load(i)).
    type(load_schedule_t), intent(in) :: load
    !> Step number, 1..n.
    integer, intent(in) :: k
    !> Table: the abscissa link's position, deg or m.
    real(wp) :: q
    !> Table: whether the step's position was found.
    logical :: ok
    select case (load%kind)
    case (load_window)
      value = assur_window(assur_phi1_deg(deck, k), load%phi_on, load%phi_off, load%value, load%idle)
    case (load_column)
      value = deck%step_values(load%offset + k)
    case (load_table)
      call table_position(deck, load, k, q, ok)
      value = 0.0_wp
      if (ok) value = table_value(load, q)
    case default
      value = load%value
    end select
    if (load%resist /= resist_none) value = -abs(value) * resist_sense(deck, load, k)
  end function assur_load_value

  !> Motion sense of a technological resistance's link at step k: +1 or -1 as the motion
  !> analogue (moment: the link's angular rate u; force: the velocity of its point along
  !> the force's line) times the input's motion sign s, 0 where that analogue is zero
  !> within roundoff (the link stops) or the step's kinematics fails.
  pure real(wp) function resist_sense(deck, load, k) result(sense)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> A resisting load.
    type(load_schedule_t), intent(in) :: load
    !> Step number, 1..n.
    integer, intent(in) :: k
    type(link_state_t) :: states(0:2 * size(deck%mech%dyads) + 1)
    type(dyad_pose_t) :: poses(size(deck%mech%dyads))
    type(error_t), allocatable :: kin_error
    type(point_state_t) :: ps
    !> Motion analogue (rad/rad or m/rad), its zero tolerance, the force's direction (rad)
    !> and the mechanism's size (m).
    real(wp) :: rate, tol, dir, size_m
    integer :: i
    sense = 0.0_wp
    call assur_kinematics(deck%mech, assur_phi1_deg(deck, k) * deg_to_rad, states, poses, kin_error)
    if (allocated(kin_error)) return
    associate (st => states(load%resist_link))
      if (load%resist == resist_moment) then
        rate = st%u
        tol = resist_zero_rel
      else
        ps = point_on(st, load%resist_at)
        dir = load%resist_angle
        if (load%resist_follow) dir = dir + st%th
        rate = dot_product(ps%v, [cos(dir), sin(dir)])
        size_m = magnitude(ps%p - deck%mech%pivot)
        do i = 1, ubound(states, 1)
          size_m = max(size_m, magnitude(states(i)%o - deck%mech%pivot))
        end do
        if (.not. size_m > 0.0_wp) size_m = 1.0_wp
        tol = resist_zero_rel * size_m
      end if
    end associate
    if (abs(rate) <= tol) return
    sense = sign(1.0_wp, rate) * assur_motion_sign(assur_omega1(deck, k))
  end function resist_sense

  !> A load's value at every step, N or N*m (for the echo and the load-edge marks; a
  !> temporary of n values).
  pure function assur_load_steps(deck, load) result(values)
    !> Validated deck.
    type(assur_deck_t), intent(in) :: deck
    !> The load's schedule.
    type(load_schedule_t), intent(in) :: load
    !> One value per step, N or N*m.
    real(wp) :: values(deck%n)
    !> Step number.
    integer :: k
    do k = 1, deck%n
      values(k) = assur_load_value(deck, load, k)
    end do
  end function assur_load_steps

  !> Position of a table load's abscissa link at step k: its angle in deg, taken modulo 360
  !> into [x1, x1 + 360) (the crank's angle modulo 720 into [x1, x1 + 720) when the table
  !> spans more than 360 deg: a four-stroke cycle), or a slider's stroke on its frame guide
  !> in m; not ok when the step's kinematics fails.
  pure subroutine table_position(deck, load, k, q, ok)
    !> Validated deck (mechanism and crank angles).
    type(assur_deck_t), intent(in) :: deck
    !> A table load.
    type(load_schedule_t), intent(in) :: load
    !> Step number, 1..n.
    integer, intent(in) :: k
    !> Position, deg or m.
    real(wp), intent(out) :: q
    !> Whether the kinematics of the step succeeded.
    logical, intent(out) :: ok
    type(link_state_t) :: states(0:2 * size(deck%mech%dyads) + 1)
    type(dyad_pose_t) :: poses(size(deck%mech%dyads))
    type(error_t), allocatable :: kin_error
    !> Speed and acceleration analogues of the position (unused).
    real(wp) :: dq, ddq
    q = 0.0_wp
    call assur_kinematics(deck%mech, assur_phi1_deg(deck, k) * deg_to_rad, states, poses, kin_error)
    ok = .not. allocated(kin_error)
    if (.not. ok) return
    call link_position(states, poses, load%link, load%pair, q, dq, ddq)
    if (load%pair /= 0) return
    q = table_angle(load, q * rad_to_deg, assur_phi1_deg(deck, k))
  end subroutine table_position

  !> The abscissa of a table over a link's angle, deg: the link's angle `q_deg` taken modulo
  !> 360 into [x1, x1 + 360), or, over the crank's angle with a table longer than a turn (a
  !> four-stroke cycle, period 720 deg), the crank angle `phi1_deg` modulo 720 into
  !> [x1, x1 + 720).
  pure real(wp) function table_angle(load, q_deg, phi1_deg) result(q)
    !> A table load over a link's angle.
    type(load_schedule_t), intent(in) :: load
    !> The abscissa link's angle and the crank angle, deg.
    real(wp), intent(in) :: q_deg, phi1_deg
    associate (x1 => load%x(1), span => load%x(size(load%x)) - load%x(1))
      if (load%link == crank_index .and. span > 360.0_wp) then
        q = table_cyclic(x1, phi1_deg, 720.0_wp)
      else
        q = table_cyclic(x1, q_deg, 360.0_wp)
      end if
    end associate
  end function table_angle

  !> A table load's value at position q (deg or m; inside the table): linear interpolation.
  pure real(wp) function table_value(load, q) result(value)
    !> A table load.
    type(load_schedule_t), intent(in) :: load
    !> Position, deg or m.
    real(wp), intent(in) :: q
    value = table_interpolate(load%x, load%v, q)
  end function table_value

end module kinetostat_assur_steps
