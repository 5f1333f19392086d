!> The one wrapper around LAPACK: dense solve with a condition estimate, `info` turned into `error_t`.
module kinetostat_lapack
  use kinetostat_kinds, only: wp
  use kinetostat_error, only: error_t, fatal_error, exit_geometry
  implicit none
  private
  public :: solve_dense, rcond_threshold

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
    !> Reciprocal condition number estimate (1-norm), if wanted.
    real(wp), intent(out), optional :: rcond
    real(wp) :: lu(size(a, 1), size(a, 1)), rhs(size(a, 1), 1), work(4 * size(a, 1))
    real(wp) :: anorm, rc
    integer :: ipiv(size(a, 1)), iwork(size(a, 1)), info, n

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
    call dgecon('1', n, lu, n, anorm, rc, work, iwork, info)
    if (present(rcond)) rcond = rc
    if (info /= 0 .or. .not. (rc >= rcond_threshold)) then
      call fatal_error(error, exit_geometry, "ill-conditioned system (dead or singular position)")
      return
    end if
    x = rhs(:, 1)
  end subroutine solve_dense

end module kinetostat_lapack
