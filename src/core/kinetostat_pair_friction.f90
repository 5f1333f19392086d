!> What the friction solves of `&assur` and `&linkage` share (docs/friction.md): a pair's
!> friction load (journal friction Q = f*r*|F|; sliding friction Q = f*|N|, with a contact
!> span c > 0 the two-contact model Q = f*max(|N|, 2|M|/c)), the fixed-point iteration's
!> tolerances and its convergence test (the contraction factor of successive changes), the
!> relative change of a reaction, and the refusals: no convergence (jamming) and self-locking.
module kinetostat_pair_friction
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_text, only: int_str, real_str
  use kinetostat_vec2, only: magnitude
  implicit none
  private
  public :: friction_tolerance, friction_max_iterations, friction_zero_rel, roundoff_rel, sign_floor_rel
  public :: friction_load, relative, note_pair_changes, reverses_at_rest, self_locking_error
  public :: friction_iteration_t

  !> Convergence tolerance of the coupled solve: every reaction to this relative accuracy
  !> (estimated from the contraction of the iteration).
  real(wp), parameter :: friction_tolerance = 1.0e-12_wp
  !> Iteration limit of the coupled solve.
  integer, parameter :: friction_max_iterations = 1000
  !> A relative analogue at or below this fraction of its scale counts as zero (no friction).
  real(wp), parameter :: friction_zero_rel = 1.0e-10_wp
  !> Consecutive growing changes after which the iteration counts as diverging.
  integer, parameter :: diverging_after = 20
  !> Roundoff floor of a reaction's change, relative to the step's largest reaction.
  real(wp), parameter :: roundoff_rel = 1.0e-14_wp
  !> A change at or below this is roundoff: the iteration has reached its fixed point.
  real(wp), parameter :: roundoff_change = 4.0_wp * epsilon(1.0_wp)
  !> A frictionless driving effort below this, relative to the step's effort scale, has no
  !> sign in the self-locking test (roundoff is zero, not a reversal).
  real(wp), parameter :: sign_floor_rel = 1.0e-12_wp

  !> The state of the coupled solve's fixed-point iteration: call `next` with each
  !> iteration's largest relative change and leave the loop when it says so.
  type :: friction_iteration_t
    !> Iterations done.
    integer :: iterations = 0
    !> Consecutive iterations whose change grew.
    integer :: growing = 0
    !> The last change and the one before.
    real(wp) :: change = 0.0_wp, previous = 0.0_wp
    !> Contraction factor: change / previous.
    real(wp) :: q = 0.0_wp
    !> Whether the iteration reached its tolerance.
    logical :: converged = .false.
  contains
    procedure :: next => iteration_next
    procedure :: failure => iteration_failure
  end type friction_iteration_t

