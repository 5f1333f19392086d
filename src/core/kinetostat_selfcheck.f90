!> Independent checks of a computed force analysis: equilibrium residual of a link and
!> the mismatch between a driving moment/force and its power-balance (virtual work) value.
module kinetostat_selfcheck
  use kinetostat_kinds, only: wp
  use kinetostat_vec2, only: cross, fast_magnitude
  implicit none
  private
  public :: link_balance_t, link_balance, balance_add_force, balance_add_couple, balance_add_balance
  public :: equilibrium_residual, power_mismatch
  public :: selfcheck_tolerance, residual_floor_rel, load_moment_scale

  !> A self-check worse than this (relative) is a bug: the CLI warns and the tests fail.
  real(wp), parameter :: selfcheck_tolerance = 1.0e-6_wp
  !> Smallest load scale of a link in its equilibrium residual, relative to the step's
  !> largest: forces against the largest sum |F_i| of a link, moments against the largest
  !> sum |r_i|*|F_i| + sum |C_j| (the size of the terms whose roundoff the moment sum
  !> carries). A link whose loads are all roundoff-level (a massless unloaded link, the
  !> moments of a two-force link) is judged against the step's load level instead of
  !> reporting a residual near 1.
  real(wp), parameter :: residual_floor_rel = 1.0e-6_wp

  !> The loads acting on one link: resultant force (N) and moment (N*m, about the link's
  !> reference point), with the sums of their magnitudes (the link's scales).
  type :: link_balance_t
    !> Resultant force, N.
    real(wp) :: sum_f(2) = 0.0_wp
    !> Resultant moment about the reference point, N*m.
    real(wp) :: sum_m = 0.0_wp
    !> Sum of the force magnitudes, N.
    real(wp) :: scale_f = 0.0_wp
    !> Sum of the moment magnitudes (forces' moments and couples), N*m.
    real(wp) :: scale_m = 0.0_wp
    !> Sum of |lever arm| * |force| and of the couples' magnitudes, N*m (>= scale_m).
    real(wp) :: lever_m = 0.0_wp
    !> Longest lever arm of a force added, whatever its magnitude (a force at roundoff level
    !> included), m: the link's size, so that a link whose forces all sit on one line
    !> through its origin still has a moment scale.
    real(wp) :: arm_max = 0.0_wp
  end type link_balance_t

contains

  !> Adds force `f` (N) applied at `at` (m) to `balance`, its moment taken about `origin` (m).
  pure subroutine balance_add_force(balance, origin, at, f, f_length)
    !> The link's loads so far.
    type(link_balance_t), intent(inout) :: balance
    !> Reference point of the link's moments, m.
    real(wp), intent(in) :: origin(2)
    !> Point of application, m.
    real(wp), intent(in) :: at(2)
    !> Force, N.
    real(wp), intent(in) :: f(2)
    !> fast_magnitude(f) when the caller has it already (a reaction added to both links it
    !> acts between), N.
    real(wp), intent(in), optional :: f_length
    real(wp) :: m, arm(2), f_mag, arm_mag
    arm = at - origin
    m = cross(arm, f)
    if (present(f_length)) then
      f_mag = f_length
    else
      f_mag = fast_magnitude(f)
    end if
    ! a force at the origin has no lever arm: hypot(0, 0) = 0 without the call
    arm_mag = 0.0_wp
    if (arm(1) /= 0.0_wp .or. arm(2) /= 0.0_wp) arm_mag = fast_magnitude(arm)
    balance%sum_f = balance%sum_f + f
    balance%scale_f = balance%scale_f + f_mag
    balance%sum_m = balance%sum_m + m
    balance%scale_m = balance%scale_m + abs(m)
    balance%lever_m = balance%lever_m + arm_mag * f_mag
    balance%arm_max = max(balance%arm_max, arm_mag)
  end subroutine balance_add_force

  !> Adds couple `c` (N*m, CCW positive) to `balance`.
  pure subroutine balance_add_couple(balance, c)
    !> The link's loads so far.
    type(link_balance_t), intent(inout) :: balance
    !> Couple, N*m.
    real(wp), intent(in) :: c
    balance%sum_m = balance%sum_m + c
    balance%scale_m = balance%scale_m + abs(c)
    balance%lever_m = balance%lever_m + abs(c)
  end subroutine balance_add_couple

  !> Adds the loads summed in `other` (moments about the same reference point) to `balance`.
  pure subroutine balance_add_balance(balance, other)
    !> The link's loads so far.
    type(link_balance_t), intent(inout) :: balance
    !> Further loads on the same link.
    type(link_balance_t), intent(in) :: other
    balance%sum_f = balance%sum_f + other%sum_f
    balance%sum_m = balance%sum_m + other%sum_m
    balance%scale_f = balance%scale_f + other%scale_f
    balance%scale_m = balance%scale_m + other%scale_m
    balance%lever_m = balance%lever_m + other%lever_m
    balance%arm_max = max(balance%arm_max, other%arm_max)
  end subroutine balance_add_balance

  !> The loads of one link: forces `f(:,i)` applied at `at(:,i)` and couples `c(:)`,
  !> moments taken about the first point.
  pure function link_balance(at, f, c) result(balance)
    !> Points of application, m (2 x n).
    real(wp), intent(in) :: at(:, :)
    !> Forces, N (2 x n).
    real(wp), intent(in) :: f(:, :)
    !> Couples, N*m (may be empty).
    real(wp), intent(in) :: c(:)
    type(link_balance_t) :: balance
    integer :: i
    do i = 1, size(c)
      call balance_add_couple(balance, c(i))
    end do
    do i = 1, size(f, 2)
      call balance_add_force(balance, at(:, 1), at(:, i), f(:, i))
    end do
  end function link_balance

  !> Largest relative equilibrium residual of the links of one step (the shared rule of every
  !> mechanism): per link max(|sum F| / S_F, |sum M| / S_M) with S_F = max(sum |F_i|,
  !> residual_floor_rel * the step's largest sum |F_i|) and S_M = max(sum |M_i|,
  !> residual_floor_rel * load_moment_scale(links)); a ratio is 0 when its scale is 0
  !> (nothing acts anywhere in the step). The moment floor cannot vanish while a force acts:
  !> a mechanism whose loads all pass through the links' origins (a transverse load on a
  !> slider) has no lever products, but its links have a size.
  pure function equilibrium_residual(links) result(residual)
    !> The loads of every link of the step.
    type(link_balance_t), intent(in) :: links(:)
    real(wp) :: residual
    real(wp) :: floor_f, floor_m, scale_f_max, lever_max, arm_max
    integer :: i
    residual = 0.0_wp
    if (size(links) == 0) return
    ! maxval(links%scale_f) and load_moment_scale(links) in one pass over the links
    call largest_scales(links, scale_f_max, lever_max, arm_max)
    floor_f = residual_floor_rel * scale_f_max
    floor_m = residual_floor_rel * max(lever_max, scale_f_max * arm_max)
    do i = 1, size(links)
      residual = max(residual, ratio(fast_magnitude(links(i)%sum_f), max(links(i)%scale_f, floor_f)), &
                     ratio(abs(links(i)%sum_m), max(links(i)%scale_m, floor_m)))
    end do
  end function equilibrium_residual

  !> A moment scale of a step's loads that cannot vanish while any force acts, N*m: the
  !> largest sum |r_i|*|F_i| + sum |C_j| of a link, or the largest force sum of a link
  !> times the longest lever arm of any link (or `length`, a size of the mechanism, when
  !> longer), whichever is larger.
  pure function load_moment_scale(links, length) result(scale)
    !> The loads of every link of the step.
    type(link_balance_t), intent(in) :: links(:)
    !> A length of the mechanism, m (e.g. the largest distance of a joint from the input
    !> pivot; 0 when not known).
    real(wp), intent(in), optional :: length
    real(wp) :: scale
    real(wp) :: arm, scale_f_max, lever_max
    scale = 0.0_wp
    if (size(links) == 0) return
    call largest_scales(links, scale_f_max, lever_max, arm)
    if (present(length)) arm = max(arm, length)
    scale = max(lever_max, scale_f_max * arm)
  end function load_moment_scale

  !> maxval(links%scale_f), maxval(links%lever_m) and maxval(links%arm_max) in one pass
  !> (as maxval takes them: a NaN is passed over unless every value is one).
  pure subroutine largest_scales(links, scale_f_max, lever_max, arm_max)
    !> The loads of every link of the step (at least one).
    type(link_balance_t), intent(in) :: links(:)
    !> The largest force sum, N, lever sum, N*m, and lever arm, m.
    real(wp), intent(out) :: scale_f_max, lever_max, arm_max
    integer :: i
    scale_f_max = links(1)%scale_f
    lever_max = links(1)%lever_m
    arm_max = links(1)%arm_max
    do i = 2, size(links)
      if (links(i)%scale_f > scale_f_max .or. is_nan(scale_f_max)) scale_f_max = links(i)%scale_f
      if (links(i)%lever_m > lever_max .or. is_nan(lever_max)) lever_max = links(i)%lever_m
      if (links(i)%arm_max > arm_max .or. is_nan(arm_max)) arm_max = links(i)%arm_max
    end do
  contains
    pure logical function is_nan(x)
      real(wp), intent(in) :: x
      is_nan = x /= x
    end function is_nan
  end subroutine largest_scales

  !> Relative mismatch of a driving moment (or force) `q` against its power-balance value
  !> `q_power`, scaled by `scale` = sum of the magnitudes of the power terms (>= |q_power|),
  !> and at least residual_floor_rel * `load_scale`: the power terms vanish when no load
  !> does work (a transverse load on a massless slider), the loads do not, so a driving
  !> effort at roundoff level is not judged against itself.
  pure function power_mismatch(q, q_power, scale, load_scale) result(mismatch)
    !> Driving moment/force from the reaction chain.
    real(wp), intent(in) :: q
    !> The same from the virtual-work balance.
    real(wp), intent(in) :: q_power
    !> Sum of |terms| of the balance, same unit as q.
    real(wp), intent(in) :: scale
    !> The size of a driving effort the step's loads make, same unit as q (for a moment:
    !> load_moment_scale; for a force: the largest force sum of a link).
    real(wp), intent(in), optional :: load_scale
    real(wp) :: mismatch
    real(wp) :: floor
    floor = 0.0_wp
    if (present(load_scale)) floor = residual_floor_rel * load_scale
    mismatch = ratio(abs(q - q_power), max(scale, abs(q), abs(q_power), floor))
  end function power_mismatch

  pure function ratio(num, den) result(r)
    real(wp), intent(in) :: num, den
    real(wp) :: r
    if (den > 0.0_wp) then
      r = num / den
    else
      r = num
    end if
  end function ratio

end module kinetostat_selfcheck
