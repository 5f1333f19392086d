!> The generic engine's machine dynamics: the reduced quantities of any `&assur` mechanism at
!> any crank angle (the links' velocity and acceleration analogues of assur_kinematics; the
!> loads' schedules at that angle), the steady cycle of a deck, and the motion per step.
module kinetostat_assur_dynamics
  use kinetostat_kinds, only: wp, deg_to_rad, rad_to_deg
  use kinetostat_error, only: error_t
  use kinetostat_vec2, only: unit_at
  use kinetostat_loads, only: gravity_force
  use kinetostat_dynamics, only: reduced_t, reduced_source_t, cycle_t, motion_t, motion_at, dynamics_none, &
    dynamics_reduced
  use kinetostat_dynamics_deck, only: deck_cycle
  use kinetostat_assur_kinematics, only: link_state_t, dyad_pose_t, point_state_t, point_on
  use kinetostat_assur, only: assur_kinematics, link_position
  use kinetostat_assur_deck, only: assur_deck_t, load_schedule_t, load_window, load_table, assur_window, &
    table_value, table_angle, assur_phi1_deg, assur_load_value
  implicit none
  private
  public :: assur_source_t, assur_cycle, assur_motion, assur_reduced_at

  !> The reduced quantities of an `&assur` deck at any crank angle.
  type, extends(reduced_source_t) :: assur_source_t
    !> The validated deck.
    type(assur_deck_t) :: deck
  contains
    procedure :: at, failure
  end type assur_source_t

contains

  !> J_red (links only), dJ_red, M_red at crank angle phi (rad).
  pure function at(self, phi) result(red)
    class(assur_source_t), intent(in) :: self
    real(wp), intent(in) :: phi
    type(reduced_t) :: red
    red = assur_reduced_at(self%deck, phi)
  end function at

  !> Why the mechanism has no reduced quantities at crank angle phi (rad): the position
  !> analysis's own message (the dyad that cannot be assembled, its lengths; a dead position).
  pure function failure(self, phi) result(text)
    class(assur_source_t), intent(in) :: self
    real(wp), intent(in) :: phi
    character(len=:), allocatable :: text
    type(link_state_t) :: states(0:2 * size(self%deck%mech%dyads) + 1)
    type(dyad_pose_t) :: poses(size(self%deck%mech%dyads))
    type(error_t), allocatable :: kin_error
    text = ""
    call assur_kinematics(self%deck%mech, phi, states, poses, kin_error)
    if (allocated(kin_error)) text = kin_error%message
  end function failure

  !> The reduced quantities at crank angle phi (rad), loads from their schedules at that angle
  !> (`step`: the step's own values instead, for a row of the run): J_red = sum m |v_Sq|^2 +
  !> J u^2, dJ_red = sum 2 m v_Sq . a_Sq + 2 J u eps_q, M_red = sum F . v_q + M u over gravity,
  !> the forces and the moments; red%ok false where the mechanism cannot be assembled or is
  !> in a dead position.
  pure function assur_reduced_at(deck, phi, step) result(red)
    type(assur_deck_t), intent(in) :: deck
    real(wp), intent(in) :: phi
    integer, intent(in), optional :: step
    type(reduced_t) :: red
    type(link_state_t) :: states(0:2 * size(deck%mech%dyads) + 1)
    type(dyad_pose_t) :: poses(size(deck%mech%dyads))
    type(error_t), allocatable :: kin_error
    type(point_state_t) :: ps
    real(wp) :: dir(2), value
    integer :: i, k
    call assur_kinematics(deck%mech, phi, states, poses, kin_error)
    if (allocated(kin_error)) then
      red%ok = .false.
      return
    end if
    do i = 1, ubound(states, 1)
      associate (lk => deck%mech%links(i), st => states(i))
        ps = point_on(st, lk%s)
        red%j = red%j + lk%m * dot_product(ps%v, ps%v) + lk%j * st%u**2
        red%dj = red%dj + 2.0_wp * (lk%m * dot_product(ps%v, ps%a) + lk%j * st%u * st%eq)
        red%m = red%m + dot_product(gravity_force(lk%m, deck%mech%g, deck%mech%down), ps%v)
      end associate
    end do
    do k = 1, size(deck%mech%forces)
      associate (fo => deck%mech%forces(k))
        ps = point_on(states(fo%link), fo%at)
        if (fo%follow) then
          dir = unit_at(fo%angle + states(fo%link)%th)
        else
          dir = unit_at(fo%angle)
        end if
        if (present(step)) then
          value = assur_load_value(deck, deck%force_load(k), step)
        else
          value = load_at(deck%force_load(k))
        end if
        red%m = red%m + value * dot_product(dir, ps%v)
      end associate
    end do
    do k = 1, size(deck%mech%moment_link)
      if (present(step)) then
        value = assur_load_value(deck, deck%moment_load(k), step)
      else
        value = load_at(deck%moment_load(k))
      end if
      red%m = red%m + value * states(deck%mech%moment_link(k))%u
    end do
    if (deck%mech%drive_dyad > 0) call to_stroke(poses(deck%mech%drive_dyad), deck%mech%drive_pair, red)
  contains
    !> A load's value at phi: constant, window, or table over a link's position.
    pure real(wp) function load_at(load)
      type(load_schedule_t), intent(in) :: load
      real(wp) :: q, dq, ddq
      select case (load%kind)
      case (load_window)
        load_at = assur_window(phi * rad_to_deg, load%phi_on, load%phi_off, load%value, load%idle)
      case (load_table)
        call link_position(states, poses, load%link, load%pair, q, dq, ddq)
        if (load%pair == 0) q = table_angle(load, q * rad_to_deg, phi * rad_to_deg)
        load_at = table_value(load, q)
      case default
        load_at = load%value
      end select
    end function load_at
  end function assur_reduced_at

  !> The crank angles where a load switches or has a kink (rad): the windows' ends, the
  !> points of tables over the crank's own angle.
  pure function load_breaks(deck) result(breaks)
    type(assur_deck_t), intent(in) :: deck
    real(wp), allocatable :: breaks(:)
    integer :: k
    allocate (breaks(0))
    do k = 1, size(deck%force_load)
      call add(deck%force_load(k))
    end do
    do k = 1, size(deck%moment_load)
      call add(deck%moment_load(k))
    end do
  contains
    pure subroutine add(load)
      type(load_schedule_t), intent(in) :: load
      if (load%kind == load_window) breaks = [breaks, [load%phi_on, load%phi_off] * deg_to_rad]
      if (load%kind == load_table .and. load%link == 1 .and. load%pair == 0) breaks = [breaks, load%x * deg_to_rad]
    end subroutine add
  end function load_breaks

  !> The steady cycle of a deck with dynamics = 'steady' or 'given'.
  pure subroutine assur_cycle(deck, path, cycle, error)
    type(assur_deck_t), intent(in) :: deck
    !> Deck path, for messages.
    character(*), intent(in) :: path
    type(cycle_t), intent(out) :: cycle
    type(error_t), allocatable, intent(out) :: error
    type(assur_source_t) :: source
    type(link_state_t) :: states(0:2 * size(deck%mech%dyads) + 1)
    type(dyad_pose_t) :: poses(size(deck%mech%dyads))
    type(error_t), allocatable :: kin_error
    type(point_state_t) :: ps
    real(wp) :: j_crank
    source%deck = deck
    ! the crank's own J_red (m |v_S1q|^2 + j1, constant): Merzalov's first group
    j_crank = 0.0_wp
    call assur_kinematics(deck%mech, deck%phi_start * deg_to_rad, states, poses, kin_error)
    if (.not. allocated(kin_error)) then
      ps = point_on(states(1), deck%mech%links(1)%s)
      j_crank = deck%mech%links(1)%m * dot_product(ps%v, ps%v) + deck%mech%links(1)%j
    end if
    call deck_cycle(source, deck%dyn, deck%phi_start * deg_to_rad, load_breaks(deck), deck%omega1_const, &
                    path//": &assur", cycle, error, j_links_constant=j_crank)
  end subroutine assur_cycle

  !> Reduced quantities per radian of the input link turned into those of a linear
  !> actuator's stroke s (pair `pair` of the driving dyad): with s' = ds/dphi1 and
  !> s'' = d2s/dphi1^2, J_s = J / s'^2 (kg), dJ_s/ds = (dJ - 2 J s''/s') / s'^3 (kg/m),
  !> M_s = M / s' (N: the force along the stroke that does the loads' work, so the
  !> actuator's force at rest is -M_s). Not ok where s' = 0 (a dead position of the actuator).
  pure subroutine to_stroke(pose, pair, red)
    !> Pose of the driving dyad.
    type(dyad_pose_t), intent(in) :: pose
    !> The driving prismatic pair of that dyad.
    integer, intent(in) :: pair
    !> Per radian of phi1 on entry, per metre of stroke on return.
    type(reduced_t), intent(inout) :: red
    real(wp) :: ds, dds
    ds = pose%stroke_v(pair)
    dds = pose%stroke_a(pair)
    if (.not. abs(ds) > 0.0_wp) then
      red%ok = .false.
      return
    end if
    red%dj = (red%dj - 2.0_wp * red%j * dds / ds) / ds**3
    red%j = red%j / ds**2
    red%m = red%m / ds
  end subroutine to_stroke

  !> The motion at step k: of the cycle with a steady cycle, else the deck's constant speed
  !> with the reduced quantities (dynamics = 'reduced').
  pure function assur_motion(source, cycle, k) result(mo)
    !> The deck as a source of reduced quantities.
    type(assur_source_t), intent(in) :: source
    type(cycle_t), intent(in) :: cycle
    integer, intent(in) :: k
    type(motion_t) :: mo
    type(reduced_t) :: red
    real(wp) :: phi
    associate (deck => source%deck)
    phi = assur_phi1_deg(deck, k) * deg_to_rad
    if (deck%dyn%mode == dynamics_none) then
      mo%omega = deck%omega1_const
    else if (deck%dyn%mode == dynamics_reduced) then
      red = assur_reduced_at(deck, phi, k)
      mo%omega = deck%omega1_const
      mo%j = red%j + deck%dyn%j_rotor
      mo%dj = red%dj
      mo%m = red%m
    else
      mo = motion_at(source, cycle, phi)
    end if
    end associate
  end function assur_motion

end module kinetostat_assur_dynamics