contains

  !> A pair's friction load: the couple f*r*|F| of a turning pair (N*m), or the force f*|N|
  !> of a sliding pair (N), f*max(|N|, 2|M|/span) with a contact span.
  pure real(wp) function friction_load(f, r, span, sliding, force, normal, couple)
    !> Friction coefficient, journal radius (m), contact span (m; 0: resultant-normal model).
    real(wp), intent(in) :: f, r, span
    !> Whether the pair slides.
    logical, intent(in) :: sliding
    !> The pair's reaction, N; a sliding pair's normal force, N, and reaction moment, N*m.
    real(wp), intent(in) :: force(2), normal, couple
    real(wp) :: n
    if (sliding) then
      n = abs(normal)
      if (span > 0.0_wp) n = max(n, 2.0_wp * abs(couple) / span)
      friction_load = f * n
    else
      friction_load = f * r * magnitude(force)
    end if
  end function friction_load

  !> num / den, 0 when num is 0 (also for den = 0), huge when only den is 0.
  pure real(wp) function relative(num, den)
    real(wp), intent(in) :: num, den
    if (.not. num > 0.0_wp) then
      relative = 0.0_wp
    else if (den > 0.0_wp) then
      relative = num / den
    else
      relative = huge(1.0_wp)
    end if
  end function relative

  !> The pairs' share of the largest relative change between two solutions: each pair's force
  !> and reaction moment relative to itself (floors: `floor` N, `floor * length` N*m); where
  !> the largest is, the pair's index.
  pure subroutine note_pair_changes(f_old, f_new, m_old, m_new, floor, length, change, where)
    !> Pair forces (2, pairs), N, and reaction moments, N*m, before and after.
    real(wp), intent(in) :: f_old(:, :), f_new(:, :), m_old(:), m_new(:)
    !> Roundoff floor of a force, N, and the length scale of moments, m.
    real(wp), intent(in) :: floor, length
    real(wp), intent(inout) :: change
    integer, intent(inout) :: where
    real(wp) :: c
    integer :: ip
    do ip = 1, size(f_new, 2)
      c = max(relative(magnitude(f_new(:, ip) - f_old(:, ip)), max(magnitude(f_new(:, ip)), floor)), &
              relative(abs(m_new(ip) - m_old(ip)), max(abs(m_new(ip)), floor * length)))
      if (.not. c <= change) then
        change = c
        where = ip
      end if
    end do
  end subroutine note_pair_changes

  !> One iteration's change: whether the iteration is done (converged, the change not finite,
  !> or diverging); `it` is the iteration's number.
  pure subroutine iteration_next(self, it, change, done)
    class(friction_iteration_t), intent(inout) :: self
    integer, intent(in) :: it
    real(wp), intent(in) :: change
    logical, intent(out) :: done
    self%iterations = it
    self%change = change
    done = .true.
    if (.not. ieee_is_finite(change)) return
    ! contraction factor q of the iteration; the remaining error is about q/(1-q)*change
    if (it > 1 .and. self%previous > 0.0_wp) self%q = change / self%previous
    self%previous = change
    self%converged = change <= roundoff_change .or. (it > 1 .and. self%q < 1.0_wp .and. &
                     change * max(1.0_wp, self%q / (1.0_wp - self%q)) <= friction_tolerance)
    if (self%converged) return
    self%growing = merge(self%growing + 1, 0, self%q >= 1.0_wp)
    done = self%growing >= diverging_after
  end subroutine iteration_next

  !> The error of an iteration that did not converge (exit 3), naming where the last change was.
  pure subroutine iteration_failure(self, where, error)
    class(friction_iteration_t), intent(in) :: self
    !> "pair F21", "M1", ...
    character(*), intent(in) :: where
    type(error_t), allocatable, intent(out) :: error
    call fatal_error(error, exit_geometry, "friction: the coupled solve of reactions and friction loads "// &
      trim(merge("diverges         ", "does not converge", self%growing >= diverging_after))//" ("// &
      int_str(self%iterations)//" iterations, last relative change "//real_str(self%change)//" in "// &
      where//", contraction factor "//real_str(self%q)//"): friction too large for this "// &
      "position (jamming: the factor reaches 1)")
  end subroutine iteration_failure

  !> Whether friction reverses the driving effort (self-locking with the input at rest): the
  !> frictionless effort has a sign (above `floor`) and the effort with friction the other.
  pure logical function reverses_at_rest(frictionless, with, floor)
    real(wp), intent(in) :: frictionless, with, floor
    reverses_at_rest = abs(frictionless) > floor .and. with /= 0.0_wp .and. &
                       sign(1.0_wp, with) /= sign(1.0_wp, frictionless)
  end function reverses_at_rest

  !> The self-locking error (exit 3): the efforts without and with friction, and the pair of
  !> the largest friction load.
  pure subroutine self_locking_error(without, with, where, error)
    character(*), intent(in) :: without, with, where
    type(error_t), allocatable, intent(out) :: error
    call fatal_error(error, exit_geometry, "friction: self-locking with the input at rest: friction reverses "// &
      "the driving effort ("//without//" without friction, "//with//" with it; largest friction load in "// &
      where//")")
  end subroutine self_locking_error

end module kinetostat_pair_friction
