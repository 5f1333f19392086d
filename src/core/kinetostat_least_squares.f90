!> Linear least squares: min |a x - b| by Householder QR (the counterweights of `kinetostat
!> balance`: a few unknowns against many sampled positions).
module kinetostat_least_squares
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  implicit none
  private
  public :: least_squares

contains

  !> Least squares min |a x - b| by Householder QR; an error when a's columns are
  !> (numerically) dependent.
  pure subroutine least_squares(a, b, x, error)
    real(wp), intent(inout) :: a(:, :)
    real(wp), intent(inout) :: b(:)
    real(wp), intent(out) :: x(:)
    type(error_t), allocatable, intent(out) :: error
    integer :: m, n, j, i
    real(wp) :: alpha, v(size(a, 1)), beta, largest
    m = size(a, 1)
    n = size(a, 2)
    x = 0.0_wp
    if (m < n) then
      call fatal_error(error, exit_geometry, "fewer equations than unknowns")
      return
    end if
    do j = 1, n
      alpha = norm2(a(j:m, j))
      if (a(j, j) > 0.0_wp) alpha = -alpha
      v = 0.0_wp
      v(j:m) = a(j:m, j)
      v(j) = v(j) - alpha
      beta = dot_product(v(j:m), v(j:m))
      if (beta > 0.0_wp) then
        do i = j, n
          a(j:m, i) = a(j:m, i) - 2.0_wp * v(j:m) * dot_product(v(j:m), a(j:m, i)) / beta
        end do
        b(j:m) = b(j:m) - 2.0_wp * v(j:m) * dot_product(v(j:m), b(j:m)) / beta
      end if
    end do
    largest = 0.0_wp
    do j = 1, n
      largest = max(largest, abs(a(j, j)))
    end do
    do j = n, 1, -1
      if (.not. abs(a(j, j)) > 1.0e-10_wp * largest) then
        call fatal_error(error, exit_geometry, "dependent columns")
        return
      end if
      x(j) = (b(j) - dot_product(a(j, j + 1:n), x(j + 1:n))) / a(j, j)
    end do
  end subroutine least_squares

end module kinetostat_least_squares
