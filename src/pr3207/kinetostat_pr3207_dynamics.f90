!> PR 3207's machine dynamics: its reduced quantities at any crank angle (the kernel's
!> transfer functions and the two-value cutting force), the steady cycle of a deck, and the
!> motion per step.
module kinetostat_pr3207_dynamics
  use kinetostat_kinds, only: wp, deg_to_rad
  use kinetostat_error, only: error_t
  use kinetostat_dynamics, only: reduced_t, reduced_source_t, cycle_t, motion_t, motion_from, dynamics_none, &
    dynamics_reduced
  use kinetostat_dynamics_deck, only: deck_cycle
  use kinetostat_pr3207, only: pr3207_reduced, pr3207_reduced_at, pr3207_position_t, pr3207_position
  use kinetostat_pr3207_deck, only: pr3207_deck_t, pr3207_cut_force, pr3207_f5c, pr3207_phi1_deg
  implicit none
  private
  public :: pr3207_source_t, pr3207_cycle, pr3207_motion

  !> The reduced quantities of a PR 3207 deck at any crank angle.
  type, extends(reduced_source_t) :: pr3207_source_t
    !> The validated deck (two-value cutting force).
    type(pr3207_deck_t) :: deck
  contains
    procedure :: at
  end type pr3207_source_t

contains

  !> J_red (links only), dJ_red, M_red at crank angle phi (rad).
  pure function at(self, phi) result(red)
    class(pr3207_source_t), intent(in) :: self
    real(wp), intent(in) :: phi
    type(reduced_t) :: red
    red = reduced_at_position(self%deck, phi, pr3207_position(self%deck%p, phi))
  end function at

  !> The same at a computed position `pos` of crank angle phi (rad).
  pure function reduced_at_position(deck, phi, pos) result(red)
    type(pr3207_deck_t), intent(in) :: deck
    real(wp), intent(in) :: phi
    type(pr3207_position_t), intent(in) :: pos
    type(reduced_t) :: red
    real(wp) :: f5c, r(3)
    f5c = pr3207_cut_force(phi / deg_to_rad, deck%phi_cut_start, deck%phi_cut_end, deck%f5c_work, deck%f5c_idle)
    r = pr3207_reduced_at(deck%p, pos, f5c)
    red%j = r(1)
    red%dj = r(2)
    red%m = r(3)
  end function reduced_at_position

  !> The steady cycle of a deck with dynamics = 'steady' or 'given' (the cutting force's
  !> switches are the quadrature's breakpoints).
  pure subroutine pr3207_cycle(deck, path, cycle, error)
    type(pr3207_deck_t), intent(in) :: deck
    !> Deck path, for messages.
    character(*), intent(in) :: path
    type(cycle_t), intent(out) :: cycle
    type(error_t), allocatable, intent(out) :: error
    type(pr3207_source_t) :: source
    source%deck = deck
    call deck_cycle(source, deck%dyn, deck%phi_start * deg_to_rad, [deck%phi_cut_start, deck%phi_cut_end] * deg_to_rad, &
                    deck%p%omega1, path//": &pr3207", cycle, error)
  end subroutine pr3207_cycle

  !> The motion at step k of `source`'s deck: of the cycle with a steady cycle, else the deck's
  !> constant speed with the reduced quantities (dynamics = 'reduced').
  pure function pr3207_motion(deck, cycle, k, pos) result(mo)
    type(pr3207_deck_t), intent(in) :: deck
    type(cycle_t), intent(in) :: cycle
    integer, intent(in) :: k
    !> Positions and transfer functions at the step's crank angle (computed once per step).
    type(pr3207_position_t), intent(in) :: pos
    type(motion_t) :: mo
    real(wp) :: phi, r(3), f5c
    phi = pr3207_phi1_deg(deck, k) * deg_to_rad
    if (deck%dyn%mode == dynamics_none) then
      mo%omega = deck%p%omega1
    else if (deck%dyn%mode == dynamics_reduced) then
      r = pr3207_reduced_at(deck%p, pos, pr3207_f5c(deck, k))
      mo%omega = deck%p%omega1
      mo%j = r(1) + deck%dyn%j_rotor
      mo%dj = r(2)
      mo%m = r(3)
    else
      mo = motion_from(cycle, phi, reduced_at_position(deck, phi, pos))
      ! the step's own load at a switch angle (the cycle integrates over it)
      f5c = pr3207_f5c(deck, k)
      if (f5c /= pr3207_cut_force(phi / deg_to_rad, deck%phi_cut_start, deck%phi_cut_end, deck%f5c_work, &
                                  deck%f5c_idle)) then
        r = pr3207_reduced_at(deck%p, pos, f5c)
        mo%m = r(3)
      end if
    end if
  end function pr3207_motion

end module kinetostat_pr3207_dynamics
