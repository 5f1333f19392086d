!> Plane vectors as `real(wp) :: v(2)`: polar construction, rotation, cross product, angles.
module kinetostat_vec2
  use, intrinsic :: iso_c_binding, only: c_double
  use kinetostat_kinds, only: wp, rad_to_deg
  implicit none
  private
  public :: polar, unit_at, perp, cross, rotate, magnitude, fast_magnitude, largest_magnitude
  public :: angle_360_deg, angle_180_deg, clean_zero, snap_noise

  interface
    !> The C library's hypot, called as such: the intrinsic HYPOT in a loop that the release
    !> build vectorizes becomes libmvec's vector hypot, which may round a last bit otherwise
    !> than the scalar one (the debug build's), so outputs would depend on the build.
    pure function c_hypot(x, y) result(r) bind(c, name="hypot")
      import :: c_double
      implicit none
      real(c_double), value, intent(in) :: x, y
      real(c_double) :: r
    end function c_hypot
  end interface

contains

  !> Vector of length `r` at angle `phi` (rad) from the x-axis.
  pure function polar(r, phi) result(v)
    !> Length (any unit).
    real(wp), intent(in) :: r
    !> Angle, rad, counter-clockwise from x.
    real(wp), intent(in) :: phi
    real(wp) :: v(2)
    v = r * [cos(phi), sin(phi)]
  end function polar

  !> Unit vector at angle `phi` (rad).
  pure function unit_at(phi) result(v)
    !> Angle, rad.
    real(wp), intent(in) :: phi
    real(wp) :: v(2)
    v = [cos(phi), sin(phi)]
  end function unit_at

  !> The vector turned by +90 degrees (i*v in complex notation).
  pure function perp(v) result(w)
    !> Any plane vector.
    real(wp), intent(in) :: v(2)
    real(wp) :: w(2)
    w = [-v(2), v(1)]
  end function perp

  !> z-component of a x b: the moment about the origin of force b applied at point a.
  pure function cross(a, b) result(c)
    !> First vector (e.g. arm, m).
    real(wp), intent(in) :: a(2)
    !> Second vector (e.g. force, N).
    real(wp), intent(in) :: b(2)
    real(wp) :: c
    c = a(1) * b(2) - a(2) * b(1)
  end function cross

  !> The vector turned by `theta` (rad) counter-clockwise.
  pure function rotate(v, theta) result(w)
    !> Vector to turn.
    real(wp), intent(in) :: v(2)
    !> Turning angle, rad.
    real(wp), intent(in) :: theta
    real(wp) :: w(2)
    w = [cos(theta) * v(1) - sin(theta) * v(2), sin(theta) * v(1) + cos(theta) * v(2)]
  end function rotate

  !> Euclidean length.
  pure function magnitude(v) result(r)
    !> Any plane vector.
    real(wp), intent(in) :: v(2)
    real(wp) :: r
    r = c_hypot(v(1), v(2))
  end function magnitude

  !> The largest length of the columns of `f` (0 when it has none): a step's largest pair
  !> force, N, as the roundoff floors and convergence tests scale by it.
  pure function largest_magnitude(f) result(r)
    !> Plane vectors, one a column (2 x n).
    real(wp), intent(in) :: f(:, :)
    real(wp) :: r
    integer :: i
    r = 0.0_wp
    do i = 1, size(f, 2)
      r = max(r, magnitude(f(:, i)))
    end do
  end function largest_magnitude

  !> Euclidean length as sqrt(x**2 + y**2) where the squares neither overflow nor lose
  !> digits to underflow (within an ulp or so of `magnitude`'s hypot, at a fraction of its
  !> cost), else hypot: for the self-check's scales and sizes, not for printed values.
  pure function fast_magnitude(v) result(r)
    !> Any plane vector.
    real(wp), intent(in) :: v(2)
    real(wp) :: r
    !> Range of the sum of squares where sqrt of it is as good as hypot.
    real(wp), parameter :: sq_low = 1.0e-290_wp, sq_high = 1.0e290_wp
    real(wp) :: sq
    sq = v(1)**2 + v(2)**2
    if (sq >= sq_low .and. sq <= sq_high) then
      r = sqrt(sq)
    else if (v(1) == 0.0_wp .and. v(2) == 0.0_wp) then
      r = 0.0_wp
    else
      r = c_hypot(v(1), v(2))
    end if
  end function fast_magnitude

  !> Angle of `v` in degrees, in [0, 360); a zero vector has angle 0.
  pure function angle_360_deg(v) result(a)
    !> Any plane vector.
    real(wp), intent(in) :: v(2)
    real(wp) :: a
    a = angle_180_deg(v)
    if (a < 0.0_wp) a = a + 360.0_wp
    if (a >= 360.0_wp) a = a - 360.0_wp
  end function angle_360_deg

  !> Angle of `v` in degrees, in (-180, 180] as ATAN2 gives it; a zero vector has angle 0.
  pure function angle_180_deg(v) result(a)
    !> Any plane vector.
    real(wp), intent(in) :: v(2)
    real(wp) :: a
    if (v(1) == 0.0_wp .and. v(2) == 0.0_wp) then
      a = 0.0_wp
    else
      ! adding +0 turns a signed zero into +0, so (x<0, -0) gives +180, not -180
      a = atan2(v(2) + 0.0_wp, v(1) + 0.0_wp) * rad_to_deg
    end if
  end function angle_180_deg

  !> The value with a negative zero replaced by +0 (so tables never print "-0.000").
  elemental function clean_zero(x) result(y)
    !> Any value.
    real(wp), intent(in) :: x
    real(wp) :: y
    y = x + 0.0_wp
  end function clean_zero

  !> The vector, or exactly zero when its length is at most `floor` (roundoff noise),
  !> so that a force that vanishes in theory prints as 0 with angle 0.
  pure function snap_noise(v, floor) result(w)
    !> Any plane vector.
    real(wp), intent(in) :: v(2)
    !> Noise floor, same unit as v (>= 0).
    real(wp), intent(in) :: floor
    real(wp) :: w(2)
    if (magnitude(v) <= floor) then
      w = 0.0_wp
    else
      w = v
    end if
  end function snap_noise

end module kinetostat_vec2
