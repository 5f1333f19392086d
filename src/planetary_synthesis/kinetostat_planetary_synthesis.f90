!> Tooth numbers of a single-row planetary train (sun 1, planets 2 on the carrier H, fixed
!> ring 3 with internal teeth; u = u_1H = 1 + z3/z1): the conditions of coaxiality
!> z3 = z1 + 2 z2, assembly ((z1 + z3)/k a whole number), neighbourhood
!> ((z1 + z2) sin(pi/k) > z2 + 2: the planets' tip circles clear, ha* = 1), the least teeth
!> and the ratio within its tolerance; the answer is the smallest ring z3 that meets them
!> all, and of its trains the one whose ratio is nearest u. Pure; no I/O.
module kinetostat_planetary_synthesis
  use kinetostat_kinds, only: wp, pi
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  use kinetostat_text, only: int_str
  implicit none
  private
  public :: planetary_spec_t, planetary_train_t, planetary_search, train_conditions, max_ring_teeth

  !> The search stops at this many teeth of the ring.
  integer, parameter :: max_ring_teeth = 20000

  !> What the train must do.
  type :: planetary_spec_t
    !> Ratio asked, u_1H (> 2).
    real(wp) :: u = 0.0_wp
    !> Number of planets.
    integer :: k = 3
    !> Tolerance of the ratio, relative to u.
    real(wp) :: u_tolerance = 0.04_wp
    !> Least teeth of the sun and the planets.
    integer :: z_min = 17
    !> Least teeth of the ring.
    integer :: z_ring_min = 85
  end type planetary_spec_t

  !> A train and how it meets each condition.
  type :: planetary_train_t
    !> Teeth of the sun, a planet, the ring.
    integer :: z1 = 0, z2 = 0, z3 = 0
    !> Its ratio u_1H = 1 + z3/z1.
    real(wp) :: u_actual = 0.0_wp
    !> (u_actual - u)/u.
    real(wp) :: u_deviation = 0.0_wp
    !> (z1 + z3)/k (a whole number for assembly with equally spaced planets).
    real(wp) :: assembly_number = 0.0_wp
    !> (z1 + z2) sin(pi/k) - (z2 + 2) (> 0: the neighbours' tip circles clear).
    real(wp) :: neighbour_margin = 0.0_wp
    !> Each condition met: coaxiality, assembly, neighbourhood, sun and planet teeth, ring
    !> teeth, ratio.
    logical :: met(6) = .false.
  end type planetary_train_t

contains

  !> How the train (z1, z2, z3) meets each condition of `spec`.
  pure function train_conditions(spec, z1, z2, z3) result(t)
    !> The conditions.
    type(planetary_spec_t), intent(in) :: spec
    !> Teeth of the sun, a planet and the ring.
    integer, intent(in) :: z1, z2, z3
    type(planetary_train_t) :: t
    t%z1 = z1
    t%z2 = z2
    t%z3 = z3
    t%u_actual = 1.0_wp + real(z3, wp) / real(z1, wp)
    t%u_deviation = (t%u_actual - spec%u) / spec%u
    t%assembly_number = real(z1 + z3, wp) / real(spec%k, wp)
    t%neighbour_margin = real(z1 + z2, wp) * sin(pi / real(spec%k, wp)) - real(z2 + 2, wp)
    t%met(1) = z3 == z1 + 2 * z2
    t%met(2) = modulo(z1 + z3, spec%k) == 0
    ! one planet has no neighbour
    t%met(3) = spec%k == 1 .or. t%neighbour_margin > 0.0_wp
    t%met(4) = z1 >= spec%z_min .and. z2 >= spec%z_min
    t%met(5) = z3 >= spec%z_ring_min
    t%met(6) = abs(t%u_actual - spec%u) <= spec%u_tolerance * spec%u
  end function train_conditions

  !> The smallest ring z3 (from z_ring_min up to max_ring_teeth) with a train that meets
  !> every condition; of its trains the ratio nearest u (then the smaller sun).
  pure subroutine planetary_search(spec, best, error)
    !> The conditions.
    type(planetary_spec_t), intent(in) :: spec
    !> The answer.
    type(planetary_train_t), intent(out) :: best
    !> No train up to max_ring_teeth.
    type(error_t), allocatable, intent(out) :: error
    type(planetary_train_t) :: t
    integer :: z1, z2, z3, z1_lo, z1_hi
    real(wp) :: u_lo, u_hi
    logical :: found
    found = .false.
    ! the ratio's window bounds the sun: z1 = z3/(u_1H - 1), u_1H within u (1 -+ tolerance)
    u_lo = spec%u * (1.0_wp - spec%u_tolerance)
    u_hi = spec%u * (1.0_wp + spec%u_tolerance)
    do z3 = max(spec%z_ring_min, 3 * spec%z_min), max_ring_teeth
      ! z3 = z1 + 2 z2 with z2 >= z_min: z1 <= z3 - 2 z_min, of the parity of z3
      z1_lo = spec%z_min
      z1_hi = z3 - 2 * spec%z_min
      if (u_hi > 1.0_wp) z1_lo = max(z1_lo, floor(real(z3, wp) / (u_hi - 1.0_wp)) - 1)
      if (u_lo > 1.0_wp) z1_hi = min(z1_hi, ceiling(real(z3, wp) / (u_lo - 1.0_wp)) + 1)
      do z1 = z1_lo, z1_hi
        if (modulo(z3 - z1, 2) /= 0) cycle
        z2 = (z3 - z1) / 2
        t = train_conditions(spec, z1, z2, z3)
        if (.not. all(t%met)) cycle
        if (found) then
          if (.not. abs(t%u_deviation) < abs(best%u_deviation)) cycle
        end if
        best = t
        found = .true.
      end do
      if (found) return
    end do
    call fatal_error(error, exit_geometry, "no single-row train with u = 1 + z3/z1 within u_tolerance*u of "// &
      "u, z1, z2 >= "//int_str(spec%z_min)// &
      ", z3 from "//int_str(spec%z_ring_min)//" to "//int_str(max_ring_teeth)//" and k = "//int_str(spec%k)// &
      " planets (assembly and neighbourhood); widen u_tolerance or take fewer planets")
  end subroutine planetary_search

end module kinetostat_planetary_synthesis
