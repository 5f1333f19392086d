!> The one wrapper around LAPACK: dense solve with a condition estimate, `info` turned into `error_t`.
!>
!> The singular-position test is dgecon's estimate against rcond_threshold, as it always was;
!> dgecon is called only when a cheap bound cannot settle it. dgecon's rcond is 1/(anorm*est)
!> with est <= ||(LU)^-1||_1 (a lower-bound estimator), and ||(LU)^-1||_1 <=
!> ||U^-1||_1 * ||L^-1||_1, which the explicit triangular inverses give in ~n^3/3 flops. When
!> 1/(anorm * that bound) is at least screen_factor * rcond_threshold, dgecon's rcond is above
!> the threshold too (by a margin far beyond the roundoff of either computation), so the
!> answer is the same without calling it; otherwise dgecon decides exactly as before.
module kinetostat_lapack
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  implicit none
  private
  public :: solve_dense, rcond_threshold, singular_by_estimate

  !> Margin of the cheap test: dgecon is skipped only when the bound puts rcond at least this
  !> many times above the threshold.
  real(wp), parameter :: screen_factor = 10.0_wp

  !> Reciprocal condition number below which a system counts as singular (dead position).
  real(wp), parameter :: rcond_threshold = 1.0e-12_wp

  ! LAPACK's Fortran 77 interfaces take assumed-size arrays.
  ! allow(assumed-size)
  interface
    !> LU factorisation and solve of a general system (LAPACK).
    pure subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      implicit none
      integer, intent(in) :: n, nrhs, lda, ldb
      real(wp), intent(inout) :: a(lda, *), b(ldb, *)
      integer, intent(out) :: ipiv(*)
      integer, intent(out) :: info
    end subroutine dgesv
    !> Reciprocal condition number estimate from an LU factorisation (LAPACK).
    pure subroutine dgecon(norm, n, a, lda, anorm, rcond, work, iwork, info)
      import :: wp
      implicit none
      character, intent(in) :: norm
      integer, intent(in) :: n, lda
      real(wp), intent(in) :: a(lda, *), anorm
      real(wp), intent(out) :: rcond
      real(wp), intent(inout) :: work(*)
      integer, intent(inout) :: iwork(*)
      integer, intent(out) :: info
    end subroutine dgecon
  end interface

contains

  !> Solve a*x = b for a small dense square system; singular or ill-conditioned -> geometry error.
  pure subroutine solve_dense(a, b, x, error, rcond)
    !> Coefficient matrix (n x n), unchanged.
    real(wp), intent(in) :: a(:, :)
    !> Right-hand side (n).
    real(wp), intent(in) :: b(:)
    !> Solution (n).
    real(wp), intent(out) :: x(:)
    !> Set when the matrix is singular or its reciprocal condition is below `rcond_threshold`.
    type(error_t), allocatable, intent(out) :: error
    !> Reciprocal condition number estimate (1-norm, dgecon's), if wanted (then always computed).
    real(wp), intent(out), optional :: rcond
    real(wp) :: lu(size(a, 1), size(a, 1)), rhs(size(a, 1), 1)
    real(wp) :: anorm, rc
    integer :: ipiv(size(a, 1)), info, n
    logical :: settled

    n = size(a, 1)
    x = 0.0_wp
    if (present(rcond)) rcond = 0.0_wp
    lu = a
    rhs(:, 1) = b
    anorm = maxval(sum(abs(a), dim=1))
    call dgesv(n, 1, lu, n, ipiv, rhs, n, info)
    if (info > 0) then
      call fatal_error(error, exit_geometry, "singular system (zero pivot)")
      return
    else if (info < 0) then
      call fatal_error(error, exit_geometry, "dgesv: illegal argument")
      return
    end if
    settled = .false.
    if (.not. present(rcond)) settled = 1.0_wp / (anorm * inverse_norm_bound(lu)) >= screen_factor * rcond_threshold
    if (.not. settled) then
      call estimate_rcond(lu, anorm, rc, info)
      if (present(rcond)) rcond = rc
      if (info /= 0 .or. .not. (rc >= rcond_threshold)) then
        call fatal_error(error, exit_geometry, "ill-conditioned system (dead or singular position)")
        return
      end if
    end if
    x = rhs(:, 1)
  end subroutine solve_dense

  !> dgecon's reciprocal condition estimate (1-norm) from the LU factors.
  pure subroutine estimate_rcond(lu, anorm, rc, info)
    real(wp), intent(in) :: lu(:, :)
    real(wp), intent(in) :: anorm
    real(wp), intent(out) :: rc
    integer, intent(out) :: info
    real(wp) :: work(4 * size(lu, 1))
    integer :: iwork(size(lu, 1)), n
    n = size(lu, 1)
    call dgecon('1', n, lu, n, anorm, rc, work, iwork, info)
  end subroutine estimate_rcond

  !> An upper bound of ||(L U)^-1||_1 from dgetrf's factors in `lu` (unit lower L below the
  !> diagonal, U on and above it): ||U^-1||_1 * ||L^-1||_1, from the explicit inverses.
  pure real(wp) function inverse_norm_bound(lu)
    real(wp), intent(in) :: lu(:, :)
    real(wp) :: col(size(lu, 1)), norm_l, norm_u, s
    integer :: n, i, j, k
    n = size(lu, 1)
    norm_u = 0.0_wp
    norm_l = 0.0_wp
    do j = 1, n
      ! column j of U^-1: U col = e_j (back substitution, rows j..1)
      col(j) = 1.0_wp / lu(j, j)
      do i = j - 1, 1, -1
        s = 0.0_wp
        do k = i + 1, j
          s = s + lu(i, k) * col(k)
        end do
        col(i) = -s / lu(i, i)
      end do
      norm_u = max(norm_u, sum(abs(col(1:j))))
      ! column j of L^-1: L col = e_j (forward substitution, rows j..n, unit diagonal)
      col(j) = 1.0_wp
      do i = j + 1, n
        s = 0.0_wp
        do k = j, i - 1
          s = s + lu(i, k) * col(k)
        end do
        col(i) = -s
      end do
      norm_l = max(norm_l, sum(abs(col(j:n))))
    end do
    inverse_norm_bound = norm_u * norm_l
  end function inverse_norm_bound

  !> The singular-position test as it was before the cheap bound: dgesv's zero pivot, or
  !> dgecon's estimate below rcond_threshold (the reference of the tests).
  pure logical function singular_by_estimate(a)
    !> Coefficient matrix (n x n).
    real(wp), intent(in) :: a(:, :)
    real(wp) :: lu(size(a, 1), size(a, 1)), rhs(size(a, 1), 1), rc
    integer :: ipiv(size(a, 1)), info, n
    n = size(a, 1)
    lu = a
    rhs = 1.0_wp
    call dgesv(n, 1, lu, n, ipiv, rhs, n, info)
    singular_by_estimate = info /= 0
    if (singular_by_estimate) return
    call estimate_rcond(lu, maxval(sum(abs(a), dim=1)), rc, info)
    singular_by_estimate = info /= 0 .or. .not. (rc >= rcond_threshold)
  end function singular_by_estimate

end module kinetostat_lapack
