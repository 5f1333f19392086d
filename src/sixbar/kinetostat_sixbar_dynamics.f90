!> T.FTN's machine dynamics: the reduced quantities at any crank angle, with the slider load
!> given per step taken as a load table over the crank angle (the steps its points, linear
!> between neighbouring steps, periodic over the turn the steps cover), the steady cycle of a
!> deck and the motion per step (with the step's own load, as the legacy program applies it).
module kinetostat_sixbar_dynamics
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_dynamics, only: reduced_t, reduced_source_t, cycle_t, motion_t, motion_at, dynamics_none, &
    dynamics_reduced
  use kinetostat_dynamics_deck, only: deck_cycle
  use kinetostat_sixbar, only: sixbar_params_t, sixbar_position_t, sixbar_position, sixbar_reduced_at, sixbar_ok
  use kinetostat_sixbar_deck, only: sixbar_deck_t, sixbar_phi1_deg
  implicit none
  private
  public :: sixbar_source_t, sixbar_source, sixbar_load_at, sixbar_cycle, sixbar_motion

  !> The reduced quantities of a T.FTN deck at any crank angle.
  type, extends(reduced_source_t) :: sixbar_source_t
    !> Mechanism data.
    type(sixbar_params_t) :: p
    !> First crank angle, deg.
    real(wp) :: phi_start = 0.0_wp
    !> Crank step, deg.
    real(wp) :: dphi = 0.0_wp
    !> Slider load at the steps, N (the table's points; n values).
    real(wp), allocatable :: f5(:)
  contains
    procedure :: at
  end type sixbar_source_t

contains

  !> The source of a validated deck (a copy of its load table; not allocated when it does
  !> not fit in memory).
  pure function sixbar_source(deck) result(source)
    type(sixbar_deck_t), intent(in) :: deck
    type(sixbar_source_t) :: source
    integer :: stat
    source%p = deck%p
    source%phi_start = deck%phi_start
    source%dphi = deck%dphi
    allocate (source%f5(deck%n), stat=stat)
    if (stat == 0) source%f5 = deck%f5(1:deck%n)
  end function sixbar_source

  !> The slider load at crank angle phi (rad) from the table of the steps: linear between
  !> neighbouring steps, the angle taken into phi_start .. phi_start + (n - 1) dphi modulo 360
  !> deg (at a step, the step's own value; at the cycle's start, the first step's).
  pure real(wp) function sixbar_load_at(source, phi) result(f5)
    type(sixbar_source_t), intent(in) :: source
    !> Crank angle, rad.
    real(wp), intent(in) :: phi
    real(wp) :: x, t
    integer :: k, n
    n = size(source%f5)
    if (n == 1) then
      f5 = source%f5(1)
      return
    end if
    x = modulo(phi / deg_to_rad - source%phi_start, 360.0_wp) / source%dphi
    k = min(max(int(x), 0), n - 2)
    t = min(max(x - real(k, wp), 0.0_wp), 1.0_wp)
    f5 = source%f5(k + 1) + t * (source%f5(k + 2) - source%f5(k + 1))
  end function sixbar_load_at

  !> J_red (with the crank's j1), dJ_red, M_red at crank angle phi (rad), with the load table.
  pure function at(self, phi) result(red)
    class(sixbar_source_t), intent(in) :: self
    real(wp), intent(in) :: phi
    type(reduced_t) :: red
    type(sixbar_position_t) :: pos
    real(wp) :: r(3)
    pos = sixbar_position(self%p, phi)
    red%ok = pos%status == sixbar_ok
    if (.not. red%ok) return
    r = sixbar_reduced_at(self%p, pos, sixbar_load_at(self, phi))
    red%j = r(1)
    red%dj = r(2)
    red%m = r(3)
  end function at

  !> The steady cycle of a deck with dynamics = 'steady' or 'given': the steps where the load
  !> table bends (its slope changes) are the quadrature's breakpoints.
  pure subroutine sixbar_cycle(deck, source, path, cycle, error)
    type(sixbar_deck_t), intent(in) :: deck
    !> The deck's reduced quantities (sixbar_source).
    type(sixbar_source_t), intent(in) :: source
    !> Deck path, for messages.
    character(*), intent(in) :: path
    type(cycle_t), intent(out) :: cycle
    type(error_t), allocatable, intent(out) :: error
    logical :: bend(deck%n)
    integer :: k
    bend = .false.
    do k = 2, deck%n - 1
      bend(k) = deck%f5(k + 1) - deck%f5(k) /= deck%f5(k) - deck%f5(k - 1)
    end do
    call deck_cycle(source, deck%dyn, deck%phi_start * deg_to_rad, &
                    pack([(sixbar_phi1_deg(deck, k) * deg_to_rad, k = 1, deck%n)], bend), &
                    deck%p%omega1, path//": &sixbar", cycle, error, j_links_constant=deck%p%j1)
  end subroutine sixbar_cycle

  !> The motion at step k with the step's own load f5(k): of the cycle with a steady cycle
  !> (eps from the step's own M_red, so that M1 = M_d where the load jumps at a step), else the
  !> deck's constant speed with the reduced quantities (dynamics = 'reduced').
  pure function sixbar_motion(deck, source, cycle, k) result(mo)
    type(sixbar_deck_t), intent(in) :: deck
    type(sixbar_source_t), intent(in) :: source
    type(cycle_t), intent(in) :: cycle
    integer, intent(in) :: k
    type(motion_t) :: mo
    type(sixbar_position_t) :: pos
    real(wp) :: phi, r(3)
    phi = sixbar_phi1_deg(deck, k) * deg_to_rad
    pos = sixbar_position(deck%p, phi)
    r = sixbar_reduced_at(deck%p, pos, deck%f5(k))
    if (deck%dyn%mode == dynamics_none) then
      mo%omega = deck%p%omega1
    else if (deck%dyn%mode == dynamics_reduced) then
      mo%omega = deck%p%omega1
      mo%j = r(1) + deck%dyn%j_rotor
      mo%dj = r(2)
      mo%m = r(3)
    else
      mo = motion_at(source, cycle, phi)
      mo%m = r(3)
      mo%eps = (mo%md + mo%m - 0.5_wp * mo%dj * mo%omega**2) / (cycle%j_flywheel + mo%j)
    end if
  end function sixbar_motion

end module kinetostat_sixbar_dynamics
