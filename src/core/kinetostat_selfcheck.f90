!> Independent checks of a computed force analysis: equilibrium residual of a link and
!> the mismatch between a driving moment/force and its power-balance (virtual work) value.
module kinetostat_selfcheck
  use kinetostat_kinds, only: wp
  use kinetostat_vec2, only: cross, magnitude
  implicit none
  private
  public :: link_residual, power_mismatch, selfcheck_tolerance

  !> A self-check worse than this (relative) is a bug: the CLI warns and the tests fail.
  real(wp), parameter :: selfcheck_tolerance = 1.0e-6_wp

contains

  !> Relative equilibrium residual of one link: forces `f(:,i)` applied at `at(:,i)` and
  !> couples `c(:)`. Returns max(|sum F| / sum |F_i|, |sum M_O| / sum |M_i|), moments taken
  !> about the first point; each ratio is 0 when its scale is 0 (nothing acts).
  pure function link_residual(at, f, c) result(residual)
    !> Points of application, m (2 x n).
    real(wp), intent(in) :: at(:, :)
    !> Forces, N (2 x n).
    real(wp), intent(in) :: f(:, :)
    !> Couples, N*m (may be empty).
    real(wp), intent(in) :: c(:)
    real(wp) :: residual
    real(wp) :: sum_f(2), sum_m, scale_f, scale_m, m_i
    integer :: i
    sum_f = 0.0_wp
    scale_f = 0.0_wp
    sum_m = sum(c)
    scale_m = sum(abs(c))
    do i = 1, size(f, 2)
      sum_f = sum_f + f(:, i)
      scale_f = scale_f + magnitude(f(:, i))
      m_i = cross(at(:, i) - at(:, 1), f(:, i))
      sum_m = sum_m + m_i
      scale_m = scale_m + abs(m_i)
    end do
    residual = max(ratio(magnitude(sum_f), scale_f), ratio(abs(sum_m), scale_m))
  end function link_residual

  !> Relative mismatch of a driving moment (or force) `q` against its power-balance value
  !> `q_power`, scaled by `scale` = sum of the magnitudes of the power terms (>= |q_power|).
  pure function power_mismatch(q, q_power, scale) result(mismatch)
    !> Driving moment/force from the reaction chain.
    real(wp), intent(in) :: q
    !> The same from the virtual-work balance.
    real(wp), intent(in) :: q_power
    !> Sum of |terms| of the balance, same unit as q.
    real(wp), intent(in) :: scale
    real(wp) :: mismatch
    mismatch = ratio(abs(q - q_power), max(scale, abs(q), abs(q_power)))
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
